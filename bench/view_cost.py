#!/usr/bin/python3
"""Benchmark (not a test): what the live view costs a run at --speed max, and what it sends.

Runs SCENARIO live at --speed max alone, then with --view and one page (a plain WebSocket
client that reads every message, as a browser tab would) connected as soon as the address is
announced, REPEAT times each, alternating. Prints each run's computing time (from its closing
report), the view's share (the medians' ratio), and what the page received.

With --callgrind each run is counted in instructions under valgrind's callgrind instead, which
does not depend on the machine's load. Under callgrind the run is some 50 times slower in wall
time, and the view updates up to 60 times per second of wall time, so it then sends some 50
times more updates per simulated second than natively: the share it reports is an upper bound.

Usage: bench/view_cost.py [SCENARIO] [--seconds S] [--repeat N] [--callgrind] [--stepdance BINARY]
       (default examples/StepASketch/scenario.toml, 42 s of simulated time: a live run lasts
       until interrupted, so S is its --duration)
"""
import argparse
import os
import re
import statistics
import subprocess
import tempfile

from view_stream import Page  # the page: a WebSocket client reading whole messages

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPORT = re.compile(r"simulated ([\d.]+) s in ([\d.]+) s of wall time \(live; ([\d.]+) s of it computing")


def callgrind_instructions(path):
    with open(path) as counts:
        for line in counts:
            if line.startswith("summary:") or line.startswith("totals:"):
                return int(line.split()[1])
    raise RuntimeError("no instruction total in " + path)


def run(args, view):
    """One live run: (simulated s, cost, messages, bytes); cost is s computing or instructions."""
    out_dir = tempfile.mkdtemp(prefix="stepdance-view-cost-")
    command = [args.stepdance, "sim", args.scenario, "--live", "--speed", "max", "--duration", args.seconds,
               "--out", out_dir, "--no-vcd"]
    if view:
        command.append("--view")
    counts = os.path.join(out_dir, "callgrind.out")
    if args.callgrind:
        command = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + counts] + command
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    page, simulated, computing = None, 0.0, 0.0
    for line in process.stdout:
        match = re.match(r"view: http://127\.0\.0\.1:(\d+)/\?token=(\w+)", line)
        if match:
            page = Page(int(match.group(1)), match.group(2))
        report = REPORT.search(line)
        if report:
            simulated, computing = float(report.group(1)), float(report.group(3))
    process.wait()
    messages, sent = 0, 0
    if page:
        page.thread.join(timeout=10)
        messages, sent = len(page.records), sum(record[2] for record in page.records)
    cost = callgrind_instructions(counts) if args.callgrind else computing
    return simulated, cost, messages, sent


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scenario", nargs="?", default=os.path.join(ROOT, "examples", "StepASketch", "scenario.toml"))
    parser.add_argument("--seconds", default="42")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--callgrind", action="store_true")
    parser.add_argument("--stepdance", default=os.path.join(ROOT, "build", "stepdance"))
    args = parser.parse_args()
    alone, viewed = [], []
    for _ in range(args.repeat):
        alone.append(run(args, False))
        viewed.append(run(args, True))
    unit = "instructions" if args.callgrind else "s computing"
    alone_cost = statistics.median(r[1] for r in alone)
    viewed_cost = statistics.median(r[1] for r in viewed)
    print(f"{args.scenario}, {args.seconds} s simulated at --speed max, {args.repeat} runs each")
    print(f"  alone:     {', '.join(f'{r[1]:.6g}' for r in alone)} {unit}")
    print(f"  with view: {', '.join(f'{r[1]:.6g}' for r in viewed)} {unit}")
    print(f"  the view's cost (medians): +{100 * (viewed_cost / alone_cost - 1):.1f} %")
    for simulated, _, messages, sent in viewed:
        print(f"  page received {messages} messages, {sent} bytes "
              f"({messages / simulated:.2f} messages, {sent / simulated / 1024:.2f} KiB per simulated second)")


if __name__ == "__main__":
    main()
