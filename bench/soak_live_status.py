#!/usr/bin/python3
"""Soak benchmark (not a test): the live simulator polled for status like a G-code sender, for an hour.

Starts `stepdance sim examples/GCodeStepASketch/live.toml --live`, sends one move, then `?` every
100 ms of simulated time (10 Hz, as Grbl senders poll) for the given simulated time, reading every
reply. At SPEED 1 (the default) that is real time; SPEED 10 runs the same hour of polls in six
minutes (`--speed 10`, polls every 10 ms). Prints the simulator's RSS after a warm-up and at the
end (and its peak sample), the lines received, the last status report's position, and the run's
own closing report. docs/simulator.md records the figures.

Usage: bench/soak_live_status.py [SECONDS] [SPEED] [STEPDANCE_BINARY]   (default 3600 1 build/stepdance)
"""
import os
import re
import signal
import subprocess
import sys
import time
import tty

SIMULATED_S = float(sys.argv[1]) if len(sys.argv) > 1 else 3600.0
SPEED = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEPDANCE = sys.argv[3] if len(sys.argv) > 3 else os.path.join(ROOT, "build", "stepdance")
SECONDS = SIMULATED_S / SPEED  # wall time
WARM_UP_S = min(30.0, SECONDS / 10)
POLL_S = 0.1 / SPEED


def rss_kb(pid):
    with open("/proc/%d/status" % pid) as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def main():
    out_dir = os.path.join("/tmp", "stepdance-soak-%d" % os.getpid())
    process = subprocess.Popen(
        [STEPDANCE, "sim", os.path.join(ROOT, "examples", "GCodeStepASketch", "live.toml"), "--live",
         "--speed", repr(SPEED), "--out", out_dir], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    announced = process.stdout.readline()
    terminal = re.fullmatch(r"serial driver: (\S+)\n", announced).group(1)
    port = os.open(terminal, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    tty.setraw(port)
    received = b""
    lines = 0
    last_status = ""
    os.write(port, b"G1 X20 Y10 F600\n")
    started = time.monotonic()
    rss_start = None
    rss_peak = 0
    next_poll = started
    while time.monotonic() - started < SECONDS:
        now = time.monotonic()
        if now >= next_poll:
            os.write(port, b"?")
            next_poll += POLL_S
        try:
            received += os.read(port, 65536)
        except BlockingIOError:
            pass
        *complete, received = received.split(b"\n")
        for line in complete:
            lines += 1
            text = line.decode(errors="replace").strip()
            if text.startswith("<"):
                last_status = text
        if rss_start is None and now - started >= WARM_UP_S:
            rss_start = rss_kb(process.pid)
        if int(now - started) % 10 == 0:
            rss_peak = max(rss_peak, rss_kb(process.pid))
        time.sleep(0.01)
    rss_end = rss_kb(process.pid)
    os.close(port)
    process.send_signal(signal.SIGINT)
    report, _ = process.communicate(timeout=60)
    position = re.search(r"MPos:([-0-9.]+),([-0-9.]+),([-0-9.]+)", last_status)
    print("soak: %.0f simulated s of polling at 10 Hz of simulated time (speed %g: %.0f s of wall time)"
          % (SIMULATED_S, SPEED, SECONDS))
    print("soak: RSS %d KiB after %.0f s, %d KiB at the end (growth %+d KiB), peak sample %d KiB"
          % (rss_start or 0, WARM_UP_S, rss_end, rss_end - (rss_start or 0), max(rss_peak, rss_end)))
    print("soak: %d lines received; last status %s" % (lines, last_status))
    if position:
        print("soak: final position X %s Y %s Z %s mm" % position.groups())
    print("soak: the simulator's report:\n" + report)


if __name__ == "__main__":
    main()
