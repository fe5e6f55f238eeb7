#!/usr/bin/python3
"""Benchmark (not a test): what a live view page receives, and how closely the run keeps time.

Runs SCENARIO live with --view at SPEED (1, 10 or max), connects one page (a plain WebSocket
client reading every message, as a browser tab would) as soon as the address is announced and,
with --gcode FILE, streams FILE to the first board's pseudo-terminal as a Grbl sender does
(character counting, 128-byte receive buffer). The run ends after SECONDS of simulated time, or
when the sender has streamed the file and the machine reports Idle.

Prints the messages and bytes per simulated second the page received, and the pacing error as
the page sees it: for each update, (wall time received − t_s / speed), less the smallest
such difference of the run. That is how late the update arrived against a clock that keeps
exact pace with the simulation, so it includes the socket's delivery too.

Usage: bench/view_stream.py SCENARIO [--speed 1|10|max] [--seconds S] [--gcode FILE]
                            [--segments N] [--stepdance BINARY]
       --segments N writes a G-code plot of N straight segments (a Lissajous figure, about
       0.3 mm each) and streams it (instead of --gcode).
"""
import argparse
import base64
import json
import math
import os
import re
import socket
import statistics
import struct
import subprocess
import tempfile
import threading
import time

import serial  # Debian: python3-serial

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GRBL_RX_BYTES = 128  # Grbl's serial receive buffer (Grbl 1.1 interface docs: character counting)


def lissajous_gcode(segments):
    """A 23:22 Lissajous figure of `segments` G1 moves (about 0.3 mm each), pen down once."""
    lines = ["G21 G90 G94", "G10 L2 P1 X20 Y120", "G54", "G0 Z4", "G0 X50 Y-50", "G1 Z-4 F2400"]
    for k in range(1, segments + 1):
        t = 2 * math.pi * k / segments
        lines.append(f"G1 X{50 + 46 * math.sin(23 * t):.3f} Y{-50 + 46 * math.sin(22 * t):.3f}")
    lines += ["G0 Z4", "G0 X0 Y0"]
    return "\n".join(lines) + "\n"


class Page:
    """A page: reads every view message, noting its wall time of arrival, t_s and size."""

    def __init__(self, port, token):
        self.records = []  # (wall_s, t_s or None, bytes, type)
        self.connection = socket.create_connection(("127.0.0.1", port))
        key = base64.b64encode(os.urandom(16)).decode()
        self.connection.sendall((f"GET /ws?token={token} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n"
                                 f"Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
                                 f"Sec-WebSocket-Version: 13\r\nOrigin: http://127.0.0.1:{port}\r\n\r\n").encode())
        self.data = b""
        while b"\r\n\r\n" not in self.data:
            self.data += self.connection.recv(4096)
        self.data = self.data.split(b"\r\n\r\n", 1)[1]
        self.thread = threading.Thread(target=self.read, daemon=True)
        self.thread.start()

    def take(self, count):
        while len(self.data) < count:
            chunk = self.connection.recv(1 << 16)
            if not chunk:
                raise EOFError
            self.data += chunk
        out, self.data = self.data[:count], self.data[count:]
        return out

    def frame(self):
        first, second = self.take(2)
        length = second & 0x7F
        if length == 126:
            length = struct.unpack(">H", self.take(2))[0]
        elif length == 127:
            length = struct.unpack(">Q", self.take(8))[0]
        return first & 0x80, first & 0x0F, self.take(length)

    def pong(self, payload):
        """Answers a ping as a browser does (a client's frames are masked; a zero mask here)."""
        self.connection.sendall(bytes([0x8A, 0x80 | len(payload), 0, 0, 0, 0]) + payload)

    def read(self):
        """Whole messages (a long one may come in fragments), until the close frame."""
        try:
            payload = b""
            while True:
                final, opcode, data = self.frame()
                if opcode == 8:
                    break
                if opcode == 9:
                    self.pong(data)
                if opcode >= 8:
                    continue  # control frames may come between a message's fragments
                payload += data
                if not final:
                    continue
                try:
                    message = json.loads(payload)
                except ValueError as error:
                    raise RuntimeError(f"a message that is not JSON: {payload[:80]!r}") from error
                self.records.append((time.monotonic(), message.get("t_s"), len(payload), message.get("type")))
                payload = b""
        except (EOFError, OSError):
            pass


def stream_gcode(path, text, stop):
    """A Grbl sender: character counting against Grbl's 128-byte buffer, then `?` until Idle."""
    link = serial.Serial(path, 115200, timeout=0.01)
    replies = b""

    def read_lines():
        nonlocal replies
        replies += link.read(max(1, link.in_waiting))
        *lines, replies = replies.split(b"\n")
        return [line.strip() for line in lines]
    # At --speed max the welcome may be printed before the port is opened: a short wait instead.
    deadline = time.monotonic() + 0.5
    while time.monotonic() < deadline:
        read_lines()
    in_flight = []
    for line in text.splitlines():
        data = (line + "\n").encode()
        while sum(in_flight) + len(data) > GRBL_RX_BYTES:
            for reply in read_lines():
                if reply == b"ok" or reply.startswith(b"error"):
                    if reply != b"ok":
                        raise RuntimeError(f"Grbl refused a line: {reply!r}")
                    in_flight.pop(0)
        link.write(data)
        in_flight.append(len(data))
    while in_flight:
        for reply in read_lines():
            if reply == b"ok":
                in_flight.pop(0)
    while not stop.is_set():
        link.write(b"?")
        if any(line.startswith(b"<Idle") for line in read_lines()):
            break
        time.sleep(0.2)
    stop.set()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scenario")
    parser.add_argument("--speed", default="1")
    parser.add_argument("--seconds", default="30")
    parser.add_argument("--gcode")
    parser.add_argument("--segments", type=int)
    parser.add_argument("--stepdance", default=os.path.join(ROOT, "build", "stepdance"))
    args = parser.parse_args()
    gcode = None
    if args.segments:
        gcode = lissajous_gcode(args.segments)
    elif args.gcode:
        gcode = open(args.gcode).read()
    out_dir = tempfile.mkdtemp(prefix="stepdance-view-stream-")
    command = [args.stepdance, "sim", args.scenario, "--live", "--view", "--speed", args.speed,
               "--duration", args.seconds, "--out", out_dir, "--no-vcd"]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    page, sender, stop, report = None, None, threading.Event(), ""
    for line in process.stdout:
        report += line
        serial_path = re.match(r"serial \S+: (\S+)", line)
        if serial_path and gcode and sender is None:
            sender = threading.Thread(target=stream_gcode, args=(serial_path.group(1), gcode, stop), daemon=True)
        view = re.match(r"view: http://127\.0\.0\.1:(\d+)/\?token=(\w+)", line)
        if view:
            page = Page(int(view.group(1)), view.group(2))
            if sender:
                sender.start()
                threading.Thread(target=lambda: (stop.wait(), process.send_signal(2)), daemon=True).start()
    process.wait()
    page.thread.join(timeout=10)
    updates = [r for r in page.records if r[3] == "update" and r[1] is not None]
    simulated_s = updates[-1][1] - updates[0][1] if len(updates) > 1 else 0.0
    total_bytes = sum(r[2] for r in page.records)
    print(f"{args.scenario} --speed {args.speed}" + (f", {args.segments} G-code segments" if args.segments else ""))
    print(f"  simulated {simulated_s:.2f} s; page received {len(page.records)} messages, {total_bytes} bytes")
    if simulated_s > 0:
        print(f"  per simulated second: {len(page.records) / simulated_s:.1f} messages, "
              f"{total_bytes / simulated_s / 1024:.1f} KiB")
    if args.speed != "max" and len(updates) > 2:
        speed = float(args.speed)
        offsets = [wall - t / speed for wall, t, _, _ in updates]
        lateness_ms = [1000 * (o - min(offsets)) for o in offsets]
        print(f"  pacing error seen by the page: mean {statistics.mean(lateness_ms):.2f} ms, "
              f"median {statistics.median(lateness_ms):.2f} ms, 99th percentile "
              f"{statistics.quantiles(lateness_ms, n=100)[98]:.2f} ms, max {max(lateness_ms):.2f} ms "
              f"over {len(updates)} updates")
    for line in re.findall(r"(?m)^(?:simulated [\d.]+ s in |pacing: ).*$", report):
        print("  " + line)  # the run's closing report, and its own pacing figure


if __name__ == "__main__":
    main()
