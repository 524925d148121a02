#!/usr/bin/python3
"""Every run's index.html in a real browser (Debian's Chromium, headless, driven by
python3-selenium and chromium-driver; started and stopped here): a tiny compare, a tiny
compare --frames, a tiny sweep and a tiny scripts/corpus.sh each write one, opened over file:// it logs no console
error, asks for nothing but file: and data: URLs, and its screenshots are not blank; on
compare's page a key press flips the viewer between the technique and the reference; on
compare --frames' page keys step the frame viewer, flip it and show the error map. A
compare and a sweep whose scene name, labels and --out folder hold "<!--<script>" and
"</script>" write pages whose data still parses and whose report script still runs.

usage: html_report_test.py TESTBED_BINARY OUTPUT_FOLDER
The screenshots stay in OUTPUT_FOLDER/screenshots (docs/html-report.md)."""
import io
import json
import os
import shutil
import subprocess
import sys
import unittest

import numpy as np
from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import WebDriverWait

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
TESTBED, OUT = sys.argv[1], os.path.abspath(sys.argv[2])
VIEWPORTS = [(1280, 800), (390, 844)]  # a laptop and a phone
CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"


def testbed(*arguments):
    run = subprocess.run([TESTBED, *arguments], capture_output=True, text=True, stdin=subprocess.DEVNULL)
    if run.returncode != 0:
        raise AssertionError(f"testbed {' '.join(arguments)} failed ({run.returncode}):\n{run.stderr}")


def start_chromium():
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    # --no-sandbox: CI runs as root, where Chromium's sandbox refuses to start.
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--disable-extensions", "--no-first-run", "--window-size=1280,800"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


# Text that ends a script element, or opens a comment that makes the parser swallow the
# report script after the data (HTML Living Standard, "script data escaped" states).
HOSTILE = "<!--<script> a </script> & \u2028 b"
HOSTILE_FOLDER = "<!--<script>"  # a folder name cannot hold '/'


def hostile_inputs(folder):
    """A copy of the wall scene and of the tiny sweep spec whose names hold HOSTILE."""
    with open(os.path.join(REPO, "scenes", "wall.json"), encoding="utf-8") as f:
        scene = json.load(f)
    scene["name"] = "wall " + HOSTILE
    scene_path = os.path.join(folder, "hostile_wall.json")
    with open(scene_path, "w", encoding="utf-8") as f:
        json.dump(scene, f)
    with open(os.path.join(HERE, "data", "sweep_tiny.json"), encoding="utf-8") as f:
        spec = json.load(f)
    spec["title"] = "title " + HOSTILE
    spec["citation"] = "citation " + HOSTILE
    spec["scenes"] = {"wall": scene_path}
    spec["rows"][0]["label"] = "row " + HOSTILE
    spec_path = os.path.join(folder, "hostile_spec.json")
    with open(spec_path, "w", encoding="utf-8") as f:
        json.dump(spec, f)
    return scene_path, spec_path


def variance_of(png_bytes):
    pixels = np.asarray(Image.open(io.BytesIO(png_bytes)).convert("L"), dtype=np.float64)
    return float(pixels.var())


class HtmlReports(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        for path in (CHROMIUM, CHROMEDRIVER):
            if not os.path.exists(path):
                raise AssertionError(f"{path} is missing: install chromium chromium-driver python3-selenium "
                                     "(scripts/setup.sh)")
        shutil.rmtree(OUT, ignore_errors=True)
        os.makedirs(os.path.join(OUT, "screenshots"))
        cls.runs = {
            "compare": os.path.join(OUT, "compare"),
            "sequence": os.path.join(OUT, "sequence"),
            "sweep": os.path.join(OUT, "sweep"),
            "corpus": os.path.join(OUT, "corpus"),
            "hostile-compare": os.path.join(OUT, "compare " + HOSTILE_FOLDER),
            "hostile-sweep": os.path.join(OUT, "sweep " + HOSTILE_FOLDER),
        }
        testbed("compare", "--scene", os.path.join(REPO, "scenes", "bunny.json"), "--techniques", "sm,pcf",
                "--size", "320x180", "--shadow-map", "256", "--out", cls.runs["compare"])
        testbed("compare", "--scene", os.path.join(REPO, "scenes", "motion", "spinning_occluder.json"),
                "--techniques", "sm", "--frames", "0:2:1", "--size", "96x64", "--shadow-map", "128",
                "--out", cls.runs["sequence"])
        testbed("sweep", "--spec", os.path.join(HERE, "data", "sweep_tiny.json"),
                "--out", cls.runs["sweep"])
        scene, spec = hostile_inputs(OUT)
        testbed("compare", "--scene", scene, "--techniques", "sm", "--size", "160x90", "--shadow-map", "128",
                "--out", cls.runs["hostile-compare"])
        testbed("sweep", "--spec", spec, "--out", cls.runs["hostile-sweep"])
        corpus = subprocess.run([os.path.join(REPO, "scripts", "corpus.sh"), "--seed", "7", "--count", "2",
                                 "--techniques", "sm,pcf", "--shadow-maps", "128,256", "--stats-map", "256",
                                 "--out", cls.runs["corpus"]], capture_output=True, text=True,
                                env={**os.environ, "TESTBED": TESTBED}, stdin=subprocess.DEVNULL)
        if corpus.returncode != 0:
            raise AssertionError(f"scripts/corpus.sh failed ({corpus.returncode}):\n{corpus.stderr}")
        cls.browser = start_chromium()

    @classmethod
    def tearDownClass(cls):
        cls.browser.quit()

    def open(self, run, viewport):
        width, height = viewport
        self.browser.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
            "width": width, "height": height, "deviceScaleFactor": 1, "mobile": width < 600})
        self.browser.get_log("browser")  # drop what earlier pages logged
        self.browser.get_log("performance")
        self.browser.get("file://" + os.path.join(self.runs[run], "index.html"))
        WebDriverWait(self.browser, 30).until(
            lambda b: b.execute_script("return document.readyState") == "complete")
        if run.endswith("compare"):
            WebDriverWait(self.browser, 30).until(
                lambda b: b.execute_script("return document.querySelector('.viewer').dataset.ready") == "true")

    def assert_clean(self, what):
        severe = [entry for entry in self.browser.get_log("browser") if entry["level"] == "SEVERE"]
        self.assertEqual(severe, [], f"{what}: console errors")
        urls = []
        for entry in self.browser.get_log("performance"):
            message = json.loads(entry["message"])["message"]
            if message["method"] == "Network.requestWillBeSent":
                urls.append(message["params"]["request"]["url"])
        self.assertTrue(any(url.endswith("index.html") for url in urls), f"{what}: the page's own request not seen")
        outside = [url for url in urls if not url.startswith(("file://", "data:"))]
        self.assertEqual(outside, [], f"{what}: requests that leave the file system")

    def screenshot(self, run, viewport):
        name = os.path.join(OUT, "screenshots", f"{run}-{viewport[0]}x{viewport[1]}.png")
        png = self.browser.get_screenshot_as_png()
        with open(name, "wb") as f:
            f.write(png)
        # A blank page (one colour, or text on white alone) has a tiny variance; the tables,
        # images and plots make it large.
        self.assertGreater(variance_of(png), 200.0, f"{name} looks blank")
        return name

    def test_every_run_page_loads_clean_and_is_not_blank_at_two_sizes(self):
        for run in self.runs:
            for viewport in VIEWPORTS:
                with self.subTest(run=run, viewport=viewport):
                    self.open(run, viewport)
                    self.screenshot(run, viewport)
                    self.assert_clean(f"{run} at {viewport}")

    def test_sweep_entries_link_to_their_cells(self):
        self.open("sweep", VIEWPORTS[0])
        links = self.browser.find_elements(By.CSS_SELECTOR, "table.records a[href^='#cell-']")
        self.assertEqual(len(links), 4)  # 2 rows x 2 columns of sweep_tiny.json
        for link in links:
            target = link.get_attribute("href").split("#")[1]
            self.assertEqual(len(self.browser.find_elements(By.ID, target)), 1, target)

    def test_corpus_tables_link_to_their_cells(self):
        self.open("corpus", VIEWPORTS[0])
        links = self.browser.find_elements(By.CSS_SELECTOR, "table.records a[href^='#cell-']")
        # The per-scene tables (2 scenes x 2 techniques) of mismatch_pct and of the four soft
        # metrics (corpus.sh judges every technique against the area light too by default),
        # and the sweep's table (2 rows x 4 columns).
        self.assertEqual(len(links), 5 * 2 * 2 + 2 * 4)
        for link in links:
            target = link.get_attribute("href").split("#")[1]
            self.assertEqual(len(self.browser.find_elements(By.ID, target)), 1, target)
        self.assertTrue(self.browser.find_elements(By.CSS_SELECTOR, "img[src^='stats/']"), "no box plots")
        self.assertTrue(self.browser.find_elements(By.CSS_SELECTOR, "img[src^='cost/']"), "no Pareto plots")
        self.assertTrue(self.browser.find_elements(By.CSS_SELECTOR, "img[src^='cost-soft_rmse/']"), "no soft Pareto plots")

    def test_corpus_matrix_is_coloured_and_its_links_unfold_the_cell_table(self):
        self.open("corpus", VIEWPORTS[0])
        matrix = self.browser.find_element(By.XPATH, "//section[h2[starts-with(., 'Every scene: mismatch_pct')]]")
        colours = {td.value_of_css_property("background-color")
                   for td in matrix.find_elements(By.CSS_SELECTOR, "td.num")}
        self.assertGreaterEqual(len(colours), 2, "matrix entries share one colour")
        folded = self.browser.find_element(By.CSS_SELECTOR, "details.folded")
        self.assertFalse(folded.get_property("open"), "the cell table starts folded")
        link = matrix.find_element(By.CSS_SELECTOR, "a[href^='#cell-']")
        target = link.get_attribute("href").split("#")[1]
        link.click()
        WebDriverWait(self.browser, 10).until(lambda b: b.find_element(By.ID, target).is_displayed())
        self.assertTrue(folded.get_property("open"))
        # The filter keeps the rows that hold every word typed.
        rows = folded.find_elements(By.CSS_SELECTOR, "tbody tr")
        box = folded.find_element(By.CSS_SELECTOR, "input.filter")
        box.send_keys("pcf 128")
        shown = [r for r in rows if r.is_displayed()]
        self.assertTrue(shown and len(shown) < len(rows), f"{len(shown)} of {len(rows)} rows shown")
        for row in shown:
            self.assertIn("pcf", row.text)
            self.assertIn("128", row.text)
        self.screenshot("corpus-matrix", VIEWPORTS[0])
        self.assert_clean("corpus after unfolding and filtering")

    def test_motion_frames_step_flip_and_show_the_error_map(self):
        self.open("sequence", VIEWPORTS[0])
        viewer = self.browser.find_element(By.CSS_SELECTOR, "section.frame-viewer")
        canvas = viewer.find_element(By.CSS_SELECTOR, ".frame-pane canvas")
        WebDriverWait(self.browser, 10).until(lambda b: b.execute_script(
            "return [...document.images].filter(i => i.src.includes('_frames_')).every(i => i.complete)"))
        showing = lambda: viewer.get_attribute("data-showing")
        self.assertEqual(showing(), "sm@0")
        first = canvas.screenshot_as_png
        self.assertGreater(variance_of(first), 50.0, "the first frame looks blank")
        viewer.click()
        keys = ActionChains(self.browser)
        keys.send_keys_to_element(viewer, Keys.ARROW_RIGHT).perform()
        self.assertEqual(showing(), "sm@1")
        self.assertNotEqual(canvas.screenshot_as_png, first, "the next frame of a spinning occluder is the same image")
        ActionChains(self.browser).send_keys_to_element(viewer, "e").perform()
        self.assertEqual(showing(), "sm:error@1")
        ActionChains(self.browser).send_keys_to_element(viewer, "f").perform()
        self.assertEqual(showing(), "groundtruth:error@1")
        ActionChains(self.browser).send_keys_to_element(viewer, Keys.END).perform()
        self.assertEqual(showing(), "groundtruth:error@2")
        self.screenshot("sequence-frames", VIEWPORTS[0])
        self.assert_clean("sequence after stepping")

    def test_hostile_names_stay_data(self):
        for run, expected in (("hostile-compare", "wall " + HOSTILE), ("hostile-sweep", "row " + HOSTILE)):
            with self.subTest(run=run):
                self.open(run, VIEWPORTS[0])
                data = self.browser.execute_script(
                    "return JSON.parse(document.getElementById('page-data').textContent)")
                self.assertIn(expected, json.dumps(data, ensure_ascii=False))
                # The report script ran: it filled <main> (a swallowed script leaves it empty).
                self.assertGreater(self.browser.execute_script(
                    "return document.getElementById('main').children.length"), 0)
                self.assertEqual(len(self.browser.find_elements(By.CSS_SELECTOR, "script")), 2)
                self.assert_clean(run)

    def pane_pixels(self):
        return self.browser.execute_script(
            "const c = document.querySelector('.pane canvas');"
            "const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;"
            "let h = 0; for (let i = 0; i < d.length; i += 1) h = (h * 31 + d[i]) >>> 0; return h;")

    def showing(self):
        return self.browser.execute_script("return document.querySelector('.viewer').dataset.showing")

    def test_a_key_flips_the_viewer_between_technique_and_reference(self):
        self.open("compare", VIEWPORTS[0])
        # Go to sm's first close-up window: the window with the most errors, where sm and the
        # ground truth must differ in pixels.
        rows = self.browser.find_elements(By.CSS_SELECTOR, "table.closeups tr")
        sm_row = next(r for r in rows if r.find_elements(By.TAG_NAME, "th")[0].text == "sm")
        sm_row.find_element(By.TAG_NAME, "canvas").click()
        self.assertEqual(self.showing(), "sm")
        technique = self.pane_pixels()
        body = self.browser.find_element(By.TAG_NAME, "body")
        ActionChains(self.browser).send_keys_to_element(body, "f").perform()
        self.assertEqual(self.showing(), "reference")
        self.assertNotEqual(self.pane_pixels(), technique, "the flip changed no pixel")
        ActionChains(self.browser).send_keys_to_element(body, "f").perform()
        self.assertEqual(self.showing(), "sm")
        self.assertEqual(self.pane_pixels(), technique)
        self.screenshot("compare-zoomed", VIEWPORTS[0])
        self.assert_clean("compare after the flips")


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
