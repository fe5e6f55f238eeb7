#!/usr/bin/python3
"""Not a test: a picture of the live view after a trip off the paper and the run's end, for the docs.

Runs examples/StepASketch/live.toml live with --view, opens the page in headless Chromium
(WIDTH × HEIGHT px, the system's colour scheme SCHEME), and by keyboard alone: Space on the pen
button (pen down), four PageDowns on knob 1 (a 24 mm stroke), Enter on the pen button (pen up),
30 ArrowUps on knob 1 (the pen to x = −6 mm: off the paper); a console line sent. Then Ctrl-C,
and once the page says "ended", an ArrowUp on the knob (the page says why it was not sent) and
the screenshot.

Usage: bench/view_screenshot.py OUTPUT.png [--scheme light|dark] [--width 1400] [--height 1000]
       [--stepdance BINARY]
"""
import argparse
import os
import signal
import subprocess
import sys
import tempfile
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import WebDriverWait

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "cli", "live"))
from headless_chromium import Chromium  # noqa: E402
from view_client import read_announcements  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--scheme", choices=("light", "dark"), default="light")
    parser.add_argument("--width", type=int, default=1400)
    parser.add_argument("--height", type=int, default=1000)
    parser.add_argument("--stepdance", default=os.path.join(ROOT, "build", "stepdance"))
    args = parser.parse_args()
    example = os.path.join(ROOT, "examples", "StepASketch")
    work = tempfile.mkdtemp(prefix="stepdance-view-screenshot-")
    scenario = os.path.join(work, "live.toml")
    with open(os.path.join(example, "live.toml")) as source, open(scenario, "w") as out:
        out.write(source.read().replace('sketch = "StepASketch.ino"',
                                        f'sketch = "{os.path.join(example, "StepASketch.ino")}"'))
    run = subprocess.Popen([args.stepdance, "sim", scenario, "--live", "--view", "--out", work],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    chromium = Chromium(arguments=(f"--window-size={args.width},{args.height}",))
    browser = chromium.driver
    try:
        browser.execute_cdp_cmd("Emulation.setEmulatedMedia",
                                {"features": [{"name": "prefers-color-scheme", "value": args.scheme}]})
        browser.get(read_announcements(run, 2)["view"][0])
        view = lambda key: browser.execute_script(f"return window.stepdanceView.{key};")  # noqa: E731
        wait = WebDriverWait(browser, 60, poll_frequency=0.05)
        wait.until(lambda _: view("pen") is not None)
        keys = lambda *pressed: ActionChains(browser).send_keys(*pressed).perform()  # noqa: E731
        pen, knob = browser.find_element(By.ID, "control-pen_button"), browser.find_element(By.ID, "control-knob_x")
        pen.send_keys(" ")
        wait.until(lambda _: view("pen.down"))
        knob.click()
        keys(Keys.PAGE_DOWN, Keys.PAGE_DOWN, Keys.PAGE_DOWN, Keys.PAGE_DOWN)
        wait.until(lambda _: abs(view("pen.x_mm") - 24) < 1e-9)
        pen.send_keys(Keys.ENTER)
        wait.until(lambda _: not view("pen.down"))
        knob.click()
        keys(*([Keys.ARROW_UP] * 30))
        wait.until(lambda _: abs(view("pen.x_mm") + 6) < 1e-9 and view("travel") and view("travel.excursions") == 1)
        browser.find_element(By.ID, "send-driver").send_keys("hello", Keys.ENTER)
        time.sleep(0.5)
        run.send_signal(signal.SIGINT)
        run.communicate(timeout=120)
        wait.until(lambda _: browser.find_element(By.ID, "connection").text == "ended")
        knob.click()
        keys(Keys.ARROW_UP)
        time.sleep(0.3)
        browser.save_screenshot(args.output)
        print("wrote", args.output)
    finally:
        chromium.quit()
        if run.poll() is None:
            run.kill()


if __name__ == "__main__":
    main()
