#!/usr/bin/python3
"""Every example through the page's own path, as a person runs it: in one headless Chromium page
served by a plain static file server from the built site, for each example in the page's picker,
pick it, press Run, press the view's "max", wait for the Summary, and compare what the page shows
with the native run of the same scenario (`stepdance sim EXAMPLE --result-json`):

- the page's result document equals the native one (step counts per motor, pen position, strokes,
  every expectation's outcome and message), the scenario's folder in messages aside (the page's
  is /examples/NAME/, the native one's is the source tree's);
- the Summary table shows the native simulated time and each motor's native step count, and the
  Expectations table one row per native expectation with its verdict.

Nothing but the built site is served: the worker fetches what a scenario names (another
example's sketch included: ChainedPlotterDriver's ../ChainedKnobsBasic/ChainedKnobsBasic.ino).

Usage: site_examples_test.py STEPDANCE_BINARY SITE_DIR SOURCE_DIR WORK_DIR [EXAMPLE...]
"""
import json
import os
import re
import subprocess
import sys
import time
import unittest

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

STEPDANCE, SITE_DIR, SOURCE_DIR, WORK_DIR = sys.argv[1:5]
ONLY = sys.argv[5:]
os.makedirs(WORK_DIR, exist_ok=True)
sys.path.insert(0, os.path.join(SOURCE_DIR, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402  (the page tests' browser)

EXAMPLES_DIR = os.path.join(os.path.realpath(SOURCE_DIR), "examples")
# A run at the page's max speed; the slowest example (Harmonograph, 66 s simulated) takes seconds.
RUN_TIMEOUT_S = 300


def native_result(example):
    """The native run's result document, its example folders written as the page's."""
    out = os.path.join(WORK_DIR, "native-" + example)
    result_path = os.path.join(WORK_DIR, example + ".native.json")
    subprocess.run([STEPDANCE, "sim", os.path.join(EXAMPLES_DIR, example), "--quiet", "--no-vcd", "--out", out,
                    "--result-json", result_path], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(result_path) as file:
        return json.loads(file.read().replace(EXAMPLES_DIR + "/", "/examples/"))


class EveryExampleInThePage(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = subprocess.Popen([sys.executable, "-u", "-m", "http.server", "0", "--bind", "127.0.0.1",
                                       "--directory", SITE_DIR], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                      text=True)
        cls.port = int(re.search(r"port (\d+)", cls.server.stdout.readline()).group(1))
        cls.chromium = Chromium()
        cls.browser = cls.chromium.driver

    @classmethod
    def tearDownClass(cls):
        cls.chromium.quit()
        cls.server.kill()
        cls.server.communicate()

    def wait_for(self, condition, seconds):
        WebDriverWait(self.browser, seconds, poll_frequency=0.05).until(lambda _: condition())

    def site(self, expression):
        return self.browser.execute_script(f"return window.stepdanceSite.{expression};")

    def in_view(self, script):
        self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
        try:
            return self.browser.execute_script(script)
        finally:
            self.browser.switch_to.default_content()

    def run_in_page(self, example):
        """Picks `example`, presses Run and then the view's max; the page's result document."""
        Select(self.browser.find_element(By.ID, "example")).select_by_value(example)
        self.wait_for(lambda: self.site("shown") == example and
                      self.browser.find_element(By.ID, "status").text.startswith("ready"), 60)
        self.browser.find_element(By.ID, "run").click()
        self.wait_for(lambda: self.site("result") is not None or self.site("problems.length") > 0 or
                      self.in_view("return !!(window.stepdanceView && window.stepdanceView.hello);"), 60)
        self.assertEqual(self.site("problems"), [], example)
        if self.site("result") is None:
            self.browser.switch_to.frame(self.browser.find_element(By.ID, "view"))
            try:
                self.browser.find_element(By.CSS_SELECTOR, "button[data-speed='max']").click()
            finally:
                self.browser.switch_to.default_content()
        self.wait_for(lambda: self.site("result") is not None or self.site("problems.length") > 0, RUN_TIMEOUT_S)
        self.assertEqual(self.site("problems"), [], example)
        return self.site("result")

    def table(self, table_id):
        return self.browser.execute_script(
            "return Array.from(document.querySelectorAll(`#${arguments[0]} tr`))"
            ".map(tr => Array.from(tr.cells).map(td => td.textContent));", table_id)

    def check_summary_shown(self, example, native):
        summary = {row[0]: row[1] for row in self.table("summary")}
        time_s, unit = summary["simulated time"].split()
        self.assertEqual((float(time_s), unit), (native["summary"]["simulated_time_s"], "s"), example)
        for motor, counts in native["summary"].get("motors", {}).items():
            self.assertEqual(summary[f"motor {motor}"], f"{counts['steps']} steps", f"{example} {motor}")
        verdicts = [row[0] for row in self.table("expectations")]
        wanted = ["not run" if not e["checked"] else "ok" if e["met"] else "FAILED" for e in native["expectations"]]
        self.assertEqual(verdicts, wanted, example)

    def test_every_example_gives_the_native_result(self):
        self.browser.get(f"http://127.0.0.1:{self.port}/")
        self.wait_for(lambda: len(self.site("examples")) > 0, 60)
        in_picker = [example["name"] for example in self.site("examples")]
        with_scenario = sorted(name for name in os.listdir(EXAMPLES_DIR)
                               if os.path.isfile(os.path.join(EXAMPLES_DIR, name, "scenario.toml")))
        self.assertEqual(sorted(in_picker), with_scenario)
        examples = ONLY or in_picker
        timings = []
        for example in examples:
            native = native_result(example)
            started = time.monotonic()
            page = self.run_in_page(example)
            timings.append(f"{example} {time.monotonic() - started:.1f} s")
            self.assertEqual(page, native, example)
            self.check_summary_shown(example, native)
        print(f"{len(examples)} examples gave the native result in the page: " + ", ".join(timings), file=sys.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
