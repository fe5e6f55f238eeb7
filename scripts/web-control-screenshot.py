#!/usr/bin/python3
"""Makes docs/images/web-control.png: `stepdance serve examples/WebControl` in headless Chromium,
after the page's controls have drawn a waved square (the clicks of examples/WebControl/scenario.toml).

Usage: scripts/web-control-screenshot.py [build/stepdance] [docs/images/web-control.png]
"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEPDANCE = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "stepdance")
PICTURE = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "images", "web-control.png")


def click(browser, name, *args):
    row = browser.find_element(By.CSS_SELECTOR, f'.control[data-name="{name}"]')
    for field, value in zip(row.find_elements(By.CSS_SELECTOR, "input.arg"), args):
        field.clear()
        field.send_keys(str(value))
    row.find_element(By.CSS_SELECTOR, "button[data-call]").click()
    time.sleep(0.2)


def wait_idle(browser):
    WebDriverWait(browser, 60).until(lambda b: b.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "window.stepdance.call('is_idle').then((r) => done(r.return === true));"))


with tempfile.TemporaryDirectory() as work:
    serve = subprocess.Popen([STEPDANCE, "serve", os.path.join(ROOT, "examples", "WebControl"), "--port", "0",
                              "--out", work], stdout=subprocess.PIPE, text=True)
    url = re.match(r"serving (\S+)", serve.stdout.readline()).group(1)
    options = Options()
    options.binary_location = "/usr/bin/chromium"
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1280,900",
                     f"--user-data-dir={work}/profile"):
        options.add_argument(argument)
    browser = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    try:
        browser.get(url)
        WebDriverWait(browser, 60).until(lambda b: b.find_elements(By.CSS_SELECTOR, '.control[data-name="go_to_xy"]'))
        click(browser, "go_to_xy", 30, 30, 60)
        click(browser, "pen_down")
        click(browser, "go_to_xy", 90, 30, 30)
        wait_idle(browser)
        click(browser, "set_noise_freq", 8)
        click(browser, "set_noise_amp", 3)
        click(browser, "go_to_xy", 90, 70, 30)
        click(browser, "go_to_xy", 30, 70, 30)
        wait_idle(browser)
        click(browser, "set_noise_amp", 0)
        click(browser, "go_to_xy", 30, 30, 30)
        wait_idle(browser)
        browser.find_element(By.CSS_SELECTOR, "details summary").click()  # unfold the planner's names
        time.sleep(1)
        browser.save_screenshot(PICTURE)
        print("wrote", PICTURE)
    finally:
        browser.quit()
        serve.send_signal(signal.SIGINT)
        serve.communicate(timeout=60)
