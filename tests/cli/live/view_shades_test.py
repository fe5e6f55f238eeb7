#!/usr/bin/python3
"""The live view of a shaded drawing (examples/ClayTexturizer: an extruding cartesian machine,
its strokes coloured by extrusion in the SVG) draws the SVG's pieces in the SVG's colours.

The texturizer's scenario runs live with `--view --speed 10` (its timeline, then on until
Ctrl-C) while the page is open in headless Chromium. After the timeline's end the run is ended
and the page's polylines (read from its DOM, with their stroke colours) must be the run's SVG
polylines one for one: the same colour (the blue–green–red scale over the drawing's shades, as
the SVG has it at the end) and the same points as the view protocol promises them
(view_client.stroke_mismatch: ends to 0.01 mm, only sub-0.05 mm points merged).

Usage: view_shades_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import unittest

from selenium.webdriver.support.ui import WebDriverWait

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_client  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
OUT = os.path.join(WORK_DIR, "view-shades")
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "ClayTexturizer")


def live_scenario():
    """scenario.toml running on until Ctrl-C, its sketch found from anywhere; and its length (s)."""
    with open(os.path.join(EXAMPLE, "scenario.toml")) as source:
        text = source.read()
    length_s = float(re.search(r"^duration_s = (\S+)$", text, re.M).group(1))
    text = re.sub(r"^duration_s = \S+$", "duration_s = 86400", text, count=1, flags=re.M)
    text = text.replace('sketch = "ClayTexturizer.ino"', f'sketch = "{os.path.join(EXAMPLE, "ClayTexturizer.ino")}"')
    os.makedirs(WORK_DIR, exist_ok=True)
    path = os.path.join(WORK_DIR, "view-shades.toml")
    with open(path, "w") as out:
        out.write(text)
    return path, length_s


class ViewShadesTest(unittest.TestCase):
    def setUp(self):
        shutil.rmtree(OUT, ignore_errors=True)
        scenario, self.length_s = live_scenario()
        self.run_live = subprocess.Popen([STEPDANCE, "sim", scenario, "--live", "--view", "--speed", "10", "--out", OUT],
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

    def test_the_page_draws_the_svg_s_pieces_in_its_colours(self):
        announced = view_client.read_announcements(self.run_live, 2)
        self.assertIsNotNone(announced["view"], announced)
        self.browser, self.profile = view_client.headless_chromium()
        self.browser.get(announced["view"][0])
        WebDriverWait(self.browser, 60).until(lambda b: self.view("hello") is not None)
        self.assertNotEqual(self.view("hello.machine.shade_name"), "")
        WebDriverWait(self.browser, 120, poll_frequency=0.1).until(lambda b: self.view("t_s") > self.length_s + 1)

        self.run_live.send_signal(signal.SIGINT)
        _, errors = self.run_live.communicate(timeout=120)
        self.assertEqual(self.run_live.returncode, 0, errors)
        self.assertEqual(self.view("errors"), [])

        svg = view_client.svg_pieces(os.path.join(OUT, "drawing.svg"))
        page = view_client.page_pieces_from_dom(self.browser)
        colours = {colour for _, colour in svg}
        self.assertGreater(len(colours), 1, "the drawing is shaded in more than one colour")
        self.assertNotIn(None, colours, "every piece is shaded")
        self.assertEqual(len(page), len(svg))
        # The cartesian machine has no fixed page: its SVG moves the drawing so its bounding box
        # starts at the origin, the page keeps machine mm. The offset: the first point's, exact in both.
        dx, dy = (page[0][0][0][0] - svg[0][0][0][0], page[0][0][0][1] - svg[0][0][0][1])
        for index, ((page_points, page_colour), (svg_points, svg_colour)) in enumerate(zip(page, svg)):
            self.assertEqual(page_colour, svg_colour, f"piece {index}")
            moved = [(x - dx, y - dy) for x, y in page_points]
            self.assertIsNone(view_client.stroke_mismatch(moved, svg_points), f"piece {index}")
        print(f"{len(svg)} pieces in {len(colours)} colours")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
