#!/usr/bin/python3
"""Benchmark (not a test): the WebAssembly simulator's speed in the page, in headless Chromium,
beside the native command's in the same minutes.

Serves SITE (build/web) with a plain static file server, opens EXAMPLE's scenario with its
duration set to SECONDS, clicks Run and notes how long the view takes to get its first update
(time to first frame: the module, the example's files and board fetched and instantiated, the
scenario read, the first frame run and drawn), then clicks the view's max speed and times the
run to its end. The first Run is in a fresh page (V8 still compiling the module into optimised
code); each later Run presses Run again in the same page, as a person re-running does.

Between two page runs, the native command runs the same scenario text (`stepdance sim`, batch,
VCD off: its summary's simulated_time_s / wall_time_s), so page and native alternate RUNS times
in one invocation and a change in the machine's load hits both. The ratio is taken per pair;
the figure is their median.

Both clocks are read where the work is: the page's run is timed in the page (performance.now()
at the max click and when the result arrives), and this script looks at it only every
POLL_S, so that watching costs the page nearly nothing. While the page runs at max, the CPU
time of every Chromium thread is read from /proc and printed by process type and thread name
per wall second (the Web Worker's thread is renderer/DedicatedWorker, the page's main thread
renderer/chromium), to show where the page's time goes; and the simulated seconds per CPU
second of the worker's thread against native's process (the code's own speed, whatever share
of the machine each got).

Usage: bench/web_page_speed.py SITE [--example StepASketch] [--seconds 600] [--runs 3]
                               [--stepdance BINARY]
"""
import argparse
import collections
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402

POLL_S = 0.25

# Notes performance.now() (the page's clock) when the run's result is handed to the page.
WATCH_RESULT = """
const site = window.stepdanceSite;
let result = site.result;
window.resultAtMs = null;
Object.defineProperty(site, 'result', {
  configurable: true,
  get: () => result,
  set: (value) => { result = value; if (value !== null && window.resultAtMs === null) window.resultAtMs = performance.now(); },
});
"""

# In the view's frame: max speed clicked, at the page's clock, and the view's simulated time then.
CLICK_MAX = """
const button = document.querySelector("button[data-speed='max']");
const at = window.parent.performance.now();
const t = window.stepdanceView.t_s;
button.click();
return [at, t];
"""


def with_duration(text, seconds):
    return re.sub(r"(?m)^duration_s = .*$", f"duration_s = {seconds}", text, count=1)


def native_speed(args, text):
    work = tempfile.mkdtemp(prefix="stepdance-web-speed-")
    scenario = os.path.join(work, "scenario.toml")
    folder = os.path.join(ROOT, "examples", args.example)
    with open(scenario, "w") as file:  # the same text, its sketch found in the example's folder
        file.write(re.sub(r'(?m)^sketch = "([^"/]+)"', lambda m: f'sketch = "{os.path.join(folder, m.group(1))}"', text))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([args.stepdance, "sim", scenario, "--out", work, "--no-vcd"], check=True,
                   stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(work, "summary.json")) as file:
        summary = json.load(file)
    cpu_s = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return summary["simulated_time_s"] / summary["wall_time_s"], summary["simulated_time_s"] / cpu_s


def chromium_thread_cpu_s():
    """{"process type/thread name": CPU seconds (user + system) so far}, over every Chromium
    process's threads (the Web Worker runs in renderer/DedicatedWorker)."""
    ticks = os.sysconf("SC_CLK_TCK")
    totals = collections.Counter()
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/comm") as comm:
                if "chrom" not in comm.read():
                    continue
            tids = os.listdir(f"/proc/{pid}/task")
            with open(f"/proc/{pid}/cmdline", "rb") as cmdline:
                kind = re.search(rb"--type=([\w-]+)", cmdline.read())
        except OSError:
            continue
        process = kind.group(1).decode() if kind else "browser"
        for tid in tids:
            try:
                with open(f"/proc/{pid}/task/{tid}/stat") as stat:
                    name, values = stat.read().rsplit(")", 1)
                fields = values.split()
                totals[f"{process}/{name.split('(', 1)[1]}"] += (int(fields[11]) + int(fields[12])) / ticks
            except (OSError, IndexError, ValueError):
                continue
    return totals


def page_run(browser, text):
    """One Run in the page: (time to first frame s, speed at max, simulated s per CPU s of the
    worker's thread, {thread: CPU s per wall s})."""
    wait = WebDriverWait(browser, 1800, poll_frequency=POLL_S)
    browser.execute_script("document.getElementById('scenario').value = arguments[0];", text)
    browser.execute_script(WATCH_RESULT)
    clicked = time.monotonic()
    browser.find_element(By.ID, "run").click()
    browser.switch_to.frame(browser.find_element(By.ID, "view"))
    fast = WebDriverWait(browser, 120, poll_frequency=0.005)  # the first frame is timed from here
    fast.until(lambda b: b.execute_script("return !!window.stepdanceView && window.stepdanceView.updates > 0;"))
    first_frame_s = time.monotonic() - clicked
    cpu_before, wall_before = chromium_thread_cpu_s(), time.monotonic()
    started_ms, started_t = browser.execute_script(CLICK_MAX)
    browser.switch_to.default_content()
    wait.until(lambda b: b.execute_script("return window.resultAtMs !== null;"))
    cpu_after, wall_after = chromium_thread_cpu_s(), time.monotonic()
    ended_ms = browser.execute_script("return window.resultAtMs;")
    seconds = browser.execute_script("return window.stepdanceSite.result.summary.simulated_time_s;")
    speed = (seconds - started_t) / ((ended_ms - started_ms) / 1000)
    per_wall = {name: (cpu_after[name] - cpu_before.get(name, 0)) / (wall_after - wall_before) for name in cpu_after}
    worker = "renderer/DedicatedWorker"
    worker_cpu_s = cpu_after[worker] - cpu_before.get(worker, 0)
    return first_frame_s, speed, (seconds - started_t) / worker_cpu_s, per_wall


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("site")
    parser.add_argument("--example", default="StepASketch")
    parser.add_argument("--seconds", type=float, default=600)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--stepdance", default=os.path.join(ROOT, "build", "stepdance"))
    args = parser.parse_args()
    server = subprocess.Popen([sys.executable, "-u", "-m", "http.server", "0", "--bind", "127.0.0.1", "--directory",
                               args.site], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    port = int(re.search(r"port (\d+)", server.stdout.readline()).group(1))
    chromium = Chromium()
    browser = chromium.driver
    pages, natives = [], []
    try:
        browser.get(f"http://127.0.0.1:{port}/#{args.example}")
        WebDriverWait(browser, 120, poll_frequency=0.05).until(
            lambda b: b.find_element(By.ID, "status").text.startswith("ready"))
        text = with_duration(browser.find_element(By.ID, "scenario").get_attribute("value"), args.seconds)
        native_speed(args, with_duration(text, 60))  # the native sketch compiled (and cached) before timing
        for _ in range(args.runs):
            pages.append(page_run(browser, text))
            natives.append(native_speed(args, text))
    finally:
        chromium.quit()
        server.kill()
    report(args, pages, natives)


def report(args, pages, natives):
    print(f"{args.example}, {args.seconds:g} s simulated, headless Chromium, {args.runs} runs alternating with native")
    ratios, cpu_ratios = [], []
    for run, ((first_frame_s, speed, per_cpu, cpu), (native, native_per_cpu)) in enumerate(zip(pages, natives), 1):
        ratios.append(speed / native)
        cpu_ratios.append(per_cpu / native_per_cpu)
        where = "a fresh page" if run == 1 else "Run pressed again"
        print(f"  run {run} ({where}): first frame {first_frame_s * 1000:.0f} ms; page at max {speed:.1f}×, "
              f"native {native:.1f}×: {speed / native:.2f} of native")
        print(f"    per CPU second: the worker's thread {per_cpu:.0f} simulated s, native {native_per_cpu:.0f} "
              f"(the page's code runs at {per_cpu / native_per_cpu:.2f} of native's)")
        busy = sorted(((s, name) for name, s in cpu.items() if s >= 0.02), reverse=True)
        print("    Chromium CPU s per wall s: " + ", ".join(f"{name} {s:.2f}" for s, name in busy) +
              f" (all {sum(cpu.values()):.2f})")
    print(f"  page ÷ native, median of {len(ratios)}: {statistics.median(ratios):.2f}; per CPU second "
          f"(the worker's thread ÷ native's process), median: {statistics.median(cpu_ratios):.2f}")


if __name__ == "__main__":
    main()
