#!/usr/bin/python3
"""The live view by keyboard alone, in headless Chromium, and axe-core on the live view and the replay page.

`stepdance sim examples/StepASketch/live.toml --live --view`, the page opened in headless
Chromium (Debian's chromium, chromium-driver, python3-selenium). Only the keyboard acts:
- Tab reaches the pen button and knob 1; knob 1 is a slider with aria-valuenow 0, and the
  focused control has a visible outline (:focus-visible).
- Space held on the pen button lowers the pen; four PageDowns on knob 1 turn it four quarter
  turns back (−2400 counts: aria-valuenow −2400); Enter on the pen button lifts it.
- Pause: no update arrives for a second (a paused run sends nothing); Resume.
- 30 ArrowUps on knob 1 (+3000 counts) take the pen from x = 24 to x = −6 mm: off the paper. The
  page marks the place and says the pen left the travel area once.
- A console line is echoed in the console; Clear empties it.
- prefers-color-scheme: dark gives the page its dark background.
Then Ctrl-C: the page says "ended", and an arrow key on the knob says why nothing was sent
(aria-valuenow stays).

Expected figures come from Step-A-Sketch's own numbers, not from the page or the simulator: a
knob turns 2400 counts a turn, 100 counts a mm, inverted (−counts → +x); a notch is a 24th of a
turn (100 counts), PageDown six notches. So the stroke runs (0, 0) → (24, 0) mm; the pen ends at
x = −6 mm with CoreXY steps a = b = −80 × (x + y) = 480; the summary counts one travel excursion.

axe-core (npm, tests/clients, installed by scripts/setup-npm-clients.sh) run on the live view
(during the run and after it ended) and on the replay page (`--html`) must find no violation of
impact "serious" or "critical".

Usage: view_keyboard_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import unittest

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import WebDriverWait

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_chromium import Chromium  # noqa: E402
from view_client import read_announcements, svg_strokes  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
LIVE_OUT = os.path.join(WORK_DIR, "view-keyboard-live")
REPLAY_OUT = os.path.join(WORK_DIR, "view-keyboard-replay")
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "StepASketch")
AXE = os.path.join(SOURCE_DIR, "tests", "clients", "node_modules", "axe-core", "axe.min.js")


def live_scenario():
    with open(os.path.join(EXAMPLE, "live.toml")) as live:
        text = live.read()
    text = text.replace('sketch = "StepASketch.ino"', f'sketch = "{os.path.join(EXAMPLE, "StepASketch.ino")}"')
    os.makedirs(WORK_DIR, exist_ok=True)
    path = os.path.join(WORK_DIR, "view-keyboard.toml")
    with open(path, "w") as out:
        out.write(text)
    return path


def serious_violations(browser):
    """axe-core's violations of impact serious or critical on the page now: [(id, help, targets)]."""
    with open(AXE) as source:
        browser.execute_script(source.read())
    result = browser.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "axe.run(document, {resultTypes: ['violations']}).then((r) => done(r.violations), (e) => done(String(e)));")
    if isinstance(result, str):
        raise AssertionError("axe-core failed: " + result)
    return [(v["id"], v["help"], [n["target"] for n in v["nodes"]]) for v in result
            if v["impact"] in ("serious", "critical")]


class ViewKeyboardTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not os.path.exists(AXE):
            raise unittest.SkipTest("axe-core is not installed: run scripts/setup-npm-clients.sh")

    def setUp(self):
        shutil.rmtree(LIVE_OUT, ignore_errors=True)
        self.run_live = subprocess.Popen([STEPDANCE, "sim", live_scenario(), "--live", "--view", "--out", LIVE_OUT],
                                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        announced = read_announcements(self.run_live, 2)
        self.assertIsNotNone(announced["view"], announced)
        self.url = announced["view"][0]
        self.chromium = Chromium()
        self.browser = self.chromium.driver

    def tearDown(self):
        self.chromium.quit()
        if self.run_live.poll() is None:
            self.run_live.kill()
            self.run_live.communicate()

    def view(self, key):
        return self.browser.execute_script(f"return window.stepdanceView.{key};")

    def wait(self, condition, seconds=60):
        WebDriverWait(self.browser, seconds, poll_frequency=0.05).until(lambda _: condition())

    def focused_id(self):
        return self.browser.execute_script("return document.activeElement && document.activeElement.id;")

    def tab_to(self, element_id):
        """Tabs from where the focus is until `element_id` has it (at most 40 presses)."""
        for _ in range(40):
            if self.focused_id() == element_id:
                return
            ActionChains(self.browser).send_keys(Keys.TAB).perform()
        self.fail(f"Tab never reached #{element_id}")

    def press_keys(self, *keys):
        for key in keys:
            ActionChains(self.browser).send_keys(key).perform()

    def hold_key(self, key, seconds):
        ActionChains(self.browser).key_down(key).perform()
        time.sleep(seconds)
        ActionChains(self.browser).key_up(key).perform()

    def test_the_keyboard_alone_draws_pauses_and_leaves_the_paper_and_axe_finds_nothing_serious(self):
        self.browser.get(self.url)
        self.wait(lambda: self.view("hello") is not None and self.view("pen") is not None)
        self.assertEqual(serious_violations(self.browser), [])

        self.tab_to("control-pen_button")
        outline = self.browser.execute_script(
            "const s = getComputedStyle(document.activeElement); return [s.outlineStyle, parseFloat(s.outlineWidth)];")
        self.assertNotEqual(outline[0], "none")
        self.assertGreaterEqual(outline[1], 2)
        self.hold_key(" ", 0.2)
        self.wait(lambda: self.view("pen.down"))

        self.tab_to("control-knob_x")
        knob = self.browser.find_element(By.ID, "control-knob_x")
        self.assertEqual(knob.get_attribute("role"), "slider")
        self.assertEqual(knob.get_attribute("aria-valuenow"), "0")
        self.press_keys(Keys.PAGE_DOWN, Keys.PAGE_DOWN, Keys.PAGE_DOWN, Keys.PAGE_DOWN)
        self.assertEqual(knob.get_attribute("aria-valuenow"), "-2400")
        self.wait(lambda: abs(self.view("pen.x_mm") - 24) < 1e-9)

        self.browser.find_element(By.ID, "control-pen_button").send_keys(Keys.ENTER)  # focus, then Enter
        self.wait(lambda: not self.view("pen.down"))

        self.check_pause_sends_nothing()
        self.check_off_paper(knob)
        self.check_console_echo_and_clear()
        self.check_dark_mode()
        self.end_run_and_check_the_page_says_so(knob)
        self.check_the_run_s_drawing()

    def check_pause_sends_nothing(self):
        self.browser.find_element(By.ID, "pause").send_keys(Keys.ENTER)
        self.wait(lambda: self.view("run.paused"))
        time.sleep(0.3)
        before = self.view("updates")
        time.sleep(1.0)
        self.assertEqual(self.view("updates"), before, "updates arrived while the run was paused")
        self.browser.find_element(By.ID, "resume").send_keys(" ")
        self.wait(lambda: not self.view("run.paused"))

    def check_off_paper(self, knob):
        knob.click()  # focus back on the knob (a click on its centre turns nothing)
        self.press_keys(*([Keys.ARROW_UP] * 30))
        self.assertEqual(knob.get_attribute("aria-valuenow"), "600")
        self.wait(lambda: abs(self.view("pen.x_mm") + 6) < 1e-9)
        self.wait(lambda: self.view("travel") is not None and self.view("travel.excursions") == 1)
        note = self.browser.find_element(By.ID, "travel-note")
        self.assertTrue(note.is_displayed())
        self.assertIn("once", note.text)
        self.assertIn("it is outside now", note.text)
        self.assertEqual(len(self.browser.find_elements(By.CSS_SELECTOR, "#excursions .excursion")), 1)
        self.assertTrue(self.browser.find_element(By.ID, "travel-area").is_displayed())

    def check_console_echo_and_clear(self):
        line = self.browser.find_element(By.ID, "send-driver")
        line.send_keys("hello from the keyboard", Keys.ENTER)
        console = self.browser.find_element(By.ID, "console-driver")
        self.wait(lambda: "> hello from the keyboard" in console.get_attribute("textContent"))
        self.assertEqual(self.browser.find_elements(By.CSS_SELECTOR, "#console-driver .sent")[-1].text,
                         "> hello from the keyboard")
        self.browser.find_element(By.ID, "clear-driver").send_keys(" ")
        self.assertEqual(console.get_attribute("textContent"), "")

    def check_dark_mode(self):
        background = "return getComputedStyle(document.body).backgroundColor;"
        light = self.browser.execute_script(background)
        self.browser.execute_cdp_cmd("Emulation.setEmulatedMedia",
                                     {"features": [{"name": "prefers-color-scheme", "value": "dark"}]})
        dark = self.browser.execute_script(background)
        self.assertEqual(light, "rgb(243, 243, 241)")
        self.assertEqual(dark, "rgb(23, 25, 27)")
        self.assertEqual(serious_violations(self.browser), [])  # the dark colours' contrast included
        self.browser.execute_cdp_cmd("Emulation.setEmulatedMedia", {"features": []})

    def end_run_and_check_the_page_says_so(self, knob):
        self.run_live.send_signal(signal.SIGINT)
        self.output, errors = self.run_live.communicate(timeout=120)
        self.assertEqual(self.run_live.returncode, 0, errors)
        self.wait(lambda: self.browser.find_element(By.ID, "connection").text == "ended", 10)
        knob.click()
        self.press_keys(Keys.ARROW_UP)
        note = self.browser.find_element(By.ID, "controls-note")
        self.assertTrue(note.is_displayed())
        self.assertIn("The run has ended", note.text)
        self.assertIn("not sent", note.text)
        self.assertEqual(knob.get_attribute("aria-valuenow"), "600")
        self.assertEqual(serious_violations(self.browser), [])

    def check_the_run_s_drawing(self):
        strokes = svg_strokes(os.path.join(LIVE_OUT, "drawing.svg"))
        self.assertEqual(len(strokes), 1)
        for point, expected in ((strokes[0][0], (0, 0)), (strokes[0][-1], (24, 0))):
            self.assertAlmostEqual(point[0], expected[0], delta=0.01)
            self.assertAlmostEqual(point[1], expected[1], delta=0.01)
        with open(os.path.join(LIVE_OUT, "summary.json")) as file:
            summary = json.load(file)
        self.assertEqual({name: motor["steps"] for name, motor in summary["motors"].items()},
                         {"driver:A": 480, "driver:B": 480})
        self.assertEqual(summary["machine"]["travel_excursions"], 1)
        self.assertRegex(self.output, r"live view: 1 page\(s\); \d+ updates sent")

    def test_the_replay_page_has_no_serious_violation(self):
        self.run_live.kill()
        self.run_live.communicate()
        html = os.path.join(REPLAY_OUT, "replay.html")
        shutil.rmtree(REPLAY_OUT, ignore_errors=True)
        run = subprocess.run([STEPDANCE, "sim", os.path.join(EXAMPLE, "scenario.toml"), "--out", REPLAY_OUT,
                              "--html", html, "--no-vcd"], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.browser.get("file://" + html)
        self.wait(lambda: self.browser.execute_script(
            "return !!window.stepdanceReplay && window.stepdanceReplay.index >= 0;"))
        self.assertEqual(serious_violations(self.browser), [])


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
