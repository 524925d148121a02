#!/usr/bin/python3
"""Adds a corpus run's statistics and equal-cost view to its sweep's index.html
(docs/corpus.md "What results/corpus shows"): the page's data (the JSON that
testbed/report/html/report.js renders) gains, before the sweep's own sections, the
statistics across scenes (stats/stats.json) as tables, a matrix of every scene's error per
technique coloured by value whose entries link to the cell's record (#cell-N, in the
sweep's folded cell table), the statistics' box plots, the equal-cost tables
(cost/cost.json) with their Pareto plots, and links to the files. Run
again on the same folder, it replaces what it added.

usage: scripts/corpus_page.py DIR   (DIR: what scripts/corpus.sh writes; index.html is
       rewritten in place)"""
import html
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import metric_table  # noqa: E402
from page_data import PAGE_DATA, script_safe_json  # noqa: E402


class InputError(Exception):
    pass


def cell(text, value=None, href=""):
    c = {"t": text}
    if value is not None and isinstance(value, (int, float)) and math.isfinite(value):
        c["v"] = value
    if href:
        c["href"] = href
    return c


def table(title, notes, columns, rows, heat=False):
    t = {"type": "table", "title": title, "notes": notes,
         "columns": [{"heading": h, "numeric": n} for h, n in columns], "rows": rows}
    if heat:
        t["heat"] = True
    return t


def number(value, digits=4):
    return "–" if value is None else f"{value:.{digits}g}"


def read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as error:
        raise InputError(f"{path}: {error}") from error


def stats_sections(folder, stats, shown):
    """The statistics' tables of the metrics `shown` (ids, in the metric table's order), and
    apart from them their box plots: the tables come first on the page, the plots after the
    per-scene matrices."""
    sections, figures = [], []
    excluded = stats.get("excluded", {})
    for metric in shown:
        per_label = stats["metrics"].get(metric)
        if not per_label:
            continue
        rows = []
        for label, entry in per_label.items():
            s, v = entry["summary"], entry.get("vs_baseline") or {}
            ci = s.get("mean_ci95")
            rows.append({"cells": [
                cell(label), cell(str(s["n"]), s["n"]), cell(number(s["median"]), s["median"]),
                cell(f"{number(s['q1'])}–{number(s['q3'])}", s["q3"] - s["q1"]), cell(number(s["mean"]), s["mean"]),
                cell("–" if ci is None else f"[{number(ci[0])}, {number(ci[1])}]", None if ci is None else ci[0]),
                cell(number(v.get("median_ratio"), 3), v.get("median_ratio")),
                cell("–" if "win_rate" not in v else f"{100 * v['win_rate']:.0f} %", v.get("win_rate")),
                cell(number(v.get("wilcoxon_p"), 3), v.get("wilcoxon_p"))]})
        reference = stats.get("metric_notes", {}).get(metric, [])
        notes = [f"Over the scenes (N per row; {len(excluded)} excluded: their ground truth cannot rank techniques). "
                 f"Paired with the baseline {stats['baseline']} scene by scene: the median ratio technique / "
                 "baseline, the win rate (a tie counts half) and the two-sided Wilcoxon signed-rank p. CI: bootstrap "
                 "(BCa) 95 % interval of the mean. stats/stats.md holds every table."] + \
            [note[0].upper() + note[1:] for note in reference]
        sections.append(table(f"Across scenes: {metric}", notes,
                              [("technique", False), ("N", True), ("median", True), ("IQR", True), ("mean", True),
                               ("mean 95 % CI", True), ("ratio to " + stats["baseline"], True), ("win rate", True),
                               ("Wilcoxon p", True)], rows))
        if os.path.isfile(os.path.join(folder, "stats", metric + ".png")):
            figures.append({"type": "figure", "title": f"{metric} per scene (box: quartiles; points: scenes)",
                            "src": f"stats/{metric}.png", "href": f"stats/{metric}.png"})
    return sections, figures


def scenes_section(records, stats, metric="mismatch_pct"):
    """Every scene's error per technique at the statistics' map size, each entry linking to
    its cell's record on this page."""
    per_label = stats["metrics"].get(metric, {})
    labels = list(per_label)
    size = stats.get("shadow_map")
    cells = {}
    for r in records:
        if isinstance(r.get("cell"), int) and (size is None or r.get("shadow_map") == size):
            label = r.get("row") or r.get("technique")
            cells[(label, r.get("scene"))] = r["cell"]
    scenes = sorted({s for entry in per_label.values() for s in entry["scenes"]})
    rows = []
    for scene in scenes:
        row = [cell(scene, href=f"scenes/{scene}.json")]
        for label in labels:
            value = per_label[label]["scenes"].get(scene)
            link = f"#cell-{cells[(label, scene)]}" if (label, scene) in cells else ""
            row.append(cell(number(value, 3), value, link))
        rows.append({"cells": row})
    where = f" at shadow map {size}²" if size else ""
    return table(f"Every scene: {metric}{where}",
                 ["Scenes × techniques, coloured by the error on one scale for the whole matrix (green: lower, red: "
                  "higher; logarithmic where it spans more than two decades). A scene's name links to its file, an "
                  "entry to its cell's record in the folded cell table below. Flagged scenes are left out."],
                 [("scene", False)] + [(label, True) for label in labels], rows, heat=True)


def cost_sections(cost, folder="cost"):
    """The equal-cost tables of one cost view (FOLDER/cost.json: cost/ for the hard error,
    cost-<metric>/ for each soft one) with their Pareto plots."""
    sections = []
    for name, rows in cost.get("tables", {}).items():
        heading = metric_table.metric(name)["heading"]
        body = [{"cells": [cell(r["budget"]), cell(str(r["n"]), r["n"]), cell(number(r["budget_cost"]), r["budget_cost"]),
                           cell(number(r["budget_error"]), r["budget_error"]), cell(r["best"]),
                           cell(number(r["best_cost"]), r["best_cost"]), cell(number(r["best_error"]), r["best_error"]),
                           cell(r["scene_winner"] or "–"),
                           cell("–" if r["scene_winner_share"] is None else f"{100 * r['scene_winner_share']:.0f} %",
                                r["scene_winner_share"])]} for r in rows]
        sections.append(table(
            f"At equal cost ({heading})" + ("" if folder == "cost" else f": {cost['error']}"),
            [f"Error: {cost['error']}, over {cost['scenes']} scenes. For each configuration as the budget: the one "
             "with the least median error at no more median cost, and the one that wins most often scene by scene. "
             f"{folder}/cost.md holds the same tables; {folder}/scenes/ the plot of every scene."],
            [("budget", False), ("N", True), ("its cost", True), ("its error", True), ("least error at no more cost", False),
             ("cost", True), ("error", True), ("wins most scenes", False), ("share", True)], body))
        sections.append({"type": "figure", "title": f"Error against {heading}: each technique's Pareto front",
                         "src": f"{folder}/cost-{name}.png", "href": f"{folder}/cost-{name}.png"})
    return sections


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    folder = argv[1]
    page_path = os.path.join(folder, "index.html")
    try:
        with open(page_path, encoding="utf-8") as f:
            page = f.read()
        match = PAGE_DATA.search(page)
        if not match:
            raise InputError(f"{page_path}: no page-data script (not a testbed report page)")
        data = json.loads(match.group(2))
        stats = read_json(os.path.join(folder, "stats", "stats.json"))
        cost = read_json(os.path.join(folder, "cost", "cost.json"))
        records = read_json(os.path.join(folder, "records.json"))
        shown = [m["id"] for m in metric_table.error_metrics()]
        # Beside the hard error: every soft metric the statistics hold, scene by scene and
        # at equal cost (scripts/corpus.sh draws cost-<metric>/ for each).
        soft = [m["id"] for m in metric_table.error_metrics() if m["reference"] == "soft" and m["id"] in stats["metrics"]]
        soft_costs = [(f"cost-{name}", read_json(os.path.join(folder, f"cost-{name}", "cost.json"))) for name in soft
                      if os.path.isfile(os.path.join(folder, f"cost-{name}", "cost.json"))]
    except (InputError, ValueError, metric_table.MetricTableError) as error:
        print(f"corpus_page: {error}", file=sys.stderr)
        return 2
    manifest = read_json(os.path.join(folder, "scenes", "manifest.json"))
    notes = []
    if os.path.isfile(os.path.join(folder, "command.txt")):
        with open(os.path.join(folder, "command.txt"), encoding="utf-8") as f:
            notes += [line.strip() for line in f if line.strip()]
    notes.append(f"Corpus: {len(manifest.get('scenes', []))} scenes, seed {manifest.get('seed')} (scenes/manifest.json).")
    stats_tables, box_plots = stats_sections(folder, stats, shown)
    added = stats_tables + [scenes_section(records, stats)] + \
        [scenes_section(records, stats, name) for name in soft] + box_plots + cost_sections(cost)
    for name, soft_cost in soft_costs:
        added += cost_sections(soft_cost, name)
    added.append({"type": "links", "title": "Corpus files", "items": [
        {"text": t, "href": h} for t, h in [("stats/findings.md (the findings as sentences)", "stats/findings.md"),
                                             ("stats/stats.md", "stats/stats.md"), ("stats/stats.json", "stats/stats.json"),
                                             ("stats-all-maps/stats.md (every map size, against sm at the largest)",
                                              "stats-all-maps/stats.md"),
                                             ("cost/cost.md", "cost/cost.md"), ("cost/cost.json", "cost/cost.json"),
                                             ("cost/scenes/ (per scene)", "cost/scenes/")] +
                                            [(f"{name}/cost.md", f"{name}/cost.md") for name, _ in soft_costs] + [
                                             ("scenes/manifest.json (what was sampled)", "scenes/manifest.json"),
                                             ("command.txt", "command.txt")] if os.path.exists(os.path.join(folder, h))]})
    # Run again (after new statistics), it replaces what it added before.
    before = data.pop("corpus_page", {"notes": 0, "sections": 0})
    data["title"] = f"Corpus: {len(manifest.get('scenes', []))} scenes, seed {manifest.get('seed')}"
    data["notes"] = notes + data.get("notes", [])[before["notes"]:]
    data["sections"] = added + data.get("sections", [])[before["sections"]:]
    data["corpus_page"] = {"notes": len(notes), "sections": len(added)}
    text = script_safe_json(data)
    page = page[:match.start(2)] + text + page[match.end(2):]
    title = f"<title>{html.escape(data['title'])}</title>"
    page = re.sub(r"<title>.*?</title>", lambda _: title, page, count=1, flags=re.S)  # no group references
    with open(page_path + ".tmp", "w", encoding="utf-8") as f:
        f.write(page)
    os.replace(page_path + ".tmp", page_path)
    print(f"corpus_page: {page_path}: {len(added)} sections added", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
