"""`stepdance serve <scenario>` runs its simulated board in a child process: a sketch that
crashes, busy-loops in setup() or loop(), or calls exit(0) ends that run with a report to the
pages (at the sketch's line for a crash), the server goes on answering (a new connection within
100 ms while the sketch spins), and a page that connects after the end starts the board again
from the files as they are now: the same server then runs a good sketch. A raw WebSocket client
(view_client.RawWebSocket) plays the control page.

Usage: serve_board_containment_test.py STEPDANCE SOURCE_DIR BUILD_DIR
"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_client import RawWebSocket  # noqa: E402

STEPDANCE = sys.argv[1] if len(sys.argv) > 1 else "build/stepdance"
CACHE = os.path.join(sys.argv[3] if len(sys.argv) > 3 else "build", "test-output", "serve-board-cache")

SCENARIO = """duration_s = 1
seed = 1

[[board]]
name = "driver"
sketch = "T.ino"
module = "driver"

[output]
directory = "out"
summary = "summary.json"
"""

PRELUDE = "#define module_driver\n#include \"stepdance.hpp\"\n#include <stdlib.h>\n"
GOOD = PRELUDE + """void setup() { Serial.begin(115200); dance_start(); }
uint32_t last_ms = 0;
void loop() {
  dance_loop();
  if (millis() - last_ms >= 100) { last_ms = millis(); Serial.println("GOOD SKETCH RUNS"); }
}
"""


def sketch(setup_body, loop_body="dance_loop();"):
    return PRELUDE + "void setup() {\n  Serial.begin(115200);\n" + setup_body + "\n  dance_start();\n}\n" + \
        "void loop() {\n" + loop_body + "\n}\n"


class ServedBoardIsContained(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="serve-board-test-")
        with open(os.path.join(self.folder, "scenario.toml"), "w") as out:
            out.write(SCENARIO)

    def tearDown(self):
        if self.server.poll() is None:
            self.server.kill()
            self.server.communicate()
        shutil.rmtree(self.folder, ignore_errors=True)

    def write_sketch(self, text):
        with open(os.path.join(self.folder, "T.ino"), "w") as out:
            out.write(text)

    def start(self, text):
        self.write_sketch(text)
        self.server = subprocess.Popen([STEPDANCE, "serve", self.folder, "--port", "0", "--cache", CACHE],
                                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.server.stdout.readline()
        self.port = int(re.search(r"serving http://127\.0\.0\.1:(\d+)/", line).group(1))

    def connect(self):
        client = RawWebSocket(self.port, "")
        client.connection.settimeout(60)
        return client

    def messages_until(self, client, found):
        while True:
            message = client.receive()
            if message is not None and found(message):
                return message

    def assert_a_good_sketch_runs_next(self):
        self.write_sketch(GOOD)
        client = self.connect()
        self.messages_until(client, lambda m: m.get("console") == "GOOD SKETCH RUNS")
        client.close()
        self.server.send_signal(signal.SIGINT)
        out, _ = self.server.communicate(timeout=60)
        self.assertEqual(self.server.returncode, 0)
        self.assertIn("wrote " + os.path.join(self.folder, "out", "summary.json"), out)

    def report_of(self, text, while_it_runs=None):
        self.start(text)
        client = self.connect()
        if while_it_runs:
            while_it_runs()
        report = self.messages_until(client, lambda m: "ended" in m)["ended"]["text"]
        client.close()
        self.assertIsNone(self.server.poll())
        return report

    def test_a_crash_is_reported_at_its_line(self):
        text = sketch("  volatile int* nowhere = nullptr;\n  *nowhere = 1;")
        line = text.split("\n").index("  *nowhere = 1;") + 1
        report = self.report_of(text)
        self.assertIn("SIGSEGV", report)
        self.assertIn(f"T.ino:{line}", report)
        self.assert_a_good_sketch_runs_next()

    def test_a_busy_loop_in_setup_is_stopped_and_the_server_answers_meanwhile(self):
        times = []

        def connect_while_it_spins():
            time.sleep(1.0)
            started = time.monotonic()
            client = RawWebSocket(self.port, "")
            self.assertIn("hello", client.receive())
            times.append(time.monotonic() - started)
            client.close()

        report = self.report_of(sketch("  while (true) {}"), connect_while_it_spins)
        self.assertIn("setup() has not returned", report)
        self.assertLess(times[0], 0.1)
        self.assert_a_good_sketch_runs_next()

    def test_a_busy_loop_in_loop_is_stopped(self):
        self.assertIn("loop() has not returned", self.report_of(sketch("", loop_body="  while (true) {}")))
        self.assert_a_good_sketch_runs_next()

    def test_exit_is_reported(self):
        self.assertIn("exit(0)", self.report_of(sketch("  exit(0);")))
        self.assert_a_good_sketch_runs_next()


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
