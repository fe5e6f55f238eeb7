#!/usr/bin/python3
"""The Python RPC client (clients/python/stepdance_rpc, pyserial) against a live simulated board.

Usage: rpc_client_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import os
import re
import signal
import subprocess
import sys
import time
import unittest

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
sys.path.insert(0, os.path.join(SOURCE_DIR, "clients", "python"))


class ImportTest(unittest.TestCase):
    def test_importing_the_client_opens_nothing(self):
        # A fresh interpreter imports the package and lists its open files: none but the std ones.
        code = ("import os, sys; sys.path.insert(0, %r); import stepdance_rpc; "
                "print(len(os.listdir('/proc/self/fd')))" % os.path.join(SOURCE_DIR, "clients", "python"))
        baseline = subprocess.run([sys.executable, "-c", "import os; print(len(os.listdir('/proc/self/fd')))"],
                                  capture_output=True, text=True).stdout
        after = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
        self.assertEqual(after.returncode, 0, after.stderr)
        self.assertEqual(after.stdout, baseline)


class LiveRpcTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.sim = subprocess.Popen(
            [STEPDANCE, "sim", os.path.join(SOURCE_DIR, "tests", "cli", "live", "RpcTarget"), "--live",
             "--speed", "1", "--out", os.path.join(WORK_DIR, "rpc-out")],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = cls.sim.stdout.readline()
        match = re.fullmatch(r"serial driver: (/dev/pts/\d+)\n", line)
        assert match, line + cls.sim.stderr.read()
        from stepdance_rpc import Board
        cls.board = Board(match.group(1), timeout=5.0)

    @classmethod
    def tearDownClass(cls):
        cls.board.close()
        cls.sim.send_signal(signal.SIGINT)
        cls.sim.communicate(timeout=60)

    def test_index_lists_exactly_the_enrolled_names(self):
        names = set(self.board.index)
        for name in ("blink", "blink_count", "scale", "label", "level", "tbi.add_move", "tbi.speed_override",
                     "tbi.output_x.read"):
            self.assertIn(name, names)
        self.assertEqual(self.board.index["level"], "parameter")
        self.assertEqual(self.board.index["scale"], "function")
        self.assertEqual({n.split(".")[0] for n in names}, {"blink", "blink_count", "scale", "label", "level", "tbi"})

    def test_functions_return_typed_values(self):
        before = self.board.blink_count()
        self.assertIsNone(self.board.blink())
        self.assertEqual(self.board.blink_count(), before + 1)
        self.assertEqual(self.board.scale(1.5, 4), 6)
        self.assertAlmostEqual(self.board.scale(0.1, 3), 0.3, places=8)
        self.assertEqual(self.board.label("pen \"up\" ✓".encode("ascii", "replace").decode()), 'pen "up" ?')

    def test_parameters_read_and_write(self):
        self.board.level = 0.75
        self.assertEqual(self.board.level, 0.75)
        self.board.level = 0.25

    def test_nested_blocks_move_the_planner(self):
        slots = self.board.tbi.add_move(1, 100.0, 5.0, 0, 0, 0, 0, 0)
        self.assertIsInstance(slots, int)
        deadline = time.monotonic() + 10
        while not self.board.tbi.is_idle() and time.monotonic() < deadline:
            time.sleep(0.05)
        self.assertEqual(self.board.tbi.output_x.read(), 5)

    def test_errors_become_exceptions(self):
        from stepdance_rpc import RpcError
        with self.assertRaises(RpcError) as caught:
            self.board.call("no_such_name")
        self.assertEqual(caught.exception.code, 10)
        with self.assertRaises(RpcError) as caught:
            self.board.scale(1)
        self.assertEqual(caught.exception.code, 11)
        with self.assertRaises(RpcError) as caught:
            self.board.scale("one", 2)
        self.assertEqual(caught.exception.code, 12)
        with self.assertRaises(AttributeError):
            self.board.nothing_here  # noqa: B018

    def test_a_malformed_line_gets_an_error_reply_and_the_link_goes_on(self):
        self.board._serial.write(b'{"name": "blink"\n')
        time.sleep(0.2)
        self.assertEqual(self.board.scale(2, 2), 4)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
