#!/usr/bin/python3
"""Statistics across scenes (docs/corpus.md) from testbed records: `compare`'s
metrics.json (a folder of one folder per scene, or the files themselves) or a sweep's
records.json. Per technique and metric: N, median, IQR, mean with a bootstrap 95 %
confidence interval; against a baseline technique, paired by scene: the median per-scene
ratio, the win rate and the Wilcoxon signed-rank p-value; a box-and-strip plot per metric.
Writes stats.md, stats.json and <metric>.png into --out.

Scenes whose ground truth has no shadow boundary, or is entirely lit or unlit from the
camera, score 0 error for every technique; records flagged so (error.flag) are excluded,
with a line saying which. Uses Debian's python3-numpy, python3-scipy, python3-matplotlib.
"""
import argparse
import json
import math
import os
import sys
import warnings

import numpy as np
from scipy import stats

# (name, where in the record, what it says); lower is better for all of them.
METRICS = [
    ("mismatch_pct", ("error", "mismatch_pct"), "% of receivers in the wrong binary state"),
    ("edge_mismatch_pct", ("error", "edge_mismatch_pct"), "% wrong within 3 px of a ground-truth boundary"),
    ("rmse", ("error", "rmse"), "RMSE of visibility"),
    ("leak_pct", ("error", "leak_pct"), "% of deep-shadow receivers lit"),
    ("overestimation_pct", ("error", "overestimation_pct"), "% of deep-lit receivers shadowed"),
    ("boundary_mean_px", ("error", "boundary_px", "mean"), "mean boundary distance, px"),
    ("boundary_p95_px", ("error", "boundary_px", "p95"), "95th percentile boundary distance, px"),
    ("soft_rmse", ("error", "soft_rmse"), "RMSE against the area-light reference"),
]
REFERENCES = {"groundtruth", "area", "raycast"}
BOOTSTRAP_RESAMPLES = 9999
BOOTSTRAP_SEED = 20261204  # fixed: the same records give the same intervals


class InputError(Exception):
    pass


def lookup(record, path):
    value = record
    for key in path:
        if not isinstance(value, dict) or key not in value:
            return None
        value = value[key]
    return value if isinstance(value, (int, float)) and not isinstance(value, bool) else None


def record_files(paths):
    """metrics.json / records.json files named, or found in a folder or its subfolders."""
    files = []
    for path in paths:
        if os.path.isfile(path):
            files.append(path)
            continue
        if not os.path.isdir(path):
            raise InputError(f"{path}: no such file or folder")
        found = [os.path.join(path, n) for n in ("metrics.json", "records.json") if os.path.isfile(os.path.join(path, n))]
        for sub in sorted(os.listdir(path)):
            candidate = os.path.join(path, sub, "metrics.json")
            if os.path.isfile(candidate):
                found.append(candidate)
        if not found:
            raise InputError(f"{path}: holds no metrics.json or records.json (nor do its subfolders)")
        files.extend(found)
    return files


def load_records(paths):
    records = []
    for file in record_files(paths):
        try:
            with open(file, encoding="utf-8") as handle:
                data = json.load(handle)
        except (OSError, ValueError) as error:
            raise InputError(f"{file}: {error}") from error
        if not isinstance(data, list):
            raise InputError(f"{file}: expected an array of records")
        for index, record in enumerate(data):
            if not isinstance(record, dict) or not isinstance(record.get("technique"), str) \
                    or not isinstance(record.get("scene"), str):
                raise InputError(f"{file}: [{index}]: expected a record with technique and scene")
            records.append(record)
    return records


def label_of(record, several_sizes):
    """The technique's id; a sweep record's row label instead (it names the parameters a
    row varies: "pcf kernel=5"), with the map size where the records hold several."""
    row = record.get("row")
    name = row if isinstance(row, str) and row else record["technique"]
    return name + (f" @{record.get('shadow_map')}" if several_sizes else "")


def organise(records):
    """{label: {scene: record}}, the flagged scenes {scene: flag}, and warning lines."""
    measured = [r for r in records if r["technique"] not in REFERENCES and isinstance(r.get("error"), dict)]
    several_sizes = len({r.get("shadow_map") for r in measured}) > 1
    flagged, table, notes = {}, {}, []
    for record in measured:
        flag = record["error"].get("flag")
        if flag:
            flagged[record["scene"]] = flag
            continue
        by_scene = table.setdefault(label_of(record, several_sizes), {})
        if record["scene"] in by_scene:
            notes.append(f"{label_of(record, several_sizes)} on {record['scene']}: more than one record, the first kept")
            continue
        by_scene[record["scene"]] = record
    for label in table:
        for scene in flagged:
            table[label].pop(scene, None)
    return table, flagged, notes


def bootstrap_mean_ci(values, confidence=0.95, resamples=BOOTSTRAP_RESAMPLES, seed=BOOTSTRAP_SEED):
    """The mean's bootstrap (BCa) confidence interval; a point when every value is equal,
    None below two values."""
    values = np.asarray(values, dtype=float)
    if values.size < 2:
        return None
    if np.all(values == values[0]):
        return (float(values[0]), float(values[0]))
    result = stats.bootstrap((values,), np.mean, confidence_level=confidence, n_resamples=resamples,
                             random_state=np.random.default_rng(seed))
    return (float(result.confidence_interval.low), float(result.confidence_interval.high))


def wilcoxon_p(values, baseline):
    """Two-sided Wilcoxon signed-rank p of the paired differences; None when every
    difference is 0 (nothing to rank)."""
    differences = np.asarray(values, dtype=float) - np.asarray(baseline, dtype=float)
    if not np.any(differences != 0):
        return None
    with warnings.catch_warnings():
        # Zeros or ties switch scipy to the normal approximation, with a warning per call;
        # the method is stated in stats.md instead.
        warnings.simplefilter("ignore", UserWarning)
        return float(stats.wilcoxon(differences).pvalue)


def summary(values):
    values = np.asarray(values, dtype=float)
    q1, median, q3 = np.percentile(values, [25, 50, 75])
    return {"n": int(values.size), "median": float(median), "q1": float(q1), "q3": float(q3),
            "mean": float(values.mean()), "mean_ci95": bootstrap_mean_ci(values)}


def paired(values, baseline):
    """Per-scene comparison of a technique with the baseline (lower is better)."""
    values, baseline = np.asarray(values, dtype=float), np.asarray(baseline, dtype=float)
    wins = float(np.sum(values < baseline) + 0.5 * np.sum(values == baseline))
    defined = baseline > 0
    ratios = values[defined] / baseline[defined]
    return {"n": int(values.size), "win_rate": wins / values.size,
            "median_ratio": float(np.median(ratios)) if ratios.size else None,
            "ratio_n": int(ratios.size), "wilcoxon_p": wilcoxon_p(values, baseline)}


def analyse(table, baseline):
    results = {}
    for name, path, _ in METRICS:
        per_label = {}
        for label in sorted(table):
            scenes = {s: lookup(r, path) for s, r in table[label].items()}
            scenes = {s: v for s, v in scenes.items() if v is not None and math.isfinite(v)}
            if not scenes:
                continue
            entry = {"summary": summary(list(scenes.values())), "scenes": scenes}
            base = table.get(baseline, {})
            common = sorted(s for s in scenes if s in base and lookup(base[s], path) is not None)
            if label != baseline and common:
                entry["vs_baseline"] = paired([scenes[s] for s in common], [lookup(base[s], path) for s in common])
            per_label[label] = entry
        if per_label:
            results[name] = per_label
    return results


def number(value, digits=4):
    return "–" if value is None else f"{value:.{digits}g}"


def markdown(results, baseline, flagged, notes):
    lines = ["# Statistics across scenes", ""]
    lines.append(f"Baseline of the paired comparison: `{baseline}`. Ratio: technique / baseline per scene "
                 "(scenes where the baseline is 0 left out of the ratio). Win: lower than the baseline (a tie counts "
                 "half). p: two-sided Wilcoxon signed-rank test of the paired differences (exact below 50 scenes without zero or tied "
                 "differences, else the normal approximation). CI: bootstrap (BCa, "
                 f"{BOOTSTRAP_RESAMPLES} resamples) 95 % confidence interval of the mean.")
    lines.append("")
    for scene, flag in sorted(flagged.items()):
        lines.append(f"- excluded: scene {scene} ({flag})")
    for note in notes:
        lines.append(f"- note: {note}")
    if flagged or notes:
        lines.append("")
    descriptions = {name: text for name, _, text in METRICS}
    for name, per_label in results.items():
        lines += [f"## {name}: {descriptions[name]}", ""]
        lines.append("| technique | N | median | IQR | mean | mean 95 % CI | vs baseline: N | median ratio | win rate | p |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|")
        for label, entry in per_label.items():
            s, v = entry["summary"], entry.get("vs_baseline")
            ci = "–" if s["mean_ci95"] is None else f"[{number(s['mean_ci95'][0])}, {number(s['mean_ci95'][1])}]"
            versus = ["–"] * 4 if v is None else [str(v["n"]), number(v["median_ratio"], 3),
                                                  f"{100 * v['win_rate']:.0f} %", number(v["wilcoxon_p"], 3)]
            lines.append(f"| {label} | {s['n']} | {number(s['median'])} | {number(s['q1'])}–{number(s['q3'])} | "
                         f"{number(s['mean'])} | {ci} | " + " | ".join(versus) + " |")
        lines.append("")
    return "\n".join(lines)


def plot(results, out_dir):
    import matplotlib
    matplotlib.use("Agg")  # headless
    # Labels come from users' specs and scenes: text, never TeX ("$5", "$\frac$").
    matplotlib.rcParams["text.parse_math"] = False
    import matplotlib.pyplot as plt
    written = []
    for name, per_label in results.items():
        labels = list(per_label)
        data = [list(per_label[label]["scenes"].values()) for label in labels]
        figure, axis = plt.subplots(figsize=(max(6, 0.6 * len(labels) + 2), 4.5))
        axis.boxplot(data, showfliers=False)
        jitter = np.random.default_rng(0)
        for index, values in enumerate(data, start=1):
            axis.scatter(index + jitter.uniform(-0.15, 0.15, len(values)), values, s=10, alpha=0.6, color="tab:blue")
        axis.set_xticks(range(1, len(labels) + 1))
        axis.set_xticklabels([f"{label}\nN={len(v)}" for label, v in zip(labels, data)], rotation=60, ha="right",
                             fontsize=7)
        axis.set_ylabel(name)
        axis.set_title(f"{name} per scene (box: quartiles; points: scenes)")
        figure.tight_layout()
        path = os.path.join(out_dir, f"{name}.png")
        figure.savefig(path, dpi=110, metadata={"Software": None})
        plt.close(figure)
        written.append(path)
    return written


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("records", nargs="+", help="metrics.json / records.json files, or folders holding them")
    parser.add_argument("--out", required=True, help="folder for stats.md, stats.json and the plots")
    parser.add_argument("--baseline", default="sm", help="technique label compared against (default: sm)")
    parser.add_argument("--shadow-map", type=int, help="only the records of this shadow-map size")
    parser.add_argument("--no-plot", action="store_true", help="skip the plots")
    args = parser.parse_args(argv)
    try:
        records = load_records(args.records)
        if args.shadow_map is not None:
            records = [r for r in records if r.get("shadow_map") == args.shadow_map]
            if not records:
                raise InputError(f"--shadow-map: no records of shadow map {args.shadow_map}")
        table, flagged, notes = organise(records)
        if not table:
            raise InputError("no technique records with an error block (besides the references)")
        if args.baseline not in table:
            raise InputError(f"--baseline: no records of '{args.baseline}' (have: {', '.join(sorted(table))})")
    except InputError as error:
        print(f"corpus_stats: {error}", file=sys.stderr)
        return 2
    results = analyse(table, args.baseline)
    os.makedirs(args.out, exist_ok=True)
    for scene, flag in sorted(flagged.items()):
        print(f"corpus_stats: excluded scene {scene}: {flag}", file=sys.stderr)
    with open(os.path.join(args.out, "stats.md"), "w", encoding="utf-8") as handle:
        handle.write(markdown(results, args.baseline, flagged, notes) + "\n")
    with open(os.path.join(args.out, "stats.json"), "w", encoding="utf-8") as handle:
        json.dump({"baseline": args.baseline, "shadow_map": args.shadow_map, "excluded": flagged, "notes": notes, "metrics": results}, handle,
                  indent=1, sort_keys=True)
        handle.write("\n")
    if not args.no_plot:
        plot(results, args.out)
    scenes = {s for per_label in table.values() for s in per_label}
    print(f"corpus_stats: {len(scenes)} scenes, {len(table)} techniques, {len(flagged)} excluded -> {args.out}",
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
