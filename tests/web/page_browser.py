"""Headless Chromium for the page's tests and screenshots: Debian's chromium and chromium-driver,
a throw-away profile, the console's messages kept (get_log("browser")), and optionally a phone's
screen (390 × 844 CSS px, 2 device pixels each, mobile, touch) through Chromium's mobile emulation."""
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service

PHONE_WIDTH_PX = 390
PHONE_HEIGHT_PX = 844
PHONE_PIXEL_RATIO = 2


def chromium(phone=False):
    """Returns (driver, profile folder); the caller quits the driver and removes the folder."""
    options = Options()
    options.binary_location = "/usr/bin/chromium"
    profile = tempfile.mkdtemp(prefix="stepdance-chromium-")
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                     f"--user-data-dir={profile}", "--window-size=1400,1000", "--allow-file-access-from-files"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    if phone:
        options.add_experimental_option("mobileEmulation", {"deviceMetrics": {
            "width": PHONE_WIDTH_PX, "height": PHONE_HEIGHT_PX, "pixelRatio": PHONE_PIXEL_RATIO, "mobile": True,
            "touch": True}})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options), profile
