#!/usr/bin/python3
"""Benchmark (not a test): time to first frame for a first Run and for the Runs after it, in the
page, in headless Chromium (the worker keeps its loaded module and boards between runs).

Serves SITE (build/web) with a plain static file server, opens EXAMPLE, and RUNS times presses
Run (the first in a fresh page: the module fetched and compiled; the others reuse it), each time
timing Run clicked → the first update handed to the new view (the view page loaded, the
example's files fetched and written, the scenario read, the boards loaded, the first frame run),
measured in the page with performance.now().

Usage: bench/web_page_rerun.py SITE [--example StepASketch] [--runs 5]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("site")
parser.add_argument("--example", default="StepASketch")
parser.add_argument("--runs", type=int, default=5)
args = parser.parse_args()


# Timed in the page (performance.now(), not by polling from here): the page's transport to the
# view is wrapped so that the first update handed to the new view notes its time.
WATCH_FIRST_UPDATE = """
const page = window;
const transport = page.stepdanceTransport;
page.stepdanceTransport = (onMessage, onState) => transport((text) => {
  if (page.firstUpdateMs === null && text.includes('"type":"update"')) page.firstUpdateMs = performance.now();
  onMessage(text);
}, onState);
"""


def first_frame_s(browser, wait):
    """Presses Run; the seconds until the new view is handed its first update."""
    clicked_ms = browser.execute_script("window.firstUpdateMs = null; const now = performance.now(); "
                                        "document.getElementById('run').click(); return now;")
    wait.until(lambda b: b.execute_script("return window.firstUpdateMs !== null;"))
    return (browser.execute_script("return window.firstUpdateMs;") - clicked_ms) / 1000


server = subprocess.Popen([sys.executable, "-u", "-m", "http.server", "0", "--bind", "127.0.0.1", "--directory",
                           args.site], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
port = int(re.search(r"port (\d+)", server.stdout.readline()).group(1))
chromium = Chromium()
browser = chromium.driver
try:
    wait = WebDriverWait(browser, 120, poll_frequency=0.005)
    browser.get(f"http://127.0.0.1:{port}/#{args.example}")
    wait.until(lambda b: b.find_element(By.ID, "status").text.startswith("ready"))
    browser.execute_script(WATCH_FIRST_UPDATE)
    times_ms = [first_frame_s(browser, wait) * 1000 for _ in range(args.runs)]
finally:
    chromium.quit()
    server.kill()
print(f"{args.example}, headless Chromium: time to first frame (Run clicked → the new view's first update, timed in the page)")
print(f"  first run (fresh page): {times_ms[0]:.0f} ms")
later = times_ms[1:]
if later:
    print(f"  runs 2–{args.runs}: " + ", ".join(f"{t:.0f}" for t in later) +
          f" ms (median {statistics.median(later):.0f} ms, worst {max(later):.0f} ms)")
