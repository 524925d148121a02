#!/usr/bin/python3
"""The scripts take their metrics from the one metric table (testbed/harness/metric_table.h,
printed by `testbed metrics --json`, read by scripts/metric_table.py):

- every script in scripts/ names only metric ids the table holds (a drifted name such as
  `boundary_mean_px` for `boundary_px.mean` fails), and
- none derives a derived figure again: none names the stored inputs the table says a
  carried derived figure is computed from (`memory_bytes` for memory_mb, `gbuffer_ms` for
  frame_ms, the invocation counters for invocations_k) or defines a function of a derived
  figure's name.

Planted sources show each rule failing. `testbed metrics --json` and `--derive` are pinned
on a record whose derived figures are known. The binary: $TESTBED (CTest sets it)."""
import ast
import glob
import json
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "scripts")
sys.path.insert(0, SCRIPTS)
import metric_table  # noqa: E402

# A string that reads like a metric's name: snake_case ending in a unit or an error word,
# optionally with a summary after a dot (boundary_px.mean).
METRIC_LIKE = re.compile(r"^[a-z][a-z0-9]*(_[a-z0-9]+)*_(pct|ms|mb|kib|k|px|bytes|rmse|mae|leak|invocations|primitives)"
                         r"(\.[a-z0-9]+)?$|^[a-z_]*(rmse|mismatch)[a-z_]*$")
# Record keys that read like metrics but are not the metric table's: the temporal figures
# of a sequence's "temporal" block (docs/motion.md "Temporal metrics"), which the sweep's
# measures name on their own.
NOT_IN_TABLE = {"crawl_pct", "crawl_missed_pct", "shading_ms"}


def rules():
    """(allowed names, {forbidden name: the derived figure it would re-derive})."""
    table = metric_table.metrics()
    paths = [m["path"].split("/")[1:] for m in table if m["path"]]
    allowed = {m["id"] for m in table} | {key for keys in paths for key in keys} | NOT_IN_TABLE
    last_keys = [keys[-1] for keys in paths]
    forbidden = {}
    for m in table:
        for source in m["from"]:
            if metric_table.metric(source)["derived"]:
                continue  # reading a carried derived figure is what scripts should do
            forbidden[source] = m["id"]
            keys = metric_table.path_keys(source)
            if last_keys.count(keys[-1]) == 1:  # a key only this input has (not "total")
                forbidden[keys[-1]] = m["id"]
    return allowed, forbidden


def problems(source, name, allowed, forbidden):
    """One line per metric the source names that the table lacks, and per re-derivation."""
    derived = {m["id"] for m in metric_table.metrics() if m["derived"]}
    found = []
    for node in ast.walk(ast.parse(source, name)):
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            text = node.value
            if text in forbidden:
                found.append(f"{name}:{node.lineno}: names '{text}', an input of {forbidden[text]}: "
                             f"read the record's {forbidden[text]} instead of deriving it")
            elif METRIC_LIKE.match(text) and text not in allowed:
                found.append(f"{name}:{node.lineno}: names metric '{text}', which `testbed metrics` lacks")
        elif isinstance(node, ast.FunctionDef) and node.name in derived:
            found.append(f"{name}:{node.lineno}: defines {node.name}, a derived figure the record carries")
    return found


class ScriptsUseTheTable(unittest.TestCase):
    def setUp(self):
        self.allowed, self.forbidden = rules()

    def test_every_script_names_only_table_metrics_and_derives_none(self):
        scripts = sorted(glob.glob(os.path.join(SCRIPTS, "*.py")))
        self.assertGreater(len(scripts), 8)
        found = []
        for path in scripts:
            with open(path, encoding="utf-8") as handle:
                found += problems(handle.read(), os.path.basename(path), self.allowed, self.forbidden)
        self.assertEqual(found, [])

    def test_a_drifted_name_fails(self):
        found = problems('SHOWN = ["mismatch_pct", "boundary_mean_px"]\n', "planted.py", self.allowed, self.forbidden)
        self.assertEqual(len(found), 1, found)
        self.assertIn("'boundary_mean_px'", found[0])

    def test_a_re_derived_figure_fails(self):
        source = ('def memory_mb(record):\n    return record["memory_bytes"] / 1048576\n'
                  'def cost(record):\n    return record["gbuffer_ms"] + record["wall_ms"]["total"]\n')
        found = problems(source, "planted.py", self.allowed, self.forbidden)
        self.assertEqual(len(found), 3, found)
        self.assertIn("defines memory_mb", found[0] + found[1] + found[2])
        self.assertTrue(any("'memory_bytes', an input of memory_" in f for f in found), found)
        self.assertTrue(any("'gbuffer_ms', an input of frame_ms" in f for f in found), found)

    def test_reading_the_table_passes(self):
        source = 'import metric_table\nx = metric_table.value(r, "frame_ms") + metric_table.value(r, "boundary_px.mean")\n'
        self.assertEqual(problems(source, "planted.py", self.allowed, self.forbidden), [])


def record(technique, wall_ms, gbuffer_ms, memory_bytes):
    """A record as the testbed writes it, before records carried derived figures."""
    return {"technique": technique, "scene": "s", "size": [64, 36], "shadow_map": 256, "depth_format": "16",
            "params": {}, "gpu_ms": {"total": 1.0, "passes": {"p": 1.0}},
            "wall_ms": {"total": wall_ms, "passes": {"p": wall_ms}}, "timing": "wall", "cpu_ms": 1.0,
            "gbuffer_ms": gbuffer_ms, "repeat": 1, "triangles": 12, "memory_bytes": memory_bytes,
            "light": {"type": "spot", "eye": [0, 1, 0], "near": 1, "far": 2, "fov": 45, "fitted": True,
                      "depth_step_world": [0.1, 0.1], "texel_world": [0.1, 0.1]},
            "backend": "test", "error": None,
            "work": {"passes": {}, "total": {"vertex_invocations": 1000, "fragment_invocations": 2500,
                                             "compute_invocations": 500, "primitives_submitted": 4,
                                             "clipping_input_primitives": 4}}}


class TheCommand(unittest.TestCase):
    def test_metrics_json_describes_each_metric(self):
        table = {m["id"]: m for m in metric_table.metrics()}
        self.assertEqual(len(table), len(metric_table.metrics()))  # ids unique
        m = table["boundary_px.mean"]
        self.assertEqual((m["path"], m["unit"], m["better"], m["reference"]), ("/error/boundary_px/mean", "px", "lower", "hard"))
        self.assertEqual(m["summaries_over_frames"], ["mean", "p95", "max"])
        self.assertEqual(table["soft_rmse"]["reference"], "soft")
        self.assertEqual(table["fps"]["better"], "higher")
        self.assertEqual(table["frame_ms"]["path"], "/derived/frame_ms")
        self.assertEqual(table["frame_ms"]["from"], ["gbuffer_ms", "technique_ms"])
        self.assertEqual(table["x_sm"]["relative_to"], "sm")
        self.assertIsNone(table["x_sm"]["path"])
        self.assertEqual(table["vertex_invocations"]["path"], "/work/total/vertex_invocations")
        self.assertTrue(all(m["description"] for m in metric_table.error_metrics()))

    def test_derive_computes_what_records_now_carry(self):
        with tempfile.TemporaryDirectory() as tmp:
            file = os.path.join(tmp, "metrics.json")
            records = [record("sm", 10.0, 2.0, 2 ** 20), record("pcf", 25.0, 2.0, 3 * 2 ** 19)]
            with open(file, "w") as handle:
                json.dump(records, handle)
            metric_table.attach_derived(file, records)
            sm, pcf = (r["derived"] for r in records)
            self.assertEqual(sm["frame_ms"], 12.0)
            self.assertEqual(sm["technique_ms"], 10.0)
            self.assertEqual(pcf["memory_mb"], 1.5)
            self.assertEqual(pcf["invocations_k"], 4.0)
            self.assertEqual(pcf["x_sm"], 2.5)
            self.assertAlmostEqual(pcf["x_sm_frame"], 27.0 / 12.0)
            self.assertEqual(metric_table.value(records[1], "frame_ms"), 27.0)

    def test_derive_refuses_a_bad_record_in_one_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            file = os.path.join(tmp, "metrics.json")
            bad = record("sm", 10.0, 2.0, 2 ** 20)
            del bad["gbuffer_ms"]
            with open(file, "w") as handle:
                json.dump([bad], handle)
            run = subprocess.run([metric_table.testbed_binary(), "metrics", "--derive", file], capture_output=True,
                                 text=True)
            self.assertEqual(run.returncode, 2)
            self.assertEqual(run.stdout, "")
            self.assertEqual(run.stderr, f"testbed: {file}: [0].gbuffer_ms: missing required key\n")


if __name__ == "__main__":
    unittest.main()
