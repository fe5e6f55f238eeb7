#!/usr/bin/python3
"""A page of the live view that never reads keeps the simulator's memory flat, and its drops are counted.

Step-A-Sketch runs live at --speed max twice for the same wall time: once without a page, once
with --view and a WebSocket client that connects, asks for the hello 6,000 times (some 6 MB of
replies, more than the kernel's socket buffers and the server's queue of 1,024 messages hold)
and never reads a byte. The simulator's resident memory (VmRSS in /proc) is read once the flood
has been sent and again at the end: with the deaf page it may grow by no more than it grows
alone plus 1 MiB (the full queue of hello replies the server may hold is about 0.8 MiB; a
server that queued every update, or kept every delta, would grow by the update rate times
their size, several MiB here). The run's closing report must count the page's losses: updates
held back (more than 0) and hello replies dropped at the full queue (more than 0).

Usage: view_leak_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
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
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "StepASketch")
RUN_S = 10          # wall seconds a run lasts
SETTLE_S = 3        # wall seconds before the first reading (start-up, the flood sent)
HELLO_REQUESTS = 6000
ALLOWED_EXTRA_KIB = 1024
REPORT = re.compile(r"live view: (\d+) page\(s\); (\d+) updates sent, (\d+) held back.*, (\d+) replies dropped")


def scenario():
    with open(os.path.join(EXAMPLE, "scenario.toml")) as source:
        text = source.read()
    text = re.sub(r"^duration_s = \S+$", "duration_s = 86400", text, count=1, flags=re.M)
    text = text.replace('sketch = "StepASketch.ino"', f'sketch = "{os.path.join(EXAMPLE, "StepASketch.ino")}"')
    os.makedirs(WORK_DIR, exist_ok=True)
    path = os.path.join(WORK_DIR, "view-leak.toml")
    with open(path, "w") as out:
        out.write(text)
    return path


def rss_kib(pid):
    with open(f"/proc/{pid}/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def live_run(with_page):
    """(RSS growth in KiB between the readings, the run's stdout)."""
    out = os.path.join(WORK_DIR, "view-leak-" + ("page" if with_page else "alone"))
    shutil.rmtree(out, ignore_errors=True)
    command = [STEPDANCE, "sim", scenario(), "--live", "--speed", "max", "--out", out, "--no-vcd"]
    if with_page:
        command.append("--view")
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    started = time.monotonic()
    page = None
    try:
        announced = view_client.read_announcements(process, 2 if with_page else 1)
        if with_page:
            _, port, token = announced["view"]
            page = view_client.RawWebSocket(port, token, receive_buffer_bytes=4096)
            for _ in range(HELLO_REQUESTS):
                page.send('{"type":"hello"}')
        time.sleep(max(0.0, started + SETTLE_S - time.monotonic()))
        first = rss_kib(process.pid)
        time.sleep(max(0.0, started + RUN_S - time.monotonic()))
        last = rss_kib(process.pid)
        process.send_signal(signal.SIGINT)
        output, _ = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
            process.communicate()
        if page:
            page.close()
    return last - first, output


class ViewLeakTest(unittest.TestCase):
    def test_a_page_that_never_reads_keeps_memory_flat_and_its_drops_are_counted(self):
        alone_kib, _ = live_run(False)
        page_kib, output = live_run(True)
        print(f"RSS growth over {RUN_S - SETTLE_S} s at --speed max: {alone_kib} KiB alone, {page_kib} KiB with "
              f"a page that never reads")
        self.assertLessEqual(page_kib, max(alone_kib, 0) + ALLOWED_EXTRA_KIB, output)
        report = REPORT.search(output)
        self.assertIsNotNone(report, "no 'live view:' report in the run's output:\n" + output)
        pages, updates, held_back, dropped = (int(group) for group in report.groups())
        print(report.group(0))
        self.assertEqual(pages, 1)
        self.assertGreater(held_back, 0, "the page never read, yet no update was held back")
        self.assertGreater(dropped, 0, f"{HELLO_REQUESTS} hello replies unread, yet none dropped")


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
