#!/usr/bin/env python3
"""Plots one table written by `testbed sweep` / `testbed merge` (TABLE.json) as
TABLE.png and TABLE.svg: our figures beside the paper's, one line per row over the
table's columns, and, when the table has a shadow-mapping row, both as cost relative to
shadow mapping (on a software rasterizer only these ratios compare with a paper's GPU).
Uses Debian's python3-matplotlib; run by the testbed itself after writing the table."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless
# Labels come from users' specs and scenes: text, never TeX ("$5", "$\frac$").
matplotlib.rcParams["text.parse_math"] = False
import matplotlib.lines  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def name(row):
    return (row["group"] + " " if row["group"] else "") + row["label"]


def color(index):
    palette = plt.get_cmap("tab20")
    return palette(index % palette.N)


def markers(rows):
    """A marker per group (the papers' scenes or kernel sizes), so colours may repeat."""
    groups = []
    for row in rows:
        if row["group"] not in groups:
            groups.append(row["group"])
    return ["osD^v<>"[groups.index(row["group"]) % 7] for row in rows]


def panel(axis, table, key, title, ylabel):
    """One line per row; a row keeps its colour in every panel."""
    x = list(range(len(table["columns"])))
    shapes = markers(table["rows"])
    for index, row in enumerate(table["rows"]):
        values = [float("nan") if v is None else v for v in row[key]]
        if any(v == v for v in values):  # not all NaN
            axis.plot(x, values, marker=shapes[index], color=color(index))
    finite = [v for row in table["rows"] for v in row[key] if v is not None and v > 0]
    if finite and max(finite) / min(finite) > 30:  # scenes of very different cost share the panel
        axis.set_yscale("log")
    axis.set_xticks(x)
    axis.set_xticklabels(table["columns"])
    axis.set_title(title, fontsize=10)
    axis.set_ylabel(ylabel)
    axis.grid(alpha=0.3)


def main(path):
    with open(path, encoding="utf-8") as f:
        table = json.load(f)
    unit = table["unit"]
    keys = [("ours", "ours (" + (table["backend"] or "no records") + ")", unit),
            ("paper", "paper", unit)]
    if table["has_ratios"]:
        keys += [("ours_ratio", "ours, cost × SM", "× SM"), ("paper_ratio", "paper, cost × SM", "× SM")]
    # A panel with no figure at all (the paper's, in a study of one's own) is left out.
    keys = [k for k in keys if k[0] == "ours" or any(v is not None for row in table["rows"] for v in row[k[0]])]
    rows = (len(keys) + 1) // 2
    legend_rows = (len(table["rows"]) + 3) // 4
    legend_height = 0.25 * legend_rows + 0.3  # inches below the panels
    height = 4.2 * rows + legend_height + 0.8
    figure, axes = plt.subplots(rows, 2, figsize=(12, height), squeeze=False)
    for axis, (key, title, ylabel) in zip(axes.flat, keys):
        panel(axis, table, key, title, ylabel)
    shapes = markers(table["rows"])
    handles = [matplotlib.lines.Line2D([], [], color=color(i), marker=shapes[i]) for i in range(len(table["rows"]))]
    labels = [name(row) for row in table["rows"]]
    figure.legend(handles, labels, loc="lower center", ncol=4, fontsize=8)
    figure.suptitle((table["title"] or table["name"]) + "\n" + (table["citation"] or "a study of one's own"), fontsize=10)
    figure.tight_layout(rect=(0, legend_height / height, 1, 1 - 0.8 / height))
    stem = os.path.splitext(path)[0]
    for extension in ("png", "svg"):
        partial = stem + ".partial." + extension
        figure.savefig(partial, dpi=110)
        os.replace(partial, stem + "." + extension)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: sweep_plot.py TABLE.json")
    main(sys.argv[1])
