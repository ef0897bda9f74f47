"""The served app in a real browser: ``python -m tests.browser_check [--out FILE.png]``.

Starts ``tui-search --serve`` on a free local port, opens its page in headless Chromium
(Debian's ``chromium``), driven over the DevTools protocol: it waits until the page's script
has drawn the app's first bytes (textual-serve's page then sets ``-first-byte`` on its body),
takes a screenshot, and checks it shows the app, not a blank page or textual-serve's
"starting" card: the light theme's white covers most of the page, and the map's wall and goal
colours are there.

Then a class (``--serve --records DIR --exercise FILE``): a visitor types their name in the
page, solves the exercise with two keys (the cursor onto the wall between start and goal, ``o``
takes it away), its record is written, and the teacher's page, opened in the same browser with
its own key, shows the visitor with the exercise solved.

Exit 0 when both hold; 1 with why not; 0 with a note when there is no Chromium (.ci/run
installs it where it can).
"""

from __future__ import annotations

import argparse
import asyncio
import base64
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib
from collections import Counter
from collections.abc import Awaitable, Callable
from pathlib import Path
from typing import Any, TypeVar

from tests.served import served

#: What Chromium needs on these machines (no GPU, no sandbox as root, no network but loopback).
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage")
WIDTH, HEIGHT = 1280, 800
THEME = "light"
BACKGROUND = (0xFF, 0xFF, 0xFF)  # the light theme's background
WALL = (0x3A, 0x3A, 0x3A)  # its map-wall
GOAL = (0xF0, 0xD0, 0x00)  # its map-goal
T = TypeVar("T")
DEVTOOLS = re.compile(r"DevTools listening on (ws://\S+)")


def chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser")


def png_pixels(data: bytes) -> tuple[int, int, list[tuple[int, int, int]]]:
    """Width, height and RGB pixels of an 8-bit RGB or RGBA, non-interlaced PNG (what
    Chromium writes)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, header = 8, b"", b""
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = body
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", header)
    assert depth == 8 and colour in (2, 6) and interlace == 0, (depth, colour, interlace)
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows: list[bytearray] = []
    prev = bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], (prev[i - bpp] if i >= bpp else 0)
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    pixels = [(row[i], row[i + 1], row[i + 2]) for row in rows for i in range(0, stride, bpp)]
    return width, height, pixels


def judge(png: bytes) -> str | None:
    """None when the screenshot shows the app; else why not."""
    width, height, pixels = png_pixels(png)
    counts = Counter(pixels)
    total = width * height
    share = {name: counts[colour] / total for name, colour in
             (("background", BACKGROUND), ("wall", WALL), ("goal", GOAL))}
    if share["background"] < 0.3:
        top = ", ".join(f"#{r:02x}{g:02x}{b:02x} {n / total:.0%}"
                        for (r, g, b), n in counts.most_common(4))
        return f"not the app's light page: the most common colours are {top}"
    if share["wall"] < 0.005 or share["goal"] < 0.0005:
        return (f"no map: walls {share['wall']:.2%} and goal {share['goal']:.3%} of the "
                "page")
    return None


def screenshot(browser: str, url: str, timeout: float = 40.0) -> bytes:
    """Open ``url`` in headless Chromium and take a screenshot once the app has drawn."""
    return in_chromium(browser, lambda ws, deadline: capture(ws, url, deadline), timeout)


def in_chromium(browser: str, work: Callable[[str, float], Awaitable[T]],
                timeout: float = 40.0) -> T:
    """Start headless Chromium and run ``work`` (given its DevTools address and a deadline)."""
    # Chromium's helper processes may still be writing the profile as the browser exits: its
    # removal waits for them (_remove_profile), and a folder left behind is not an error.
    with tempfile.TemporaryDirectory(prefix="tui-search-chromium-",
                                     ignore_cleanup_errors=True) as profile:
        process = subprocess.Popen(
            [browser, *FLAGS, f"--user-data-dir={profile}", f"--window-size={WIDTH},{HEIGHT}",
             "--remote-debugging-port=0", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        try:
            assert process.stderr is not None
            deadline = time.monotonic() + timeout
            while True:
                line = process.stderr.readline()
                if not line and process.poll() is not None:
                    raise AssertionError(f"chromium exited ({process.returncode})")
                if match := DEVTOOLS.search(line):
                    break
                if time.monotonic() > deadline:
                    raise AssertionError("chromium did not start its DevTools")
            return asyncio.run(work(match.group(1), deadline))
        finally:
            process.terminate()
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
            _remove_profile(profile)


def _remove_profile(profile: str, timeout: float = 10.0) -> None:
    """Remove Chromium's profile folder, again while its last helpers still write in it."""
    deadline = time.monotonic() + timeout
    while os.path.exists(profile) and time.monotonic() < deadline:
        shutil.rmtree(profile, ignore_errors=True)
        if os.path.exists(profile):
            time.sleep(0.1)  # polling: the helpers exit on their own


class DevTools:
    """The browser's first page over the DevTools protocol: ``call`` a method, ``value`` of
    an expression, ``key`` presses."""

    def __init__(self, ws: Any, deadline: float) -> None:
        self.ws, self.deadline, self.ids = ws, deadline, iter(range(1, 1_000_000))

    async def call(self, method: str, **params: object) -> dict[str, Any]:
        n = next(self.ids)
        await self.ws.send_str(json.dumps({"id": n, "method": method, "params": params}))
        while True:
            left = max(self.deadline - time.monotonic(), 0.1)
            message = json.loads((await self.ws.receive(timeout=left)).data)
            if message.get("id") == n:
                if "error" in message:
                    raise AssertionError(f"{method}: {message['error']}")
                result: dict[str, Any] = message["result"]
                return result

    async def value(self, expression: str) -> Any:
        result = await self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        return result["result"].get("value")

    async def until(self, what: str, check: Callable[[], Awaitable[object]]) -> object:
        """Poll ``check`` until it answers something true (the page and the server work on
        their own clocks: there is no event to wait for)."""
        while not (answer := await check()):
            if time.monotonic() > self.deadline:
                raise AssertionError(f"timed out waiting for {what}")
            await asyncio.sleep(0.2)
        return answer

    async def open_app(self, url: str) -> None:
        await self.call("Page.navigate", url=url)
        drawn = "document.body !== null && document.body.classList.contains('-first-byte')"
        await self.until("the page to draw the app (-first-byte)", lambda: self.value(drawn))

    async def key(self, key: str, code: int = 0, text: str = "") -> None:
        """A key pressed and released in the page's terminal (which has the focus)."""
        down: dict[str, object] = {"type": "keyDown", "key": key, "code": key,
                                   "windowsVirtualKeyCode": code or ord(key.upper()[0])}
        if text:
            down["text"] = text
        await self.call("Input.dispatchKeyEvent", **down)
        await self.call("Input.dispatchKeyEvent", type="keyUp", key=key, code=key,
                        windowsVirtualKeyCode=down["windowsVirtualKeyCode"])

    async def type(self, text: str) -> None:
        for char in text:
            await self.key(char, ord(char.upper()), char)


async def with_page(browser_ws: str, deadline: float,
                    work: Callable[[DevTools], Awaitable[T]]) -> T:
    import aiohttp

    devtools = browser_ws.split("/devtools/")[0].replace("ws://", "http://")
    async with aiohttp.ClientSession() as session:
        async with session.get(f"{devtools}/json/list") as response:
            pages = [t for t in await response.json() if t["type"] == "page"]
        async with session.ws_connect(pages[0]["webSocketDebuggerUrl"], max_msg_size=0) as ws:
            return await work(DevTools(ws, deadline))


async def capture(browser_ws: str, url: str, deadline: float) -> bytes:
    """Over the DevTools protocol: load ``url`` in the browser's page, wait for the app's
    first bytes, and return a PNG screenshot."""
    async def work(page: DevTools) -> bytes:
        await page.open_app(url)
        await asyncio.sleep(2.0)  # the card fades out (0.3 s); the frame completes
        shot = await page.call("Page.captureScreenshot", format="png")
        return base64.b64decode(shot["data"])

    return await with_page(browser_ws, deadline, work)


#: The class's exercise: a wall between start and goal; BFS finds the goal once it is gone.
EXERCISE = """title = "Open the way"
text = "Take the wall away so that BFS finds the goal."
map = "wall.txt"
searches = ["bfs"]
edits = ["obstacles"]
solved = "bfs.found"
"""
VISITOR = "Ada Browser"
TEACHER = re.compile(r"^(http://\S+/teacher\?key=\S+)$", re.MULTILINE)


def events(records: Path) -> list[dict[str, Any]]:
    """Every event the records folder holds so far (a line being written is left for later)."""
    found = []
    for path in sorted(records.glob("*.jsonl")):
        for line in path.read_text(encoding="utf-8").splitlines():
            try:
                found.append(json.loads(line))
            except ValueError:
                continue
    return found


async def a_visitor_solves(browser_ws: str, deadline: float, url: str, teacher: str,
                           records: Path) -> str:
    """The visitor's name typed, the exercise solved, then the teacher's page's text."""
    async def work(page: DevTools) -> str:
        await page.open_app(url)
        focus = ("(() => { const t = document.querySelector('.xterm-helper-textarea');"
                 " if (t) { t.focus(); } return t !== null; })()")
        await page.until("the page's terminal", lambda: page.value(focus))

        async def started() -> bool:
            return any(e.get("event") == "start" for e in events(records))

        async def solved() -> bool:
            return any(e.get("event") == "exercise" and e.get("solved")
                       for e in events(records))

        # The name: typed until the app has it (keys sent before the dialog has the focus
        # are not lost to a test that waits only for its own end).
        await page.type(VISITOR)
        await page.key("Enter", 13, "\r")
        await page.until("the visitor's first record (their name taken)", started)
        await page.key("ArrowRight", 39)
        await page.key("o", ord("O"), "o")
        await page.until("the exercise's solved record", solved)
        await page.call("Page.navigate", url=teacher)
        text = "document.body ? document.body.innerText : ''"
        return str(await page.until(f"{VISITOR} on the teacher's page",
                                    lambda: _has(page, text, VISITOR)))

    return await with_page(browser_ws, deadline, work)


async def _has(page: DevTools, expression: str, wanted: str) -> str:
    got = str(await page.value(expression) or "")
    return got if wanted in got else ""


def class_check(browser: str) -> str | None:
    """The class's run (the module's docstring): None when it holds, else why not."""
    with tempfile.TemporaryDirectory(prefix="tui-search-class-") as folder:
        root = Path(folder)
        (root / "wall.txt").write_text("S#G\n")
        (root / "open.toml").write_text(EXERCISE)
        records = root / "records"
        with served("--theme", THEME, "--records", str(records),
                    "--exercise", str(root / "open.toml")) as server:
            teacher = TEACHER.search(server.banner)
            if teacher is None:
                return f"no teacher's link in the banner: {server.banner!r}"
            try:
                page = in_chromium(browser, lambda ws, deadline: a_visitor_solves(
                    ws, deadline, server.url, teacher.group(1), records), timeout=90.0)
            except AssertionError as err:
                return f"{err} (records: {events(records)})"
        row = next((line.split("\t") for line in page.splitlines()
                    if line.startswith(VISITOR + "\t")), [])
        if row[1:2] != ["Open the way"]:  # the column of the exercises solved
            return f"the teacher's page does not show the exercise solved: {page!r}"
    return None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.browser_check", description=__doc__)
    parser.add_argument("--out", type=Path, default=Path(tempfile.gettempdir())
                        / "tui-search-browser-check.png", help="where the screenshot goes")
    args = parser.parse_args(argv)
    browser = chromium()
    if browser is None:
        print("browser check: no chromium here (apt-get install chromium): not run")
        return 0
    started = time.monotonic()
    with served("--theme", THEME, "maps/tutorial.txt") as server:
        png = screenshot(browser, server.url)
    args.out.write_bytes(png)
    problem = judge(png)
    took = time.monotonic() - started
    if problem:
        print(f"browser check: FAILED: {problem} (screenshot {args.out})")
        return 1
    print(f"browser check: the app drew in Chromium in {took:.1f} s (screenshot {args.out})")
    started = time.monotonic()
    problem = class_check(browser)
    if problem:
        print(f"browser check: FAILED: a served class: {problem}")
        return 1
    print(f"browser check: a visitor named themself, solved an exercise and showed on the "
          f"teacher's page in {time.monotonic() - started:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
