#!/usr/bin/python3
"""Error at equal cost (docs/corpus.md "Equal-cost view") from a sweep's records over
techniques × shadow-map sizes (× parameters a row varies): each configuration's error
against its cost (frame time, memory, shader invocations where the records count them),
with each technique's Pareto front, per scene and across the scenes (medians), and a table
answering "at the cost of T at size s, which technique and size has the least error".
Writes cost.md, cost.json, cost-<cost>.png and scenes/<scene>.png into --out.

A configuration is a record's row label (a sweep names it; else the technique id) at its
shadow-map size; a technique's front joins its configurations that no cheaper one of the
same technique beats. Records whose ground truth is flagged (error.flag) are left out, as
in corpus_stats.py. Uses Debian's python3-numpy and python3-matplotlib.
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import metric_table  # noqa: E402
from markdown_text import markdown_text  # noqa: E402
from corpus_stats import REFERENCES, InputError, load_records  # noqa: E402

# The costs, as derived figures the records carry (computed by the testbed, never here).
COSTS = ["frame_ms", "memory_mb", "invocations_k"]


def cost_title(cost):
    return metric_table.metric(cost)["heading"]


def configuration(record):
    row = record.get("row")
    label = row if isinstance(row, str) and row else record["technique"]
    return f"{label} @{record.get('shadow_map')}"


def organise(records, error_name):
    """{scene: {config: {"technique", "error", cost...}}} and the flagged scenes."""
    scenes, flagged = {}, {}
    for record in records:
        if record.get("technique") in REFERENCES or not isinstance(record.get("error"), dict):
            continue
        if record["error"].get("flag"):
            flagged[record["scene"]] = record["error"]["flag"]
            continue
        error = metric_table.value(record, error_name)
        if error is None:
            continue
        point = {"technique": record["technique"], "error": error}
        for name in COSTS:
            point[name] = metric_table.value(record, name)
        scenes.setdefault(record["scene"], {})[configuration(record)] = point
    for scene in flagged:
        scenes.pop(scene, None)
    return scenes, flagged


def pareto_front(points):
    """The (cost, error, name) points no cheaper-or-equal point beats, in cost order."""
    front, best = [], float("inf")
    for cost, error, name in sorted(points):
        if error < best:
            front.append((cost, error, name))
            best = error
    return front


def corpus_medians(scenes, cost_name):
    """Per configuration: technique, N, median cost, median error over the scenes holding it."""
    values = {}
    for per_config in scenes.values():
        for config, point in per_config.items():
            if point[cost_name] is not None:
                entry = values.setdefault(config, {"technique": point["technique"], "cost": [], "error": []})
                entry["cost"].append(point[cost_name])
                entry["error"].append(point["error"])
    return {config: {"technique": v["technique"], "n": len(v["cost"]), "cost": float(np.median(v["cost"])),
                     "error": float(np.median(v["error"]))} for config, v in values.items()}


def equal_cost_table(scenes, medians, cost_name):
    """For each configuration as the budget: the least-error configuration at no more cost,
    over the corpus's medians, and per scene (how often each configuration wins)."""
    rows = []
    for config, budget in sorted(medians.items()):
        affordable = [(m["error"], m["cost"], c) for c, m in medians.items() if m["cost"] <= budget["cost"]]
        error, cost, best = min(affordable)
        wins, n = {}, 0
        for per_config in scenes.values():
            own = per_config.get(config)
            if own is None or own[cost_name] is None:
                continue
            options = [(p["error"], p[cost_name], c) for c, p in per_config.items()
                       if p[cost_name] is not None and p[cost_name] <= own[cost_name]]
            winner = min(options)[2]
            wins[winner] = wins.get(winner, 0) + 1
            n += 1
        top = max(wins.items(), key=lambda item: (item[1], item[0])) if wins else (None, 0)
        rows.append({"budget": config, "budget_cost": budget["cost"], "budget_error": budget["error"], "best": best,
                     "best_cost": cost, "best_error": error, "n": n, "scene_winner": top[0],
                     "scene_winner_share": top[1] / n if n else None})
    return rows


def number(value, digits=4):
    return "–" if value is None else f"{value:.{digits}g}"


def markdown(tables, error_name, flagged, scene_count):
    lines = ["# Error at equal cost", "",
             f"Error: `{error_name}` (lower is better). {scene_count} scenes; a configuration's point is its median "
             "cost and median error over the scenes that hold it (N). For each configuration as the budget: the "
             "configuration with the least median error at no more median cost, and the configuration that wins most "
             "often scene by scene (least error at no more cost on that scene), with its share of the scenes.", ""]
    for scene, flag in sorted(flagged.items()):
        lines.append(f"- excluded: scene {markdown_text(scene)} ({flag})")
    if flagged:
        lines.append("")
    for cost_name, title, rows in tables:
        lines += [f"## At the cost of …: {title}", "",
                  "| budget: configuration | N | its cost | its error | least error at no more cost | cost | error | "
                  "wins most scenes | share |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for r in rows:
            share = "–" if r["scene_winner_share"] is None else f"{100 * r['scene_winner_share']:.0f} %"
            lines.append(f"| {markdown_text(r['budget'])} | {r['n']} | {number(r['budget_cost'])} | {number(r['budget_error'])} | "
                         f"{markdown_text(r['best'])} | {number(r['best_cost'])} | {number(r['best_error'])} | "
                         f"{markdown_text(r['scene_winner'] or '–')} | {share} |")
        lines.append("")
    return "\n".join(lines)


def draw(axis, points, xlabel, ylabel):
    """Every configuration as a point, each technique's front as a line."""
    import matplotlib.pyplot as plt
    palette = plt.get_cmap("tab20")
    techniques = sorted({t for t, _, _, _ in points})
    for index, technique in enumerate(techniques):
        own = [(cost, error, name) for t, cost, error, name in points if t == technique]
        colour = palette(index % palette.N)
        axis.scatter([p[0] for p in own], [p[1] for p in own], s=14, color=colour, alpha=0.5)
        front = pareto_front(own)
        axis.plot([p[0] for p in front], [p[1] for p in front], marker="o", color=colour, label=technique)
    axis.set_xscale("log")
    axis.set_xlabel(xlabel)
    axis.set_ylabel(ylabel)
    axis.grid(alpha=0.3)


def plot(scenes, tables, error_name, out_dir):
    import matplotlib
    matplotlib.use("Agg")  # headless
    # Labels come from users' specs and scenes: text, never TeX ("$5", "$\frac$").
    matplotlib.rcParams["text.parse_math"] = False
    import matplotlib.pyplot as plt
    for cost_name, title, _ in tables:
        medians = corpus_medians(scenes, cost_name)
        figure, axis = plt.subplots(figsize=(8, 5.5))
        draw(axis, [(m["technique"], m["cost"], m["error"], c) for c, m in medians.items()], title,
             f"median {error_name}")
        axis.set_title(f"{error_name} against {title}: medians over {len(scenes)} scenes, each technique's front")
        axis.legend(fontsize=7, ncol=2)
        figure.tight_layout()
        figure.savefig(os.path.join(out_dir, f"cost-{cost_name}.png"), dpi=110, metadata={"Software": None})
        plt.close(figure)
    os.makedirs(os.path.join(out_dir, "scenes"), exist_ok=True)
    for scene, per_config in sorted(scenes.items()):
        figure, axes = plt.subplots(1, len(tables), figsize=(5 * len(tables), 4.5), squeeze=False)
        for axis, (cost_name, title, _) in zip(axes.flat, tables):
            draw(axis, [(p["technique"], p[cost_name], p["error"], c) for c, p in per_config.items()
                        if p[cost_name] is not None], title, error_name)
        axes.flat[0].legend(fontsize=7)
        figure.suptitle(f"{scene}: {error_name} against cost, each technique's front")
        figure.tight_layout()
        figure.savefig(os.path.join(out_dir, "scenes", f"{scene}.png"), dpi=90, metadata={"Software": None})
        plt.close(figure)


def soft_metrics_held(records):
    """The metric table's soft metrics (measured against the area-light reference) that a
    technique record holds, in table order."""
    measured = [r for r in records if r.get("technique") not in REFERENCES and isinstance(r.get("error"), dict)]
    return [m["id"] for m in metric_table.error_metrics()
            if m["reference"] == "soft" and any(metric_table.value(r, m["id"]) is not None for r in measured)]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("records", nargs="+", help="a sweep's records.json, or folders holding them")
    parser.add_argument("--out", help="folder for cost.md, cost.json and the plots")
    parser.add_argument("--error", default="mismatch_pct", help="error metric (an id of `testbed metrics`)")
    parser.add_argument("--no-plot", action="store_true", help="skip the plots")
    parser.add_argument("--list-soft", action="store_true",
                        help="print the soft metrics (against the area-light reference) some record holds, one a "
                             "line, and write nothing: scripts/corpus.sh draws a view of each")
    args = parser.parse_args(argv)
    if not args.list_soft and not args.out:
        parser.error("--out is required")
    try:
        if args.list_soft:
            print("\n".join(soft_metrics_held(load_records(args.records))))
            return 0
        if args.error not in metric_table.ids():
            raise InputError(f"--error: no metric '{args.error}' in the testbed's metric table")
        if metric_table.metric(args.error)["reference"] == "none":
            raise InputError(f"--error: {args.error} is not an error metric")
        scenes, flagged = organise(load_records(args.records, with_derived=True), args.error)
        if not scenes:
            raise InputError(f"--error: no technique record has error.{args.error} (besides references and flagged scenes)")
    except (InputError, metric_table.MetricTableError) as error:
        print(f"corpus_cost: {error}", file=sys.stderr)
        return 2
    tables = []
    for cost_name in COSTS:
        medians = corpus_medians(scenes, cost_name)
        if medians:
            tables.append((cost_name, cost_title(cost_name), equal_cost_table(scenes, medians, cost_name)))
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "cost.md"), "w", encoding="utf-8") as handle:
        handle.write(markdown(tables, args.error, flagged, len(scenes)) + "\n")
    with open(os.path.join(args.out, "cost.json"), "w", encoding="utf-8") as handle:
        json.dump({"error": args.error, "scenes": len(scenes), "excluded": flagged,
                   "tables": {name: rows for name, _, rows in tables},
                   "medians": {name: corpus_medians(scenes, name) for name, _, _ in tables}}, handle, indent=1,
                  sort_keys=True)
        handle.write("\n")
    if not args.no_plot:
        plot(scenes, tables, args.error, args.out)
    print(f"corpus_cost: {len(scenes)} scenes, {len(tables)} costs, {len(flagged)} excluded -> {args.out}",
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
