#!/usr/bin/python3
"""Live pacing under load (a benchmark, not a test): a 20,003-line G-code job streamed with Grbl's
character-counting protocol into `stepdance sim examples/GCodeStepASketch/live.toml --live` at
`--speed SPEED` while CPU hogs (one busy process per core by default) load the machine.

The job is 3 set-up lines and 20,000 moves of 0.25 mm along a spiral at F3000 (5 ms each at 1x):
a sender must keep the planner fed at 800 lines a second of wall time at 4x. A `?` goes out every
50 ms of wall time. Printed:
  - Idle reports mid-job: status reports saying Idle after the first `ok` and before the last
    (the planner ran dry while the sender still had lines: starvation). The goal is 0.
  - the lowest feed (FS:) reported while the queue held more than 4 blocks (Bf: free < 124),
    not counting the first and last 200 lines (the job's own ramps); F3000 is the plan.
  - lines acknowledged, wall time, and the simulator's own closing report (its pacing line).
docs/gcode.md records the figures. PACING_DEBUG=1 prints each mid-job Idle report with the
sender's bytes in flight. PACING_TRACE=FILE writes one line per event to FILE: wall time (ms),
W (a line written), R (a reply read) or S (a status report), lines sent, lines acknowledged,
and the reply or report.

Usage: bench/live_stream_under_load.py [SPEED] [HOGS] [STEPDANCE_BINARY]
       (defaults: 4, the number of cores, build/stepdance; HOGS 0 runs without load)
"""
import math
import os
import re
import select
import signal
import subprocess
import sys
import time
import tty

SPEED = float(sys.argv[1]) if len(sys.argv) > 1 else 4.0
HOGS = int(sys.argv[2]) if len(sys.argv) > 2 else os.cpu_count()
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEPDANCE = sys.argv[3] if len(sys.argv) > 3 else os.path.join(ROOT, "build", "stepdance")
RX_BUFFER_BYTES = 128  # Grbl's serial receive buffer: a character-counting sender keeps one byte free
POLL_S = 0.05
PLANNER_BLOCKS = 128
EDGE_LINES = 200
SEGMENT_MM = 0.25


def job():
    """3 set-up lines, then 20,000 segments of 0.25 mm along a spiral round (150, 109)."""
    lines = ["G21 G90", "G0 X150 Y19", "G1 F3000"]
    radius, angle = 90.0, -math.pi / 2
    for _ in range(20000):
        angle += SEGMENT_MM / radius
        radius -= 0.004  # 80 mm over the job: about 16 turns, 5 mm apart
        lines.append("G1 X%.3f Y%.3f" % (150 + radius * math.cos(angle), 109 + radius * math.sin(angle)))
    return lines


def start_hogs(count):
    return [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(count)]


def stop(processes):
    for process in processes:
        process.kill()
        process.wait()


class Stream:
    """The sender: character counting, replies read as they come, a `?` every POLL_S."""

    def __init__(self, port, lines):
        self.port, self.lines = port, lines
        self.sent = self.acked = 0
        self.in_flight = []  # lengths of lines sent and not yet answered
        self.received = b""
        self.idle_mid_job = 0
        self.min_feed = None
        self.reports = 0
        self.errors = []
        self.trace = open(os.environ["PACING_TRACE"], "w") if os.environ.get("PACING_TRACE") else None
        self.read_at = None  # when the first reply not yet answered by a write was read
        self.answer_s = []   # from reading a reply to writing the next line, s: the sender's own latency

    def note(self, event, text):
        if self.trace:
            self.trace.write("%.3f %s %d %d %s\n" % (time.monotonic() * 1e3, event, self.sent, self.acked, text))

    def send_what_fits(self):
        while self.sent < len(self.lines):
            line = (self.lines[self.sent] + "\n").encode()
            if sum(self.in_flight) + len(line) > RX_BUFFER_BYTES - 1:
                return
            os.write(self.port, line)
            self.in_flight.append(len(line))
            self.sent += 1
            self.note("W", "")
            if self.read_at is not None:
                self.answer_s.append(time.monotonic() - self.read_at)
                self.read_at = None

    def read_replies(self):
        try:
            self.received += os.read(self.port, 65536)
        except BlockingIOError:
            return
        *complete, self.received = self.received.split(b"\n")
        for raw in complete:
            text = raw.decode(errors="replace").strip()
            if text == "ok" or text.startswith("error"):
                if text != "ok":
                    self.errors.append((self.acked, text))
                self.in_flight.pop(0)
                self.acked += 1
                self.note("R", text)
                if self.read_at is None:
                    self.read_at = time.monotonic()
            elif text.startswith("<"):
                self.status(text)

    def status(self, text):
        self.reports += 1
        self.note("S", text)
        mid_job = 0 < self.acked < len(self.lines)
        if mid_job and text.startswith("<Idle"):
            self.idle_mid_job += 1
            if os.environ.get("PACING_DEBUG"):
                print("idle: %d bytes in flight, %d lines sent, %d acked: %s" % (sum(self.in_flight), self.sent, self.acked, text))
        buffer = re.search(r"Bf:(\d+),", text)
        feed = re.search(r"FS:([0-9.]+),", text)
        inside = EDGE_LINES < self.acked < len(self.lines) - EDGE_LINES
        if buffer and feed and inside and PLANNER_BLOCKS - int(buffer.group(1)) > 4:
            value = float(feed.group(1))
            self.min_feed = value if self.min_feed is None else min(self.min_feed, value)


def main():
    out_dir = os.path.join("/tmp", "stepdance-pacing-%d" % os.getpid())
    process = subprocess.Popen(
        [STEPDANCE, "sim", os.path.join(ROOT, "examples", "GCodeStepASketch", "live.toml"), "--live",
         "--speed", repr(SPEED), "--out", out_dir], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    terminal = re.fullmatch(r"serial driver: (\S+)\n", process.stdout.readline()).group(1)
    port = os.open(terminal, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    tty.setraw(port)
    time.sleep(0.5)
    stream = Stream(port, job())
    hogs = start_hogs(HOGS)
    started = time.monotonic()
    next_poll = started
    try:
        # As a sender's serial thread: wake when replies come, answer each `ok` with what fits.
        while stream.acked < len(stream.lines) and time.monotonic() - started < 600:
            stream.send_what_fits()
            select.select([port], [], [], max(0.0, next_poll - time.monotonic()))
            stream.read_replies()
            if time.monotonic() >= next_poll:
                os.write(port, b"?")
                next_poll += POLL_S
        wall_s = time.monotonic() - started
    finally:
        stop(hogs)
    os.close(port)
    process.send_signal(signal.SIGINT)
    report, _ = process.communicate(timeout=120)
    print("pacing: %d lines at --speed %g beside %d CPU hog(s) on %d cores: %d acknowledged (%d errors) in %.1f s"
          % (len(stream.lines), SPEED, HOGS, os.cpu_count(), stream.acked, len(stream.errors), wall_s))
    print("pacing: %d status reports; Idle mid-job: %d; lowest feed with more than 4 blocks queued: %s mm/min"
          % (stream.reports, stream.idle_mid_job, "%.0f" % stream.min_feed if stream.min_feed is not None else "-"))
    answers = sorted(stream.answer_s)
    if answers:
        print("pacing: the sender, from reading a reply to writing the next line: median %.0f us, 99th percentile"
              " %.0f us, longest %.1f ms, %.2f s in all" % (answers[len(answers) // 2] * 1e6,
              answers[len(answers) * 99 // 100] * 1e6, answers[-1] * 1e3, sum(answers)))
    print("pacing: the simulator's report:\n" + report)


if __name__ == "__main__":
    main()
