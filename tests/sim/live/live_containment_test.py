#!/usr/bin/python3
"""A live run stays in the user's hands whatever its sketch does.

- A sketch stuck in a busy loop: Ctrl-C (SIGINT) ends the run within a second, outputs written.
- A run paced at --speed 1e-9 with the sketch waiting in delay(): Ctrl-C ends it within a second,
  and the delay was paced (almost no simulated time passed).
- A run of 1.5 s at real speed reports its real wall time (about 1.5 s), and its computing time
  apart (far less).

Usage: live_containment_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import os
import re
import signal
import subprocess
import sys
import time
import unittest

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
FIXTURES = os.path.join(SOURCE_DIR, "tests", "sim", "kernel", "fixtures", "Contained")


class LiveContainmentTest(unittest.TestCase):
    def start(self, name, *options):
        out_dir = os.path.join(WORK_DIR, "live-contained-" + name)
        process = subprocess.Popen(
            [STEPDANCE, "sim", os.path.join(FIXTURES, name), "--live", "--out", out_dir] + list(options),
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = process.stdout.readline()
        self.assertRegex(line, r"^serial driver: /dev/pts/\d+\n$")
        return process, out_dir

    def interrupt(self, process):
        """Sends SIGINT; returns (seconds until the process ended, stdout, stderr)."""
        sent = time.monotonic()
        process.send_signal(signal.SIGINT)
        try:
            out, err = process.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            out, err = process.communicate()
            self.fail("still running 10 s after SIGINT")
        return time.monotonic() - sent, out, err

    def test_ctrl_c_ends_a_sketch_stuck_in_a_busy_loop(self):
        process, out_dir = self.start("BusyLoop", "--watchdog-s", "60")
        time.sleep(1.5)
        waited, out, err = self.interrupt(process)
        self.assertLess(waited, 1.0)
        self.assertIn("board 'driver': interrupted (SIGINT) in loop()", err)
        self.assertTrue(os.path.exists(os.path.join(out_dir, "summary.json")), out + err)

    def test_ctrl_c_ends_a_run_paced_at_a_crawl(self):
        process, out_dir = self.start("HaltInDelay", "--speed", "1e-9")
        time.sleep(1.5)
        waited, out, err = self.interrupt(process)
        self.assertLess(waited, 1.0)
        match = re.search(r"simulated ([0-9.]+) s in ([0-9.]+) s of wall time", out)
        self.assertIsNotNone(match, out + err)
        # 1.5 s of wall time at 1e-9 is 1.5 ns of simulated time: the pacer's first millisecond
        # at most, although the sketch sits in delay(1000) the whole time.
        self.assertLessEqual(float(match.group(1)), 0.001)

    def test_wall_time_is_the_real_one_and_computing_is_apart(self):
        out_dir = os.path.join(WORK_DIR, "live-contained-walltime")
        started = time.monotonic()
        result = subprocess.run(
            [STEPDANCE, "sim", os.path.join(FIXTURES, "HaltInDelay"), "--live", "--duration", "1.5",
             "--out", out_dir], capture_output=True, text=True, timeout=30)
        elapsed = time.monotonic() - started
        match = re.search(r"simulated 1\.500 s in ([0-9.]+) s of wall time \(live; ([0-9.]+) s of it computing",
                          result.stdout)
        self.assertIsNotNone(match, result.stdout + result.stderr)
        wall, computing = float(match.group(1)), float(match.group(2))
        self.assertGreaterEqual(wall, 1.45)
        self.assertLessEqual(wall, elapsed)
        self.assertLess(computing, wall / 2)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
