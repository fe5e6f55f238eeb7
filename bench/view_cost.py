#!/usr/bin/python3
"""Benchmark (not a test): what the live view costs a run at --speed max, and what it sends.

Runs SCENARIO live at --speed max twice: alone, then with --view and one page (a plain
WebSocket client that reads every message, as a browser tab would) connected as soon as the
address is announced. Prints each run's computing time from its closing report, the view's
share, and the messages and bytes the page received per simulated second.

Usage: bench/view_cost.py [SCENARIO] [SECONDS] [STEPDANCE_BINARY]
       (default examples/StepASketch/scenario.toml 42 build/stepdance; a live run lasts until
       interrupted, so SECONDS is its --duration)
"""
import base64
import os
import re
import socket
import struct
import subprocess
import sys
import threading

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIO = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "examples", "StepASketch", "scenario.toml")
DURATION_S = sys.argv[2] if len(sys.argv) > 2 else "42"
STEPDANCE = sys.argv[3] if len(sys.argv) > 3 else os.path.join(ROOT, "build", "stepdance")
REPORT = re.compile(r"simulated ([\d.]+) s in ([\d.]+) s of wall time \(live; ([\d.]+) s of it computing")


def read_page(port, token, totals):
    connection = socket.create_connection(("127.0.0.1", port))
    key = base64.b64encode(os.urandom(16)).decode()
    connection.sendall((f"GET /ws?token={token} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n"
                        f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
                        f"Origin: http://127.0.0.1:{port}\r\n\r\n").encode())
    data = b""
    while b"\r\n\r\n" not in data:
        data += connection.recv(4096)
    data = data.split(b"\r\n\r\n", 1)[1]

    def take(count):
        nonlocal data
        while len(data) < count:
            chunk = connection.recv(1 << 16)
            if not chunk:
                raise EOFError
            data += chunk
        out, data = data[:count], data[count:]
        return out
    try:
        while True:
            first, second = take(2)
            length = second & 0x7F
            if length == 126:
                length = struct.unpack(">H", take(2))[0]
            elif length == 127:
                length = struct.unpack(">Q", take(8))[0]
            take(length)
            if first & 0x0F == 8:
                break
            totals["messages"] += 1
            totals["bytes"] += length
    except (EOFError, OSError):
        pass


def run(view):
    command = [STEPDANCE, "sim", SCENARIO, "--live", "--speed", "max", "--duration", DURATION_S, "--out", "/tmp/stepdance-view-cost", "--no-vcd"]
    if view:
        command.append("--view")
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    totals = {"messages": 0, "bytes": 0}
    reader = None
    for line in process.stdout:
        match = re.match(r"view: http://127\.0\.0\.1:(\d+)/\?token=(\w+)", line)
        if match:
            reader = threading.Thread(target=read_page, args=(int(match.group(1)), match.group(2), totals))
            reader.start()
        report = REPORT.search(line)
        if report:
            simulated, computing = float(report.group(1)), float(report.group(3))
    process.wait()
    if reader:
        reader.join(timeout=10)
    return simulated, computing, totals


alone_s, alone_computing, _ = run(False)
viewed_s, viewed_computing, totals = run(True)
print(f"alone:     {alone_s:.3f} s simulated, {alone_computing:.3f} s computing")
print(f"with view: {viewed_s:.3f} s simulated, {viewed_computing:.3f} s computing "
      f"(+{100 * (viewed_computing / alone_computing - 1):.1f} %)")
print(f"page received {totals['messages']} messages, {totals['bytes']} bytes: "
      f"{totals['messages'] / viewed_s:.1f} messages and {totals['bytes'] / viewed_s / 1024:.1f} KiB per simulated second")
