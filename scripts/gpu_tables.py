#!/usr/bin/env python3
"""Prints the tables of results/gpu/README.md from the committed records (docs/gpu.md).

1. Per-pass GPU ms of the techniques with software-rasterizer devices, per shadow-map size,
   from GI 2016 Table 2's records (dragon, 1280x720), beside shadow mapping's passes.
2. Agreement with llvmpipe: per bundled scene at 1024², each technique's mismatch % and
   mean boundary distance on the GPU (results/gpu/compare, metrics.egl.json) and on llvmpipe (results/).
Usage: scripts/gpu_tables.py [RESULTS_DIR]   (default: the repository's results/)
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import metric_table  # noqa: E402

results = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "results")


def records(path):
    data = json.load(open(path))
    return data if isinstance(data, list) else data["records"]


def passes_table():
    rows = {}
    for r in records(os.path.join(results, "gpu/paper/gi2016-table2/records.json")):
        for name, ms in r["gpu_ms"]["passes"].items():
            rows.setdefault((r["technique"], name), {})[r["shadow_map"]] = ms
    sizes = sorted({s for v in rows.values() for s in v})
    print("| technique | pass | " + " | ".join(f"{s}² ms" for s in sizes) + " |")
    print("|---|---|" + "---:|" * len(sizes))
    for (technique, name), by_size in sorted(rows.items()):
        print(f"| {technique} | {name} | " + " | ".join(f"{by_size.get(s, float('nan')):.3f}" for s in sizes) + " |")


def agreement_table():
    print("| scene | technique | mismatch % GPU | mismatch % llvmpipe | boundary px GPU | boundary px llvmpipe |")
    print("|---|---|---:|---:|---:|---:|")
    for scene in sorted(os.listdir(os.path.join(results, "gpu/compare"))):
        ours = {r["technique"]: r for r in records(os.path.join(results, "gpu/compare", scene, "metrics.egl.json"))}
        cpu = {r["technique"]: r for r in records(os.path.join(results, scene, "metrics.json"))}
        for technique in sorted(ours):
            if technique == "groundtruth" or technique not in cpu:
                continue
            cells = [metric_table.value(r[technique], name) for name in ("mismatch_pct", "boundary_px.mean")
                     for r in (ours, cpu)]
            print(f"| {scene} | {technique} | " + " | ".join(f"{v:.3f}" for v in cells) + " |")


if __name__ == "__main__":
    passes_table()
    print()
    agreement_table()
