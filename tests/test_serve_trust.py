"""What a visitor cannot do to ``tui-search --serve`` (issue 21, "The served app"): sizes are
clamped, no app outlives its visitor, a runaway app is ended, only the server's own host
names (and, off loopback, its token) are answered, no folder listing, a malformed message is
one line in the log, each visitor saves in a folder of their own.  Real servers on free local
ports, driven by aiohttp and by hand-made websockets (tests/served.py)."""

from __future__ import annotations

import asyncio
import contextlib
import json
import re
import signal
import socket
import struct
import time
from pathlib import Path

import aiohttp
import pytest

from tests.helpers import MAPS
from tests.served import (
    apps_of,
    descendants,
    first_screen,
    frame,
    raw_websocket,
    running,
    screen_text,
    served,
    wait_for,
)

TUTORIAL = str(MAPS / "tutorial.txt")
pytestmark = pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc")
MOVE = re.compile(r"\x1b\[(\d+);(\d+)H")


async def open_app(url: str, query: str = "width=100&height=30", *,
                   resize: tuple[int, int] | None = None, then=None) -> str:
    """Open the page's app, read its output until the first frame (the footer's "Quit"),
    then await ``then(ws)`` if given; the output's text with its escapes."""
    async with aiohttp.ClientSession(cookie_jar=aiohttp.CookieJar(unsafe=True)) as session:
        async with session.get(url) as response:
            page = await response.text()
        ws_url = re.search(r'data-session-websocket-url="([^"]+)"', page).group(1)
        async with session.ws_connect(f"{ws_url}?{query}") as ws:
            if resize:
                await ws.send_str(json.dumps(["resize", {"width": resize[0],
                                                         "height": resize[1]}]))
            received = b""
            while "Quit" not in screen_text(received):
                message = await ws.receive(timeout=30)
                assert message.type == aiohttp.WSMsgType.BINARY, message
                received += message.data
            if then is not None:
                await then(ws)
            return received.decode("utf-8", "replace")


# -- sizes ----------------------------------------------------------------------------------


def test_sizes_are_clamped() -> None:
    from tui_search.serve.visit import MAX_HEIGHT, MAX_WIDTH, clamp

    assert clamp(100000, 100000) == (MAX_WIDTH, MAX_HEIGHT) == (500, 200)
    assert clamp("120", -5) == (120, 1)
    for bad in (("x", 1), (None, 1), (True, 5), ([], 1)):
        with pytest.raises((TypeError, ValueError)):
            clamp(*bad)


def test_a_huge_terminal_asked_for_is_drawn_at_most_500_by_200() -> None:
    """The page's ?width=&height= and its ["resize", ...] at 100000: the app draws no row
    past 200 nor column past 500, and stays small."""
    with served(TUTORIAL) as server:
        peak: list[int] = []

        async def rss_after_resize(ws) -> None:
            """Resize again, then watch the app's resident size for two seconds of its
            output (the old app grew 25-48 MB a second drawing 100000 x 100000)."""
            await ws.send_str(json.dumps(["resize", {"width": 100000, "height": 100000}]))
            (app,) = apps_of(server)
            until = time.monotonic() + 2.0
            while time.monotonic() < until:
                with contextlib.suppress(asyncio.TimeoutError):
                    await ws.receive(timeout=0.25)
                peak.append(int(Path(f"/proc/{app}/statm").read_text().split()[1]) * 4096)

        output = asyncio.run(open_app(server.url, "width=100000&height=100000",
                                      resize=(100000, 100000), then=rss_after_resize))
        moves = [(int(y), int(x)) for y, x in MOVE.findall(output)]
        assert moves and max(y for y, _ in moves) <= 200 and max(x for _, x in moves) <= 500
        assert max(y for y, _ in moves) > 100  # it did grow to what it was allowed
        assert peak and max(peak) < 100 * 2**20, f"{max(peak) / 2**20:.0f} MB resident"


# -- no app outlives its visitor --------------------------------------------------------------


def test_an_app_ends_within_5_s_of_its_visitor_closing_the_page() -> None:
    with served(TUTORIAL) as server:
        apps: list[int] = []

        async def note(ws) -> None:
            apps.extend(apps_of(server))

        asyncio.run(open_app(server.url, then=note))
        assert len(apps) == 1
        assert wait_for(lambda: not running(apps[0]), 5) < 5


def test_an_app_ends_within_5_s_of_its_visitors_connection_dropping() -> None:
    """The connection reset (no websocket close), and one that just falls silent."""
    with served(TUTORIAL) as server:
        for silent in (False, True):
            sock = raw_websocket(server.url)
            wait_for(lambda: apps_of(server), 30)
            (app,) = apps_of(server)
            if not silent:
                sock.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
                sock.close()  # a reset
            wait_for(lambda a=app: not running(a), 5)
            sock.close()


@pytest.mark.skipif(not __import__("shutil").which("chromium"), reason="no chromium")
def test_a_headless_chromium_screenshot_visit_leaves_no_app(tmp_path) -> None:
    import subprocess

    from tests.browser_check import FLAGS

    with served(TUTORIAL) as server:
        subprocess.run(["chromium", *FLAGS, f"--user-data-dir={tmp_path / 'profile'}",
                        f"--screenshot={tmp_path / 'x.png'}", "--window-size=800,600",
                        server.url], check=False, capture_output=True, timeout=120)
        wait_for(lambda: not apps_of(server), 5)


def test_an_app_over_its_memory_limit_is_ended_with_one_line_in_the_log() -> None:
    with served(TUTORIAL, "--app-memory", "20") as server:
        with pytest.raises((AssertionError, aiohttp.ClientError, asyncio.TimeoutError)):
            asyncio.run(open_app(server.url))  # ended before or soon after its first frame
        wait_for(lambda: not apps_of(server), 5)
        log = server.log()
    said = [line for line in log.splitlines() if "MB of memory" in line]
    assert len(said) == 1 and said[0].startswith("tui-search: a visitor's app (process ")
    assert said[0].endswith("used more than 20 MB of memory: ended"), said
    assert "Traceback" not in log


def test_ctrl_c_stops_the_server_within_5_s_and_leaves_no_process() -> None:
    with served(TUTORIAL) as server:
        socks = [raw_websocket(server.url) for _ in range(2)]
        wait_for(lambda: len(apps_of(server)) == 2, 30)
        everyone = descendants(server.process.pid)
        start = time.monotonic()
        server.process.send_signal(signal.SIGINT)
        server.process.wait(timeout=10)
        assert time.monotonic() - start < 5
        assert len(everyone) == 3 and not [pid for pid in everyone if running(pid)]
        for sock in socks:
            sock.close()


# -- who may connect ----------------------------------------------------------------------------


async def status(url: str, host: str | None = None, origin: str | None = None,
                 websocket: bool = False, cookies: dict[str, str] | None = None) -> int:
    headers = {k: v for k, v in (("Host", host), ("Origin", origin)) if v}
    async with aiohttp.ClientSession(cookies=cookies) as session:
        if websocket:
            try:
                async with session.ws_connect(url, headers=headers):
                    return 101
            except aiohttp.WSServerHandshakeError as refused:
                return refused.status
        async with session.get(url, headers=headers) as response:
            return response.status


def test_only_the_servers_own_host_names_are_answered() -> None:
    """DNS rebinding: another name pointed at 127.0.0.1 gets 403, page and websocket."""
    with served() as server:
        port = server.url.rsplit(":", 1)[1].strip("/")
        ws = server.url.replace("http", "ws") + "ws"
        evil = f"evil.example:{port}"
        assert asyncio.run(status(server.url, host=evil)) == 403
        assert asyncio.run(status(ws, host=evil, origin=f"http://{evil}", websocket=True)) == 403
        assert asyncio.run(status(server.url + "static/css/xterm.css", host=evil)) == 403
        for good in (f"localhost:{port}", f"127.0.0.1:{port}", f"[::1]:{port}"):
            assert asyncio.run(status(server.url, host=good)) == 200, good
        assert asyncio.run(status(ws, origin="http://evil.example", websocket=True)) == 403


def test_the_guards_names() -> None:
    from tui_search.serve.guard import Guard, host_name

    assert host_name("[::1]:80") == "::1" and host_name("LocalHost.:8000") == "localhost"
    local = Guard.for_host("127.0.0.1")
    assert local.token is None and not local.host_allowed("10.0.0.5:80")
    named = Guard.for_host("teacher.lan")
    assert named.token and named.host_allowed("teacher.lan:8000")
    assert not named.host_allowed("evil.example") and not named.host_allowed("10.0.0.5")
    every = Guard.for_host("0.0.0.0")
    assert every.token and every.host_allowed("192.168.1.20:8000")
    assert every.host_allowed("[fe80::1]:8000") and not every.host_allowed("evil.example")


def test_off_loopback_a_token_is_required_then_carried_by_a_cookie() -> None:
    with served("--host", "0.0.0.0") as server:
        assert server.token and "Warning: every computer on this computer's networks can " \
            "reach port" in server.banner
        assert f"?token={server.token}" in server.banner
        ws = server.url.replace("http", "ws") + "ws"
        assert asyncio.run(status(server.url)) == 403
        assert asyncio.run(status(server.url + "?token=wrong")) == 403
        assert asyncio.run(status(ws, websocket=True)) == 403
        assert asyncio.run(status(server.url + "static/css/xterm.css")) == 403
        assert asyncio.run(status(server.page)) == 200
        cookie = {"tui_search_token": server.token}
        assert asyncio.run(status(server.url + "static/css/xterm.css", cookies=cookie)) == 200
        _, screen = asyncio.run(first_screen(server.page, "Quit"))  # the page's cookie
        assert "tutorial" in screen


def test_the_static_folder_is_not_listed_but_its_files_are_served() -> None:
    with served() as server:
        assert asyncio.run(status(server.url + "static/")) == 404
        assert asyncio.run(status(server.url + "static/js/")) == 404
        assert asyncio.run(status(server.url + "static/js/textual.js")) == 200


# -- malformed messages ------------------------------------------------------------------------


def test_malformed_messages_are_one_line_in_the_log_and_the_app_goes_on() -> None:
    with served(TUTORIAL) as server:
        async def send_garbage(ws) -> None:
            for bad in ("not json", "[]", "{}", '["resize"]', '["resize", {"width": "x"}]',
                        '["resize", {"width": 5}]', '["stdin"]', "[1, 2]", "null"):
                await ws.send_str(bad)
            await ws.send_bytes(b"\xff\x00")
            await ws.send_str(json.dumps(["stdin", "?"]))  # the help: the app still answers
            received = b""
            while "Help" not in screen_text(received):
                received += (await ws.receive(timeout=30)).data

        asyncio.run(open_app(server.url, then=send_garbage))
        sock = raw_websocket(server.url)  # a frame no websocket has: opcode 3
        sock.sendall(frame(3, b"??") + frame(1, b"\xff\xfe"))
        sock.settimeout(30)
        with contextlib.suppress(OSError):  # the server reads the frames, then hangs up
            while sock.recv(65536):
                pass
        sock.close()
        wait_for(lambda: not apps_of(server), 5)
        log = server.log()
    said = [line for line in log.splitlines() if "malformed" in line]
    assert len(said) == 1 and said[0].startswith("visitor -: a malformed message ignored ("), log
    assert "Traceback" not in log and "locals" not in log, log


# -- each visitor's own folder ----------------------------------------------------------------


def test_each_visitor_saves_in_a_folder_of_their_own_named_in_their_app(tmp_path) -> None:
    with served(TUTORIAL, "--save-dir", str(tmp_path)) as server:
        assert "each in a folder of their own" in server.banner
        ids = []
        for _ in range(3):
            _, screen = asyncio.run(first_screen(server.url, "You are visitor"))
            ids += re.findall(r"You are visitor ([0-9a-f]{6}):", screen)
        assert len(set(ids)) == 3
        assert sorted(p.name for p in tmp_path.iterdir()) == sorted(ids)


def test_a_shared_save_dir_is_one_folder_for_all(tmp_path) -> None:
    with served(TUTORIAL, "--save-dir", str(tmp_path), "--shared-save-dir") as server:
        assert "each in a folder" not in server.banner
        _, screen = asyncio.run(first_screen(server.url, "Quit"))
        assert "You are visitor" not in screen
    assert list(tmp_path.iterdir()) == []


def test_a_visitors_folder_is_made_by_the_app_from_its_id(tmp_path) -> None:
    from tui_search.tui.model.file_rules import FileAccess, NameRefused

    access = FileAccess.for_app(True, str(tmp_path), "0a1b2c")
    assert access.folder == (tmp_path / "0a1b2c").resolve() and access.folder.is_dir()
    with pytest.raises(NameRefused, match="not a visitor's id"):
        FileAccess.for_app(True, str(tmp_path), "../x")
    assert FileAccess.for_app(False, str(tmp_path), "0a1b2c") == FileAccess()


def test_servers_behind_one_proxy_share_the_token_of_their_token_file(tmp_path: Path) -> None:
    """Two servers started with one ``--token-file`` (as behind a proxy, docs/06-browser.md):
    each prints that token and opens an app with it, reached by an address the student typed
    (the proxy passes it as ``Host``); another token is refused by both."""
    token = "class-of-2026_" + "x" * 10
    (tmp_path / "class.token").write_text(token + "\n")
    flags = ("--host", "0.0.0.0", "--token-file", str(tmp_path / "class.token"))
    with served(*flags) as first, served(*flags) as second:
        for server in (first, second):
            assert server.token == token and f"?token={token}" in server.banner
            assert asyncio.run(status(server.url + "?token=" + "y" * 24)) == 403
            assert asyncio.run(status(server.url, host="10.1.2.3:80",
                                      cookies={"tui_search_token": token})) == 200
            _, screen = asyncio.run(first_screen(server.page, "Quit"))
            assert "tutorial" in screen


@pytest.mark.parametrize(("flags", "message"), [
    (["--token-file", "{tmp}/gone"], "cannot read it: no such file"),
    (["--token-file", "{tmp}/short"], "the first line must be a token of at least 16"),
    (["--token-file", "{tmp}/short", "--host", "127.0.0.1"], "needs no token: give --host"),
])
def test_a_bad_token_file_is_one_line(capsys, tmp_path: Path, flags: list[str],
                                      message: str) -> None:
    from tests.test_cli import run_cli

    (tmp_path / "short").write_text("abc\n")
    argv = [f.format(tmp=tmp_path) for f in flags]
    if "--host" not in argv:
        argv += ["--host", "0.0.0.0"]
    code, out, err = run_cli(capsys, "--serve", *argv)
    assert (code, out) == (2, "") and message in err and err.count("\n") == 1
    code, _, err = run_cli(capsys, "--token-file", str(tmp_path / "short"))
    assert code == 2 and "--token-file goes with --serve" in err
