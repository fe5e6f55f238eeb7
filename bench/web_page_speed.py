#!/usr/bin/python3
"""Benchmark (not a test): the WebAssembly simulator's speed in the page, in headless Chromium.

Serves SITE (build/web) with a plain static file server, opens EXAMPLE's scenario with its
duration set to SECONDS, clicks Run and notes how long the view takes to get its first update
(time to first frame: the module, the example's files and board fetched and instantiated, the
scenario read, the first frame run and drawn), then clicks the view's max speed and times the
run to its end. Prints simulated seconds per wall second in the page, and the native command's
for the same scenario text (`stepdance sim`, batch: its summary's wall_time_s) for the ratio.

Usage: bench/web_page_speed.py SITE [--example StepASketch] [--seconds 600] [--stepdance BINARY]
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402


def with_duration(text, seconds):
    return re.sub(r"(?m)^duration_s = .*$", f"duration_s = {seconds}", text, count=1)


def native_speed(example, text):
    work = tempfile.mkdtemp(prefix="stepdance-web-speed-")
    scenario = os.path.join(work, "scenario.toml")
    folder = os.path.join(ROOT, "examples", example)
    with open(scenario, "w") as file:  # the same text, its sketch found in the example's folder
        file.write(re.sub(r'(?m)^sketch = "([^"/]+)"', lambda m: f'sketch = "{os.path.join(folder, m.group(1))}"', text))
    subprocess.run([args.stepdance, "sim", scenario, "--out", work, "--no-vcd"], check=True,
                   stdout=subprocess.DEVNULL)
    with open(os.path.join(work, "summary.json")) as file:
        summary = json.load(file)
    return summary["simulated_time_s"] / summary["wall_time_s"]


parser = argparse.ArgumentParser()
parser.add_argument("site")
parser.add_argument("--example", default="StepASketch")
parser.add_argument("--seconds", type=float, default=600)
parser.add_argument("--stepdance", default=os.path.join(ROOT, "build", "stepdance"))
args = parser.parse_args()

server = subprocess.Popen([sys.executable, "-u", "-m", "http.server", "0", "--bind", "127.0.0.1", "--directory",
                           args.site], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
port = int(re.search(r"port (\d+)", server.stdout.readline()).group(1))
chromium = Chromium()
browser = chromium.driver
try:
    wait = WebDriverWait(browser, 600, poll_frequency=0.005)
    browser.get(f"http://127.0.0.1:{port}/#{args.example}")
    wait.until(lambda b: b.find_element(By.ID, "status").text.startswith("ready"))
    text = with_duration(browser.find_element(By.ID, "scenario").get_attribute("value"), args.seconds)
    browser.execute_script("document.getElementById('scenario').value = arguments[0];", text)
    clicked = time.monotonic()
    browser.find_element(By.ID, "run").click()
    browser.switch_to.frame(browser.find_element(By.ID, "view"))
    wait.until(lambda b: b.execute_script("return !!window.stepdanceView && window.stepdanceView.updates > 0;"))
    first_frame_s = time.monotonic() - clicked
    browser.find_element(By.CSS_SELECTOR, "button[data-speed='max']").click()
    started, started_t = time.monotonic(), browser.execute_script("return window.stepdanceView.t_s;")
    browser.switch_to.default_content()
    wait.until(lambda b: b.execute_script("return window.stepdanceSite.result !== null;"))
    page_speed = (args.seconds - started_t) / (time.monotonic() - started)
finally:
    chromium.quit()
    server.kill()
native = native_speed(args.example, text)
print(f"{args.example}, {args.seconds:g} s simulated, headless Chromium")
print(f"  time to first frame (Run clicked → the view's first update): {first_frame_s * 1000:.0f} ms")
print(f"  in the page at max speed: {page_speed:.0f}× real time")
print(f"  native (stepdance sim, batch): {native:.0f}× real time; the page runs at {page_speed / native:.2f} of native")
