#!/usr/bin/python3
"""The live view draws a polar turntable as one: the table, the paper on it turned by the
table's angle with the drawing on it, the arm out to the pen's radius.

examples/PolarTurntable's sketch and timeline run on a polar machine (motor A turns the table,
B moves the arm) live with `--view --speed 2`, the page open in headless Chromium. Once the
table has turned and the arm moved, the page's DOM must show them as the update said: the
#paper group rotated by the table's angle in degrees, the #arm line out to the radius, the
strokes and the pen inside the turning paper; then the page is checked again a while later.

Usage: view_turntable_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import math
import os
import re
import subprocess
import sys
import unittest

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_client  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "PolarTurntable")


def turntable_scenario():
    with open(os.path.join(EXAMPLE, "scenario.toml")) as source:
        text = source.read()
    text = text.replace('[machine]\ntype = "corexy_plotter"\nboard = "driver"\n',
                        '[machine]\ntype = "polar"\nboard = "driver"\nangle = "A"\nradius = "B"\n')
    text = text[:text.index("[[expect]]")]
    text = text.replace('sketch = "PolarTurntable.ino"', f'sketch = "{os.path.join(EXAMPLE, "PolarTurntable.ino")}"')
    text = re.sub(r'^directory = .*$', f'directory = "{os.path.join(WORK_DIR, "view-turntable")}"', text, flags=re.M)
    os.makedirs(WORK_DIR, exist_ok=True)
    path = os.path.join(WORK_DIR, "view-turntable.toml")
    with open(path, "w") as out:
        out.write(text)
    return path


class ViewTurntableTest(unittest.TestCase):
    def setUp(self):
        self.run_live = subprocess.Popen([STEPDANCE, "sim", turntable_scenario(), "--live", "--view", "--speed", "2",
                                          "--no-vcd"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.browser = None

    def tearDown(self):
        if self.browser is not None:
            self.browser.quit()
            import shutil
            shutil.rmtree(self.profile, ignore_errors=True)
        if self.run_live.poll() is None:
            self.run_live.kill()
            self.run_live.communicate()

    def view(self, key):
        return self.browser.execute_script(f"return window.stepdanceView.{key};")

    def check_page_shows_the_table(self):
        # One snapshot of what the page received and drew, taken in one script run.
        table, transform, arm_x2, in_paper = self.browser.execute_script(
            "const v = window.stepdanceView; return [v.table, document.getElementById('paper').getAttribute('transform'),"
            " document.getElementById('arm').getAttribute('x2'),"
            " document.querySelector('#paper #strokes') !== null && document.querySelector('#paper #pen') !== null];")
        angle = float(re.fullmatch(r"rotate\(([-0-9.e]+)\)", transform).group(1))
        self.assertAlmostEqual(angle, table["angle_rad"] * 180 / math.pi, places=9)
        self.assertAlmostEqual(float(arm_x2), table["radius_mm"], places=9)
        self.assertTrue(in_paper, "the drawing and the pen turn with the paper")
        return table

    def test_the_page_shows_the_table_turned_and_the_arm_out(self):
        announced = view_client.read_announcements(self.run_live, 2)
        self.assertIsNotNone(announced["view"], announced)
        self.browser, self.profile = view_client.headless_chromium()
        self.browser.get(announced["view"][0])
        WebDriverWait(self.browser, 60).until(lambda b: self.view("hello") is not None)
        self.assertEqual(self.view("hello.machine.kind"), "polar")
        self.assertEqual(len(self.browser.find_elements(By.ID, "turntable")), 1)
        WebDriverWait(self.browser, 120, poll_frequency=0.1).until(
            lambda b: self.view("table") is not None and self.view("table.angle_rad") != 0 and self.view("table.radius_mm") != 0)
        first = self.check_page_shows_the_table()
        WebDriverWait(self.browser, 60, poll_frequency=0.1).until(lambda b: self.view("table.angle_rad") != first["angle_rad"])
        self.check_page_shows_the_table()


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
