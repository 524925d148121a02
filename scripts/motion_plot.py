#!/usr/bin/env python3
"""Plots a sequence's per-frame error series as T_error_over_time.png, one per technique
(docs/motion.md, "Temporal metrics").

Input: a JSON list of per-frame records, each with "technique", "frame" and the "error"
block of a metrics.json record (the metrics PLOTTED names, read where the metric table of
`testbed metrics --json` says), and, from the
second frame of a run on, "temporal": {"flicker": ...} for the pair (previous frame,
this frame). Panels: mismatch %, RMSE and boundary px over frames; the top one's second
axis: flicker per frame pair (plotted at the pair's later frame). Uses Debian's python3-matplotlib.

Usage: motion_plot.py SERIES.json [OUTPUT_FOLDER]   (default: SERIES.json's folder)
Bad input: one line naming the file and the key path on stderr, exit 2, nothing written."""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless
# Labels come from users' specs and scenes: text, never TeX ("$5", "$\frac$").
matplotlib.rcParams["text.parse_math"] = False
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import metric_table  # noqa: E402

# (metric id, line style): one panel each; the keys and labels are the metric table's.
PLOTTED = [("mismatch_pct", "-"), ("rmse", "--"), ("boundary_px.mean", ":")]
FLICKER = ("temporal", "flicker")


def error_series():
    """(key path in a record, label, line style) of each plotted metric."""
    return [(metric_table.path_keys(name), metric_table.metric(name)["heading"], style) for name, style in PLOTTED]


class InputError(Exception):
    pass


def number(record, path, where, required=True):
    """The finite number at `path` in `record`; None when absent and not required."""
    value = record
    for depth, key in enumerate(path):
        if not isinstance(value, dict) or key not in value or value[key] is None:
            if required:
                raise InputError(where + "/" + "/".join(path[:depth + 1]) + ": missing")
            return None
        value = value[key]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(where + "/" + "/".join(path) + ": expected a finite number")
    return float(value)


def read_series(path):
    """{technique: [(frame, {label: value}, flicker or None)]}, frames ascending."""
    try:
        with open(path, encoding="utf-8") as f:
            records = json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(": " + str(e)) from e
    if not isinstance(records, list) or not records:
        raise InputError(": expected a non-empty JSON list of per-frame records")
    series = {}
    for index, record in enumerate(records):
        where = "/" + str(index)
        if not isinstance(record, dict):
            raise InputError(where + ": expected an object")
        technique = record.get("technique")
        if not isinstance(technique, str) or not technique or "/" in technique:
            raise InputError(where + "/technique: expected a technique id")
        frame = number(record, ("frame",), where)
        values = {label: number(record, key, where) for key, label, _ in error_series()}
        flicker = number(record, FLICKER, where, required=False)
        series.setdefault(technique, []).append((frame, values, flicker))
    for points in series.values():
        points.sort(key=lambda p: p[0])
    return series


def plot(technique, points, out_file):
    """One panel per error series (their units differ), frames shared; the top panel
    carries the flicker per frame pair on its second axis."""
    frames = [p[0] for p in points]
    series = error_series()
    figure, axes = plt.subplots(len(series), 1, sharex=True, figsize=(8, 6.5), dpi=100)
    for axis, (_, label, style) in zip(axes, series):
        axis.plot(frames, [p[1][label] for p in points], style, color="tab:blue", marker=".", label=label)
        axis.set_ylabel(label, color="tab:blue")
        axis.grid(alpha=0.3)
    axes[-1].set_xlabel("frame")
    axes[-1].xaxis.get_major_locator().set_params(integer=True)
    flicker_axis = axes[0].twinx()
    pairs = [(p[0], p[2]) for p in points if p[2] is not None]
    flicker_axis.plot([f for f, _ in pairs], [v for _, v in pairs], "-", color="tab:red", marker=".")
    flicker_axis.set_ylabel("flicker (frame pair)", color="tab:red")
    axes[0].set_title(technique + ": error over time", fontsize=10)
    figure.tight_layout()
    # Rendered beside the final name and moved into place, so no half-written PNG is left.
    temporary = os.path.join(os.path.dirname(out_file) or ".", "." + os.path.basename(out_file) + ".partial")
    try:
        figure.savefig(temporary, format="png")
        os.replace(temporary, out_file)
    finally:
        plt.close(figure)
        if os.path.exists(temporary):
            os.remove(temporary)


def main(argv):
    if len(argv) not in (2, 3):
        sys.stderr.write("usage: motion_plot.py SERIES.json [OUTPUT_FOLDER]\n")
        return 2
    path = argv[1]
    out_dir = argv[2] if len(argv) == 3 else (os.path.dirname(path) or ".")
    try:
        series = read_series(path)
    except InputError as e:
        sys.stderr.write(path + str(e) + "\n")
        return 2
    except metric_table.MetricTableError as e:
        sys.stderr.write(f"motion_plot.py: {e}\n")
        return 2
    for technique, points in sorted(series.items()):
        plot(technique, points, os.path.join(out_dir, technique + "_error_over_time.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
