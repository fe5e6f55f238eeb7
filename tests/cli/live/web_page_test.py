#!/usr/bin/python3
"""The web control page of `stepdance serve`, in headless Chromium (Debian's chromium,
chromium-driver and python3-selenium), against a live simulated AxiDraw running
tests/cli/live/WebPanelTarget, whose RPC names no example uses.

Checks: the page lists controls for exactly the sketch's names; two tabs using the same request
ids each get their own replies; moves clicked in two tabs move the simulated pen where they asked
(the page's live readout and the simulator's summary.json); a WebSocket from a foreign origin is
refused; the bridge keeps answering a tab while another client floods it, and reports the drops.

Usage: web_page_test.py STEPDANCE_BINARY SOURCE_DIR WORK_DIR
"""
import base64
import json
import os
import re
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time
import unittest

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

STEPDANCE, SOURCE_DIR, WORK_DIR = sys.argv[1:4]
OUT_DIR = os.path.join(WORK_DIR, "web-page-out")
ENROLLED = {"plot_to": "function", "nib_down": "function", "nib_up": "function", "tally": "function",
            "feed_mm_s": "parameter"}


def websocket_handshake(port, origin, host=None):
    """Opens a TCP connection and asks for a WebSocket on /ws; returns (socket, status line)."""
    connection = socket.create_connection(("127.0.0.1", port), timeout=10)
    key = base64.b64encode(os.urandom(16)).decode()
    request = (f"GET /ws HTTP/1.1\r\nHost: {host or f'127.0.0.1:{port}'}\r\nUpgrade: websocket\r\n"
               f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n")
    if origin is not None:
        request += f"Origin: {origin}\r\n"
    connection.sendall((request + "\r\n").encode())
    response = b""
    while b"\r\n\r\n" not in response:
        chunk = connection.recv(4096)
        if not chunk:
            break
        response += chunk
    return connection, response.split(b"\r\n", 1)[0].decode()


def websocket_frame(text):
    """One masked text frame, as a client must send it (RFC 6455 §5.2)."""
    payload = text.encode()
    mask = os.urandom(4)
    header = bytes([0x81])
    if len(payload) < 126:
        header += bytes([0x80 | len(payload)])
    else:
        header += bytes([0x80 | 126]) + struct.pack(">H", len(payload))
    return header + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload))


class WebPageTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(OUT_DIR, ignore_errors=True)
        cls.serve = subprocess.Popen(
            [STEPDANCE, "serve", os.path.join(SOURCE_DIR, "tests", "cli", "live", "WebPanelTarget"), "--port", "0",
             "--out", OUT_DIR], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = cls.serve.stdout.readline()
        match = re.fullmatch(r"serving (http://127\.0\.0\.1:(\d+)/) for simulated board driver\n", line)
        assert match, line + cls.serve.stderr.read()
        cls.url, cls.port = match.group(1), int(match.group(2))
        options = Options()
        options.binary_location = "/usr/bin/chromium"
        cls.profile = tempfile.mkdtemp(prefix="stepdance-chromium-")
        for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                         f"--user-data-dir={cls.profile}"):
            options.add_argument(argument)
        cls.browser = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
        cls.browser.set_script_timeout(60)
        cls.browser.get(cls.url)
        cls.tab_a = cls.browser.current_window_handle
        cls.browser.switch_to.new_window("tab")
        cls.browser.get(cls.url)
        cls.tab_b = cls.browser.current_window_handle
        for tab in (cls.tab_a, cls.tab_b):
            cls.browser.switch_to.window(tab)
            WebDriverWait(cls.browser, 60).until(
                lambda b: len(b.find_elements(By.CSS_SELECTOR, ".control[data-name] output.result")) == len(ENROLLED)
                and b.find_element(By.CSS_SELECTOR, '.control[data-name="feed_mm_s"] output').get_attribute("value"))

    @classmethod
    def tearDownClass(cls):
        cls.browser.quit()
        shutil.rmtree(cls.profile, ignore_errors=True)
        if cls.serve.poll() is None:
            cls.serve.send_signal(signal.SIGINT)
            cls.serve.communicate(timeout=60)

    # ---- helpers ----
    def in_tab(self, tab):
        self.browser.switch_to.window(tab)
        return self.browser

    def control(self, name):
        return self.browser.find_element(By.CSS_SELECTOR, f'.control[data-name="{name}"]')

    def click_call(self, name, *args):
        row = self.control(name)
        fields = row.find_elements(By.CSS_SELECTOR, "input.arg")
        self.assertEqual(len(fields), len(args), name)
        for field, value in zip(fields, args):
            field.clear()
            field.send_keys(str(value))
        row.find_element(By.CSS_SELECTOR, "button[data-call]").click()

    def result(self, name):
        return self.control(name).find_element(By.CSS_SELECTOR, "output.result").get_attribute("value")

    def wait_result(self, name, pattern, seconds=30):
        WebDriverWait(self.browser, seconds).until(lambda b: re.fullmatch(pattern, self.result(name) or ""))
        return self.result(name)

    # ---- tests, run in name order ----
    def test_1_controls_for_exactly_the_enrolled_names(self):
        for tab in (self.tab_a, self.tab_b):
            browser = self.in_tab(tab)
            rows = browser.find_elements(By.CSS_SELECTOR, ".control[data-name]")
            self.assertEqual({row.get_attribute("data-name"): row.get_attribute("data-kind") for row in rows}, ENROLLED)
            self.assertEqual(len(self.control("plot_to").find_elements(By.CSS_SELECTOR, "input.arg")), 2)
            self.assertEqual(len(self.control("nib_down").find_elements(By.CSS_SELECTOR, "input.arg")), 0)
            self.assertEqual(len(self.control("feed_mm_s").find_elements(By.CSS_SELECTOR, "input[type=range]")), 1)
            self.assertEqual(self.result("feed_mm_s"), "20")  # the sketch's initial value

    def test_2_two_tabs_with_the_same_ids_get_their_own_replies(self):
        # Each tab numbers its requests from 1, so both send the same ids; click tally in both at once.
        self.in_tab(self.tab_a)
        self.click_call("tally")
        self.in_tab(self.tab_b)
        self.click_call("tally")
        first = int(self.wait_result("tally", r"\d+"))
        self.in_tab(self.tab_a)
        second = int(self.wait_result("tally", r"\d+"))
        self.assertEqual({first, second}, {1, 2})
        # Twenty calls in flight from each tab: every reply comes back to the tab that asked, once.
        script = ("const done = arguments[arguments.length - 1];"
                  "Promise.all(Array.from({length: 20}, () => window.stepdance.call('tally')))"
                  ".then((replies) => done(replies.map((r) => r.return)));")
        self.in_tab(self.tab_a)
        self.browser.execute_script("window.burst = Promise.all(Array.from({length: 20}, () => window.stepdance.call('tally')));")
        self.in_tab(self.tab_b)
        from_b = self.browser.execute_async_script(script)
        self.in_tab(self.tab_a)
        from_a = self.browser.execute_async_script(
            "const done = arguments[arguments.length - 1]; window.burst.then((r) => done(r.map((x) => x.return)));")
        self.assertEqual(len(from_a), 20)
        self.assertEqual(len(from_b), 20)
        self.assertEqual(sorted(from_a + from_b), list(range(3, 43)))
        self.assertEqual(from_a, sorted(from_a))  # in the order asked
        self.assertEqual(from_b, sorted(from_b))

    def test_3_moves_clicked_in_two_tabs_move_the_pen_there(self):
        browser = self.in_tab(self.tab_a)
        field = self.control("feed_mm_s").find_element(By.CSS_SELECTOR, "input[type=number]")
        field.clear()
        field.send_keys("40")
        self.control("feed_mm_s").find_element(By.CSS_SELECTOR, "button[data-set]").click()
        self.wait_result("feed_mm_s", "ok")
        self.click_call("nib_down")
        self.click_call("plot_to", 30, 20)
        self.in_tab(self.tab_b)
        self.click_call("plot_to", 45, 35)
        self.wait_result("plot_to", r"\d+")
        self.control("feed_mm_s").find_element(By.XPATH, ".//button[text()='read']").click()
        self.wait_result("feed_mm_s", "40")
        # The live readout follows the simulated pen to where tab B asked.
        WebDriverWait(browser, 60).until(
            lambda b: b.find_element(By.ID, "pen-x").get_attribute("value") == "45.00"
            and b.find_element(By.ID, "pen-y").get_attribute("value") == "35.00")
        self.assertEqual(browser.find_element(By.ID, "pen-state").get_attribute("value"), "pen down")
        self.assertFalse(browser.find_element(By.ID, "drawing").get_attribute("hidden"))

    def test_4_a_foreign_origin_is_refused(self):
        for origin in ("http://evil.example", "null", None):
            connection, status = websocket_handshake(self.port, origin)
            connection.close()
            self.assertEqual(status, "HTTP/1.1 403 Forbidden", origin)
        connection, status = websocket_handshake(self.port, "http://attacker.example:%d" % self.port,
                                                 host="attacker.example:%d" % self.port)
        connection.close()
        self.assertEqual(status, "HTTP/1.1 403 Forbidden")
        connection, status = websocket_handshake(self.port, f"http://127.0.0.1:{self.port}")
        connection.close()
        self.assertEqual(status, "HTTP/1.1 101 Switching Protocols")
        # And a page from elsewhere, in the browser itself: its WebSocket never opens.
        browser = self.in_tab(self.tab_a)
        browser.switch_to.new_window("tab")
        browser.get("data:text/html,<title>elsewhere</title>")
        outcome = browser.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            f"const ws = new WebSocket('ws://127.0.0.1:{self.port}/ws');"
            "ws.onopen = () => done('open'); ws.onerror = () => done('refused');")
        browser.close()
        self.assertEqual(outcome, "refused")

    def test_5_the_bridge_keeps_serving_while_a_client_floods_it(self):
        flooder, status = websocket_handshake(self.port, f"http://127.0.0.1:{self.port}")
        self.assertEqual(status, "HTTP/1.1 101 Switching Protocols")
        flood = b"".join(websocket_frame(json.dumps({"name": "feed_mm_s", "id": i})) for i in range(20000))
        flooder.settimeout(None)
        flooder.sendall(flood)  # and never read a reply
        self.in_tab(self.tab_b)
        self.click_call("nib_up")
        self.wait_result("nib_up", "ok", seconds=30)
        self.click_call("tally")
        self.wait_result("tally", "43", seconds=30)
        # The page shows the bridge's counters, with the flood's refused requests among the drops.
        WebDriverWait(self.browser, 30).until(
            lambda b: int(re.search(r"(\d+) dropped", b.find_element(By.ID, "bridge").text or "0 dropped").group(1)) > 0)
        flooder.close()

    def test_6_the_simulator_drew_where_the_page_asked(self):
        self.serve.send_signal(signal.SIGINT)
        stdout, stderr = self.serve.communicate(timeout=120)
        self.assertEqual(self.serve.returncode, 0, stderr)
        self.assertIn("requests and", stderr)  # the drops were reported on the terminal too
        with open(os.path.join(OUT_DIR, "summary.json")) as file:
            summary = json.load(file)
        machine = summary["machine"]
        self.assertAlmostEqual(machine["pen_mm"][0], 45, delta=0.05)
        self.assertAlmostEqual(machine["pen_mm"][1], 35, delta=0.05)
        self.assertEqual(machine["strokes"], 1)
        self.assertTrue(os.path.exists(os.path.join(OUT_DIR, "drawing.svg")))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
