#!/usr/bin/python3
"""scripts/corpus_stats.py pinned on known answers: a bootstrap interval on a known
distribution covers its mean, the Wilcoxon test on a textbook case gives its exact p,
Holm's adjustment on a worked case, the findings' sentences on planted cases (ties and
zero differences force the approximation; median and paired ratio disagreeing is said),
and the script on a small synthetic record set writes its tables and plots. docs/corpus.md
quotes results/corpus's generated findings as they stand."""
import json
import os
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "scripts", "corpus_stats.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
import corpus_stats  # noqa: E402


class KnownAnswers(unittest.TestCase):
    def test_bootstrap_interval_covers_the_mean_of_a_known_distribution(self):
        # 200 samples of 40 draws from an exponential of mean 2 (skewed, as error metrics
        # are): a 95 % interval should cover 2 in about 95 % of them (binomial sd 1.5 %);
        # its width about 2 · 1.96 · 2 / sqrt(40) = 1.24.
        rng = np.random.default_rng(7)
        covered, widths = 0, []
        for i in range(200):
            low, high = corpus_stats.bootstrap_mean_ci(rng.exponential(2.0, 40), resamples=2000, seed=i)
            covered += low < 2.0 < high
            widths.append(high - low)
        self.assertGreaterEqual(covered, 176)  # 88 %
        self.assertLessEqual(covered, 199)
        self.assertAlmostEqual(float(np.median(widths)), 1.24, delta=0.25)
        self.assertEqual(corpus_stats.bootstrap_mean_ci([2.0, 2.0, 2.0]), (2.0, 2.0))
        self.assertIsNone(corpus_stats.bootstrap_mean_ci([1.0]))

    def test_wilcoxon_on_darwins_maize_gives_the_exact_p(self):
        # Darwin's cross- minus self-fertilised Zea mays heights (eighths of an inch), as
        # Fisher analysed them in The Design of Experiments (1935), section 17: 15 pairs,
        # W+ = 96, W- = 24; the exact two-sided p of the signed-rank test is 0.041259765625
        # (= 2 · 1352 / 2^15).
        d = np.array([6, 8, 14, 16, 23, 24, 28, 29, 41, -48, 49, 56, 60, -67, 75], dtype=float)
        baseline = np.full(d.size, 100.0)
        self.assertAlmostEqual(corpus_stats.wilcoxon_p(baseline + d, baseline), 0.041259765625, places=12)
        test = corpus_stats.wilcoxon(baseline + d, baseline)
        self.assertEqual((test["method"], test["w_plus"], test["w_minus"]), ("exact", 96.0, 24.0))
        self.assertIsNone(corpus_stats.wilcoxon_p(baseline, baseline))

    def test_holm_on_a_worked_case(self):
        # m = 4: 0.005·4 = 0.02, 0.01·3 = 0.03, 0.03·2 = 0.06, 0.04·1 = 0.04 → 0.06 (monotone).
        self.assertEqual(corpus_stats.holm([0.01, 0.04, 0.03, 0.005]), [0.03, 0.06, 0.06, 0.02])
        self.assertEqual(corpus_stats.holm([None, 0.02, 0.9]), [None, 0.04, 0.9])

    def test_paired_comparison(self):
        result = corpus_stats.paired([1.0, 4.0, 2.0, 0.0], [2.0, 2.0, 2.0, 0.0])
        self.assertEqual(result["n"], 4)
        self.assertAlmostEqual(result["win_rate"], (1 + 0.5 + 0.5) / 4)
        self.assertEqual(result["ratio_n"], 3)  # the baseline's 0 leaves the ratio undefined
        self.assertAlmostEqual(result["median_ratio"], 1.0)


MISMATCH = {"id": "mismatch_pct", "better": "lower"}


def compared(values, baseline, holm_p=None, techniques=1):
    v = corpus_stats.paired(values, baseline)
    v["holm_p"] = v["wilcoxon_p"] if holm_p is None else holm_p
    v["holm_m"] = techniques
    return v


class Findings(unittest.TestCase):
    def test_ties_and_zero_differences_force_the_approximation_and_are_counted(self):
        baseline = np.arange(1.0, 11.0)
        d = np.array([0, 0, 0.5, 0.5, -0.5, 1, 2, 3, 4, 5])
        v = compared(baseline + d, baseline)
        self.assertEqual(v["wilcoxon"]["method"], "approx")
        self.assertAlmostEqual(v["wilcoxon_p"], float(corpus_stats.stats.wilcoxon(d, method="approx").pvalue))
        sentence = corpus_stats.finding("pcf", "sm", MISMATCH, v)
        self.assertIn("normal approximation with tie correction (2 zero differences, 3 tied absolute differences; "
                      "8 differences ranked)", sentence)
        self.assertNotIn("exact", sentence)

    def test_untied_differences_are_tested_exactly(self):
        baseline = np.full(15, 100.0)
        d = np.array([6, 8, 14, 16, 23, 24, 28, 29, 41, -48, 49, 56, 60, -67, 75], dtype=float)
        sentence = corpus_stats.finding("pcf", "sm", MISMATCH, compared(baseline + d, baseline))
        self.assertIn("two-sided Wilcoxon signed-rank test, exact (no zero or tied differences), W+ = 96, W− = 24, "
                      "p = 0.0413, Holm-adjusted over 1 technique p = 0.0413: evidence at α = 0.05 that its "
                      "mismatch_pct is higher (worse) than sm's.", sentence)
        self.assertIn("Median, mean and paired ratio agree: higher (worse)", sentence)

    def test_median_and_paired_ratio_disagreeing_is_said(self):
        # Three large-error scenes 10 % lower, four small ones mixed: the per-scene ratio's
        # median is 0.9 and the mean falls, while the median over scenes rises 1 → 2.
        baseline = np.array([10, 10, 10, 1, 1, 1, 1], dtype=float)
        values = np.array([9, 9, 9, 2, 2, 0.9, 0.9])
        v = compared(values, baseline, holm_p=0.5, techniques=13)
        sentence = corpus_stats.finding("msm", "sm", MISMATCH, v)
        self.assertIn("Holm-adjusted over 13 techniques p = 0.5: no evidence of a difference at α = 0.05.", sentence)
        self.assertIn("The effect measures disagree: mean and paired ratio lower; median higher (lower is better): "
                      "median 2 against 1, mean 4.69 against 4.86, median per-scene ratio 0.9 over 7 scenes, "
                      "win rate 71 %.", sentence)

    def test_all_equal_has_nothing_to_test(self):
        sentence = corpus_stats.finding("esm", "sm", MISMATCH, compared([1.0, 2.0], [1.0, 2.0]))
        self.assertIn("every scene's mismatch_pct equals sm's", sentence)


def record(technique, scene, mismatch, flag=None):
    error = {"mismatch_pct": mismatch, "edge_mismatch_pct": 2 * mismatch, "rmse": mismatch / 10, "leak_pct": 0.0,
             "overestimation_pct": 0.0, "boundary_px": {"mean": mismatch, "p95": 3 * mismatch}, "soft_rmse": None}
    if flag:
        error["flag"] = flag
    return {"technique": technique, "scene": scene, "shadow_map": 1024, "error": error}


class Script(unittest.TestCase):
    def test_tables_and_plots_from_scene_folders(self):
        with tempfile.TemporaryDirectory() as tmp:
            for i in range(6):
                flag = "no shadow boundary" if i == 5 else None
                records = [record("groundtruth", f"s{i}", 0.0), record("sm", f"s{i}", 1.0 + i, flag),
                           record("pcf", f"s{i}", 0.5 + 0.4 * i, flag)]
                os.makedirs(os.path.join(tmp, "runs", f"s{i}"))
                with open(os.path.join(tmp, "runs", f"s{i}", "metrics.json"), "w") as handle:
                    json.dump(records, handle)
            out = os.path.join(tmp, "stats")
            run = subprocess.run([sys.executable, SCRIPT, os.path.join(tmp, "runs"), "--out", out],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertIn("excluded scene s5: no shadow boundary", run.stderr)
            with open(os.path.join(out, "stats.md")) as handle:
                table = handle.read()
            self.assertIn("excluded: scene s5 (no shadow boundary)", table)
            self.assertIn("| pcf | 5 |", table)   # N stated, the flagged scene left out
            self.assertIn("| sm | 5 |", table)
            with open(os.path.join(out, "stats.json")) as handle:
                result = json.load(handle)
            pcf = result["metrics"]["mismatch_pct"]["pcf"]
            self.assertAlmostEqual(pcf["summary"]["median"], 0.5 + 0.4 * 2)
            self.assertEqual(pcf["vs_baseline"]["win_rate"], 1.0)
            self.assertEqual([f["metric"] for f in result["findings"]], ["mismatch_pct", "edge_mismatch_pct", "rmse", "leak_pct",
                                                        "overestimation_pct", "boundary_px.mean", "boundary_px.p95"])
            with open(os.path.join(out, "findings.md")) as handle:
                self.assertIn("- **pcf** against sm, N = 5 paired scenes: two-sided Wilcoxon", handle.read())
            for name in ("mismatch_pct", "rmse", "boundary_px.p95"):
                self.assertGreater(os.path.getsize(os.path.join(out, f"{name}.png")), 1000)
            self.assertFalse(os.path.exists(os.path.join(out, "soft_rmse.png")))  # no values: no plot

    def test_sweep_rows_label_varied_parameters(self):
        # A sweep's records name their row: two pcf kernels stay apart, not "the first kept".
        records = []
        for i in range(4):
            records.append(dict(record("sm", f"s{i}", 2.0 + i), row="sm"))
            for kernel, scale in ((3, 0.5), (5, 0.25)):
                records.append(dict(record("pcf", f"s{i}", scale * (2.0 + i)), row=f"pcf kernel={kernel}"))
        table, flagged, notes = corpus_stats.organise(records)
        self.assertEqual(sorted(table), ["pcf kernel=3", "pcf kernel=5", "sm"])
        self.assertEqual(notes, [])
        self.assertEqual(flagged, {})

    def test_bad_input_exits_2_with_one_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            run = subprocess.run([sys.executable, SCRIPT, os.path.join(tmp, "missing"), "--out", tmp],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 2)
            self.assertEqual(run.stderr.count("\n"), 1, run.stderr)
            self.assertIn("missing: no such file or folder", run.stderr)


def soft_record(technique, scene, mismatch, soft):
    """A record judged against the area-light reference too: every soft metric of the
    table, and the reference it was taken against (area_reference)."""
    r = record(technique, scene, mismatch)
    r["error"].update({"soft_rmse": soft, "soft_penumbra_mae": 2 * soft, "soft_outside_mae": soft / 2,
                       "soft_umbra_leak": soft / 4})
    r["area_reference"] = {"samples": 64, "light_radius": 1.5 + scene.count("1")}
    return r


class SoftMetrics(unittest.TestCase):
    def run_stats(self, records):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "records.json")
            with open(path, "w") as handle:
                json.dump(records, handle)
            out = os.path.join(tmp, "stats")
            run = subprocess.run([sys.executable, SCRIPT, path, "--out", out, "--no-plot"], capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            with open(os.path.join(out, "stats.md")) as handle:
                table = handle.read()
            with open(os.path.join(out, "stats.json")) as handle:
                return table, json.load(handle)

    def test_every_soft_metric_gets_a_table_with_n_and_ci_and_paired_comparison(self):
        # Reference "both": sm and pcf judged against the area light on 6 scenes; pcf's soft
        # error is lower on every one, so it wins all and each soft table compares it with sm.
        records = []
        for i in range(6):
            records += [soft_record("sm", f"s{i}", 1.0 + i, 0.2 + 0.01 * i), soft_record("pcf", f"s{i}", 1.1 + i, 0.1 + 0.01 * i)]
        table, result = self.run_stats(records)
        soft = [m["id"] for m in corpus_stats.metric_table.error_metrics() if m["reference"] == "soft"]
        self.assertEqual(len(soft), 4)  # soft_rmse, penumbra MAE, outside MAE, umbra leak
        for name in soft:
            pcf = result["metrics"][name]["pcf"]
            self.assertEqual(pcf["summary"]["n"], 6)
            self.assertIsNotNone(pcf["summary"]["mean_ci95"])
            self.assertEqual(pcf["vs_baseline"]["win_rate"], 1.0)
            self.assertIn(f"## {name}:", table)
            self.assertIn(name, [f["metric"] for f in result["findings"]])
            self.assertIn("against the area-light reference of 64 samples, light radius 1.5–2.5 over the scenes",
                          result["metric_notes"][name][0])
        self.assertIn("| pcf | 6 |", table.split("## soft_umbra_leak")[1])

    def test_hard_outputs_judged_by_the_hard_truth_only_are_named(self):
        # The default reference judges sm (a hard output) against the hard ground truth only:
        # the soft tables hold pcf alone and say why there is no paired comparison.
        records = []
        for i in range(4):
            records += [record("sm", f"s{i}", 1.0 + i), soft_record("pcf", f"s{i}", 1.1 + i, 0.1)]
        table, result = self.run_stats(records)
        self.assertEqual(list(result["metrics"]["soft_rmse"]), ["pcf"])
        notes = result["metric_notes"]["soft_rmse"]
        self.assertIn("judged against the hard ground truth only (no soft_rmse): sm.", notes)
        self.assertTrue(any(n.startswith("no paired comparison: the baseline sm has no soft_rmse") for n in notes), notes)
        self.assertIn("- no paired comparison: the baseline sm has no soft_rmse", table)


class DocsQuoteTheFindings(unittest.TestCase):
    def test_every_quoted_line_is_a_generated_one(self):
        # docs/corpus.md "What results/corpus shows": between <!-- findings: FILE --> and
        # <!-- end findings -->, only lines of FILE as scripts/corpus_stats.py wrote it.
        root = os.path.join(HERE, "..")
        with open(os.path.join(root, "docs", "corpus.md"), encoding="utf-8") as handle:
            doc = handle.read()
        blocks = re.findall(r"<!-- findings: (\S+) -->\n(.*?)<!-- end findings -->", doc, re.S)
        self.assertEqual(len(blocks), 2)
        for file, quoted in blocks:
            with open(os.path.join(root, file), encoding="utf-8") as handle:
                generated = set(handle.read().splitlines())
            lines = quoted.strip().splitlines()
            self.assertGreater(len(lines), 3, file)
            for line in lines:
                self.assertIn(line, generated, file)
        self.assertNotIn("exact, N = 40", doc)


if __name__ == "__main__":
    unittest.main()
