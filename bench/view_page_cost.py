#!/usr/bin/python3
"""Benchmark (not a test): what an open Chromium page of the live view costs a run at --speed max.

Runs SCENARIO live at --speed max for SECONDS of simulated time alone, then with --view and the
view's page open in headless Chromium (Debian's chromium, through python3-selenium), REPEAT times
each, alternating, in one invocation. The browser is started before the first run and waits on a
blank page, so its start-up is not counted; the page is opened as soon as the run announces its
address (the run's first few hundred ms go unwatched, a favour to the page the report states).
Each run's speed is the closing report's simulated seconds over its wall time; the ratio of the
medians is the figure (issue 40's goal: at least 0.8). Also printed: what the page received
(its updates, from the page's own test hook), the page's own view of the speed (its t_s over
the wall time between two readings, once it had drawn), and the CPU time Chromium's processes
took during the run, per second of it (on 2 cores, what it can take from the simulation).

Usage: bench/view_page_cost.py [SCENARIO] [--seconds S] [--repeat N] [--stepdance BINARY]
       (default examples/StepASketch/scenario.toml, 1800 s simulated: its timeline draws the
       house in the first 42 s, then the board idles with its pen up)
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402

REPORT = re.compile(r"simulated ([\d.]+) s in ([\d.]+) s of wall time \(live")
VIEW = re.compile(r"view: (http://127\.0\.0\.1:\d+/\?token=\w+)")


def scenario_text(path):
    """The scenario with its sketch paths made absolute, so it runs from a temporary folder."""
    folder = os.path.dirname(os.path.abspath(path))
    with open(path) as source:
        text = source.read()
    return re.sub(r'(?m)^sketch = "([^"/]+)"', lambda m: f'sketch = "{os.path.join(folder, m.group(1))}"', text)


def browser_cpu_s():
    """CPU seconds (user + system) used so far by every Chromium process on the machine."""
    ticks = os.sysconf("SC_CLK_TCK")
    total = 0
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/stat") as stat:
                fields = stat.read().rsplit(")", 1)
            if "chrom" not in fields[0]:
                continue
            values = fields[1].split()
            total += int(values[11]) + int(values[12])
        except (OSError, IndexError):
            continue
    return total / ticks


def run(args, scenario, browser):
    """One live run; `browser` None runs it without a page. Returns (speed, page figures or None)."""
    out_dir = tempfile.mkdtemp(prefix="stepdance-view-page-cost-")
    command = [args.stepdance, "sim", scenario, "--live", "--speed", "max", "--duration", str(args.seconds),
               "--out", out_dir, "--no-vcd"]
    if browser:
        command.append("--view")
    cpu_before, wall_before = browser_cpu_s(), time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    speed, page = None, None
    for line in process.stdout:
        match = VIEW.search(line)
        if match and browser:
            browser.get(match.group(1))
            page = watch(browser)
        report = REPORT.search(line)
        if report:
            speed = float(report.group(1)) / float(report.group(2))
    process.wait()
    if page is not None:
        page["browser_cpu"] = (browser_cpu_s() - cpu_before) / (time.monotonic() - wall_before)
        page["updates"] = browser.execute_script("return window.stepdanceView.updates;")
        browser.get("about:blank")
    return speed, page


def watch(browser):
    """The page's own speed: its t_s over one second of wall time after its first update."""
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        if browser.execute_script("return !!window.stepdanceView && window.stepdanceView.updates > 0;"):
            break
        time.sleep(0.05)
    first_t, first_wall = browser.execute_script("return window.stepdanceView.t_s;"), time.monotonic()
    time.sleep(1.0)
    second_t, second_wall = browser.execute_script("return window.stepdanceView.t_s;"), time.monotonic()
    return {"page_speed": (second_t - first_t) / (second_wall - first_wall)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scenario", nargs="?", default=os.path.join(ROOT, "examples", "StepASketch", "scenario.toml"))
    parser.add_argument("--seconds", type=float, default=1800)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--stepdance", default=os.path.join(ROOT, "build", "stepdance"))
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="stepdance-view-page-cost-")
    scenario = os.path.join(work, "scenario.toml")
    with open(scenario, "w") as out:
        out.write(scenario_text(args.scenario))
    chromium = Chromium()
    alone, viewed = [], []
    try:
        chromium.driver.get("about:blank")
        for _ in range(args.repeat):
            alone.append(run(args, scenario, None)[0])
            viewed.append(run(args, scenario, chromium.driver))
    finally:
        chromium.quit()
    with_page = [speed for speed, _ in viewed]
    print(f"{args.scenario}, {args.seconds:g} s simulated at --speed max, {args.repeat} runs each, alternating")
    print(f"  alone:                {', '.join(f'{s:.1f}' for s in alone)} × real time")
    print(f"  with a Chromium page: {', '.join(f'{s:.1f}' for s in with_page)} × real time")
    print(f"  with ÷ alone (medians): {statistics.median(with_page) / statistics.median(alone):.2f}")
    for speed, page in viewed:
        if page:
            print(f"  page: {page['updates']} updates; it saw {page['page_speed']:.1f}× real time over one second; "
                  f"Chromium used {page['browser_cpu']:.2f} s of CPU a second of the run")


if __name__ == "__main__":
    main()
