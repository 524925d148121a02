#!/usr/bin/python3
"""Statistics across scenes (docs/corpus.md) from testbed records: `compare`'s
metrics.json (a folder of one folder per scene, or the files themselves) or a sweep's
records.json. Per technique and error metric (the metric table's, `testbed metrics
--json`): N, median, IQR, mean with a bootstrap 95 % confidence interval; against a
baseline technique, paired by scene: the median per-scene ratio, the win rate and the
Wilcoxon signed-rank p-value, Holm-adjusted across the techniques compared; the findings
written as sentences from those figures; a box-and-strip plot per metric. Writes stats.md,
findings.md, stats.json and <metric>.png into --out.

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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import metric_table  # noqa: E402
from markdown_text import markdown_code, markdown_text  # noqa: E402

REFERENCES = {"groundtruth", "area", "raycast"}
BOOTSTRAP_RESAMPLES = 9999
BOOTSTRAP_SEED = 20261204  # fixed: the same records give the same intervals
# The family-wise error rate the findings hold their "evidence" to, after Holm's correction
# across the techniques compared on one metric.
ALPHA = 0.05
# scipy's exact signed-rank distribution is for untied ranks of up to this many differences.
EXACT_LIMIT = 50
TEST_NAME = "two-sided Wilcoxon signed-rank test"


class InputError(Exception):
    pass


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


def load_records(paths, with_derived=False):
    """Every record of the files; with_derived: each with its "derived" block as the
    testbed computes it (records written before they carried it get it from `testbed
    metrics --derive`)."""
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
        if with_derived and not all(isinstance(r.get("derived"), dict) for r in data):
            metric_table.attach_derived(file, data)
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


def wilcoxon(values, baseline):
    """The two-sided Wilcoxon signed-rank test of the paired differences values - baseline,
    with the method chosen, and why: scipy's exact null distribution holds only for
    untied, non-zero differences (scipy 1.10's "auto" would compute an "exact" p from
    truncated tied ranks), so zero differences (dropped before ranking, zero_method
    "wilcox") or tied absolute differences force the normal approximation with scipy's tie
    correction, as does N > 50. None when every difference is 0 (nothing to rank)."""
    differences = np.asarray(values, dtype=float) - np.asarray(baseline, dtype=float)
    nonzero = differences[differences != 0]
    if nonzero.size == 0:
        return None
    zeros = int(differences.size - nonzero.size)
    _, counts = np.unique(np.abs(nonzero), return_counts=True)
    tied = int(counts[counts > 1].sum())  # differences sharing their |value| with another
    reasons = []
    if zeros:
        reasons.append(f"{zeros} zero difference{'s' * (zeros != 1)}")
    if tied:
        reasons.append(f"{tied} tied absolute differences")
    if nonzero.size > EXACT_LIMIT:
        reasons.append(f"{nonzero.size} differences, above the exact table's {EXACT_LIMIT}")
    method = "approx" if reasons else "exact"
    with warnings.catch_warnings():
        # The small-sample warning of the approximation: the method is stated instead.
        warnings.simplefilter("ignore", UserWarning)
        p = float(stats.wilcoxon(differences, method=method).pvalue)
    ranks = stats.rankdata(np.abs(nonzero))
    return {"p": p, "method": method, "reason": ", ".join(reasons), "zeros": zeros, "tied": tied,
            "ranked": int(nonzero.size), "w_plus": float(ranks[nonzero > 0].sum()),
            "w_minus": float(ranks[nonzero < 0].sum())}


def wilcoxon_p(values, baseline):
    test = wilcoxon(values, baseline)
    return None if test is None else test["p"]


def holm(p_values):
    """Holm's step-down adjustment (S. Holm, "A simple sequentially rejective multiple test
    procedure", Scandinavian Journal of Statistics 6(2), 1979): the i-th smallest of m
    p-values times (m - i + 1), made monotone, capped at 1. None stays None and does not
    count among the m."""
    order = sorted((p, i) for i, p in enumerate(p_values) if p is not None)
    adjusted, running = [None] * len(p_values), 0.0
    for rank, (p, i) in enumerate(order):
        running = max(running, min(1.0, (len(order) - rank) * p))
        adjusted[i] = running
    return adjusted


def summary(values):
    values = np.asarray(values, dtype=float)
    q1, median, q3 = np.percentile(values, [25, 50, 75])
    return {"n": int(values.size), "median": float(median), "q1": float(q1), "q3": float(q3),
            "mean": float(values.mean()), "mean_ci95": bootstrap_mean_ci(values)}


def paired(values, baseline):
    """Per-scene comparison of a technique with the baseline (lower is better): the win
    rate, the median per-scene ratio, the medians and means of both over the paired
    scenes, and the signed-rank test."""
    values, baseline = np.asarray(values, dtype=float), np.asarray(baseline, dtype=float)
    wins = float(np.sum(values < baseline) + 0.5 * np.sum(values == baseline))
    defined = baseline > 0
    ratios = values[defined] / baseline[defined]
    test = wilcoxon(values, baseline)
    return {"n": int(values.size), "win_rate": wins / values.size,
            "median_ratio": float(np.median(ratios)) if ratios.size else None, "ratio_n": int(ratios.size),
            "median": float(np.median(values)), "baseline_median": float(np.median(baseline)),
            "mean": float(values.mean()), "baseline_mean": float(baseline.mean()),
            "wilcoxon": test, "wilcoxon_p": None if test is None else test["p"]}


def analyse(table, baseline):
    results = {}
    for m in metric_table.error_metrics():
        name, per_label = m["id"], {}
        base = {s: metric_table.value(r, name) for s, r in table.get(baseline, {}).items()}
        for label in sorted(table):
            scenes = {s: metric_table.value(r, name) for s, r in table[label].items()}
            scenes = {s: v for s, v in scenes.items() if v is not None and math.isfinite(v)}
            if not scenes:
                continue
            entry = {"summary": summary(list(scenes.values())), "scenes": scenes}
            common = sorted(s for s in scenes if base.get(s) is not None)
            if label != baseline and common:
                entry["vs_baseline"] = paired([scenes[s] for s in common], [base[s] for s in common])
            per_label[label] = entry
        versus = [e["vs_baseline"] for e in per_label.values() if "vs_baseline" in e]
        for v, adjusted in zip(versus, holm([v["wilcoxon_p"] for v in versus])):
            v["holm_p"] = adjusted
            v["holm_m"] = sum(w["wilcoxon_p"] is not None for w in versus)
        if per_label:
            results[name] = per_label
    return results


def reference_notes(table, results, baseline):
    """{metric: [line]}: what each soft metric (the metric table's, against the area-light
    reference) was measured against and what it leaves out: the reference's samples and
    light radii as the records name them (area_reference), the techniques judged against
    the hard ground truth only (a hard output under a spec's default reference), and a
    baseline without the metric, which leaves the soft table without paired comparisons."""
    notes = {}
    for m in metric_table.error_metrics():
        name = m["id"]
        if m["reference"] != "soft" or name not in results:
            continue
        judged = [r for per_scene in table.values() for r in per_scene.values()
                  if metric_table.value(r, name) is not None]
        areas = [r["area_reference"] for r in judged if isinstance(r.get("area_reference"), dict)]
        samples = sorted({a.get("samples") for a in areas if isinstance(a.get("samples"), int)})
        radii = [a["light_radius"] for a in areas if isinstance(a.get("light_radius"), (int, float))]
        line = "against the area-light reference"
        if samples:
            line += f" of {', '.join(str(n) for n in samples)} samples"
        if radii:
            low, high = min(radii), max(radii)
            line += f", light radius {number(low, 3)}" + (f"–{number(high, 3)} over the scenes" if high > low else "")
        lines = [line + f" ({len(judged)} records)."]
        missing = sorted(label for label in table if label not in results[name])
        if missing:
            lines.append("judged against the hard ground truth only (no " + name + "): " + ", ".join(missing) + ".")
        if baseline not in results[name]:
            lines.append(f"no paired comparison: the baseline {baseline} has no {name} (a sweep spec's \"reference\": "
                         "\"both\" judges every technique against the area-light reference).")
        notes[name] = lines
    return notes


def number(value, digits=4):
    return "–" if value is None else f"{value:.{digits}g}"


def direction(value, reference):
    return "lower" if value < reference else "higher" if value > reference else "equal"


def finding(label, baseline, m, v):
    """The sentences that the figures of one technique against the baseline support."""
    label, baseline = markdown_text(label), markdown_text(baseline)  # names from users' specs
    better = m["better"]
    worse = "higher" if better == "lower" else "lower"
    test = v["wilcoxon"]
    text = f"**{label}** against {baseline}, N = {v['n']} paired scenes: "
    if test is None:
        return text + f"every scene's {m['id']} equals {baseline}'s; there is nothing to test."
    if test["method"] == "exact":
        text += f"{TEST_NAME}, exact (no zero or tied differences), "
    else:
        text += (f"{TEST_NAME}, normal approximation with tie correction ({test['reason']}; "
                 f"{test['ranked']} differences ranked), ")
    text += f"W+ = {test['w_plus']:g}, W− = {test['w_minus']:g}, p = {number(test['p'], 3)}"
    text += f", Holm-adjusted over {v['holm_m']} technique{'s' * (v['holm_m'] != 1)} p = {number(v['holm_p'], 3)}: "
    if v["holm_p"] >= ALPHA:
        text += f"no evidence of a difference at α = {ALPHA}."
    else:
        lean = "lower" if test["w_plus"] < test["w_minus"] else "higher"
        verdict = "better" if lean == better else "worse"
        text += f"evidence at α = {ALPHA} that its {m['id']} is {lean} ({verdict}) than {baseline}'s."
    effects = [("median", direction(v["median"], v["baseline_median"]),
                f"median {number(v['median'], 3)} against {number(v['baseline_median'], 3)}"),
               ("mean", direction(v["mean"], v["baseline_mean"]),
                f"mean {number(v['mean'], 3)} against {number(v['baseline_mean'], 3)}")]
    if v["median_ratio"] is not None:
        effects.append(("paired ratio", direction(v["median_ratio"], 1.0),
                        f"median per-scene ratio {number(v['median_ratio'], 3)} over {v['ratio_n']} scenes"))
    wins = f"win rate {100 * v['win_rate']:.0f} %"
    directions = {d for _, d, _ in effects}
    if len(directions) == 1:
        d = directions.pop()
        word = "no better or worse" if d == "equal" else ("better" if d == better else "worse")
        text += f" Median, mean and paired ratio agree: {d} ({word}); " + ", ".join(e for _, _, e in effects)
        return text + f", {wins}."
    parts = {d: [name for name, e, _ in effects if e == d] for d in (better, worse, "equal")}
    said = [f"{' and '.join(names)} {d}" for d, names in parts.items() if names]
    text += (" The effect measures disagree: " + "; ".join(said) + f" ({better} is better): "
             + ", ".join(e for _, _, e in effects) + f", {wins}.")
    return text


def findings(results, baseline):
    """{metric: [sentence per technique]} for every metric with a baseline comparison."""
    out = {}
    for name, per_label in results.items():
        m = metric_table.metric(name)
        lines = [finding(label, baseline, m, entry["vs_baseline"]) for label, entry in per_label.items()
                 if "vs_baseline" in entry]
        if lines:
            out[name] = lines
    return out


def findings_markdown(sentences, baseline):
    lines = ["# Findings across scenes", "",
             f"Written by scripts/corpus_stats.py from stats.json: each technique against {markdown_code(baseline)}, paired by "
             f"scene; \"evidence\" means a Holm-adjusted p below α = {ALPHA} (the family: the techniques compared "
             "on that metric).", ""]
    for name, per_metric in sentences.items():
        m = metric_table.metric(name)
        lines += [f"## {name}: {m['description']} ({m['better']} is better)", ""]
        lines += [f"- {s}" for s in per_metric] + [""]
    return "\n".join(lines)


def markdown(results, baseline, flagged, notes, metric_notes=None):
    lines = ["# Statistics across scenes", ""]
    lines.append(f"Baseline of the paired comparison: {markdown_code(baseline)}. Ratio: technique / baseline per scene "
                 "(scenes where the baseline is 0 left out of the ratio). Win: lower than the baseline (a tie counts "
                 f"half). p: {TEST_NAME} of the paired differences (exact for at most {EXACT_LIMIT} differences "
                 "without zeros or ties, else the normal approximation with tie correction: the method column says "
                 "which, and why); Holm p: adjusted across the techniques compared on the metric. CI: bootstrap (BCa, "
                 f"{BOOTSTRAP_RESAMPLES} resamples) 95 % confidence interval of the mean. findings.md states what "
                 "the figures support.")
    lines.append("")
    for scene, flag in sorted(flagged.items()):
        lines.append(f"- excluded: scene {markdown_text(scene)} ({flag})")
    for note in notes:
        lines.append(f"- note: {note}")
    if flagged or notes:
        lines.append("")
    for name, per_label in results.items():
        m = metric_table.metric(name)
        lines += [f"## {name}: {m['description']} ({m['better']} is better)", ""]
        lines += [f"- {note}" for note in (metric_notes or {}).get(name, [])]
        if (metric_notes or {}).get(name):
            lines.append("")
        lines.append("| technique | N | median | IQR | mean | mean 95 % CI | vs baseline: N | median ratio | win rate | "
                     "p | method | Holm p |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for label, entry in per_label.items():
            s, v = entry["summary"], entry.get("vs_baseline")
            ci = "–" if s["mean_ci95"] is None else f"[{number(s['mean_ci95'][0])}, {number(s['mean_ci95'][1])}]"
            if v is None:
                versus = ["–"] * 6
            else:
                test = v["wilcoxon"]
                method = "–" if test is None else test["method"] + (f" ({test['reason']})" if test["reason"] else "")
                versus = [str(v["n"]), number(v["median_ratio"], 3), f"{100 * v['win_rate']:.0f} %",
                          number(v["wilcoxon_p"], 3), method, number(v.get("holm_p"), 3)]
            lines.append(f"| {markdown_text(label)} | {s['n']} | {number(s['median'])} | {number(s['q1'])}–{number(s['q3'])} | "
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
        axis.set_ylabel(metric_table.metric(name)["heading"])
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
    parser.add_argument("--out", required=True, help="folder for stats.md, findings.md, stats.json and the plots")
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
        results = analyse(table, args.baseline)
    except (InputError, metric_table.MetricTableError) as error:
        print(f"corpus_stats: {error}", file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    for scene, flag in sorted(flagged.items()):
        print(f"corpus_stats: excluded scene {scene}: {flag}", file=sys.stderr)
    with open(os.path.join(args.out, "stats.md"), "w", encoding="utf-8") as handle:
        metric_notes = reference_notes(table, results, args.baseline)
        handle.write(markdown(results, args.baseline, flagged, notes, metric_notes) + "\n")
    sentences = findings(results, args.baseline)
    with open(os.path.join(args.out, "findings.md"), "w", encoding="utf-8") as handle:
        handle.write(findings_markdown(sentences, args.baseline) + "\n")
    with open(os.path.join(args.out, "stats.json"), "w", encoding="utf-8") as handle:
        json.dump({"baseline": args.baseline, "shadow_map": args.shadow_map, "excluded": flagged, "notes": notes,
                   "metric_notes": metric_notes,
                   "alpha": ALPHA, "metrics": results,
                   "findings": [{"metric": name, "sentences": lines} for name, lines in sentences.items()]}, handle, indent=1, sort_keys=True)
        handle.write("\n")
    if not args.no_plot:
        plot(results, args.out)
    scenes = {s for per_label in table.values() for s in per_label}
    print(f"corpus_stats: {len(scenes)} scenes, {len(table)} techniques, {len(flagged)} excluded -> {args.out}",
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
