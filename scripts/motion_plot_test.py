#!/usr/bin/env python3
"""ctest for motion_plot.py: a tiny synthetic series gives one non-blank PNG per
technique; a record without its RMSE is refused with one line, exit 2, nothing written."""
import json
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.image  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "motion_plot.py")


def record(technique, frame):
    r = {"technique": technique, "frame": frame,
         "error": {"mismatch_pct": 1.0 + 0.1 * frame, "rmse": 0.05 + 0.01 * (frame % 3),
                   "boundary_px": {"mean": 0.5 + 0.2 * frame, "p95": 2.0}}}
    if frame > 0:
        r["temporal"] = {"flicker": 0.01 * frame, "crawl_pct": 0.5, "crawl_missed_pct": 0.1}
    return r


def run(path, out_dir):
    return subprocess.run([sys.executable, SCRIPT, path, out_dir], capture_output=True, text=True, check=False)


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        series = os.path.join(tmp, "series.json")
        with open(series, "w", encoding="utf-8") as f:
            json.dump([record(t, k) for k in range(6) for t in ("sm", "pcf")], f)
        result = run(series, tmp)
        if result.returncode != 0:
            failures.append("exit %d: %s" % (result.returncode, result.stderr))
        for technique in ("sm", "pcf"):
            png = os.path.join(tmp, technique + "_error_over_time.png")
            if not os.path.isfile(png):
                failures.append(png + " not written")
                continue
            image = matplotlib.image.imread(png)
            if image.std() == 0 or (image[..., :3] < 0.9).mean() < 0.005:
                failures.append(png + " is blank")

        bad_dir = os.path.join(tmp, "bad")
        os.mkdir(bad_dir)
        records = [record("sm", k) for k in range(3)]
        del records[2]["error"]["rmse"]
        with open(series, "w", encoding="utf-8") as f:
            json.dump(records, f)
        result = run(series, bad_dir)
        lines = result.stderr.strip().splitlines()
        if result.returncode != 2 or len(lines) != 1 or not lines[0].startswith(series + "/2/error/rmse"):
            failures.append("bad record: exit %d, stderr %r" % (result.returncode, result.stderr))
        if os.listdir(bad_dir):
            failures.append("bad record wrote " + ", ".join(os.listdir(bad_dir)))
    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
