#!/usr/bin/env python3
"""Before/after speed tables from two sets of `testbed compare` outputs.

    scripts/time_tables.py BEFORE_ROOT AFTER_ROOT SCENE [SCENE ...]

Each ROOT holds one compare output folder per scene (ROOT/SCENE/metrics.json). Prints
markdown: the technique-only `× sm` of every technique on every scene, before → after, and
per scene where each technique's time goes (its passes in the record's own measure,
longest first). The figures are read from the records, nothing is typed in.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import metric_table  # noqa: E402


def load(root, scene):
    """The scene's records by technique, each with the derived figures the testbed
    computes (technique_ms, x_sm against the file's sm)."""
    path = os.path.join(root, scene, "metrics.json")
    try:
        with open(path) as f:
            records = json.load(f)
        metric_table.attach_derived(path, records)
    except (OSError, ValueError, metric_table.MetricTableError) as e:
        sys.exit(f"time_tables.py: {path}: {e}")
    return {r["technique"]: r for r in records}


def ratio(records, technique):
    return metric_table.value(records[technique], "x_sm")


def passes(record):
    # The passes of the measure the record's "timing" names, which technique_ms totals.
    parts = sorted(record[record["timing"] + "_ms"]["passes"].items(), key=lambda kv: -kv[1])
    total = metric_table.value(record, "technique_ms")
    return ", ".join(f"{name} {ms:.1f}" for name, ms in parts) + f" = {total:.1f} ms"


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    before_root, after_root, scenes = argv[1], argv[2], argv[3:]
    before = {s: load(before_root, s) for s in scenes}
    after = {s: load(after_root, s) for s in scenes}
    techniques = sorted(set.intersection(*(set(r) for r in after.values())), key=lambda t: (t != "sm", t))
    print("| technique | " + " | ".join(f"`{s}`" for s in scenes) + " |")
    print("|---|" + "---:|" * len(scenes))
    for t in techniques:
        cells = []
        for s in scenes:
            old = f"{ratio(before[s], t):.2f}" if t in before[s] else "–"
            cells.append(f"{old} → {ratio(after[s], t):.2f}")
        print(f"| `{t}` | " + " | ".join(cells) + " |")
    for s in scenes:
        print(f"\n`{s}`, wall ms per pass (before → after):\n")
        print("| technique | before | after |\n|---|---|---|")
        for t in techniques:
            old = f"{passes(before[s][t])} ({ratio(before[s], t):.2f}×)" if t in before[s] else "–"
            print(f"| `{t}` | {old} | {passes(after[s][t])} ({ratio(after[s], t):.2f}×) |")


if __name__ == "__main__":
    main(sys.argv)
