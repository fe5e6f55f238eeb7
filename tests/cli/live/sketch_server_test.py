"""The sketch server (`stepdance serve` without a target) contains what a page sends it: a sketch
that crashes, hangs in setup() or loop(), calls exit(), or outlives its limits ends its own run
with a report, and the same server then runs a good sketch to its result; a sketch cannot read
or write outside its run folder, open a socket, or leave a process behind; its folder is gone
after any end, and a dead server's folders are removed at start. A raw WebSocket client
(view_client.RawWebSocket) plays the page.

Usage: sketch_server_test.py STEPDANCE SOURCE_DIR BUILD_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_client import RawWebSocket  # noqa: E402

STEPDANCE = sys.argv[1] if len(sys.argv) > 1 else "build/stepdance"
ORIGIN = "http://127.0.0.1:8000"

SCENARIO = """duration_s = 0.5
seed = 1

[[board]]
name = "driver"
sketch = "T.ino"
module = "driver"
"""

PRELUDE = """#define module_driver
#include "stepdance.hpp"
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>
"""

GOOD = PRELUDE + """void setup() { Serial.begin(115200); Serial.println("GOOD SKETCH RAN"); dance_start(); }
void loop() { dance_loop(); }
"""


def sketch(setup_body, loop_body="dance_loop();"):
    return PRELUDE + "void setup() {\n  Serial.begin(115200);\n" + setup_body + "\n  dance_start();\n}\n" + \
        "void loop() {\n" + loop_body + "\n}\n"


def processes_named(name):
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open(f"/proc/{pid}/comm") as comm:
                if comm.read().strip() == name:
                    found.append(int(pid))
        except OSError:
            pass
    return found


class SketchServerContainsItsRuns(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="sketch-server-test-")
        # A folder a dead server left (no process has this id: above the largest pid).
        cls.stale = os.path.join(cls.tmp, "stepdance-serve-99999999-AbCdEf")
        os.makedirs(os.path.join(cls.stale, "T"))
        environment = dict(os.environ, TMPDIR=cls.tmp)
        cls.server = subprocess.Popen([STEPDANCE, "serve", "--port", "0", "--allow-origin", ORIGIN],
                                      stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=environment)
        line = cls.server.stdout.readline()
        while line and not line.startswith("serving sketches"):
            line = cls.server.stdout.readline()
        cls.port = int(re.search(r"serving sketches on http://127\.0\.0\.1:(\d+)/", line).group(1))

    @classmethod
    def tearDownClass(cls):
        cls.server.terminate()
        cls.server.communicate(timeout=60)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def connect(self):
        client = RawWebSocket(self.port, "", origin=ORIGIN)
        client.connection.settimeout(120)
        self.assertEqual(client.receive()["type"], "serve_hello")
        return client

    def run_sketch(self, text, on_started=None):
        """Sends a run; returns (the messages by type, the console text) once it is over."""
        client = self.connect()
        client.send(__import__("json").dumps({"type": "sketch_run", "example": "T", "scenario": "scenario.toml",
                                              "files": {"T.ino": text, "scenario.toml": SCENARIO}}))
        seen = {}
        console = ""
        while True:
            message = client.receive()
            kind = message.get("type")
            seen.setdefault(kind, []).append(message)
            for entry in message.get("console", []) or []:
                console += entry["text"]
            if kind == "started" and on_started:
                on_started()
            if kind in ("result", "failed") or (kind == "ended" and message["cause"] == "process"):
                break
        client.close()
        return seen, console

    def assert_server_still_runs_a_good_sketch(self):
        seen, console = self.run_sketch(GOOD)
        self.assertIn("result", seen, seen.get("failed"))
        self.assertIsNone(seen["result"][0]["result"]["stopped"])
        self.assertIn("GOOD SKETCH RAN", console)

    def assert_no_run_folders(self):
        deadline = time.time() + 5
        while time.time() < deadline and [n for n in os.listdir(self.tmp) if n.startswith("stepdance-serve-")]:
            time.sleep(0.1)
        self.assertEqual([n for n in os.listdir(self.tmp) if n.startswith("stepdance-serve-")], [])

    def assert_ended(self, seen, cause):
        self.assertIn("ended", seen, seen)
        self.assertEqual(seen["ended"][0]["cause"], cause, seen["ended"][0])
        return seen["ended"][0]["text"]

    def test_a_dead_servers_folder_is_removed_at_start(self):
        self.assertFalse(os.path.exists(self.stale))

    def test_a_crash_is_reported_at_its_line_and_its_folder_removed(self):
        text = sketch("  volatile int* nowhere = nullptr;\n  *nowhere = 1;")
        line = text.split("\n").index("  *nowhere = 1;") + 1
        seen, _ = self.run_sketch(text)
        report = self.assert_ended(seen, "crashed")
        self.assertRegex(report, rf"(?m)^T\.ino:{line}: board 'driver': SIGSEGV")
        self.assertIn("result", seen)
        self.assert_no_run_folders()
        self.assert_server_still_runs_a_good_sketch()

    def test_a_busy_loop_in_setup_is_stopped_and_the_server_answers_meanwhile(self):
        times = []

        def connect_while_it_spins():
            time.sleep(1.0)
            started = time.monotonic()
            client = RawWebSocket(self.port, "", origin=ORIGIN)
            self.assertEqual(client.receive()["type"], "serve_hello")
            times.append(time.monotonic() - started)
            client.close()

        seen, _ = self.run_sketch(sketch("  while (true) {}"), on_started=connect_while_it_spins)
        self.assertIn("setup() has not returned", self.assert_ended(seen, "hung"))
        self.assertLess(times[0], 0.1)
        self.assert_server_still_runs_a_good_sketch()

    def test_a_busy_loop_in_loop_is_stopped(self):
        seen, _ = self.run_sketch(sketch("", loop_body="  while (true) {}"))
        self.assertIn("loop()", self.assert_ended(seen, "hung"))
        self.assert_server_still_runs_a_good_sketch()

    def test_exit_is_reported(self):
        seen, _ = self.run_sketch(sketch("  exit(0);"))
        self.assertIn("exit(0)", self.assert_ended(seen, "ended"))
        self.assert_server_still_runs_a_good_sketch()

    def test_reading_outside_its_folder_is_refused(self):
        seen, console = self.run_sketch(sketch(
            '  int fd = open("/etc/passwd", O_RDONLY);\n'
            '  Serial.println(fd < 0 ? "passwd refused" : "passwd READ");'))
        self.assertIn("result", seen)
        self.assertIn("passwd refused", console)

    def test_including_a_file_outside_its_folder_is_refused_at_compile(self):
        seen, _ = self.run_sketch('#include "/etc/passwd"\n' + GOOD)
        self.assertIn("failed", seen)
        self.assertIn("Permission denied", seen["failed"][0]["text"])

    def test_writing_outside_its_folder_is_refused(self):
        target = os.path.join(self.tmp, "escaped.txt")
        seen, console = self.run_sketch(sketch(
            f'  int fd = open("{target}", O_WRONLY | O_CREAT, 0600);\n'
            '  Serial.println(fd < 0 ? "write refused" : "write DONE");'))
        self.assertIn("result", seen)
        self.assertIn("write refused", console)
        self.assertFalse(os.path.exists(target))

    def test_a_socket_is_refused(self):
        seen, console = self.run_sketch(sketch(
            '  int fd = socket(AF_INET, SOCK_STREAM, 0);\n'
            '  int local = socket(AF_UNIX, SOCK_STREAM, 0);\n'
            '  Serial.println(fd < 0 && local < 0 ? "socket refused" : "socket OPENED");'))
        self.assertIn("result", seen)
        self.assertIn("socket refused", console)

    def test_a_forked_child_does_not_outlive_its_run(self):
        seen, console = self.run_sketch(sketch(
            '  if (fork() == 0) { prctl(PR_SET_NAME, "sd38orphan"); setsid(); sleep(1000); _exit(0); }\n'
            '  Serial.println("forked");'))
        self.assertIn("result", seen)
        self.assertIn("forked", console)
        deadline = time.time() + 5
        while time.time() < deadline and processes_named("sd38orphan"):
            time.sleep(0.1)
        self.assertEqual(processes_named("sd38orphan"), [])
        self.assert_no_run_folders()

    def test_writing_past_the_file_size_limit_ends_the_run(self):
        seen, _ = self.run_sketch(sketch(
            '  static char block[1 << 20];\n'
            '  FILE* out = fopen("big.bin", "w");\n'
            '  for (int i = 0; i < 100 && out; ++i) fwrite(block, 1, sizeof block, out);\n'
            '  fflush(out);'))
        self.assertIn("file-size limit", self.assert_ended(seen, "process"))
        self.assert_no_run_folders()
        self.assert_server_still_runs_a_good_sketch()


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
