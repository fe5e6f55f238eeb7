#!/usr/bin/python3
"""The replay page of Step-A-Sketch (`stepdance sim examples/StepASketch --html run.html`) in
headless Chromium, opened from a file:// URL with the network off.

Expected values come from the run's own SVG (parsed here) and from the scenario's timeline (read
here with tomllib), not from the replay's code: at the end the page shows the house (its
strokes equal the SVG's to 0.01 mm), the pen at the last [[expect]] pen_mm and up (an even number
of clicks), each knob's count the sum of its turns, the button released, and the console what
the sketch printed (the run's own echo). Just before 12 s, between two walls, the drawing is a prefix of
the final one, with the pen down (one click so far) at the corner the finished turns reach.
During a turn the wire strip shows STEP pulses of 2–7 µs, each labelled with its signal.

STEPDANCE_REPLAY_SCREENSHOT=path saves a screenshot of the final instant there.

Usage: replay_page_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import json
import os
import re
import subprocess
import sys
import tomllib
import unittest

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import WebDriverWait

from headless_chromium import Chromium, svg_strokes
from view_client import page_strokes_from_dom  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
OUT = os.path.join(WORK_DIR, "replay-page")
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "StepASketch")
HTML = os.path.join(OUT, "run.html")
MAX_BYTES = 4 << 20  # docs/simulator.md: Step-A-Sketch's replay is well under this


def timeline():
    with open(os.path.join(EXAMPLE, "scenario.toml"), "rb") as scenario:
        return tomllib.load(scenario)


def inputs_at(scenario, t_s):
    """Each knob's count (the sum of the turns finished by t_s) and how many clicks began by then."""
    counts = {"knob_x": 0, "knob_y": 0}
    clicks = 0
    for action in scenario["at"]:
        if "turn" in action and action["time_s"] <= t_s:
            assert action["time_s"] + action["over_s"] <= t_s, "pick an instant between turns"
            counts[action["turn"]] += action["counts"]
        if "click" in action and action["time_s"] <= t_s:
            clicks += 1
    return counts, clicks


class ReplayPageTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        os.makedirs(OUT, exist_ok=True)
        run = subprocess.run([STEPDANCE, "sim", EXAMPLE, "--out", OUT, "--html", HTML, "--no-vcd"],
                             capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        assert f"wrote {HTML}\n" in run.stdout, run.stdout
        cls.echo = run.stdout
        cls.svg = svg_strokes(os.path.join(OUT, "drawing.svg"))
        cls.scenario = timeline()
        cls.chromium = Chromium(arguments=("--host-resolver-rules=MAP * ~NOTFOUND", "--proxy-server=127.0.0.1:9",
                                           "--no-proxy-server=false"), performance_log=True)
        cls.browser = cls.chromium.driver
        cls.browser.set_network_conditions(offline=True, latency=0, download_throughput=0, upload_throughput=0)
        cls.browser.get("file://" + HTML)
        WebDriverWait(cls.browser, 60).until(
            lambda b: b.execute_script("return window.stepdanceReplay && window.stepdanceReplay.index") is not None
            and b.execute_script("return window.stepdanceReplay.index") >= 0)

    @classmethod
    def tearDownClass(cls):
        cls.chromium.quit()

    def script(self, text):
        return self.browser.execute_script(text)

    def move_slider_to_time(self, t_s):
        """Moves the slider as a hand would (value set, an input event) to the instant nearest t_s."""
        index = self.script(f"""
            const samples = window.stepdanceReplay.recording.samples;
            let best = 0;
            samples.forEach((s, i) => {{ if (Math.abs(s.update.t_s - {t_s}) < Math.abs(samples[best].update.t_s - {t_s})) best = i; }});
            const slider = document.getElementById("replay-slider");
            slider.value = best;
            slider.dispatchEvent(new Event("input"));
            return best;""")
        self.assertEqual(self.script("return window.stepdanceReplay.index"), index)
        return self.script(f"return window.stepdanceReplay.recording.samples[{index}].update.t_s")

    def page_strokes(self):
        return page_strokes_from_dom(self.browser)

    def assert_points_equal(self, page, svg):
        self.assertEqual(len(page), len(svg))
        for (px, py), (sx, sy) in zip(page, svg):
            self.assertAlmostEqual(px, sx, delta=0.01)
            self.assertAlmostEqual(py, sy, delta=0.01)

    def printed_lines(self):
        """The run's echo of the sketch's lines, "… the same line N more times" expanded."""
        lines = []
        for line in self.echo.splitlines():
            repeated = re.fullmatch(r"\[driver\] … the same line (\d+) more times?", line)
            if repeated:
                lines += [lines[-1]] * int(repeated.group(1))
            elif line.startswith("[driver] "):
                lines.append(line[len("[driver] "):])
        return lines

    def console_lines(self):
        shown = self.browser.find_element(By.ID, "console-driver").get_attribute("textContent")
        return [line.rstrip("\r") for line in shown.splitlines()]

    def input_value(self, device, key):
        return self.browser.find_element(By.CSS_SELECTOR, f'td[data-device="{device}"][data-input="{key}"]').text

    def test_1_the_file_is_self_contained_and_bounded(self):
        size = os.path.getsize(HTML)
        self.assertLess(size, MAX_BYTES)
        with open(HTML) as page:
            text = page.read()
        self.assertIsNone(re.search(r"<(script|link|img|iframe)[^>]*\s(src|href)=", text))
        self.assertNotIn("url(", text)
        self.assertIn("Content-Security-Policy", text)
        # Nothing the page asked for left it: every request the browser saw is the file itself.
        requests = [json.loads(entry["message"])["message"] for entry in self.browser.get_log("performance")]
        urls = [m["params"]["request"]["url"] for m in requests if m["method"] == "Network.requestWillBeSent"]
        self.assertIn("file://" + HTML, urls)
        for url in urls:  # the browser's own chrome:// pages aside
            self.assertNotRegex(url, r"^(https?|wss?|ftp):", url)
        self.assertEqual(self.script("return performance.getEntriesByType('resource').length"), 0)

    def test_2_the_end_shows_the_house(self):
        slider = self.browser.find_element(By.ID, "replay-slider")
        slider.send_keys(Keys.HOME)
        self.assertEqual(self.script("return window.stepdanceReplay.index"), 0)
        self.assertEqual(self.page_strokes(), [])
        slider.send_keys(Keys.END)
        count = self.script("return window.stepdanceReplay.count")
        self.assertEqual(self.script("return window.stepdanceReplay.index"), count - 1)
        self.assertEqual(self.script("return window.stepdanceView.errors"), [])
        self.assertEqual(self.browser.find_element(By.ID, "replay-time").text, f"t = {self.scenario['duration_s']:.3f} s")

        page = self.page_strokes()
        self.assertEqual(len(page), len(self.svg))
        self.assertEqual(len(page), 4)  # walls, roof, door, window
        for page_stroke, svg_stroke in zip(page, self.svg):
            self.assert_points_equal(page_stroke, svg_stroke)

        pen = [e["pen_mm"] for e in self.scenario["expect"] if "pen_mm" in e][0]
        self.assertEqual(self.browser.find_element(By.ID, "pen-x").text, f"{pen[0]:.2f}")
        self.assertEqual(self.browser.find_element(By.ID, "pen-y").text, f"{pen[1]:.2f}")
        counts, clicks = inputs_at(self.scenario, self.scenario["duration_s"])
        self.assertEqual(self.browser.find_element(By.ID, "pen-state").text, "down" if clicks % 2 else "up")
        for knob, value in counts.items():
            self.assertEqual(self.input_value(knob, "counts"), str(value))
        self.assertEqual(self.input_value("pen_button", "pressed"), "no")
        self.assertNotIn("down", self.browser.find_element(By.ID, "control-pen_button").get_attribute("class"))

        # The console holds what the sketch printed: the lines the run echoed as "[driver] …".
        self.assertEqual(self.console_lines(), self.printed_lines())
        # Step-A-Sketch reports its load once a second (LoopDelay, 1000 ms), at 1 s … 42 s: 42 lines.
        self.assertEqual(len(self.printed_lines()), self.scenario["duration_s"])

        screenshot = os.environ.get("STEPDANCE_REPLAY_SCREENSHOT")
        if screenshot:
            self.browser.set_window_size(1400, 1250)
            self.browser.save_screenshot(screenshot)

    def test_3_an_instant_between_two_walls_is_a_prefix_of_the_house(self):
        t_s = self.move_slider_to_time(12.0)
        self.assertAlmostEqual(t_s, 12.0, delta=0.02)
        counts, clicks = inputs_at(self.scenario, t_s)
        for knob, value in counts.items():
            self.assertEqual(self.input_value(knob, "counts"), str(value))
        self.assertEqual(self.browser.find_element(By.ID, "pen-state").text, "down" if clicks % 2 else "up")
        # The knobs are inverted, 100 counts a mm: the pen is at −counts / 100.
        self.assertEqual(self.browser.find_element(By.ID, "pen-x").text, f"{-counts['knob_x'] / 100:.2f}")
        self.assertEqual(self.browser.find_element(By.ID, "pen-y").text, f"{-counts['knob_y'] / 100:.2f}")
        # The load report's lines so far: one a second, the first at 1 s (LoopDelay's first call
        # only starts its clock), and t_s is just short of 12 s.
        self.assertLess(t_s, 12.0)
        self.assertEqual(self.console_lines(), self.printed_lines()[:int(t_s)])
        page = self.page_strokes()
        self.assertEqual(len(page), 1)
        self.assert_points_equal(page[0], self.svg[0][:len(page[0])])
        self.assertLess(len(page[0]), len(self.svg[0]))
        self.assertEqual(page[0][-1], (-counts["knob_x"] / 100, -counts["knob_y"] / 100))

    def test_4_the_wire_strip_labels_each_pulse_with_its_width(self):
        t_s = self.move_slider_to_time(5.5)  # the first wall: knob 1 turning
        self.assertAlmostEqual(t_s, 5.5, delta=0.02)
        labels = self.browser.find_elements(By.CSS_SELECTOR, "#wire-strip text.pulse")
        self.assertTrue(labels)
        for label in labels:
            width = int(label.get_attribute("data-width-us"))
            self.assertIn(width, range(2, 8))
            self.assertEqual(label.text, f"{'XYRTZE'[width - 2]} {width} µs")
        self.move_slider_to_time(0.1)  # nothing has moved yet: a quiet wire
        self.assertEqual(self.browser.find_elements(By.CSS_SELECTOR, "#wire-strip text.pulse"), [])


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
