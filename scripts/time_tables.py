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


def load(root, scene):
    path = os.path.join(root, scene, "metrics.json")
    try:
        with open(path) as f:
            records = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"time_tables.py: {path}: {e}")
    return {r["technique"]: r for r in records}


def measure(record):
    return record["wall_ms"] if record.get("timing") == "wall" else record["gpu_ms"]


def ratio(records, technique):
    return measure(records[technique])["total"] / measure(records["sm"])["total"]


def passes(record):
    m = measure(record)
    parts = sorted(m["passes"].items(), key=lambda kv: -kv[1])
    return ", ".join(f"{name} {ms:.1f}" for name, ms in parts) + f" = {m['total']:.1f} ms"


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
