#!/usr/bin/python3
"""The view page draws the parts a kind gives by their type, not by the kind (docs/simulator.md,
"The view protocol"; docs/architecture.md, "Where things go"), in headless Chromium on replay pages
(`stepdance sim --html`), which feed the page the run's own hello and updates.

- examples/Pantograph: its five-bar arm's "arms" part is drawn as the linkage the last update gave
  (pivots to arms to elbow to stylus).
- examples/PolarTurntable on a polar machine: the machine's "table" part turns the paper (the
  drawing and pen inside it) by the table's angle, the arm out to the pen's radius.
- Each again with hello's declared "parts" taken out (a recording made before hello declared
  them): the page sets the drawing up at the first update carrying the part.
- A part type the page does not know (put into the recording here, a device's and a declared
  machine one) is shown as its JSON text beside its device, or below the drawing.

Expected values are read here from the recording's JSON, not from the page's code.

Usage: view_parts_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import json
import math
import os
import re
import subprocess
import sys
import unittest

from selenium.webdriver.support.ui import WebDriverWait

from headless_chromium import Chromium

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
OUT = os.path.join(WORK_DIR, "view-parts")
RECORDING = re.compile(r'(<script type="application/json" id="stepdance-replay">)(.*?)(</script>)', re.S)


def polar_scenario():
    """examples/PolarTurntable's sketch and timeline on a polar machine (as view_turntable_test.py)."""
    example = os.path.join(SOURCE_DIR, "examples", "PolarTurntable")
    with open(os.path.join(example, "scenario.toml")) as source:
        text = source.read()
    text = text.replace('[machine]\ntype = "corexy_plotter"\nboard = "driver"\n',
                        '[machine]\ntype = "polar"\nboard = "driver"\nangle = "A"\nradius = "B"\n')
    text = text[:text.index("[[expect]]")]
    text = text.replace('sketch = "PolarTurntable.ino"', f'sketch = "{os.path.join(example, "PolarTurntable.ino")}"')
    path = os.path.join(OUT, "polar.toml")
    with open(path, "w") as out:
        out.write(text)
    return path


def replay(scenario, name):
    """Runs `scenario` with --html; returns the page's text."""
    html = os.path.join(OUT, name + ".html")
    run = subprocess.run([STEPDANCE, "sim", scenario, "--out", os.path.join(OUT, name), "--html", html, "--no-vcd",
                          "--quiet"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    with open(html) as page:
        return page.read()


def recording_of(page):
    return json.loads(RECORDING.search(page).group(2))


def with_recording(page, recording, name):
    """The page with `recording` in place of its own, written as OUT/name.html; returns its path."""
    text = json.dumps(recording).replace("</", "<\\/")
    path = os.path.join(OUT, name + ".html")
    with open(path, "w") as out:
        out.write(RECORDING.sub(lambda m: m.group(1) + text + m.group(3), page, count=1))
    return path


def undeclared(recording):
    """The recording with hello's "parts" taken out."""
    copy = json.loads(json.dumps(recording))
    if copy["hello"]["machine"]:
        copy["hello"]["machine"].pop("parts", None)
    for board in copy["hello"]["boards"]:
        for device in board["devices"]:
            device.pop("parts", None)
    return copy


def last_part(recording, field):
    """The last value of update field `field` in the recording (the page's final instant)."""
    values = [sample["update"][field] for sample in recording["samples"] if field in sample["update"]]
    assert values, field
    return values[-1]


class ViewPartsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        os.makedirs(OUT, exist_ok=True)
        cls.pantograph = replay(os.path.join(SOURCE_DIR, "examples", "Pantograph"), "pantograph")
        cls.polar = replay(polar_scenario(), "polar")
        cls.chromium = Chromium()
        cls.browser = cls.chromium.driver

    @classmethod
    def tearDownClass(cls):
        cls.chromium.quit()

    def open(self, path):
        self.browser.get("file://" + path)
        WebDriverWait(self.browser, 60).until(
            lambda b: b.execute_script("return window.stepdanceReplay && window.stepdanceReplay.index") is not None
            and b.execute_script("return window.stepdanceReplay.index") == b.execute_script(
                "return window.stepdanceReplay.count") - 1)

    def script(self, text):
        return self.browser.execute_script(text)

    def check_arm(self, recording):
        arm = [entry for entry in last_part(recording, "arms") if entry["device"] == "arm"][-1]
        right, left = self.script("const svg = document.getElementById('arm-arm');"
                                  " return [svg.querySelector('.right-side').getAttribute('points'),"
                                  " svg.querySelector('.left-side').getAttribute('points')];")
        parse = lambda text: [tuple(float(v) for v in pair.split(",")) for pair in text.split()]
        self.assertEqual(parse(right), [tuple(arm[k]) for k in ("right_pivot", "c", "e", "t")])
        self.assertEqual(parse(left), [tuple(arm[k]) for k in ("left_pivot", "d", "e")])

    def check_table(self, recording):
        table = last_part(recording, "table")
        self.assertEqual(self.script("return document.querySelectorAll('#turntable').length"), 1)
        transform, arm_x2, in_paper = self.script(
            "return [document.getElementById('paper').getAttribute('transform'),"
            " document.getElementById('arm').getAttribute('x2'),"
            " document.querySelector('#paper #strokes') !== null && document.querySelector('#paper #pen') !== null];")
        angle = float(re.fullmatch(r"rotate\((.*)\)", transform).group(1))
        self.assertAlmostEqual(angle, table["angle_rad"] * 180 / math.pi, places=9)
        self.assertAlmostEqual(float(arm_x2), table["radius_mm"], places=9)
        self.assertTrue(in_paper, "the drawing and the pen turn with the paper")

    def test_hello_declares_the_parts(self):
        devices = {device["name"]: device for device in recording_of(self.pantograph)["hello"]["boards"][0]["devices"]}
        self.assertEqual(devices["arm"]["parts"], ["arms"])
        self.assertNotIn("parts", devices["pen_button"])
        self.assertEqual(recording_of(self.polar)["hello"]["machine"]["parts"], ["table"])

    def test_an_arm_is_drawn_declared_or_not(self):
        recording = recording_of(self.pantograph)
        for name, variant in (("arm-declared", recording), ("arm-undeclared", undeclared(recording))):
            with self.subTest(name):
                self.open(with_recording(self.pantograph, variant, name))
                self.check_arm(recording)

    def test_a_table_is_drawn_declared_or_not(self):
        recording = recording_of(self.polar)
        for name, variant in (("table-declared", recording), ("table-undeclared", undeclared(recording))):
            with self.subTest(name):
                self.open(with_recording(self.polar, variant, name))
                self.check_table(recording)

    def test_a_part_type_the_page_does_not_know_is_shown_as_text(self):
        recording = recording_of(self.pantograph)
        recording["hello"]["machine"]["parts"] = ["dial"]
        recording["samples"][-1]["update"]["gauges"] = [{"device": "arm", "reading": 3}]
        recording["samples"][-1]["update"]["dial"] = {"turns": 2}
        self.open(with_recording(self.pantograph, recording, "unknown-parts"))
        self.assertEqual(self.script("return document.getElementById('part-arm-gauges').textContent"), '{"reading":3}')
        self.assertEqual(self.script("return document.getElementById('part-machine-dial').textContent"), '{"turns":2}')
        self.check_arm(recording)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
