#!/usr/bin/python3
"""Screenshots of the Stepdance page (docs/web.md's figures): Step-A-Sketch run to its end at max
speed in headless Chromium, from the built site served by a plain static file server.

  scripts/web-page-screenshot.py SITE OUT.png [--phone]

Without --phone: a 1400 × 1000 window (docs/images/web-page.png). With --phone: a 390 × 844
phone screen, 2 device pixels a CSS pixel, scrolled to the top (docs/images/web-page-phone.png).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "web"))
from page_browser import chromium  # noqa: E402  (the page tests' browser, phone or not)

parser = argparse.ArgumentParser()
parser.add_argument("site")
parser.add_argument("out")
parser.add_argument("--phone", action="store_true")
args = parser.parse_args()

server = subprocess.Popen([sys.executable, "-u", "-m", "http.server", "0", "--bind", "127.0.0.1", "--directory",
                           args.site], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
port = int(re.search(r"port (\d+)", server.stdout.readline()).group(1))
browser, profile = chromium(args.phone)
try:
    wait = WebDriverWait(browser, 300, poll_frequency=0.05)
    browser.get(f"http://127.0.0.1:{port}/#StepASketch")
    wait.until(lambda b: b.find_element(By.ID, "status").text.startswith("ready"))
    browser.find_element(By.ID, "run").click()
    browser.switch_to.frame(browser.find_element(By.ID, "view"))
    wait.until(lambda b: b.execute_script("return !!(window.stepdanceView && window.stepdanceView.hello);"))
    browser.find_element(By.CSS_SELECTOR, "button[data-speed='max']").click()
    browser.switch_to.default_content()
    wait.until(lambda b: b.execute_script("return window.stepdanceSite.result !== null;"))
    if args.phone:
        browser.execute_script("window.scrollTo(0, 0);")
    browser.save_screenshot(args.out)
finally:
    browser.quit()
    shutil.rmtree(profile, ignore_errors=True)
    server.kill()
print(f"wrote {args.out}")
