#!/usr/bin/python3
"""The live view draws the pantograph (examples/Pantograph: a five-bar arm a hand moves, its
joint encoders steering the plotter) as its linkage: the page's arm picture shows the joints the
last update gave, pivots to arms to elbow to stylus.

The example runs live with `--view --speed 2`, the page open in headless Chromium; once the hand
has moved the stylus, the DOM's polylines must hold exactly the update's joints, twice.

Usage: view_pantograph_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import math
import os
import shutil
import subprocess
import sys
import unittest

from selenium.webdriver.support.ui import WebDriverWait

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_client  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
SCENARIO = os.path.join(SOURCE_DIR, "examples", "Pantograph", "scenario.toml")


class ViewPantographTest(unittest.TestCase):
    def setUp(self):
        self.run_live = subprocess.Popen([STEPDANCE, "sim", SCENARIO, "--live", "--view", "--speed", "2", "--no-vcd",
                                          "--out", os.path.join(WORK_DIR, "view-pantograph")],
                                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.browser = None

    def tearDown(self):
        if self.browser is not None:
            self.browser.quit()
            shutil.rmtree(self.profile, ignore_errors=True)
        if self.run_live.poll() is None:
            self.run_live.kill()
            self.run_live.communicate()

    def view(self, key):
        return self.browser.execute_script(f"return window.stepdanceView.{key};")

    def check_page_shows_the_linkage(self):
        arm, right, left = self.browser.execute_script(
            "const svg = document.getElementById('arm-arm'); return [window.stepdanceView.arms[0],"
            " svg.querySelector('.right-side').getAttribute('points'), svg.querySelector('.left-side').getAttribute('points')];")
        parse = lambda text: [tuple(float(n) for n in pair.split(",")) for pair in text.split()]
        self.assertEqual(parse(right), [tuple(arm[k]) for k in ("right_pivot", "c", "e", "t")])
        self.assertEqual(parse(left), [tuple(arm[k]) for k in ("left_pivot", "d", "e")])
        return arm

    def test_the_page_shows_the_pantograph_s_linkage(self):
        announced = view_client.read_announcements(self.run_live, 2)
        self.assertIsNotNone(announced["view"], announced)
        self.browser, self.profile = view_client.headless_chromium()
        self.browser.get(announced["view"][0])
        WebDriverWait(self.browser, 60).until(lambda b: self.view("arms") is not None)
        home = self.check_page_shows_the_linkage()
        # The hand starts at 2.5 s: wait for the stylus to have moved 5 mm.
        WebDriverWait(self.browser, 120, poll_frequency=0.1).until(
            lambda b: math.dist(self.view("arms[0].t"), home["t"]) > 5)
        self.check_page_shows_the_linkage()


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
