#!/usr/bin/python3
"""A page of the live view that stops reading for a while loses no stroke.

Step-A-Sketch draws its house (examples/StepASketch/scenario.toml's timeline, run live with
`--view --speed 2`, so it takes about 21 s of wall time). A raw WebSocket client with a small
receive buffer reads the hello, asks for it again 12,000 times, and stops reading for 25 s: the
replies fill the server's queue for it (1,024 messages, beyond the kernel's buffers), so a server
that queued an update at every tick would drop the updates the house is drawn in. Then it reads again, until the house is done and the run has
ended, and the strokes it put together from the updates (as a page does: keep `from` points,
append) are the run's SVG strokes as the view protocol promises them (view_client.stroke_mismatch).
The SVG is parsed here on its own.

Usage: view_backpressure_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_client  # noqa: E402

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
OUT = os.path.join(WORK_DIR, "view-backpressure")
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "StepASketch")
PAUSE_S = 25
# More hello replies (about 0.8 kB each) than the server's queue (1,024 messages) and the
# kernel's socket buffers (a few MB on loopback) hold together.
HELLO_REQUESTS = 12000


def house_scenario():
    """scenario.toml running on (the live run ends at Ctrl-C), its sketch found from anywhere;
    and the house's simulated length (s)."""
    with open(os.path.join(EXAMPLE, "scenario.toml")) as source:
        text = source.read()
    length_s = float(re.search(r"^duration_s = (\S+)$", text, re.M).group(1))
    text = re.sub(r"^duration_s = \S+$", "duration_s = 86400", text, count=1, flags=re.M)
    text = text.replace('sketch = "StepASketch.ino"', f'sketch = "{os.path.join(EXAMPLE, "StepASketch.ino")}"')
    os.makedirs(WORK_DIR, exist_ok=True)
    path = os.path.join(WORK_DIR, "view-backpressure.toml")
    with open(path, "w") as out:
        out.write(text)
    return path, length_s


class ViewBackPressureTest(unittest.TestCase):
    def setUp(self):
        shutil.rmtree(OUT, ignore_errors=True)
        scenario, self.length_s = house_scenario()
        self.run_live = subprocess.Popen([STEPDANCE, "sim", scenario, "--live", "--view", "--speed", "2", "--out", OUT],
                                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)

    def tearDown(self):
        if self.run_live.poll() is None:
            self.run_live.kill()
            self.run_live.communicate()

    def test_a_page_that_stops_reading_gets_every_stroke_afterwards(self):
        announced = view_client.read_announcements(self.run_live, 2)
        self.assertIsNotNone(announced["view"], announced)
        _, port, token = announced["view"]
        page = view_client.RawWebSocket(port, token, receive_buffer_bytes=4096)
        self.assertIn("101", page.status)
        self.assertEqual(page.receive()["type"], "hello")

        # Not reading while the house is drawn, and asking for the hello again and again: its
        # replies fill the server's queue for this page (the kernel's socket buffers first), so
        # a server that queued an update at every tick would drop them now.
        for _ in range(HELLO_REQUESTS):
            page.send('{"type":"hello"}')
        time.sleep(PAUSE_S)  # the server must hold its updates back, not drop them

        drawing = view_client.PageStrokes()
        updates = 0
        while True:
            message = page.receive()
            self.assertIsNotNone(message, "the server closed the page's socket")
            self.assertNotEqual(message["type"], "error", message)
            if message["type"] != "update":
                continue
            updates += 1
            drawing.apply(message)
            if message["t_s"] > self.length_s + 1 and not message["pen"]["down"]:
                break
        self.run_live.send_signal(signal.SIGINT)
        # The run's last updates, then the socket closes.
        try:
            while (message := page.receive()) is not None:
                if message["type"] == "update":
                    drawing.apply(message)
        except (EOFError, ConnectionResetError):
            pass
        page.close()
        _, errors = self.run_live.communicate(timeout=120)
        self.assertEqual(self.run_live.returncode, 0, errors)

        svg = view_client.svg_strokes(os.path.join(OUT, "drawing.svg"))
        self.assertGreater(len(svg), 1)
        self.assertIsNone(view_client.strokes_mismatch(drawing.strokes, svg))
        print(f"{updates} updates, {len(svg)} strokes, {sum(map(len, drawing.strokes))} page points")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
