#!/usr/bin/python3
"""The Stepdance page (build/web/, the WebAssembly build) in headless Chromium, served by a plain
static file server, as a person uses it:

- Harmonograph, run to its end at max speed: the drawing's stroke count and the final pen
  position on the page are the native run's (`stepdance sim examples/Harmonograph`, summary.json),
  and so are the page's summary table figures (motor steps).
- Step-A-Sketch's live scenario (no timeline): the pen button clicked and knob 1 dragged one whole
  turn counter-clockwise draw a stroke from (0, 0) to (24, 0) mm. That end comes from the sketch's
  own numbers, not from either build: 2400 counts a turn, 100 counts a mm, inverted.
- Step-A-Sketch's scenario edited into a syntax error: the page shows the scenario reader's
  message at its line, the same message and line the native command prints for that text.

Usage: site_page_test.py STEPDANCE_BINARY SITE_DIR SOURCE_DIR WORK_DIR
"""
import json
import math
import os
import re
import subprocess
import sys
import unittest

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

STEPDANCE, SITE_DIR, SOURCE_DIR, WORK_DIR = sys.argv[1:5]
sys.path.insert(0, os.path.join(SOURCE_DIR, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402  (the page tests' browser)


def native_summary(example):
    out = os.path.join(WORK_DIR, "native-" + example)
    subprocess.run([STEPDANCE, "sim", os.path.join(SOURCE_DIR, "examples", example), "--out", out, "--no-vcd"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as summary:
        return json.load(summary)


class SitePage(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = subprocess.Popen([sys.executable, "-u", "-m", "http.server", "0", "--bind", "127.0.0.1",
                                       "--directory", SITE_DIR], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                      text=True)
        cls.port = int(re.search(r"port (\d+)", cls.server.stdout.readline()).group(1))

    @classmethod
    def tearDownClass(cls):
        cls.server.kill()
        cls.server.communicate()

    def setUp(self):
        self.chromium = Chromium()
        self.browser = self.chromium.driver

    def tearDown(self):
        self.chromium.quit()

    def open_example(self, name, scenario="scenario.toml", query=""):
        self.browser.get(f"http://127.0.0.1:{self.port}/{query}#{name}")
        self.wait_for(lambda: self.browser.find_element(By.ID, "status").text.startswith("ready"), 60)
        Select(self.browser.find_element(By.ID, "scenario-file")).select_by_value(scenario)

    def wait_for(self, condition, seconds):
        WebDriverWait(self.browser, seconds, poll_frequency=0.05).until(lambda _: condition())

    def site(self, expression):
        return self.browser.execute_script(f"return window.stepdanceSite.{expression};")

    def in_view(self, script):
        """Runs `script` in the view's frame and returns its value."""
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        try:
            return self.browser.execute_script(script)
        finally:
            self.browser.switch_to.default_content()

    def wait_view(self, expression, seconds=60):
        self.wait_for(lambda: self.in_view(
            f"return !!(window.stepdanceView && window.stepdanceView.hello && ({expression}));"), seconds)

    def test_harmonograph_at_max_speed_ends_as_the_native_run(self):
        native = native_summary("Harmonograph")
        self.open_example("Harmonograph")
        self.browser.find_element(By.ID, "run").click()
        self.wait_view("true")
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        self.browser.find_element(By.CSS_SELECTOR, "button[data-speed='max']").click()
        self.browser.switch_to.default_content()
        self.wait_for(lambda: self.site("result") is not None, 600)
        strokes = self.in_view("return window.stepdanceView.strokes.length;")
        pen = self.in_view("return window.stepdanceView.pen;")
        polylines = self.in_view("return document.querySelectorAll('#strokes polyline').length;")
        self.assertEqual(strokes, native["machine"]["strokes"])
        self.assertEqual(polylines, native["machine"]["strokes"])
        self.assertAlmostEqual(pen["x_mm"], native["machine"]["pen_mm"][0], places=6)
        self.assertAlmostEqual(pen["y_mm"], native["machine"]["pen_mm"][1], places=6)
        page_summary = self.site("result.summary")
        for motor, counts in native["motors"].items():
            self.assertEqual(page_summary["motors"][motor]["steps"], counts["steps"], motor)
        cells = self.browser.execute_script(
            "return Array.from(document.querySelectorAll('#summary td')).map(td => td.textContent);")
        self.assertIn(str(native["machine"]["strokes"]), cells)

    def test_a_knob_turned_on_the_page_draws_a_stroke(self):
        self.open_example("StepASketch", "live.toml")
        self.browser.find_element(By.ID, "run").click()
        self.wait_view("window.stepdanceView.pen")
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        try:
            self.browser.find_element(By.ID, "control-pen_button").click()
            self.wait_for(lambda: self.browser.execute_script("return window.stepdanceView.pen.down;"), 60)
            knob = self.browser.find_element(By.ID, "control-knob_x")
            radius, steps = 24, 48
            points = [(round(radius * math.cos(-2 * math.pi * k / steps)),
                       round(radius * math.sin(-2 * math.pi * k / steps))) for k in range(steps + 1)]
            actions = ActionChains(self.browser, duration=20)
            actions.move_to_element_with_offset(knob, *points[0]).click_and_hold()
            for (x0, y0), (x1, y1) in zip(points, points[1:]):
                actions.move_by_offset(x1 - x0, y1 - y0)
            actions.release().perform()
            self.wait_for(lambda: abs(self.browser.execute_script("return window.stepdanceView.pen.x_mm;") - 24) < 1e-6,
                          60)
            strokes = self.browser.execute_script("return window.stepdanceView.strokes;")
        finally:
            self.browser.switch_to.default_content()
        self.assertEqual(len(strokes), 1)
        first, last = strokes[0][0], strokes[0][-1]
        self.assertLess(math.dist(first, (0, 0)), 0.01)
        self.assertLess(math.dist(last, (24, 0)), 0.01)

    def test_a_syntax_error_is_shown_at_its_line(self):
        self.open_example("StepASketch")
        text = self.browser.find_element(By.ID, "scenario").get_attribute("value")
        lines = text.split("\n")
        bad_line = next(i for i, line in enumerate(lines) if line.startswith("duration_s")) + 1
        lines[bad_line - 1] = "duration_s = = 42"
        broken = "\n".join(lines)
        # The native reader's word on the same text, as a file in the example's folder.
        broken_path = os.path.join(WORK_DIR, "broken.toml")
        with open(broken_path, "w") as file:
            file.write(broken)
        native = subprocess.run([STEPDANCE, "sim", broken_path, "--out", os.path.join(WORK_DIR, "broken-out")],
                                capture_output=True, text=True)
        self.assertNotEqual(native.returncode, 0)
        native_line = re.search(re.escape(broken_path) + r":(\d+)(?::\d+)?: ?(.*)", native.stderr)
        self.assertIsNotNone(native_line, native.stderr)
        self.assertEqual(int(native_line.group(1)), bad_line)
        self.browser.execute_script("const box = document.getElementById('scenario'); box.value = arguments[0]; "
                                    "box.dispatchEvent(new Event('input'));", broken)
        self.browser.find_element(By.ID, "run").click()
        self.wait_for(lambda: len(self.site("problems")) > 0, 120)
        problems = self.site("problems")
        self.assertEqual(problems[0]["line"], bad_line)
        self.assertEqual(problems[0]["message"], native_line.group(2))
        shown = self.browser.find_element(By.ID, "problems").text
        self.assertIn(f"line {bad_line}: {native_line.group(2)}", shown)
        marked = self.browser.execute_script(
            "return Array.from(document.querySelectorAll('#scenario-lines .bad')).map(s => s.textContent.trim());")
        self.assertEqual(marked, [str(bad_line)])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
