#!/usr/bin/env python3
"""Checks that the documentation's links and the code's citations of it resolve.

    scripts/check_doc_links.py [REPO_ROOT]

1. Every relative link and image in README.md and docs/*.md names a file or folder that
   exists. An anchor (`#...`) must be the slug of a heading in the target file, by
   GitHub's rules.
2. Every citation of a section in the code names a heading that exists in the file it
   cites. Citations look like `README "Command line"`, `README, "Techniques"` or
   `docs/paper-runs.md "Slurm"`, and may list several: `README "Techniques", "Layout"`. A
   comment may break a citation across lines. A docs/*.md path without a heading must
   name a file that exists.

Prints one line per problem (FILE:LINE: what) and exits 1 if there is any, 0 otherwise.
"""
import os
import re
import sys
import unicodedata

FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
INLINE_CODE = re.compile(r"`[^`]*`")
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s*\[[^\]]+\]:\s*(\S+)")
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")

# A citation: the cited file, a separator, then one or more quoted headings.
DOC = r"(README(?:\.md)?|docs/[A-Za-z0-9_.-]+\.md)"
QUOTED = r'\\?"([^"\\\n]+)\\?"'
CITATION = re.compile(DOC + r'(?:\s*[,:]\s*|\s+)' + QUOTED)
MORE = re.compile(r'\s*(?:,|and)\s*' + QUOTED)
DOC_PATH = re.compile(r"(?<![A-Za-z0-9_./-])(docs/[A-Za-z0-9_-]+\.md)\b")
# Comment continuations: a citation broken across `//` or `#` comment lines reads as one line.
CONTINUATION = re.compile(r"\n[ \t]*(?://|#)[ \t]*")

CODE_SUFFIXES = (".cpp", ".h", ".glsl", ".frag", ".vert", ".comp", ".geom", ".sh", ".py", ".cmake",
                 ".txt", ".sbatch", ".json")
SKIP_DIRS = {".git", "build", "assets", "results", "node_modules"}
# Other build folders (build-unity, build-sanitize) hold generated text too.
SKIP_PREFIXES = ("build-",)
# Its planted trees cite headings that do not exist, on purpose.
SKIP_FILES = {os.path.join("tests", "doc_links_test.py")}


def slug(heading):
    """GitHub's anchor for a heading: its rendered text, lower case, punctuation dropped,
    spaces as hyphens (github-slugger)."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text
    text = text.lower()
    kept = []
    for ch in text:
        if ch in " -_":
            kept.append(ch)
        elif unicodedata.category(ch)[0] in "LNM":  # letters, numbers, marks
            kept.append(ch)
    return "".join(kept).replace(" ", "-")


def markdown_lines(text):
    """(line number, line) of the lines outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def headings(path):
    """The heading texts of a markdown file and their anchors (duplicates get -1, -2, ...)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    texts, anchors, seen = [], set(), {}
    for _, line in markdown_lines(text):
        m = HEADING.match(line)
        if not m:
            continue
        texts.append(m.group(2))
        base = slug(m.group(2))
        n = seen.get(base, 0)
        anchors.add(base if n == 0 else f"{base}-{n}")
        seen[base] = n + 1
    return texts, anchors


class Checker:
    def __init__(self, root):
        self.root = os.path.abspath(root)
        self.problems = []
        self._headings = {}

    def headings_of(self, path):
        if path not in self._headings:
            self._headings[path] = headings(path)
        return self._headings[path]

    def problem(self, path, line, what):
        self.problems.append(f"{os.path.relpath(path, self.root)}:{line}: {what}")

    def check_markdown(self, path):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for number, line in markdown_lines(text):
            line = INLINE_CODE.sub("", line)
            targets = [m.group(1) for m in LINK.finditer(line)]
            m = REFERENCE.match(line)
            if m:
                targets.append(m.group(1))
            for target in targets:
                self.check_link(path, number, target)

    def check_link(self, path, line, target):
        if SCHEME.match(target):
            return  # a web address: not ours to check offline
        file_part, _, anchor = target.partition("#")
        resolved = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
        if not os.path.exists(resolved):
            self.problem(path, line, f"link to {target}: no such file")
            return
        if anchor:
            if not resolved.endswith(".md") or os.path.isdir(resolved):
                self.problem(path, line, f"link to {target}: an anchor into a file that is not markdown")
            elif anchor not in self.headings_of(resolved)[1]:
                self.problem(path, line, f"link to {target}: {os.path.relpath(resolved, self.root)} has no "
                             f"heading whose anchor is #{anchor}")

    def check_code(self, path):
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except UnicodeDecodeError:
            return
        # Continuations become spaces of the same length, so positions stay those of `text`.
        joined = CONTINUATION.sub(lambda c: " " * len(c.group(0)), text)

        def line_of(position):
            return text.count("\n", 0, position) + 1

        for m in CITATION.finditer(joined):
            doc = "README.md" if m.group(1).startswith("README") else m.group(1)
            cited = [m.group(2)]
            end = m.end()
            while True:
                more = MORE.match(joined, end)
                if not more:
                    break
                cited.append(more.group(1))
                end = more.end()
            self.check_citation(path, line_of(m.start()), doc, cited)
        for m in DOC_PATH.finditer(joined):
            if not os.path.isfile(os.path.join(self.root, m.group(1))):
                self.problem(path, line_of(m.start()), f"cites {m.group(1)}: no such file")

    def check_citation(self, path, line, doc, cited):
        target = os.path.join(self.root, doc)
        if not os.path.isfile(target):
            self.problem(path, line, f"cites {doc}: no such file")
            return
        texts = self.headings_of(target)[0]
        plain = {INLINE_CODE.sub(lambda c: c.group(0)[1:-1], t) for t in texts} | set(texts)
        for heading in cited:
            heading = re.sub(r"\s+", " ", heading).strip()
            if heading not in plain:
                self.problem(path, line, f'cites {doc} "{heading}": no such heading')

    def markdown_files(self):
        files = [os.path.join(self.root, "README.md")]
        docs = os.path.join(self.root, "docs")
        if os.path.isdir(docs):
            files += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
        return [f for f in files if os.path.isfile(f)]

    def code_files(self):
        for directory, dirs, files in os.walk(self.root):
            dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith(".") and not d.startswith(SKIP_PREFIXES))
            for name in sorted(files):
                path = os.path.join(directory, name)
                if name.endswith(CODE_SUFFIXES) and os.path.relpath(path, self.root) not in SKIP_FILES:
                    yield path

    def run(self):
        for path in self.markdown_files():
            self.check_markdown(path)
        for path in self.code_files():
            self.check_code(path)
        return self.problems


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    problems = Checker(root).run()
    for p in problems:
        print(p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
