#!/usr/bin/python3
"""The live simulator's serial port, driven by pyserial as any host program would.

Starts `stepdance sim tests/cli/live/SerialEcho --live --speed max`, reads the announced
terminal, sends every byte value 0..255 through the echo sketch and back, closes and reopens
the port, changes the baud rate, then interrupts the run with SIGINT and checks that it ends
cleanly having written its output files.

Usage: live_pty_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import os
import re
import signal
import subprocess
import sys
import time
import unittest

import serial

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
EXAMPLE = os.path.join(SOURCE_DIR, "tests", "cli", "live", "SerialEcho")


def read_exactly(port, count, timeout_s=20.0):
    """Reads `count` bytes, however they arrive; fails the test on timeout."""
    data = b""
    deadline = time.monotonic() + timeout_s
    while len(data) < count and time.monotonic() < deadline:
        data += port.read(count - len(data))
    return data


class LivePtyTest(unittest.TestCase):
    def setUp(self):
        self.out_dir = os.path.join(WORK_DIR, "live-pty-out")
        self.link = os.path.join(WORK_DIR, "live-pty-link")
        os.makedirs(self.out_dir, exist_ok=True)
        for name in os.listdir(self.out_dir):
            os.remove(os.path.join(self.out_dir, name))
        self.process = subprocess.Popen(
            [STEPDANCE, "sim", EXAMPLE, "--live", "--speed", "max", "--out", self.out_dir,
             "--serial-link", "driver=" + self.link],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        match = re.fullmatch(r"serial driver: (/dev/pts/\d+)\n", line)
        self.assertIsNotNone(match, "announcement was %r; stderr: %s" % (line, self.read_stderr()))
        self.path = match.group(1)

    def read_stderr(self):
        if self.process.poll() is None:
            return ""
        return self.process.stderr.read()

    def tearDown(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()

    def test_all_byte_values_both_ways_reopen_and_sigint(self):
        self.assertEqual(os.path.realpath(self.link), self.path)
        every_byte = bytes(range(256))
        with serial.Serial(self.path, 115200, timeout=0.5) as port:
            port.reset_input_buffer()
            port.write(every_byte)
            self.assertEqual(read_exactly(port, 256), every_byte)
        # Closed and reopened (through the symlink), at another baud rate: still a working link.
        with serial.Serial(self.link, 9600, timeout=0.5) as port:
            port.baudrate = 1000000
            payload = every_byte[::-1] * 4
            port.write(payload)
            self.assertEqual(read_exactly(port, len(payload)), payload)
        self.process.send_signal(signal.SIGINT)
        stdout, stderr = self.process.communicate(timeout=60)
        self.assertEqual(self.process.returncode, 0, stderr)
        for name in ("summary.json", "echo.vcd"):
            path = os.path.join(self.out_dir, name)
            self.assertTrue(os.path.getsize(path) > 0, name + " was not written")
            self.assertIn("wrote " + path, stdout)
        self.assertFalse(os.path.lexists(self.link), "the symlink outlived the run")


class LivePacingTest(unittest.TestCase):
    def test_real_time_pacing_and_end_of_duration(self):
        # At --speed 1 a 1.5 s run cannot finish in less than 1.5 s of wall time (a lower bound
        # only: a loaded machine may be slower, never faster).
        out_dir = os.path.join(WORK_DIR, "live-pacing-out")
        started = time.monotonic()
        result = subprocess.run(
            [STEPDANCE, "sim", EXAMPLE, "--live", "--speed", "1", "--duration", "1.5", "--out", out_dir],
            capture_output=True, text=True, timeout=120)
        elapsed = time.monotonic() - started
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertRegex(result.stdout, r"^serial driver: /dev/pts/\d+\n")
        self.assertGreaterEqual(elapsed, 1.5)
        self.assertIn("simulated 1.500 s", result.stdout)

    def test_bad_speed_is_refused(self):
        result = subprocess.run([STEPDANCE, "sim", EXAMPLE, "--live", "--speed", "fast"],
                                capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 2)
        self.assertIn("--speed", result.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
