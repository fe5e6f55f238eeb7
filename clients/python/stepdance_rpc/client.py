"""The Board class: a serial connection, request ids, replies matched to requests, and an
attribute proxy built from the board's __index__."""
import itertools
import time
import json

import serial


class RpcError(Exception):
    """The board refused a call; .code and .message are the board's."""

    def __init__(self, name, code, message):
        super().__init__(f"{name}: {message} (code {code})")
        self.name = name
        self.code = code
        self.message = message


class RpcTimeout(TimeoutError):
    """No reply within the timeout."""


class _Node:
    """A dotted path: a function to call, a parameter to read or write, or a prefix of either."""

    def __init__(self, board, path):
        object.__setattr__(self, "_board", board)
        object.__setattr__(self, "_path", path)

    def __getattr__(self, name):
        return self._board._resolve(f"{self._path}.{name}")

    def __setattr__(self, name, value):
        self._board._assign(f"{self._path}.{name}", value)

    def __call__(self, *args):
        return self._board.call(self._path, *args)

    def __dir__(self):
        prefix = self._path + "."
        return sorted({name[len(prefix):].split(".")[0] for name in self._board.index if name.startswith(prefix)})

    def __repr__(self):
        return f"<stepdance {self._path}>"


class Board:
    """A board (or a simulated one) that runs an RPC block on a serial port.

    Attributes mirror the enrolled names: functions are called, parameters read and written,
    blocks are prefixes (board.tbi.add_move(...)). Every call waits for its own reply (matched by
    id) for at most `timeout` seconds.
    """

    def __init__(self, port, timeout=2.0, baudrate=115200):
        self.timeout = timeout
        self._serial = serial.Serial(port, baudrate, timeout=0.05)
        self._ids = itertools.count(1)
        self._buffer = b""
        self.index = {}
        self.index = self.call("__index__")

    def close(self):
        self._serial.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def call(self, name, *args):
        """Calls `name` with `args`; returns the board's return value (None for none)."""
        request_id = next(self._ids)
        line = json.dumps({"name": name, "args": list(args), "id": request_id}) + "\n"
        self._serial.write(line.encode("ascii"))
        reply = self._reply(request_id, name)
        if reply.get("result") != "ok":
            raise RpcError(name, reply.get("code"), reply.get("error", "error"))
        return reply.get("return")

    def _reply(self, request_id, name):
        deadline = time.monotonic() + self.timeout
        while time.monotonic() < deadline:
            while b"\n" in self._buffer:
                line, self._buffer = self._buffer.split(b"\n", 1)
                line = line.strip()
                if not line:
                    continue
                try:
                    reply = json.loads(line)
                except ValueError:
                    continue  # something else the sketch printed
                if reply.get("id") == request_id:
                    return reply
            self._buffer += self._serial.read(4096)
        raise RpcTimeout(f"{name}: no reply within {self.timeout} s")

    def _resolve(self, path):
        kind = self.index.get(path)
        if kind == "parameter":
            return self.call(path)
        if kind == "function" or any(name.startswith(path + ".") for name in self.index):
            return _Node(self, path)
        raise AttributeError(f"the board has no '{path}'")

    def _assign(self, path, value):
        if self.index.get(path) != "parameter":
            raise AttributeError(f"'{path}' is not a parameter")
        self.call(path, value)

    def __getattr__(self, name):
        if name.startswith("_") or name in ("index", "timeout"):
            raise AttributeError(name)
        return self._resolve(name)

    def __setattr__(self, name, value):
        if name.startswith("_") or name in ("index", "timeout") or name not in self.__dict__.get("index", {}):
            object.__setattr__(self, name, value)
        else:
            self._assign(name, value)

    def __dir__(self):
        return sorted({name.split(".")[0] for name in self.index})
