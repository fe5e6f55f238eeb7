#!/usr/bin/python3
"""The live view of `stepdance sim examples/StepASketch/live.toml --live --view` in headless
Chromium (Debian's chromium, chromium-driver and python3-selenium).

A person's hand on the page: the pen button clicked (pen down), knob 1 dragged one whole turn
counter-clockwise around its centre, the pen button clicked again (pen up). Then Ctrl-C. The
run's SVG must hold exactly the stroke a batch scenario with the same click, turn and click
draws: one stroke, the same endpoints to 0.01 mm, and the same motor step counts in both runs'
summary.json. Independently of either run, Step-A-Sketch's own numbers give that stroke: 2400
counts a turn, 100 counts a mm, inverted, so −2400 counts draw from (0, 0) to (24, 0) mm, and
the CoreXY motors take a = −80 × (x + y) = −1920 and b = −80 × (x − y) = −1920 microsteps.

Also checked on the way: the page draws the stroke it received (its test hook), the announced
address carries a token, and a WebSocket without it, or from a foreign origin, is refused.

Bad input on the socket: no token, a wrong one, a foreign origin (403); malformed, unknown,
out-of-range and oversized messages (an error message each, the socket stays); a message over
the server's 64 KiB (that socket closed); 100 connections at once (at most 32 pages, the rest
refused). Afterwards the same click, turn and click sent as raw messages still draw exactly the
timeline's stroke: the run was not disturbed.

Usage: view_page_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import unittest

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_chromium import Chromium  # noqa: E402
from view_client import RawWebSocket, svg_strokes, websocket_status  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
LIVE_OUT = os.path.join(WORK_DIR, "view-page-live")
BATCH_OUT = os.path.join(WORK_DIR, "view-page-batch")
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "StepASketch")


def batch_scenario():
    """live.toml with the page's actions as a timeline: click, one turn of −2400 counts, click."""
    with open(os.path.join(EXAMPLE, "live.toml")) as live:
        text = live.read()
    text = text.replace("duration_s = 86400", "duration_s = 5")
    text = text.replace('sketch = "StepASketch.ino"', f'sketch = "{os.path.join(EXAMPLE, "StepASketch.ino")}"')
    text += ('\n[[at]]\ntime_s = 0.5\nclick = "pen_button"\n'
             '\n[[at]]\ntime_s = 1.5\nturn = "knob_x"\ncounts = -2400\nover_s = 1\n'
             '\n[[at]]\ntime_s = 4\nclick = "pen_button"\n')
    os.makedirs(WORK_DIR, exist_ok=True)
    path = os.path.join(WORK_DIR, "view-page-batch.toml")
    with open(path, "w") as out:
        out.write(text)
    return path


def motor_steps(out_dir):
    with open(os.path.join(out_dir, "summary.json")) as summary:
        motors = json.load(summary)["motors"]
    return {name: motor["steps"] for name, motor in motors.items()}


class ViewPageTest(unittest.TestCase):
    def setUp(self):
        shutil.rmtree(LIVE_OUT, ignore_errors=True)
        shutil.rmtree(BATCH_OUT, ignore_errors=True)
        self.run_live = subprocess.Popen(
            [STEPDANCE, "sim", os.path.join(EXAMPLE, "live.toml"), "--live", "--view", "--out", LIVE_OUT],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.url = None
        for _ in range(4):
            line = self.run_live.stdout.readline()
            match = re.fullmatch(r"view: (http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{32}))\n", line)
            if match:
                self.url, self.port, self.token = match.group(1), int(match.group(2)), match.group(3)
                break
            self.assertRegex(line, r"^serial driver: /dev/pts/\d+\n$")
        self.assertIsNotNone(self.url, self.run_live.stderr.read() if self.run_live.poll() is not None else "")
        self.browser = None

    def open_browser(self):
        self.chromium = Chromium()
        self.browser = self.chromium.driver

    def tearDown(self):
        if self.browser is not None:
            self.chromium.quit()
        if self.run_live.poll() is None:
            self.run_live.kill()
            self.run_live.communicate()

    def view(self, key):
        return self.browser.execute_script(f"return window.stepdanceView.{key};")

    def wait_pen(self, down, x_mm=None):
        def reached(_):
            pen = self.view("pen")
            return pen is not None and pen["down"] == down and (x_mm is None or abs(pen["x_mm"] - x_mm) < 1e-9)
        WebDriverWait(self.browser, 60, poll_frequency=0.05).until(reached)

    def click_pen_button(self, down):
        self.browser.find_element(By.ID, "control-pen_button").click()
        self.wait_pen(down)

    def drag_knob_one_turn_counter_clockwise(self, name):
        knob = self.browser.find_element(By.ID, f"control-{name}")
        radius, steps = 24, 48
        points = [(round(radius * math.cos(-2 * math.pi * k / steps)), round(radius * math.sin(-2 * math.pi * k / steps)))
                  for k in range(steps + 1)]
        actions = ActionChains(self.browser, duration=20)
        actions.move_to_element_with_offset(knob, *points[0]).click_and_hold()
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            actions.move_by_offset(x1 - x0, y1 - y0)
        actions.release().perform()

    def test_a_turn_and_two_clicks_on_the_page_draw_the_timeline_s_stroke(self):
        # Without the token, or from another origin, no WebSocket.
        self.assertIn("403", websocket_status(self.port, "/ws", f"http://127.0.0.1:{self.port}"))
        self.assertIn("403", websocket_status(self.port, f"/ws?token={self.token}", "http://evil.example"))
        self.assertIn("101", websocket_status(self.port, f"/ws?token={self.token}", f"http://127.0.0.1:{self.port}"))

        self.open_browser()
        self.browser.get(self.url)
        WebDriverWait(self.browser, 60).until(lambda b: self.view("hello") is not None and self.view("pen") is not None)
        self.assertEqual(self.view("hello.machine.page_mm"), [0, 300, 0, 218])
        self.click_pen_button(down=True)
        self.drag_knob_one_turn_counter_clockwise("knob_x")
        self.wait_pen(down=True, x_mm=24)
        self.click_pen_button(down=False)
        self.assertEqual(self.view("errors"), [])
        page_strokes = self.view("strokes")
        self.assertEqual(len(page_strokes), 1)
        self.assertEqual(page_strokes[0][0], [0, 0])
        self.assertEqual(page_strokes[0][-1], [24, 0])
        self.assertEqual(len(self.browser.find_elements(By.CSS_SELECTOR, "#strokes g.stroke")), 1)
        self.assertEqual(len(self.browser.find_elements(By.CSS_SELECTOR, "#strokes polyline")), 1)

        self.check_run_drew_the_timeline_stroke()

    def check_run_drew_the_timeline_stroke(self):
        """Ends the live run and compares its drawing and steps with the batch scenario's."""
        self.run_live.send_signal(signal.SIGINT)
        output, errors = self.run_live.communicate(timeout=120)
        self.assertEqual(self.run_live.returncode, 0, errors)
        live_strokes = svg_strokes(os.path.join(LIVE_OUT, "drawing.svg"))

        batch = subprocess.run([STEPDANCE, "sim", batch_scenario(), "--quiet", "--no-vcd", "--out", BATCH_OUT],
                               capture_output=True, text=True)
        self.assertEqual(batch.returncode, 0, batch.stderr)
        batch_strokes = svg_strokes(os.path.join(BATCH_OUT, "drawing.svg"))

        self.assertEqual(len(live_strokes), 1)
        self.assertEqual(len(batch_strokes), 1)
        # The SVG's points are machine mm (its margin is a translate() around them).
        for live_end, batch_end, expected in ((live_strokes[0][0], batch_strokes[0][0], (0, 0)),
                                              (live_strokes[0][-1], batch_strokes[0][-1], (24, 0))):
            for axis in range(2):
                self.assertAlmostEqual(live_end[axis], batch_end[axis], delta=0.01)
                self.assertAlmostEqual(live_end[axis], expected[axis], delta=0.01)
        steps = {"driver:A": -1920, "driver:B": -1920}
        self.assertEqual(motor_steps(LIVE_OUT), steps)
        self.assertEqual(motor_steps(BATCH_OUT), steps)

    def test_bad_input_on_the_socket_is_refused_and_the_run_goes_on(self):
        # No token, a wrong one, a foreign origin: 403 before any WebSocket exists.
        self.assertIn("403", websocket_status(self.port, "/ws", f"http://127.0.0.1:{self.port}"))
        self.assertIn("403", websocket_status(self.port, "/ws?token=" + "0" * 32, f"http://127.0.0.1:{self.port}"))
        foreign = RawWebSocket(self.port, self.token, origin="http://evil.example")
        self.assertIn("403", foreign.status)
        foreign.close()
        page = RawWebSocket(self.port, self.token)
        self.assertIn("101", page.status)
        self.assertEqual(page.receive_type("hello")["version"], 2)
        for text, error in (("{not json", "not a JSON object"),
                            ('{"type":"teleport"}', 'unknown message type "teleport"'),
                            ('{"type":"input","device":"knob_x","action":"press"}', 'input: an encoder does not take "press"'),
                            ('{"type":"run","action":"speed","speed":2}', 'run: "speed" must be 1, 10 or "max"'),
                            (" " * 5000, "message of 5000 bytes refused: at most 4096")):
            page.send(text)
            self.assertEqual(page.receive_type("error")["message"][:len(error)], error)
        # Over the server's 64 KiB a message closes that socket; the others stay.
        flood = RawWebSocket(self.port, self.token)
        flood.send(" " * 70000)
        flood.wait_closed()  # the socket's 20 s timeout here fails the test
        flood.close()
        # 100 connections at once: at most 32 pages; the rest refused (503) or closed.
        crowd = [RawWebSocket(self.port, self.token) for _ in range(100)]
        accepted = sum("101" in member.status for member in crowd)
        self.assertLessEqual(accepted, 32)
        self.assertGreaterEqual(accepted, 1)
        for member in crowd:
            member.close()
        # The run was not disturbed: the page's actions still draw exactly the timeline's stroke.
        # (Version 2: an update carries the pen only when it changed; the page keeps the last.)
        pen = {"down": False, "x_mm": 0}

        def next_pen():
            pen.update(page.receive_type("update").get("pen", {}))
            return pen

        page.send('{"type":"input","device":"pen_button","action":"click"}')
        while not next_pen()["down"]:
            pass
        for _ in range(48):
            page.send('{"type":"input","device":"knob_x","action":"turn","counts":-50}')
        while next_pen()["x_mm"] != 24:
            pass
        page.send('{"type":"input","device":"pen_button","action":"click"}')
        while next_pen()["down"]:
            pass
        page.close()
        self.check_run_drew_the_timeline_stroke()


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
