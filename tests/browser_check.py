"""The served app in a real browser: ``python -m tests.browser_check [--out FILE.png]``.

Starts ``tui-search --serve`` on a free local port, opens its page in headless Chromium
(Debian's ``chromium``), driven over the DevTools protocol: it waits until the page's script
has drawn the app's first bytes (textual-serve's page then sets ``-first-byte`` on its body),
takes a screenshot, and checks it shows the app, not a blank page or textual-serve's
"starting" card: the light theme's white covers most of the page, and the map's wall and goal
colours are there.  Exit 0 and the screenshot's path when it does; 1 with why not; 0 with a
note when there is no Chromium (.ci/run installs it where it can).
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
from pathlib import Path

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
            return asyncio.run(capture(match.group(1), url, deadline))
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


async def capture(browser_ws: str, url: str, deadline: float) -> bytes:
    """Over the DevTools protocol: load ``url`` in the browser's page, wait for the app's
    first bytes, and return a PNG screenshot."""
    import aiohttp

    devtools = browser_ws.split("/devtools/")[0].replace("ws://", "http://")
    async with aiohttp.ClientSession() as session:
        async with session.get(f"{devtools}/json/list") as response:
            pages = [t for t in await response.json() if t["type"] == "page"]
        async with session.ws_connect(pages[0]["webSocketDebuggerUrl"], max_msg_size=0) as ws:
            ids = iter(range(1, 1_000_000))

            async def call(method: str, **params: object) -> dict:
                n = next(ids)
                await ws.send_str(json.dumps({"id": n, "method": method, "params": params}))
                while True:
                    left = max(deadline - time.monotonic(), 0.1)
                    message = json.loads((await ws.receive(timeout=left)).data)
                    if message.get("id") == n:
                        if "error" in message:
                            raise AssertionError(f"{method}: {message['error']}")
                        return message["result"]

            await call("Page.navigate", url=url)
            drawn = "document.body !== null && document.body.classList.contains('-first-byte')"
            while not (await call("Runtime.evaluate", expression=drawn,
                                  returnByValue=True))["result"].get("value"):
                if time.monotonic() > deadline:
                    raise AssertionError("the page never drew the app (no -first-byte)")
                await asyncio.sleep(0.2)
            await asyncio.sleep(2.0)  # the card fades out (0.3 s); the frame completes
            shot = await call("Page.captureScreenshot", format="png")
            return base64.b64decode(shot["data"])


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
    return 0


if __name__ == "__main__":
    sys.exit(main())
