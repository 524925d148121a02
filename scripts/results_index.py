#!/usr/bin/python3
"""Writes results/index.html: a link to every committed run in results/ (the compare runs,
the papers' tables, the animated scenes, the corpus, the GPU runs), each run's page
(index.html) where it has one and its tables otherwise, from the files git tracks, so the
page names only what a clone holds. Also lists committed tables that carry an absolute path
(a machine's folder: they should carry paths relative to the repository).

usage: scripts/results_index.py [--check]
  --check: write nothing; exit 1 when results/index.html is out of date or a table holds an
           absolute path."""
import fnmatch
import html
import os
import re
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STYLE = os.path.join(REPO, "testbed", "report", "html", "report.css")

# (title, how it is made, folder patterns under the repository root), in page order.
SECTIONS = [
    ("Comparisons on llvmpipe", "scripts/results.sh", ["results/*-[0-9]*"]),
    ("Paper tables", "scripts/paper.sh", ["results/paper/*"]),
    ("Animated scenes", "scripts/motion.sh", ["results/motion/*"]),
    ("Corpus", "scripts/corpus.sh", ["results/corpus"]),
    ("GPU runs", "scripts/gpu_run.sh", ["results/gpu", "results/gpu/compare/*", "results/gpu/paper/*"]),
    ("Debug views", "scripts/results.sh", ["results/debug"]),
]
PAGES = ["index.html", "report.md", "stats.md", "README.md"]  # a run's main page, first found
SHOWN = (".html", ".md", ".svg", ".png")
ABSOLUTE = re.compile(r"(?<![\w.])/(?:work|home|tmp|root|mnt|scratch)/[^\s\"'`|)]+")


def tracked():
    out = subprocess.run(["git", "-C", REPO, "ls-files", "results"], capture_output=True, text=True, check=True)
    return [line for line in out.stdout.splitlines() if line]


def folders_of(files):
    by_folder = {}
    for path in files:
        by_folder.setdefault(os.path.dirname(path), []).append(os.path.basename(path))
    return by_folder


def main_page(folder, names):
    for name in PAGES + [os.path.basename(folder) + ".md"]:
        if name in names:
            return name
    markdown = sorted(n for n in names if n.endswith(".md"))
    return markdown[0] if markdown else sorted(names)[0]


def run_entry(folder, names, by_folder):
    relative = os.path.relpath(folder, "results")
    page = main_page(folder, names)
    links = [f'<a href="{html.escape(relative)}/{html.escape(page)}"><b>{html.escape(relative)}</b></a>']
    shown = sorted(n for n in names if n.endswith(SHOWN) and n != page and not n.endswith("_error_over_time.png"))
    # A run's own subfolders with a table (a corpus's stats/ and cost/), but not its scenes.
    shown += sorted(os.path.relpath(os.path.join(sub, main_page(sub, by_folder[sub])), folder) for sub in by_folder
                    if os.path.dirname(sub) == folder and os.path.basename(sub) != "scenes"
                    and main_page(sub, by_folder[sub]).endswith((".md", ".html")))
    links += [f'<a href="{html.escape(relative)}/{html.escape(n)}">{html.escape(n)}</a>' for n in shown]
    videos = sum(n.endswith(".mp4") for n in names)
    if videos:
        links.append(f"{videos} videos")
    return "<li>" + " · ".join(links) + "</li>"


def page(files):
    by_folder = folders_of(files)
    placed = {"results"}
    body = []
    for title, script, patterns in SECTIONS:
        runs = sorted(f for f in by_folder if any(fnmatch.fnmatch(f, p) and f.count("/") == p.count("/")
                                                    for p in patterns))
        placed.update(runs)
        if not runs:
            continue
        body.append(f"<h2>{html.escape(title)}</h2>\n<p class=\"note\">Made by <code>{script}</code>.</p>\n<ul>")
        body += [run_entry(f, by_folder[f], by_folder) for f in runs]
        body.append("</ul>")
    # Folders inside a listed run (a corpus's runs/, its scenes/) belong to it.
    others = sorted(f for f in by_folder if not any(f == p or f.startswith(p + "/") for p in placed))
    if others:
        body.append("<h2>Other</h2>\n<ul>")
        body += [run_entry(f, by_folder[f], by_folder) for f in others]
        body.append("</ul>")
    with open(STYLE) as f:
        style = f.read()
    top = [n for n in ("README.md", "paper/README.md", "gpu/README.md") if os.path.join("results", n) in files]
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            "<link rel=\"icon\" href=\"data:,\">\n<title>Results</title>\n<style>\n" + style + "</style>\n</head>\n"
            "<body>\n<h1>Results</h1>\n<p class=\"note\">Every run committed in results/, made by "
            "<code>scripts/results_index.py</code> from the files git tracks. A run's index.html (sortable "
            "records, image viewer, plots: docs/html-report.md) where it has one, its tables otherwise. "
            "The tables in one file: " + ", ".join(f'<a href="{n}">{n}</a>' for n in top) + ".</p>\n"
            + "\n".join(body) + "\n</body>\n</html>\n")


def absolute_paths(files):
    """Committed tables (Markdown and their JSON) that name a machine's folder."""
    found = []
    for path in files:
        if not path.endswith((".md", ".json")) or "/scenes/" in path or path.endswith("/spec.json"):
            continue
        with open(os.path.join(REPO, path), errors="replace") as f:
            for number, line in enumerate(f, 1):
                for match in ABSOLUTE.findall(line):
                    found.append(f"{path}:{number}: {match}")
    return found


def main(argv):
    check = argv[1:] == ["--check"]
    if argv[1:] and not check:
        print(__doc__, file=sys.stderr)
        return 2
    files = tracked()
    files_for_page = [f for f in files if f != "results/index.html"]
    text = page(files_for_page)
    target = os.path.join(REPO, "results", "index.html")
    problems = absolute_paths(files)
    for line in problems:
        print(f"results_index: absolute path in a committed table: {line}", file=sys.stderr)
    if check:
        current = open(target).read() if os.path.exists(target) else ""
        if current != text:
            print("results_index: results/index.html is out of date (run scripts/results_index.py)", file=sys.stderr)
            return 1
        return 1 if problems else 0
    with open(target, "w") as f:
        f.write(text)
    print(f"results_index: wrote {os.path.relpath(target, REPO)}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
