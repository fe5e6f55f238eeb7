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
- With `stepdance serve` (no target: the sketch server) on loopback, allowing the page's origin:
  the sketch becomes editable; an edit that does not compile shows the compiler's error at the
  edited line; an edit that prints a line compiles, runs there with the page as its view (the
  line on the view's console), and ends with every expectation met. Without a server the page
  says how to start one. The server refuses a foreign origin, file names with folders in them,
  and messages that are not run requests.

Usage: site_page_test.py STEPDANCE_BINARY SITE_DIR SOURCE_DIR WORK_DIR
"""
import json
import math
import os
import re
import subprocess
import sys
import time
import unittest

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

STEPDANCE, SITE_DIR, SOURCE_DIR, WORK_DIR = sys.argv[1:5]
os.makedirs(WORK_DIR, exist_ok=True)
sys.path.insert(0, os.path.join(SOURCE_DIR, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402  (the page tests' browser)
from view_client import RawWebSocket, websocket_status  # noqa: E402


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


class SketchServer(SitePage):
    """The edit path: the page with a local `stepdance serve` compiling its sketch."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.serve = subprocess.Popen([STEPDANCE, "serve", "--port", "0", "--allow-origin", f"http://127.0.0.1:{cls.port}",
                                      "--cache", os.path.join(WORK_DIR, "serve-cache")],
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        cls.serve_port = int(re.search(r"serving sketches on http://127\.0\.0\.1:(\d+)/", cls.serve.stdout.readline()).group(1))

    @classmethod
    def tearDownClass(cls):
        cls.serve.terminate()
        cls.serve.communicate(timeout=60)
        super().tearDownClass()

    # The page tests above run here too, with the server: they need not.
    test_harmonograph_at_max_speed_ends_as_the_native_run = None
    test_a_knob_turned_on_the_page_draws_a_stroke = None
    test_a_syntax_error_is_shown_at_its_line = None

    def edited_sketch(self, edit):
        self.open_example("StepASketch", query=f"?serve={self.serve_port}")
        self.wait_for(lambda: self.site("server") is not None and
                      self.browser.find_element(By.ID, "sketch-editor").is_displayed(), 60)
        lines = self.browser.find_element(By.ID, "sketch-editor").get_attribute("value").split("\n")
        at = next(i for i, line in enumerate(lines) if line.startswith("void setup()"))
        edit(lines, at)
        self.browser.execute_script("document.getElementById('sketch-editor').value = arguments[0];", "\n".join(lines))
        self.browser.find_element(By.ID, "run").click()
        return at

    def test_an_edit_that_does_not_compile_shows_the_error_at_its_line(self):
        at = self.edited_sketch(lambda lines, at: lines.insert(at, "int broken = ;"))
        self.wait_for(lambda: any(p["file"] == "StepASketch.ino" for p in self.site("problems")), 300)
        problem = next(p for p in self.site("problems") if p["file"] == "StepASketch.ino")
        self.assertEqual(problem["line"], at + 1)
        self.assertTrue(problem["message"].startswith("error:"), problem)

    def test_an_edited_sketch_runs_on_the_server_with_the_page_as_its_view(self):
        self.edited_sketch(lambda lines, at: lines.insert(at + 1, '  Serial.println("edited on the page");'))
        self.wait_view("true", 300)
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        self.browser.find_element(By.CSS_SELECTOR, "button[data-speed='max']").click()
        self.browser.switch_to.default_content()
        self.wait_for(lambda: self.site("result") is not None, 300)
        console = self.in_view("return Array.from(document.querySelectorAll('[id^=console-]')).map(e => e.textContent).join('');")
        self.assertIn("edited on the page", console)
        expectations = self.site("result.expectations")
        self.assertEqual(len(expectations), 4)
        self.assertTrue(all(e["checked"] and e["met"] for e in expectations), expectations)
        self.assertEqual(self.in_view("return window.stepdanceView.strokes.length;"), 4)

    def sim_time_over(self, wall_s):
        """The view's simulated time gained over `wall_s` seconds of wall time."""
        before = self.in_view("return window.stepdanceView.t_s;")
        time.sleep(wall_s)
        return self.in_view("return window.stepdanceView.t_s;") - before

    def click_in_view(self, selector):
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        try:
            self.browser.find_element(By.CSS_SELECTOR, selector).click()
        finally:
            self.browser.switch_to.default_content()

    def test_the_view_run_controls_act_on_a_run_on_the_server(self):
        # Issue 40: the view's `run` control and the edit protocol's run request shared a type name,
        # so with the server up Pause, 1x, 10x and max were answered "run: needs `example`…".
        self.edited_sketch(lambda lines, at: None)
        self.wait_view("window.stepdanceView.t_s > 0", 300)
        self.click_in_view("#pause")
        self.wait_for(lambda: self.in_view("return !document.getElementById('resume').hidden;"), 10)
        self.assertEqual(self.sim_time_over(1.0), 0.0)
        self.click_in_view("#resume")
        self.click_in_view("button[data-speed='1']")
        self.wait_for(lambda: self.in_view("return document.querySelector(\"button[data-speed='1']\").classList.contains('active');"), 10)
        one_x = self.sim_time_over(2.0)
        self.assertGreater(one_x, 2.0 * 0.6)
        self.assertLess(one_x, 2.0 * 1.4)
        self.click_in_view("button[data-speed='10']")
        self.wait_for(lambda: self.in_view("return document.querySelector(\"button[data-speed='10']\").classList.contains('active');"), 10)
        ten_x = self.sim_time_over(1.0)
        self.assertGreater(ten_x, 10 * 0.5)
        self.assertLess(ten_x, 10 * 1.4)
        self.click_in_view("button[data-speed='max']")
        self.wait_for(lambda: self.site("result") is not None, 120)
        self.assertEqual(self.in_view("return window.stepdanceView.errors;"), [])
        self.assertTrue(all(e["checked"] and e["met"] for e in self.site("result.expectations")))

    def test_a_scenario_naming_another_examples_sketch_runs_on_the_server(self):
        # ChainedPlotterDriver's knobs board runs ../ChainedKnobsBasic/ChainedKnobsBasic.ino: the page
        # sends it as one of `others`, and the server writes it beside the run's example.
        native = native_summary("ChainedPlotterDriver")
        self.open_example("ChainedPlotterDriver", query=f"?serve={self.serve_port}")
        self.wait_for(lambda: self.site("server") is not None, 60)
        self.browser.find_element(By.ID, "run").click()
        self.wait_view("true", 300)
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        self.browser.find_element(By.CSS_SELECTOR, "button[data-speed='max']").click()
        self.browser.switch_to.default_content()
        self.wait_for(lambda: self.site("result") is not None, 300)
        self.assertEqual(self.site("problems"), [])
        expectations = self.site("result.expectations")
        self.assertTrue(expectations and all(e["checked"] and e["met"] for e in expectations), expectations)
        self.assertEqual(self.site("result.summary.machine.strokes"), native["machine"]["strokes"])

    def test_the_server_refuses_foreign_origins_and_bad_requests(self):
        self.assertIn("403", websocket_status(self.serve_port, "/ws", "http://evil.example"))
        client = RawWebSocket(self.serve_port, "", origin=f"http://127.0.0.1:{self.port}")
        self.assertIn("101", client.status)
        self.assertEqual(client.receive()["type"], "serve_hello")
        for bad in ({"type": "sketch_run", "example": "StepASketch", "files": {"../x.ino": ""}, "scenario": "../x.ino"},
                    {"type": "sketch_run", "example": "../up", "files": {}, "scenario": "scenario.toml"},
                    {"type": "sketch_run", "example": "StepASketch", "files": {"a.toml": ""}, "scenario": "b.toml"},
                    {"type": "sketch_run", "example": "StepASketch", "files": {"a.toml": ""}, "scenario": "a.toml",
                     "others": {"..": {"x.ino": ""}}},
                    {"type": "sketch_run", "example": "StepASketch", "files": {"a.toml": ""}, "scenario": "a.toml",
                     "others": {"Other": {"../x.ino": ""}}},
                    {"type": "input", "device": "knob_x", "action": "turn", "counts": 1},
                    {"type": "run", "action": "pause"}):  # the view's run control, with no run going
            client.send(json.dumps(bad))
            self.assertEqual(client.receive()["type"], "error", bad)
        client.close()


class WithoutAServer(SitePage):
    test_harmonograph_at_max_speed_ends_as_the_native_run = None
    test_a_knob_turned_on_the_page_draws_a_stroke = None
    test_a_syntax_error_is_shown_at_its_line = None

    def test_the_page_says_how_to_start_a_server(self):
        # A port nobody listens on (the static server's, once it is gone, is not safe: this one is ours and closed).
        self.open_example("StepASketch", query="?serve=9")
        self.wait_for(lambda: "stepdance serve --allow-origin" in self.browser.find_element(By.ID, "serve-state").text, 30)
        self.assertIn(f"stepdance serve --allow-origin http://127.0.0.1:{self.port}",
                      self.browser.find_element(By.ID, "serve-state").text)
        self.assertFalse(self.browser.find_element(By.ID, "sketch-editor").is_displayed())


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
