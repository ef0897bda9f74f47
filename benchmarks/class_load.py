"""Section "class_load" (issues 21 and 42): a class connecting to ``tui-search --serve`` at once.

A real server on a free local port, the tutorial map; 1, 10 and 30 visitors open the page and
its websocket within one second (all at once), each as textual-serve's page does
(``?width=120&height=36``, a resize).  A visitor's **first frame** is the time from its
websocket open to the first output that shows the map (the tutorial's status line, ``START
(0,0)``, and the footer, drawn in one frame).  While the 30 are connected, one of them presses
``n`` five times: **a step answered** is the time from the key sent to the output showing the
next step (a round trip on its websocket).

The **floor** is measured first, on the fork server alone (no websocket): the CPU time a
visitor's forked app spends from the fork to its first frame (read from ``/proc``), the part
of a start that cannot be shared.  The visitors' own CPU to their first frames, summed, over
the CPUs, is the least time the slowest of them can wait: measured with 30 (and 10) apps
started together, as a class's are (each one's CPU is more than an app's alone: they share
the caches), one at a time beside it.  The targets (issue 42): the slowest of 30 first frames
≤ 1.5 × the floor; every step answered in ≤ 0.5 s with the 30 connected.  Without ``--quick``
the **old design** (textual-serve's own server starting ``python -m tui_search --served`` per
visitor) is measured beside it.

    python benchmarks/class_load.py [--quick]      # or: bench.py --only class_load
"""

from __future__ import annotations

import asyncio
import json
import os
import re
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

if __name__ == "__main__":  # run as a script: the checkout first, this folder not a package
    HERE = Path(__file__).resolve().parent
    sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != HERE]
    sys.path.insert(0, str(HERE.parent))

from benchmarks.harness import fmt_time, med
from benchmarks.table import ROWS, Row, add, print_table
from tui_search.serve.visit import stop_process

TUTORIAL = str(Path(__file__).resolve().parent.parent / "maps" / "tutorial.txt")
WANT = ("START (0,0)", "Quit")  # in the first frame: the status line and the footer
ESCAPES = re.compile(r"\x1b\[[0-9;?<>=]*[ -/]*[@-~]|\x1b[PX^_\]].*?(?:\x1b\\|\x07)|\x1b.")
CLOCK_TICKS = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def _text(data: bytes) -> str:
    return ESCAPES.sub("", data.decode("utf-8", "replace"))


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _start(argv: list[str], port: int) -> subprocess.Popen[bytes]:
    process = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               cwd=Path(TUTORIAL).parent.parent)
    deadline = time.monotonic() + 60
    while True:
        try:
            socket.create_connection(("127.0.0.1", port), timeout=1).close()
            return process
        except OSError:
            if time.monotonic() > deadline:
                process.kill()
                raise
            time.sleep(0.05)


async def _visitor(url: str, start: asyncio.Event, drawn: object, framed: asyncio.Event,
                   finished: asyncio.Event, steps: int = 0) -> tuple[float, list[float]]:
    """One visitor: its first frame's time (``drawn()`` called then); it stays connected,
    reading what comes (the server's pings answered), until ``finished``.  With ``steps``,
    once ``framed`` (every visitor has its first frame) it takes them, each step's answer
    time read, then sets ``finished``."""
    import aiohttp

    async with aiohttp.ClientSession() as session:
        async with session.get(url) as response:
            page = await response.text()
        ws_url = re.search(r'data-session-websocket-url="([^"]+)"', page).group(1)  # type: ignore[union-attr]
        await start.wait()
        async with session.ws_connect(f"{ws_url}?width=120&height=36") as ws:
            opened = time.perf_counter()
            await ws.send_str(json.dumps(["resize", {"width": 120, "height": 36}]))
            await _read_until(ws, lambda t: all(w in t for w in WANT))
            first = time.perf_counter() - opened
            drawn()  # type: ignore[operator]
            await _read_while(ws, framed if steps else finished)
            answers = []
            for k in range(1, steps + 1):
                sent = time.perf_counter()
                await ws.send_str(json.dumps(["stdin", "n"]))
                await _read_until(ws, lambda t, k=k: f"step {k}/" in t)
                answers.append(time.perf_counter() - sent)
            if steps:
                finished.set()
            await ws.send_str(json.dumps(["stdin", "q"]))
            return first, answers


async def _read_while(ws: Any, until: asyncio.Event) -> None:
    """Read (and drop) what the app sends until ``until`` is set."""
    while not until.is_set():
        try:
            await ws.receive(timeout=0.05)
        except asyncio.TimeoutError:
            pass


async def _read_until(ws: object, done: object) -> str:
    import aiohttp

    received = b""
    while not done(_text(received)):  # type: ignore[operator]
        message = await ws.receive(timeout=120)  # type: ignore[attr-defined]
        if message.type != aiohttp.WSMsgType.BINARY:
            raise RuntimeError(f"the websocket closed: {message.type}")
        received += message.data
    return _text(received)


async def _class(url: str, visitors: int, steps: int = 0) -> tuple[list[float], list[float]]:
    """``visitors`` at once (their pages fetched first, their websockets opened together):
    their first frames' times, and the steps' answers of the first, taken once every visitor
    has its first frame (so all are connected)."""
    start, framed, finished = asyncio.Event(), asyncio.Event(), asyncio.Event()
    counted: list[int] = []
    if not steps:
        finished.set()

    def drawn() -> None:
        counted.append(1)
        if len(counted) == visitors:
            framed.set()

    tasks = [asyncio.create_task(_visitor(url, start, drawn, framed, finished,
                                          steps if i == 0 else 0))
             for i in range(visitors)]
    await asyncio.sleep(0.2)  # every page fetched: the websockets open within the second
    start.set()
    results = await asyncio.gather(*tasks)
    return [first for first, _ in results], results[0][1]


def floor_cpu(repeats: int, at_once: int = 1) -> list[float]:
    """CPU seconds of each forked app from the fork to its first frame (the fork server
    alone, asked directly: no server, no websocket): ``at_once`` apps started together,
    ``repeats`` times; each app's CPU read from ``/proc`` as its frame arrives."""
    from tui_search.cli.main import FORK_COMMAND
    from tui_search.serve.visit import Forks
    from tui_search.serve.web import APP_MEMORY_MB

    forks = Forks(FORK_COMMAND, [TUTORIAL, "--served"], APP_MEMORY_MB)
    forks.start()

    async def one() -> tuple[float, Any]:
        app = await forks.open_app(120, 36, None)
        await _read_pipe(app.stdout)
        fields = Path(f"/proc/{app.pid}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / CLOCK_TICKS, app

    async def together() -> list[float]:
        started = await asyncio.gather(*(one() for _ in range(at_once)))
        for _, app in started:  # once every one has its frame
            app.end()
        return [cpu for cpu, _ in started]

    try:
        return [cpu for _ in range(repeats) for cpu in asyncio.run(together())]
    finally:
        forks.stop()


async def _read_pipe(stdout: asyncio.StreamReader) -> None:
    received = b""
    while not all(w in _text(received) for w in WANT):
        chunk = await asyncio.wait_for(stdout.read(65536), 60)
        if not chunk:
            raise RuntimeError("the app ended before its first frame")
        received += chunk


def _server(old: bool, port: int) -> subprocess.Popen[bytes]:
    if old:  # textual-serve as it comes: a fresh ``python -m tui_search`` per visitor
        command = f"exec {sys.executable} -m tui_search --served {TUTORIAL}"
        code = (f"from textual_serve.server import Server; Server({command!r}, "
                f"host='127.0.0.1', port={port}).serve()")
        return _start([sys.executable, "-c", code], port)
    return _start([sys.executable, "-m", "tui_search", "--serve", "--port", str(port),
                   TUTORIAL], port)


def bench_class_load(quick: bool) -> None:
    print("class_load ...", file=sys.stderr, flush=True)
    cpus = os.cpu_count() or 1
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    # The floor first: the visitors' own CPU to their first frames, summed, over the CPUs --
    # for 30 (and 10) started together, as a class's are; one at a time beside it.
    alone_cpu = floor_cpu(3 if quick else 5)
    add(Row("class_load", "an app's own CPU to its first frame, one at a time",
            fmt_time(alone_cpu), f"× 30 ÷ {cpus} CPUs = {med(alone_cpu) * 30 / cpus:.2f} s"))
    floors = {}
    for visitors in (10, 30):
        together = floor_cpu(1, visitors)
        floors[visitors] = sum(together) / cpus
        add(Row("class_load", f"floor: {visitors} apps started together, their own CPU to "
                "their first frames", f"{sum(together):.2f} s (median "
                f"{med(together) * 1e3:.0f} ms)", f"÷ {cpus} CPUs = {floors[visitors]:.2f} s"))
    for old in (False,) if quick else (False, True):
        design = "old: a fresh process per visitor" if old else "fork server"
        port = _free_port()
        server = _server(old, port)
        url = f"http://127.0.0.1:{port}/"
        try:
            alone = [asyncio.run(_class(url, 1))[0][0] for _ in range(3)]
            add(Row("class_load", f"{design}: 1 visitor, first frame", fmt_time(alone),
                    target="baseline"))
            for visitors in ((30,) if old else (10, 30)):
                firsts, steps = asyncio.run(_class(url, visitors, steps=0 if old else 5))
                median, slowest = med(firsts), max(firsts)
                add(Row("class_load", f"{design}: {visitors} visitors, median first frame",
                        f"{median:.2f} s", f"1 alone {med(alone):.2f} s",
                        median / med(alone)))
                judged = visitors == 30 and not old
                least = floors[visitors]
                add(Row("class_load", f"{design}: {visitors} visitors, slowest first frame",
                        f"{slowest:.2f} s", f"floor {least:.2f} s", slowest / least,
                        "≤ 1.5" if judged else "", slowest / least <= 1.5 if judged else None))
                if steps:
                    add(Row("class_load", f"{design}: a step answered, {visitors} connected "
                            "(slowest of 5)", f"{max(steps) * 1e3:.0f} ms "
                            f"(median {med(steps) * 1e3:.0f} ms)", "", None, "≤ 0.5 s",
                            max(steps) <= 0.5))
        finally:
            stop_process(server, signal.SIGINT, 20)
    after = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    add(Row("class_load", "load average (1 min) before / after", f"{load:.1f} / {after:.1f}"))


if __name__ == "__main__":
    bench_class_load("--quick" in sys.argv)
    print_table(ROWS)
