#!/usr/bin/python3
"""A real Grbl sender, bCNC (Debian's bcnc), streams a G-code file to the live simulator.

bCNC's own Sender class (its serial thread, Grbl 1.1 controller driver, character-counting
streaming and status polling) runs without its Tk window against the pseudo-terminal of
`stepdance sim examples/GCodeStepASketch/live.toml --live`. Checks: every line bCNC sent was
acknowledged with `ok` and none with an error, bCNC saw the machine go Run → Idle and parsed the
final machine position from our status reports, and after SIGINT the simulator wrote the drawing
and met the scenario's expectations (two strokes, pen home).

Usage: bcnc_sender_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import unittest

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
BCNC = "/usr/share/bcnc/bCNC"
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "GCodeStepASketch")
PROGRAM = os.path.join(EXAMPLE, "star.gcode")


def headless_sender():
    """bCNC's Sender, with the two window-only hooks it calls during a run stubbed out."""
    sys.path[:0] = [BCNC, BCNC + "/lib", BCNC + "/controllers", BCNC + "/plugins"]
    os.environ["HOME"] = tempfile.mkdtemp(prefix="bcnc-home-")  # bCNC keeps its config there
    import Utils
    Utils.loadConfiguration()
    from Sender import Sender

    class HeadlessSender(Sender):
        def disable(self):
            pass

        def enable(self):
            pass

    return HeadlessSender()


class BcncSenderTest(unittest.TestCase):
    def test_bcnc_streams_the_star_through_the_live_simulator(self):
        out_dir = os.path.join(WORK_DIR, "bcnc-out")
        simulator = subprocess.Popen(
            [STEPDANCE, "sim", os.path.join(EXAMPLE, "live.toml"), "--live", "--speed", "10", "--out", out_dir],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            announcement = simulator.stdout.readline()
            match = re.fullmatch(r"serial driver: (/dev/pts/\d+)\n", announcement)
            self.assertIsNotNone(match, announcement)

            from CNC import CNC, WAIT  # noqa: E402 (after headless_sender set the path)
            sender = self.sender
            sender.open(match.group(1), 115200)
            sender.load(PROGRAM)
            sender.initRun()
            sender._runLines = sys.maxsize
            sender._gcount = 0
            paths = sender.gcode.compile(sender.queue, lambda: False)
            sender._runLines = len(paths) + 1
            sender.queue.put((WAIT,))
            log = []
            deadline = time.monotonic() + 180
            while sender._gcount < sender._runLines and time.monotonic() < deadline:
                while not sender.log.empty():
                    log.append(sender.log.get())
                time.sleep(0.05)
            while not sender.log.empty():
                log.append(sender.log.get())
            finished = sender._gcount >= sender._runLines
            sender.runEnded()
            state = CNC.vars["state"]
            machine = (CNC.vars["mx"], CNC.vars["my"], CNC.vars["mz"])
            sender.close()
        finally:
            simulator.send_signal(signal.SIGINT)
            stdout, stderr = simulator.communicate(timeout=120)

        self.assertTrue(finished, "bCNC did not finish: %d of %d lines" % (sender._gcount, sender._runLines))
        sent = [text for kind, text in log if kind == sender.MSG_BUFFER]
        oks = [text for kind, text in log if kind == sender.MSG_OK]
        errors = [text for kind, text in log if kind == sender.MSG_ERROR or "error" in str(text).lower()]
        self.assertGreaterEqual(len(sent), 14)  # the file's motion and mode lines
        # bCNC opens the link with two empty lines, which Grbl acknowledges too.
        self.assertEqual(len(oks), len(sent) + 2, log)
        self.assertEqual(errors, [])
        self.assertEqual(state, "Idle")
        self.assertEqual(machine, (0.0, 0.0, 4.0))
        self.assertEqual(simulator.returncode, 0, stdout + stderr)
        self.assertIn("ok      ", stdout)
        self.assertTrue(os.path.getsize(os.path.join(out_dir, "drawing.svg")) > 0)

    @classmethod
    def setUpClass(cls):
        cls.sender = headless_sender()


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
