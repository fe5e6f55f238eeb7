"""What the live view's tests share: a raw WebSocket client of the view, headless Chromium, the
drawing of a run's SVG, and the view protocol's promise about strokes checked against it.

Nothing here runs a test; view_page_test.py, saxi_view_test.py and view_backpressure_test.py use it.
"""
import base64
import json
import os
import re
import socket
import struct
import xml.etree.ElementTree as ElementTree

# The protocol's display resolution (docs/simulator.md, "The view protocol"): a stroke's points
# closer than this to the point kept before them are merged; first and last points always kept.
RESOLUTION_MM = 0.05
# Our SVG writer rounds to 0.001 mm; a point is "the same" to 0.01 mm.
SAME_POINT_MM = 0.01


def svg_strokes(path):
    """The pen-down polylines of a run's SVG (not the dashed pen-up travel), as lists of (x, y) in
    machine mm (the SVG's margin is a translate() around them)."""
    strokes = []
    for group in ElementTree.parse(path).iter():
        if not group.tag.endswith("}g") or group.get("stroke-dasharray") is not None:
            continue
        for element in group:
            if element.tag.endswith("polyline"):
                numbers = [float(n) for n in re.split(r"[ ,]+", element.get("points").strip())]
                strokes.append(list(zip(numbers[0::2], numbers[1::2])))
    return strokes


def svg_pieces(path):
    """The pen-down polylines of a run's SVG with their colour: [(points, "#rrggbb" or None)]."""
    pieces = []
    for group in ElementTree.parse(path).iter():
        if not group.tag.endswith("}g") or group.get("stroke-dasharray") is not None:
            continue
        for element in group:
            if element.tag.endswith("polyline"):
                numbers = [float(n) for n in re.split(r"[ ,]+", element.get("points").strip())]
                pieces.append((list(zip(numbers[0::2], numbers[1::2])), element.get("stroke")))
    return pieces


# The page's strokes, as the DOM holds them: per stroke a <g class="stroke"> under #strokes with,
# for a black stroke, its settled paths ("M x,y L x,y …", each sharing its last point with what
# follows) and one polyline with the rest; for a shaded stroke, one polyline per shade, coloured.
_DOM_STROKES = """
return Array.from(document.querySelectorAll('#strokes g.stroke')).map(g => Array.from(g.children).map(e =>
    [e.tagName, e.tagName === 'path' ? (e.getAttribute('d') || '') : (e.getAttribute('points') || ''),
     e.getAttribute('stroke')]));"""


def _numbers_to_points(text):
    numbers = [float(n) for n in re.split(r"[ ,MLml]+", text.strip()) if n]
    return list(zip(numbers[0::2], numbers[1::2]))


def _dom_groups(browser):
    """Per stroke group: [(points, colour or None)] for its elements, a black stroke's joined into one."""
    groups = []
    for elements in browser.execute_script(_DOM_STROKES):
        if any(tag == "path" for tag, _, _ in elements):
            joined = []
            for _, text, _ in elements:
                points = _numbers_to_points(text)
                joined.extend(points if not joined else points[1:])
            groups.append([(joined, None)])
        else:
            groups.append([(_numbers_to_points(text), colour) for _, text, colour in elements])
    return groups


def page_pieces_from_dom(browser):
    """The page's strokes with their own colour: [(points, "#rrggbb" or None)], a shaded stroke's
    pieces one by one, a black stroke's settled paths and polyline joined into one."""
    return [piece for group in _dom_groups(browser) for piece in group]


def page_strokes_from_dom(browser):
    """The strokes the page drew, as (x, y) lists: each black stroke whole, each shaded piece apart."""
    return [points for points, _ in page_pieces_from_dom(browser)]


def _distance(a, b):
    return ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5


def stroke_mismatch(page, svg):
    """Why the page's stroke is not the SVG's stroke thinned as the protocol promises, or None.

    The promise: the same first and last points; every other page point is one of the SVG's, in
    order; every SVG point the page left out lies within the resolution of the page point kept
    before it (only sub-resolution points are merged), or, before the last point, within twice
    the resolution of it (the last point replaces a kept neighbour closer than the resolution);
    the page's interior points are at least the resolution apart (it did thin). Distances allow SAME_POINT_MM for the SVG's rounding.
    """
    if len(svg) == 2 and svg[0] == svg[1] and len(page) <= 2:
        svg = svg[:1]  # a dot: the SVG writes its one point twice, and so may the page
        page = page[:1]
    if not page:
        return "the page has no points"
    if _distance(page[0], svg[0]) > SAME_POINT_MM:
        return f"first point {page[0]} on the page, {svg[0]} in the SVG"
    if _distance(page[-1], svg[-1]) > SAME_POINT_MM:
        return f"last point {page[-1]} on the page, {svg[-1]} in the SVG"
    j = 0
    for k in range(1, len(page)):
        last = k == len(page) - 1
        while True:
            j += 1
            if j >= len(svg):
                return f"page point {k} {page[k]} is not among the SVG's points in order"
            if (_distance(svg[j], page[k]) <= SAME_POINT_MM and (not last or j == len(svg) - 1)):
                break
            # The stroke's last point replaces a kept point within the resolution of it.
            near_end = last and _distance(svg[j], page[k]) <= 2 * RESOLUTION_MM + SAME_POINT_MM
            if _distance(svg[j], page[k - 1]) > RESOLUTION_MM + SAME_POINT_MM and not near_end:
                return (f"SVG point {j} {svg[j]} left out though {_distance(svg[j], page[k - 1]):.4f} mm from the "
                        f"page's point before it")
        if 1 <= k < len(page) - 1 and _distance(page[k], page[k - 1]) < RESOLUTION_MM - SAME_POINT_MM:
            return f"page points {k - 1} and {k} closer than the resolution: not thinned"
    return None


def strokes_mismatch(page, svg):
    """Why the page's strokes are not the SVG's, stroke for stroke, or None."""
    if len(page) != len(svg):
        return f"{len(page)} strokes on the page, {len(svg)} in the SVG"
    for index, (page_stroke, svg_stroke) in enumerate(zip(page, svg)):
        problem = stroke_mismatch(page_stroke, svg_stroke)
        if problem:
            return f"stroke {index}: {problem}"
    return None


def headless_chromium():
    """Headless Chromium (headless_chromium.Chromium): (browser, profile directory to remove)."""
    from headless_chromium import Chromium
    chromium = Chromium()
    return chromium.driver, chromium.profile


def read_announcements(process, count):
    """The first `count` lines the run prints: {"view": (url, port, token), "serial": {board: pty}}."""
    found = {"view": None, "serial": {}}
    for _ in range(count):
        line = process.stdout.readline()
        match = re.fullmatch(r"view: (http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{32}))\n", line)
        if match:
            found["view"] = (match.group(1), int(match.group(2)), match.group(3))
            continue
        match = re.fullmatch(r"serial (\S+): (/dev/pts/\d+)\n", line)
        if match:
            found["serial"][match.group(1)] = match.group(2)
    return found


def websocket_status(port, path, origin):
    connection = socket.create_connection(("127.0.0.1", port), timeout=10)
    key = base64.b64encode(os.urandom(16)).decode()
    connection.sendall((f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n"
                        f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
                        f"Origin: {origin}\r\n\r\n").encode())
    response = b""
    while b"\r\n" not in response:
        chunk = connection.recv(4096)
        if not chunk:
            break
        response += chunk
    connection.close()
    return response.split(b"\r\n", 1)[0].decode()


class RawWebSocket:
    """A WebSocket client on a plain socket (RFC 6455), to send what no browser would, or to
    stop reading. `receive_buffer_bytes` shrinks the socket's kernel buffer (set before
    connecting), so a client that stops reading holds back the server soon."""

    def __init__(self, port, token, origin=None, receive_buffer_bytes=None):
        self.connection = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        if receive_buffer_bytes:
            self.connection.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, receive_buffer_bytes)
        self.connection.settimeout(20)
        self.connection.connect(("127.0.0.1", port))
        key = base64.b64encode(os.urandom(16)).decode()
        self.connection.sendall((f"GET /ws?token={token} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n"
                                 f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
                                 f"Origin: {origin or f'http://127.0.0.1:{port}'}\r\n\r\n").encode())
        self.buffer = b""
        while b"\r\n\r\n" not in self.buffer:
            chunk = self.connection.recv(4096)
            if not chunk:
                break
            self.buffer += chunk
        head, _, self.buffer = self.buffer.partition(b"\r\n\r\n")
        self.status = head.split(b"\r\n", 1)[0].decode()

    def send(self, text):
        payload = text.encode()
        mask = os.urandom(4)
        if len(payload) < 126:
            header = bytes([0x81, 0x80 | len(payload)])
        elif len(payload) < 65536:
            header = bytes([0x81, 0x80 | 126]) + struct.pack(">H", len(payload))
        else:
            header = bytes([0x81, 0x80 | 127]) + struct.pack(">Q", len(payload))
        self.connection.sendall(header + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))

    def read_exactly(self, count):
        while len(self.buffer) < count:
            chunk = self.connection.recv(65536)
            if not chunk:
                raise EOFError("closed")
            self.buffer += chunk
        data, self.buffer = self.buffer[:count], self.buffer[count:]
        return data

    def receive(self):
        """The next message as JSON; None for a close frame. Raises EOFError when the socket closes."""
        first, second = self.read_exactly(2)
        length = second & 0x7F
        if length == 126:
            length = struct.unpack(">H", self.read_exactly(2))[0]
        elif length == 127:
            length = struct.unpack(">Q", self.read_exactly(8))[0]
        payload = self.read_exactly(length)
        if first & 0x0F == 8:
            return None
        return json.loads(payload)

    def receive_type(self, wanted):
        while True:
            message = self.receive()
            if message is None or message["type"] == wanted:
                return message

    def wait_closed(self):
        """Reads until the server closes: a close frame or the end of the stream."""
        try:
            while self.receive() is not None:
                pass
        except EOFError:
            pass

    def close(self):
        self.connection.close()


class PageStrokes:
    """The drawing as a page following the protocol keeps it: stroke i keeps its first `from`
    points and appends the update's."""

    def __init__(self):
        self.strokes = []

    def apply(self, update):
        for part in update.get("strokes", []):
            while len(self.strokes) <= part["i"]:
                self.strokes.append([])
            stroke = self.strokes[part["i"]]
            del stroke[part["from"]:]
            stroke.extend(tuple(point) for point in part["points"])
