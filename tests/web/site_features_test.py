#!/usr/bin/python3
"""The Stepdance page's own features (issue 40), in headless Chromium on the built site served by
a plain static file server:

- edits persist per example across a reload and across switching scenario files; Revert drops them;
- a share link carries the edited scenario, compressed, and opening it (with nothing stored)
  restores it: the shared scenario's duration is the run's simulated time;
- after a run the Summary is in view; a failed expectation's row jumps to its line, which is
  marked in the margin; a run that does not start leaves no stale drawing;
- a phone (390 px, Chromium's mobile emulation): one column, the drawing at least 90 % of the
  width; the screenshot is kept (WORK_DIR/phone-390.png);
- loading logs nothing (no sketch-server probe, a favicon); from file:// it says how to serve;
- the first visit opens Step-A-Sketch with a "press Run" hint; the sketch has line numbers;
  compiler warnings are told apart from errors; dark mode follows prefers-color-scheme;
- a running view is handed at most 30 updates a second (it draws no more often), and still some.

Usage: site_features_test.py SITE_DIR SOURCE_DIR WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import time
import unittest

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

SITE_DIR, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
os.makedirs(WORK_DIR, exist_ok=True)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_browser import PHONE_PIXEL_RATIO, PHONE_WIDTH_PX, chromium  # noqa: E402
class PageTest(unittest.TestCase):
    phone = False

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
        self.browser, self.profile = chromium(self.phone)

    def tearDown(self):
        self.browser.quit()
        shutil.rmtree(self.profile, ignore_errors=True)

    def url(self, fragment=""):
        return f"http://127.0.0.1:{self.port}/{fragment}"

    def wait_for(self, condition, seconds=60):
        WebDriverWait(self.browser, seconds, poll_frequency=0.05).until(lambda _: condition())

    def site(self, expression):
        return self.browser.execute_script(f"return window.stepdanceSite.{expression};")

    def open_page(self, fragment="#StepASketch"):
        self.browser.get(self.url(fragment))
        self.wait_for(lambda: self.site("shown") is not None and
                      self.browser.find_element(By.ID, "status").text.startswith("ready"))

    def scenario(self):
        return self.browser.find_element(By.ID, "scenario").get_attribute("value")

    def type_scenario(self, text):
        """Puts `text` into the scenario editor as typing does (an input event)."""
        self.browser.execute_script("const box = document.getElementById('scenario'); box.value = arguments[0]; "
                                    "box.dispatchEvent(new Event('input'));", text)

    def in_view(self, script):
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        try:
            return self.browser.execute_script(script)
        finally:
            self.browser.switch_to.default_content()

    def run_at_max(self):
        self.browser.find_element(By.ID, "run").click()
        self.wait_for(lambda: self.in_view("return !!(window.stepdanceView && window.stepdanceView.hello);"))
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        self.browser.find_element(By.CSS_SELECTOR, "button[data-speed='max']").click()
        self.browser.switch_to.default_content()
        self.wait_for(lambda: self.site("result") is not None, 300)


def with_duration(text, seconds):
    return re.sub(r"(?m)^duration_s = .*$", f"duration_s = {seconds}", text)


class KeepAndShare(PageTest):
    def test_edits_persist_across_a_reload_and_a_scenario_switch(self):
        self.open_page()
        original = self.scenario()
        edited = with_duration(original, 7)
        self.type_scenario(edited)
        Select(self.browser.find_element(By.ID, "scenario-file")).select_by_value("live.toml")
        self.assertNotEqual(self.scenario(), edited)
        Select(self.browser.find_element(By.ID, "scenario-file")).select_by_value("scenario.toml")
        self.assertEqual(self.scenario(), edited)
        self.open_page()  # a reload
        self.assertEqual(self.scenario(), edited)
        self.assertIn("edited", self.browser.find_element(By.ID, "edit-state").text)
        self.browser.find_element(By.ID, "revert").click()
        self.browser.switch_to.alert.accept()
        self.assertEqual(self.scenario(), original)
        self.open_page()
        self.assertEqual(self.scenario(), original)

    def test_a_share_link_restores_the_edited_scenario(self):
        self.open_page()
        edited = self.scenario().replace("strokes = 4", "strokes = 5") + "\n# shared from the page\n"
        self.type_scenario(edited)
        self.browser.find_element(By.ID, "share").click()
        self.wait_for(lambda: self.browser.find_element(By.ID, "share-link").get_attribute("value") != "")
        link = self.browser.find_element(By.ID, "share-link").get_attribute("value")
        shared = re.search(r"#StepASketch&edits=([A-Za-z0-9_-]+)$", link)
        self.assertIsNotNone(shared, link)
        self.assertLess(len(shared.group(1)), len(edited) / 2)  # compressed (base64 of deflate)
        # A browser with nothing stored: the link alone brings the edits.
        self.browser.execute_script("localStorage.clear();")
        self.browser.get("about:blank")
        self.browser.get(link)
        self.wait_for(lambda: self.site("shown") == "StepASketch")
        self.assertEqual(self.scenario(), edited)
        self.assertEqual(self.browser.current_url, self.url("#StepASketch"))  # the edits are now kept here
        self.run_at_max()
        verdicts = {e["message"].split(": ", 1)[1].split(":")[0]: e["met"] for e in self.site("result.expectations")}
        self.assertEqual(verdicts["pen-down strokes"], False)  # the shared edit asks 5; the house has 4
        self.assertEqual(self.site("result.summary.machine.strokes"), 4)

    def test_a_damaged_share_link_shows_the_example(self):
        self.browser.get(self.url("#StepASketch&edits=not-a-share-link"))
        self.wait_for(lambda: self.site("shown") == "StepASketch")
        self.assertIn("damaged", self.browser.find_element(By.ID, "status").text)
        with open(os.path.join(SOURCE_DIR, "examples/StepASketch/scenario.toml")) as file:
            self.assertEqual(self.scenario(), file.read())


class AfterARun(PageTest):
    def test_the_summary_shows_and_a_failed_expectation_jumps_to_its_line(self):
        self.open_page()
        lines = self.scenario().split("\n")
        strokes_line = lines.index("strokes = 4") + 1
        lines[strokes_line - 1] = "strokes = 5"
        # An expectation's message names its table's header line, as `stepdance sim` prints it.
        expect_line = strokes_line - 1
        self.assertEqual(lines[expect_line - 1], "[[expect]]")
        self.type_scenario("\n".join(lines))
        self.run_at_max()
        top, bottom, height = self.browser.execute_script(
            "const box = document.getElementById('result').getBoundingClientRect();"
            "return [box.top, box.bottom, window.innerHeight];")
        self.assertGreaterEqual(top, 0)
        self.assertLess(top, height)
        rows = self.browser.find_elements(By.CSS_SELECTOR, "#expectations tr")
        failed = [row for row in rows if row.find_element(By.TAG_NAME, "td").text == "FAILED"]
        self.assertEqual(len(failed), 1)
        failed[0].find_element(By.CSS_SELECTOR, "button.line-link").click()
        start, end = self.browser.execute_script(
            "const box = document.getElementById('scenario'); return [box.selectionStart, box.selectionEnd];")
        self.assertEqual(self.scenario()[:start].count("\n") + 1, expect_line)
        self.assertEqual(self.scenario()[start:end], "[[expect]]")
        marked = self.browser.execute_script(
            "return Array.from(document.querySelectorAll('#scenario-lines .failed')).map(s => s.textContent.trim());")
        self.assertEqual(marked, [str(expect_line)])

    def test_a_run_that_does_not_start_clears_the_drawing(self):
        self.open_page()
        good = self.scenario()
        self.run_at_max()
        self.assertGreater(self.in_view("return window.stepdanceView.strokes.length;"), 0)
        self.type_scenario(good.replace("duration_s = 42", "duration_s = = 42"))
        self.browser.find_element(By.ID, "run").click()
        self.wait_for(lambda: len(self.site("problems")) > 0)
        self.wait_for(lambda: "Nothing runs" in (self.browser.find_element(By.ID, "view").get_attribute("srcdoc") or ""))
        self.assertIsNone(self.in_view("return window.stepdanceView || null;"))


class Phone(PageTest):
    phone = True

    def test_one_column_and_the_drawing_fills_the_width(self):
        self.open_page()
        self.assertEqual(self.browser.execute_script("return window.innerWidth;"), PHONE_WIDTH_PX)
        self.run_at_max()
        view = self.browser.find_element(By.ID, "view").rect
        sources = self.browser.find_element(By.ID, "sources").rect
        self.assertGreaterEqual(sources["y"], view["y"] + view["height"] - 1)  # stacked: one column
        drawing_px = self.in_view("return document.getElementById('drawing').getBoundingClientRect().width;")
        print(f"390 px phone: the drawing is {drawing_px:.0f} px wide, {drawing_px / PHONE_WIDTH_PX:.1%} of the width",
              file=sys.stderr)
        self.assertGreaterEqual(drawing_px, 0.9 * PHONE_WIDTH_PX)
        self.browser.execute_script("window.scrollTo(0, 0);")
        shot = os.path.join(WORK_DIR, "phone-390.png")
        self.browser.save_screenshot(shot)
        with open(shot, "rb") as png:
            header = png.read(24)
        width_px = int.from_bytes(header[16:20], "big")
        self.assertEqual(width_px, PHONE_WIDTH_PX * PHONE_PIXEL_RATIO)  # the screenshot is the phone's screen


class SmallThings(PageTest):
    def test_loading_logs_nothing(self):
        self.open_page("")
        time.sleep(1)
        severe = [entry for entry in self.browser.get_log("browser") if entry["level"] == "SEVERE"]
        self.assertEqual(severe, [])
        self.assertEqual(self.site("server"), None)
        self.assertIn("stepdance serve --allow-origin", self.browser.find_element(By.ID, "serve-state").text)

    def test_the_first_visit_opens_step_a_sketch_with_a_hint(self):
        self.open_page("")
        self.assertEqual(Select(self.browser.find_element(By.ID, "example")).first_selected_option.text, "StepASketch")
        self.assertTrue(self.browser.find_element(By.ID, "hint").is_displayed())
        self.run_at_max()
        self.assertFalse(self.browser.find_element(By.ID, "hint").is_displayed())
        self.open_page("")
        self.assertFalse(self.browser.find_element(By.ID, "hint").is_displayed())

    def test_from_file_it_says_how_to_serve(self):
        self.browser.get("file://" + os.path.realpath(os.path.join(SITE_DIR, "index.html")))
        self.wait_for(lambda: "http.server" in self.browser.find_element(By.ID, "status").text)

    def test_the_sketch_has_line_numbers(self):
        self.open_page()
        with open(os.path.join(SOURCE_DIR, "examples/StepASketch/StepASketch.ino")) as file:
            sketch = file.read()
        count = self.browser.execute_script("return document.querySelectorAll('#sketch-lines span').length;")
        self.assertEqual(count, len(sketch.split("\n")))

    def test_compiler_warnings_are_told_apart_from_errors(self):
        self.open_page()
        # g++'s own form, as the sketch server hands it back.
        text = ("StepASketch.ino:12:7: warning: unused variable 'spare' [-Wunused-variable]\n"
                "   12 |   int spare;\n"
                "StepASketch.ino:14:3: error: 'undefined_name' was not declared in this scope\n"
                "StepASketch.ino:3:6: note: declared here\n")
        self.browser.execute_script("showProblems(arguments[0]);", text)
        kinds = [(p["line"], p["kind"]) for p in self.site("problems")]
        self.assertEqual(kinds, [(12, "warning"), (14, "error")])
        classes = self.browser.execute_script(
            "return Array.from(document.querySelectorAll('#problems li')).map(li => li.className);")
        self.assertEqual(classes, ["warning", "error"])
        marks = self.browser.execute_script(
            "const spans = document.querySelectorAll('#sketch-lines span'); return [spans[11].className, spans[13].className];")
        self.assertEqual(marks, ["warn", "bad"])

    def test_dark_mode_follows_the_system(self):
        self.open_page()
        light = self.browser.execute_script("return getComputedStyle(document.body).backgroundColor;")
        self.browser.execute_cdp_cmd("Emulation.setEmulatedMedia",
                                     {"features": [{"name": "prefers-color-scheme", "value": "dark"}]})
        dark = self.browser.execute_script("return getComputedStyle(document.body).backgroundColor;")
        self.assertEqual(light, "rgb(246, 246, 244)")
        self.assertEqual(dark, "rgb(27, 29, 31)")


# Notes the page's clock at each update the page hands its view (the worker's, through the page).
WATCH_UPDATES = """
window.updateTimesMs = [];
const transport = window.stepdanceTransport;
window.stepdanceTransport = (onMessage, onState) => transport((text) => {
  if (text.includes('"type":"update"')) window.updateTimesMs.push(performance.now());
  onMessage(text);
}, onState);
"""


class ViewCadence(PageTest):
    # The view draws at most about 30 times a second: the worker hands it no more updates than
    # that (the protocol allows 60), and at least a few while the pen moves.
    SECONDS = 3

    def test_the_worker_hands_the_view_at_most_30_updates_a_second(self):
        self.open_page()
        self.browser.execute_script(WATCH_UPDATES)
        self.browser.find_element(By.ID, "run").click()  # at 1×: the house is drawn over 42 s
        self.wait_for(lambda: self.browser.execute_script("return window.updateTimesMs.length > 0;"))
        time.sleep(self.SECONDS + 0.5)
        times = self.browser.execute_script("return window.updateTimesMs;")
        window = [t for t in times if times[0] + 250 <= t < times[0] + 250 + self.SECONDS * 1000]
        self.assertLessEqual(len(window), 30 * self.SECONDS + 2)
        self.assertGreaterEqual(len(window), 5 * self.SECONDS)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
