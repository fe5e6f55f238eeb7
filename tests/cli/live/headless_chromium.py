"""Headless Chromium for the page tests: Debian's chromium, chromium-driver and python3-selenium,
a throw-away profile, and the SVG's strokes read independently of the simulator's code."""
import re
import shutil
import tempfile
import xml.etree.ElementTree as ElementTree

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service


class Chromium:
    """A headless Chromium (window 1400 × 1000) with its own profile; quit() removes both.
    `arguments`: more command-line switches; `performance_log`: keep the DevTools network events
    (get_log("performance"))."""

    def __init__(self, arguments=(), performance_log=False):
        options = Options()
        options.binary_location = "/usr/bin/chromium"
        self.profile = tempfile.mkdtemp(prefix="stepdance-chromium-")
        for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                         f"--user-data-dir={self.profile}", "--window-size=1400,1000", *arguments):
            options.add_argument(argument)
        if performance_log:
            options.set_capability("goog:loggingPrefs", {"performance": "ALL"})
        self.driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)

    def quit(self):
        self.driver.quit()
        shutil.rmtree(self.profile, ignore_errors=True)


def svg_strokes(path):
    """The pen-down polylines of a run's SVG, as lists of (x, y) in mm."""
    strokes = []
    for element in ElementTree.parse(path).iter():
        if element.tag.endswith("polyline"):
            numbers = [float(n) for n in re.split(r"[ ,]+", element.get("points").strip())]
            strokes.append(list(zip(numbers[0::2], numbers[1::2])))
    return strokes
