#!/usr/bin/python3
"""saxi plots through `stepdance sim examples/AxiDrawInterface/live.toml --live --view` while the
view's page is open in headless Chromium, and the page shows the run's drawing, stroke for stroke.

saxi (npm, tests/cli/live/saxi_plot_pty.js) plots a square, a triangle and a circle on the board's
pseudo-terminal. When it is done and the page shows the pen up with three strokes, Ctrl-C ends
the run. The strokes the page drew (the points of its SVG polylines, read from its DOM) must be
the run's SVG strokes as the view protocol promises them (view_client.stroke_mismatch): the same
strokes, the same first and last points to 0.01 mm, interior points among the SVG's in order with
only points closer than 0.05 mm to the kept one before them left out. The SVG is parsed here, on
its own, and the count of strokes is saxi's three paths.

Usage: saxi_view_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR NODE
"""
import os
import shutil
import signal
import subprocess
import sys
import unittest

from selenium.webdriver.support.ui import WebDriverWait

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_client  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR, NODE = sys.argv[1:5]
OUT = os.path.join(WORK_DIR, "saxi-view")
SCENARIO = os.path.join(SOURCE_DIR, "examples", "AxiDrawInterface", "live.toml")
PLOTTER = os.path.join(SOURCE_DIR, "tests", "cli", "live", "saxi_plot_pty.js")
SAXI_PATHS = 3  # saxi_plot_test.js's drawing: a square, a triangle, a circle


class SaxiViewTest(unittest.TestCase):
    def setUp(self):
        shutil.rmtree(OUT, ignore_errors=True)
        self.run_live = subprocess.Popen([STEPDANCE, "sim", SCENARIO, "--live", "--view", "--speed", "4", "--out", OUT],
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

    def test_the_page_shows_saxi_s_plot_stroke_for_stroke(self):
        announced = view_client.read_announcements(self.run_live, 2)
        self.assertIsNotNone(announced["view"], announced)
        self.assertIn("driver", announced["serial"])
        self.browser, self.profile = view_client.headless_chromium()
        self.browser.get(announced["view"][0])
        WebDriverWait(self.browser, 60).until(lambda b: self.view("hello") is not None and self.view("pen") is not None)

        saxi = subprocess.run([NODE, PLOTTER, announced["serial"]["driver"]], capture_output=True, text=True, timeout=400)
        self.assertEqual(saxi.returncode, 0, saxi.stderr)
        # saxi waits until the machine is idle (QM): the page shows it once an update has come.
        WebDriverWait(self.browser, 60, poll_frequency=0.1).until(
            lambda b: len(self.view("strokes")) == SAXI_PATHS and not self.view("pen")["down"])
        updates_seen = self.view("updates")
        WebDriverWait(self.browser, 60, poll_frequency=0.1).until(lambda b: self.view("updates") > updates_seen + 2)

        self.run_live.send_signal(signal.SIGINT)
        _, errors = self.run_live.communicate(timeout=120)
        self.assertEqual(self.run_live.returncode, 0, errors)
        self.assertEqual(self.view("errors"), [])

        svg = view_client.svg_strokes(os.path.join(OUT, "drawing.svg"))
        self.assertEqual(len(svg), SAXI_PATHS)
        page = view_client.page_strokes_from_dom(self.browser)
        hook = [[tuple(point) for point in stroke] for stroke in self.view("strokes")]
        self.assertEqual(len(page), len(hook))
        self.assertIsNone(view_client.strokes_mismatch(page, svg))
        self.assertIsNone(view_client.strokes_mismatch(hook, svg))
        # The page thinned the strokes (saxi's moves make points much denser than 0.05 mm) and
        # kept at least every corner: a square has 5 points, a triangle 4, the 48-gon 49.
        for stroke, (page_stroke, svg_stroke) in enumerate(zip(page, svg)):
            self.assertLess(len(page_stroke), len(svg_stroke), f"stroke {stroke} not thinned")
            self.assertGreaterEqual(len(page_stroke), (5, 4, 49)[stroke])
        print(f"page strokes: {[len(s) for s in page]} points; SVG: {[len(s) for s in svg]}")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
