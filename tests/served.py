"""A real ``tui-search --serve`` in a subprocess on a free local port, and a client that talks
to it as textual-serve's page does (its ``static/js/textual.js``): fetch the page, read the
websocket address from the terminal element's ``data-session-websocket-url``, connect with
``?width=W&height=H``, send ``["resize", {"width": W, "height": H}]``, and read the app's
output -- terminal escape sequences -- from the binary messages.

Used by tests/test_serve.py and by the Chromium check (tests/browser_check.py)."""

from __future__ import annotations

import asyncio
import html
import json
import os
import re
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from tests.helpers import ROOT
from tui_search.serve.visit import stop_process

TOKEN = re.compile(r"\?token=([A-Za-z0-9_-]+)")
WS_URL = re.compile(r'data-session-websocket-url="([^"]+)"')
ESCAPES = re.compile(r"\x1b\[[0-9;?<>=]*[ -/]*[@-~]|\x1b[PX^_\]].*?(?:\x1b\\|\x07)|\x1b.")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@dataclass
class Served:
    process: subprocess.Popen[str]
    url: str
    banner: str
    token: str | None = None

    @property
    def page(self) -> str:
        """The page's address as the banner gives it (with the token, if any)."""
        return self.url + (f"?token={self.token}" if self.token else "")

    def log(self) -> str:
        """Everything the server printed after its banner, once it has stopped (SIGINT)."""
        assert self.process.stdout is not None
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
        return self.process.stdout.read()


@contextmanager
def served(*args: str, timeout: float = 30.0) -> Iterator[Served]:
    """``tui-search --serve --port P ARGS`` until the block ends (then stopped with SIGINT,
    as Ctrl+C does, and waited for)."""
    port = free_port()
    process = subprocess.Popen(
        [sys.executable, "-m", "tui_search", "--serve", "--port", str(port), *args],
        cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
        env={**os.environ, "PYTHONUNBUFFERED": "1"},
    )
    try:
        assert process.stdout is not None
        banner = process.stdout.readline()  # "Serving tui-search (...) on http://...": listening
        if not banner.startswith("Serving"):
            raise AssertionError(f"the server did not start: {banner}{process.stdout.read()}")
        while not banner.endswith("Press Ctrl+C to stop.\n"):
            banner += process.stdout.readline()
        token = TOKEN.search(banner)
        # Listening starts right after on_startup prints; wait until it accepts.
        deadline = time.monotonic() + timeout
        while True:
            try:
                socket.create_connection(("127.0.0.1", port), timeout=1).close()
                break
            except OSError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.05)
        yield Served(process, f"http://127.0.0.1:{port}/", banner,
                     token.group(1) if token else None)
    finally:
        stop_process(process, signal.SIGINT, 10)


def descendants(pid: int) -> list[int]:
    """The processes ``pid`` started, and theirs, from ``/proc`` (Linux)."""
    found: list[int] = []
    try:
        children = [int(p) for p in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return found
    for child in children:
        found += [child, *descendants(child)]
    return found


def running(pid: int) -> bool:
    """Is ``pid`` a live process (not gone, not a zombie waiting for a parent to reap it)?"""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return False
    return state not in ("Z", "X")


def screen_text(data: bytes) -> str:
    """The characters of the app's output, escape sequences removed."""
    return ESCAPES.sub("", data.decode("utf-8", "replace"))


async def first_screen(url: str, want: str, width: int = 120, height: int = 36,
                       timeout: float = 30.0, origin: str | None = None) -> tuple[str, str]:
    """The page at ``url`` and the app's output text once it shows ``want`` (or AssertionError
    with what arrived by ``timeout``)."""
    page, screens = await visit(url, [("", want)], width, height, timeout, origin)
    return page, screens[0]


async def visit(url: str, steps: list[tuple[str, str]], width: int = 120, height: int = 36,
                timeout: float = 30.0, origin: str | None = None) -> tuple[str, list[str]]:
    """Open the page's app and, for each step, type its keys (what the page sends as
    ``["stdin", keys]``: "\x13" is ctrl+s) and read the output until it shows the step's
    text; the page and each step's output.  Then ``q`` quits the app."""
    import aiohttp

    # unsafe: the token's cookie of a server at an IP address is kept too
    async with aiohttp.ClientSession(cookie_jar=aiohttp.CookieJar(unsafe=True)) as session:
        async with session.get(url) as response:
            assert response.status == 200, response.status
            page = await response.text()
        match = WS_URL.search(page)
        assert match, "the page names no websocket"
        ws_url = f"{html.unescape(match.group(1))}?width={width}&height={height}"
        headers = {"Origin": origin} if origin else None
        screens = []
        async with session.ws_connect(ws_url, headers=headers) as ws:
            await ws.send_str(json.dumps(["resize", {"width": width, "height": height}]))
            await ws.send_str(json.dumps(["ping", "1"]))
            loop = asyncio.get_running_loop()
            for keys, want in steps:
                if keys:
                    await ws.send_str(json.dumps(["stdin", keys]))
                received = bytearray()
                deadline = loop.time() + timeout
                while want not in screen_text(bytes(received)):
                    left = deadline - loop.time()
                    if left <= 0:
                        raise AssertionError(f"no {want!r} in the app's output: "
                                             f"{screen_text(bytes(received))[-600:]!r}")
                    try:
                        message = await ws.receive(timeout=left)
                    except asyncio.TimeoutError:
                        continue
                    if message.type == aiohttp.WSMsgType.BINARY:
                        received += message.data
                    elif message.type in (aiohttp.WSMsgType.CLOSE, aiohttp.WSMsgType.CLOSED,
                                          aiohttp.WSMsgType.ERROR):
                        raise AssertionError("the websocket closed: "
                                             f"{screen_text(bytes(received))!r}")
                screens.append(screen_text(bytes(received)))
            await ws.send_str(json.dumps(["stdin", "q"]))  # quit the visitor's app
        return page, screens


def raw_websocket(url: str, host: str | None = None) -> socket.socket:
    """A websocket to ``url``'s server opened by hand (an upgrade request on a plain socket):
    a visitor who can send bad frames, fall silent, or drop the connection."""
    import base64

    port = int(url.rsplit(":", 1)[1].strip("/"))
    sock = socket.create_connection(("127.0.0.1", port), timeout=10)
    key = base64.b64encode(os.urandom(16)).decode()
    sock.sendall((f"GET /ws?width=80&height=24 HTTP/1.1\r\nHost: {host or f'127.0.0.1:{port}'}"
                  f"\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: {key}"
                  "\r\nSec-WebSocket-Version: 13\r\n\r\n").encode())
    answer = b""
    while b"\r\n\r\n" not in answer:
        answer += sock.recv(1)
    assert answer.startswith(b"HTTP/1.1 101"), answer
    return sock


def frame(opcode: int, payload: bytes) -> bytes:
    """One masked client frame (the mask all zeros: the payload as it is); short payloads."""
    assert len(payload) < 126
    return bytes([0x80 | opcode, 0x80 | len(payload)]) + b"\0\0\0\0" + payload


def apps_of(server: Served) -> list[int]:
    """The visitors' apps running under ``server``: its fork server's descendants."""
    pid = server.process.pid
    forks = [int(p) for p in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    return [app for fork in forks for app in descendants(fork) if running(app)]


def wait_for(test, timeout: float) -> float:
    """Seconds until ``test()`` is true (AssertionError after ``timeout``)."""
    start = time.monotonic()
    while not test():
        if time.monotonic() - start > timeout:
            raise AssertionError(f"not within {timeout} s")
        time.sleep(0.05)
    return time.monotonic() - start
