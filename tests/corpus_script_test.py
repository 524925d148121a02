#!/usr/bin/python3
"""scripts/corpus.sh end to end on a tiny corpus (3 scenes, sm and pcf, maps 128² and 256²):
one sweep over the corpus folder writes the records of every scene × map × technique, the
statistics at the chosen map size, the equal-cost view over both sizes and an index.html
whose corpus tables link to cells the page holds; the committed files name no machine's
folder; a run interrupted during the sweep resumes from its records; bad options write
nothing.

usage: corpus_script_test.py TESTBED_BINARY OUTPUT_FOLDER"""
import json
import os
import re
import shutil
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
SCRIPT = os.path.join(REPO, "scripts", "corpus.sh")
TESTBED, OUT = sys.argv[1], os.path.abspath(sys.argv[2])
OPTIONS = ["--seed", "7", "--count", "3", "--techniques", "sm,pcf", "--shadow-maps", "128,256", "--stats-map", "256",
           "--area-samples", "16"]
DATA = re.compile(r'<script type="application/json" id="page-data">(.*?)</script>', re.S)


def corpus(out, *extra):
    return subprocess.run([SCRIPT, *OPTIONS, "--out", out, *extra], capture_output=True, text=True,
                          env={**os.environ, "TESTBED": TESTBED}, stdin=subprocess.DEVNULL)


def page_data(folder):
    with open(os.path.join(folder, "index.html"), encoding="utf-8") as f:
        return json.loads(DATA.search(f.read()).group(1).replace("<\\/", "</"))


class CorpusScript(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(OUT, ignore_errors=True)
        os.makedirs(OUT)
        cls.run_dir = os.path.join(OUT, "whole")
        cls.result = corpus(cls.run_dir)
        if cls.result.returncode != 0:
            raise AssertionError(f"corpus.sh failed ({cls.result.returncode}):\n{cls.result.stderr}")

    def test_one_sweep_holds_every_scene_map_and_technique(self):
        with open(os.path.join(self.run_dir, "records.json"), encoding="utf-8") as f:
            records = json.load(f)
        scenes = sorted(n[:-5] for n in os.listdir(os.path.join(self.run_dir, "scenes")) if n != "manifest.json")
        self.assertEqual(len(scenes), 3)
        measured = {(r["scene"], r["shadow_map"], r["technique"]) for r in records if r["technique"] != "groundtruth"}
        self.assertEqual(measured, {(s, m, t) for s in scenes for m in (128, 256) for t in ("sm", "pcf")})
        with open(os.path.join(self.run_dir, "sweep.json"), encoding="utf-8") as f:
            self.assertEqual(json.load(f)["spec"], "corpus")

    def test_statistics_at_the_chosen_map_and_cost_over_both(self):
        with open(os.path.join(self.run_dir, "stats", "stats.json"), encoding="utf-8") as f:
            stats = json.load(f)
        self.assertEqual(stats["shadow_map"], 256)
        self.assertEqual(set(stats["metrics"]["mismatch_pct"]), {"sm", "pcf"})  # one map: no "@size" labels
        with open(os.path.join(self.run_dir, "cost", "cost.json"), encoding="utf-8") as f:
            cost = json.load(f)
        budgets = {row["budget"] for row in cost["tables"]["frame_ms"]}
        self.assertEqual(budgets, {f"{t} @{m}" for t in ("sm", "pcf") for m in (128, 256)})

    def test_both_references_give_every_soft_metric_its_statistics_and_cost_view(self):
        # The default --reference both: sm and pcf judged against the area light too, one
        # reference per scene; the soft metrics' tables, equal-cost views and page sections.
        with open(os.path.join(self.run_dir, "stats", "stats.json"), encoding="utf-8") as f:
            stats = json.load(f)
        soft = [name for name in stats["metrics"] if name.startswith("soft_")]
        self.assertEqual(len(soft), 4, sorted(stats["metrics"]))
        for name in soft:
            self.assertEqual(set(stats["metrics"][name]), {"sm", "pcf"})
            self.assertEqual(stats["metrics"][name]["pcf"]["summary"]["n"], 3)
            self.assertIn("vs_baseline", stats["metrics"][name]["pcf"])
            self.assertIn("of 16 samples", stats["metric_notes"][name][0])
            with open(os.path.join(self.run_dir, f"cost-{name}", "cost.json"), encoding="utf-8") as f:
                self.assertEqual(json.load(f)["error"], name)
        self.assertEqual(self.result.stderr.count("] area-light reference (16 samples)"), 3, self.result.stderr)
        titles = [s.get("title", "") for s in page_data(self.run_dir)["sections"]]
        for name in soft:
            self.assertIn(f"Across scenes: {name}", titles)
            self.assertIn(f"Every scene: {name} at shadow map 256²", titles)
            self.assertIn(f"At equal cost (frame ms): {name}", titles)

    def test_the_page_shows_the_corpus_and_links_resolve(self):
        data = page_data(self.run_dir)
        titles = [s.get("title", "") for s in data["sections"]]
        self.assertIn("Across scenes: mismatch_pct", titles)
        self.assertTrue(any(t.startswith("At equal cost") for t in titles), titles)
        ids = {row["id"] for s in data["sections"] if s["type"] == "table" for row in s["rows"] if "id" in row}
        scenes_table = next(s for s in data["sections"] if s.get("title", "").startswith("Every scene"))
        links = [c["href"] for row in scenes_table["rows"] for c in row["cells"][1:] if "href" in c]
        self.assertEqual(len(links), 3 * 2)  # 3 scenes x 2 techniques, each to its cell
        for link in links:
            self.assertIn(link[1:], ids)
        for section in data["sections"]:
            if section["type"] == "figure":
                self.assertTrue(os.path.isfile(os.path.join(self.run_dir, section["src"])), section["src"])

    def test_the_page_script_run_again_replaces_what_it_added(self):
        copy = os.path.join(OUT, "page-again")
        shutil.copytree(self.run_dir, copy)
        subprocess.run(["/usr/bin/python3", os.path.join(REPO, "scripts", "corpus_page.py"), copy], check=True,
                       capture_output=True)
        self.assertEqual(page_data(copy), page_data(self.run_dir))

    def test_committed_files_name_no_machine_folder(self):
        for name in ("spec.json", "corpus.md", "corpus.json", "sweep.json", "command.txt", "stats/stats.md",
                     "cost/cost.md"):
            with open(os.path.join(self.run_dir, name), encoding="utf-8") as f:
                self.assertNotIn(OUT, f.read(), name)

    def test_an_interrupted_run_resumes_from_its_records(self):
        out = os.path.join(OUT, "interrupted")
        process = subprocess.Popen([SCRIPT, *OPTIONS, "--out", out], stderr=subprocess.PIPE, text=True,
                                   env={**os.environ, "TESTBED": TESTBED}, stdin=subprocess.DEVNULL,
                                   start_new_session=True)
        for line in process.stderr:
            if line.startswith("[4/"):  # a few cells written: stop it mid-sweep
                os.killpg(process.pid, 9)
                break
        process.wait()
        process.stderr.close()
        self.assertTrue(os.path.isdir(out + ".partial"))
        self.assertFalse(os.path.exists(out))
        again = corpus(out)
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertRegex(again.stderr, r"resuming: [1-9][0-9]* cells")
        self.assertFalse(os.path.exists(out + ".partial"))
        with open(os.path.join(out, "records.json"), encoding="utf-8") as f:
            resumed = json.load(f)
        with open(os.path.join(self.run_dir, "records.json"), encoding="utf-8") as f:
            whole = json.load(f)
        self.assertEqual([(r["cell"], r["error"]) for r in resumed], [(r["cell"], r["error"]) for r in whole])

    def test_bad_options_write_nothing(self):
        for options, field in ((["--stats-map", "512"], "--stats-map"), (["--count", "0"], "count"),
                               (["--reference", "area"], "--reference"), (["--area-samples", "0"], "--area-samples"),
                               (["--reference", "hard", "--light-radius", "2"], "--light-radius")):
            out = os.path.join(OUT, "bad")
            run = corpus(out, *options)
            self.assertEqual(run.returncode, 2, run.stderr)
            self.assertIn(field, run.stderr)
            self.assertFalse(os.path.exists(out))
            self.assertFalse(os.path.exists(out + ".partial"))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
