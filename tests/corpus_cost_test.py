#!/usr/bin/python3
"""scripts/corpus_cost.py on planted configurations whose answers are known: the Pareto
front of a technique, the least-error configuration at no more cost, the per-scene winner,
flagged scenes left out, and the tables and plots written."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "scripts", "corpus_cost.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
import corpus_cost  # noqa: E402


def record(technique, scene, shadow_map, ms, mismatch, flag=None, row=None):
    error = {"mismatch_pct": mismatch}
    if flag:
        error["flag"] = flag
    # As the testbed writes records: the costs in the "derived" block, computed there.
    r = {"technique": technique, "scene": scene, "shadow_map": shadow_map, "timing": "wall",
         "derived": {"frame_ms": ms, "memory_mb": shadow_map * shadow_map * 2 / 2 ** 20}, "error": error}
    if row:
        r["row"] = row
    return r


# Per scene: sm halves its error per doubling of the map at double the time; smsr costs
# 1.5× sm at the same size with a third of its error. So at the time of sm @2048 (8 ms),
# smsr @1024 (6 ms) has the least error: 1/3 of sm @1024's 2 = 0.667 < sm @2048's 1.
def planted(scenes=4):
    records = []
    for i in range(scenes):
        scene = f"s{i}"
        records.append(record("groundtruth", scene, 512, 9, 0.0))
        for size, ms, error in ((512, 2, 4.0), (1024, 4, 2.0), (2048, 8, 1.0)):
            records.append(record("sm", scene, size, ms, error))
            records.append(record("smsr", scene, size, 1.5 * ms, error / 3))
    records.append(record("sm", "flat", 1024, 4, 0.0, flag="entirely lit from the camera"))
    return records


class KnownAnswers(unittest.TestCase):
    def test_pareto_front_keeps_only_points_no_cheaper_one_beats(self):
        points = [(1, 5, "a"), (2, 6, "b"), (3, 4, "c"), (4, 4, "d"), (5, 1, "e")]
        self.assertEqual([p[2] for p in corpus_cost.pareto_front(points)], ["a", "c", "e"])

    def test_least_error_at_equal_cost(self):
        scenes, flagged = corpus_cost.organise(planted(), "mismatch_pct")
        self.assertEqual(flagged, {"flat": "entirely lit from the camera"})
        self.assertNotIn("flat", scenes)
        medians = corpus_cost.corpus_medians(scenes, "frame_ms")
        self.assertEqual(medians["sm @2048"]["cost"], 8.0)
        rows = {r["budget"]: r for r in corpus_cost.equal_cost_table(scenes, medians, "frame_ms")}
        self.assertEqual(rows["sm @2048"]["best"], "smsr @1024")
        self.assertAlmostEqual(rows["sm @2048"]["best_error"], 2.0 / 3)
        self.assertEqual(rows["sm @2048"]["scene_winner"], "smsr @1024")
        self.assertEqual(rows["sm @2048"]["scene_winner_share"], 1.0)
        self.assertEqual(rows["sm @512"]["best"], "sm @512")  # nothing cheaper
        self.assertEqual(rows["sm @2048"]["n"], 4)
        # Memory: smsr holds what sm holds at the same size here, so it wins at every size.
        memory = {r["budget"]: r for r in corpus_cost.equal_cost_table(
            scenes, corpus_cost.corpus_medians(scenes, "memory_mb"), "memory_mb")}
        self.assertEqual(memory["sm @1024"]["best"], "smsr @1024")

    def test_script_writes_tables_and_plots(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "records.json"), "w") as handle:
                json.dump(planted(), handle)
            out = os.path.join(tmp, "cost")
            run = subprocess.run([sys.executable, SCRIPT, tmp, "--out", out], capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            with open(os.path.join(out, "cost.md")) as handle:
                text = handle.read()
            self.assertIn("| sm @2048 | 4 | 8 | 1 | smsr @1024 | 6 | 0.6667 | smsr @1024 | 100 % |", text)
            self.assertIn("excluded: scene flat (entirely lit from the camera)", text)
            self.assertNotIn("shader invocations", text)  # no work counters in these records
            for name in ("cost-frame_ms.png", "cost-memory_mb.png", os.path.join("scenes", "s0.png")):
                self.assertGreater(os.path.getsize(os.path.join(out, name)), 1000, name)

    def test_soft_metrics_get_their_own_view(self):
        # scripts/corpus.sh draws a view per soft metric that a record holds (--list-soft):
        # here smsr alone was judged against the area light, on soft_rmse and the umbra leak.
        records = planted()
        for r in records:
            if r["technique"] == "smsr":
                r["error"].update({"soft_rmse": r["error"]["mismatch_pct"] / 10, "soft_umbra_leak": 0.0})
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "records.json"), "w") as handle:
                json.dump(records, handle)
            run = subprocess.run([sys.executable, SCRIPT, tmp, "--list-soft"], capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertEqual(run.stdout.split(), ["soft_rmse", "soft_umbra_leak"])
            out = os.path.join(tmp, "cost-soft_rmse")
            run = subprocess.run([sys.executable, SCRIPT, tmp, "--error", "soft_rmse", "--out", out, "--no-plot"],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            with open(os.path.join(out, "cost.json")) as handle:
                cost = json.load(handle)
            self.assertEqual(cost["error"], "soft_rmse")
            self.assertEqual(sorted(cost["medians"]["frame_ms"]), ["smsr @1024", "smsr @2048", "smsr @512"])
            planted_only = os.path.join(tmp, "hard.json")
            with open(planted_only, "w") as handle:
                json.dump(planted(), handle)
            run = subprocess.run([sys.executable, SCRIPT, planted_only, "--list-soft"], capture_output=True, text=True)
            self.assertEqual((run.returncode, run.stdout.strip()), (0, ""))

    def test_bad_input_exits_2_with_one_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "records.json"), "w") as handle:
                json.dump(planted(), handle)
            run = subprocess.run([sys.executable, SCRIPT, tmp, "--out", tmp, "--error", "joules"],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 2)
            self.assertEqual(run.stderr.count("\n"), 1, run.stderr)
            self.assertIn("--error: no metric 'joules' in the testbed's metric table", run.stderr)
            run = subprocess.run([sys.executable, SCRIPT, tmp, "--out", tmp, "--error", "frame_ms"],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 2)
            self.assertIn("--error: frame_ms is not an error metric", run.stderr)


if __name__ == "__main__":
    unittest.main()
