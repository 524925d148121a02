#!/usr/bin/env python3
"""ctest for sweep_plot.py: a table whose labels and title hold what matplotlib would read as
TeX (unbalanced or invalid "$...$") still gives its PNG and SVG, and the SVG carries the labels
as written rather than typeset."""
import json
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "sweep_plot.py")
LABELS = [r"bad $\frac$ label", "costs $5 and $6", "plain"]


def table():
    rows = [{"group": "", "label": label, "not_measured": "", "ours": [1.0 + i, 2.0 + i],
             "ours_ratio": [1.0, 1.5], "paper": [None, None], "paper_ratio": [None, None]}
            for i, label in enumerate(LABELS)]
    return {"backend": "osmesa", "citation": "", "columns": ["512²", "1024²"], "has_ratios": True,
            "header": "", "name": "dollars", "rows": rows, "title": r"a $\sqrt$ study", "unit": "ms"}


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "dollars.json")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(table(), f)
        result = subprocess.run([sys.executable, SCRIPT, path], capture_output=True, text=True, check=False)
        if result.returncode != 0:
            failures.append("exit %d: %s" % (result.returncode, result.stderr.strip().splitlines()[-1:]))
        for extension in ("png", "svg"):
            written = os.path.join(tmp, "dollars." + extension)
            if not os.path.exists(written) or os.path.getsize(written) == 0:
                failures.append("no " + written)
        svg = os.path.join(tmp, "dollars.svg")
        if os.path.exists(svg):
            # Text is drawn as glyph paths, each run of text preceded by a comment with the string.
            with open(svg, encoding="utf-8") as f:
                content = f.read()
            for label in LABELS:
                if label not in content:
                    failures.append("label not drawn as written: " + label)
    for failure in failures:
        print(failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
