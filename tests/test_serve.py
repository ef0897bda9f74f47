"""``tui-search --serve``: the flags it refuses, the command each visitor's app is started
with, where a served app may read and write (tested as plain functions), and a real server on
a free local port whose page and websocket deliver the app's first screen."""

from __future__ import annotations

import asyncio
import os
import re
import sys
from pathlib import Path

import pytest

from tests.helpers import MAPS, flags_of
from tests.served import descendants, first_screen, running, served, visit, wait_for
from tests.test_cli import run_cli
from tui_search.cli.flags import EXIT_BAD_INPUT
from tui_search.cli.main import FORK_COMMAND
from tui_search.cli.options import FLAGS, Options
from tui_search.cli.parse import parse_options
from tui_search.cli.parser import build_parser
from tui_search.cli.serve_flags import NEEDS_EXTRA, SERVER_FLAGS, served_args
from tui_search.tui.config import Config, config_path
from tui_search.tui.model.file_rules import OFF_MESSAGE, FileAccess, NameRefused

TUTORIAL = str(MAPS / "tutorial.txt")


# -- the command line -------------------------------------------------------------------


@pytest.mark.parametrize(("argv", "says"), [
    (["--serve", "--headless"], "--serve serves the app: --headless is for a search without it"),
    (["--serve", "--json"], "--json is for a search without it"),
    (["--serve", "--trace", "t.jsonl"], "--trace is for a search without it"),
    (["--serve", "--served"], "--served is what --serve gives the visitors' apps"),
    (["--host", "0.0.0.0"], "--host goes with --serve"),
    (["--port", "9000", "--save-dir", "."], "--port, --save-dir go with --serve"),
    (["--serve", "--port", "0"], "'0' is not a port (1 to 65535)"),
    (["--serve", "--port", "http"], "'http' is not a port"),
    (["--serve", "--save-dir", "no/such/folder"], "--save-dir 'no/such/folder': not a folder"),
    (["--serve", "--headless", "--compare", "bfs,dfs"], "--headless is for a search without it"),
    (["--serve", "no-such-map.txt"], "no-such-map.txt"),
    (["--serve", "--replay", "t.jsonl"], "--replay shows one trace beside one search in the app"),
])
def test_nonsense_with_serve_is_one_line_and_exit_2(capsys, argv: list[str], says: str) -> None:
    code, out, err = run_cli(capsys, *argv)
    assert code == EXIT_BAD_INPUT and out == ""
    assert err.count("\n") == 1 and says in err, err


def test_without_the_web_extra_serve_says_how_to_get_it(capsys, monkeypatch) -> None:
    import tui_search.cli.serve_flags

    monkeypatch.setattr(tui_search.cli.serve_flags, "web_extra_installed", lambda: False)
    code, out, err = run_cli(capsys, "--serve")
    assert (code, out, err) == (EXIT_BAD_INPUT, "", f"tui-search: error: {NEEDS_EXTRA}\n")


def parse(*argv: str) -> Options:
    return flags_of(*argv)


def visitors_args(options: Options, save_folder: str | None = None) -> list[str]:
    return served_args(build_parser(), options, save_folder)


def test_the_served_apps_command_line_carries_the_apps_flags_and_none_of_the_servers(
        tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)  # a relative map becomes an absolute path
    (tmp_path / "my map's copy.txt").write_text(Path(TUTORIAL).read_text())
    (tmp_path / "saves").mkdir()
    args = parse("my map's copy.txt", "-a", "astar", "--heuristic", "octile", "--theme",
                 "light", "--order", "N,E,S,W", "--tree-search", "--max-steps", "500",
                 "--serve", "--host", "0.0.0.0", "--port", "9999", "--save-dir", "saves",
                 "--app-memory", "300")
    words = visitors_args(args, str((tmp_path / "saves").resolve()))
    assert words[-2:] == ["--", str(tmp_path / "my map's copy.txt")]
    app_args = parse(*words)
    assert app_args.served and app_args.save_dir == str((tmp_path / "saves").resolve())
    for dest in FLAGS:
        value = getattr(args, dest)
        if dest in ("map", "served", *SERVER_FLAGS):
            continue
        assert getattr(app_args, dest) == value, dest
    assert not app_args.serve and app_args.host is None and app_args.port is None
    assert app_args.app_memory is None and app_args.visitor is None


def test_the_served_apps_open_the_built_in_graph_by_its_name(tmp_path, monkeypatch) -> None:
    """``--serve romania``: each visitor's app opens the built-in Romania (not a file called
    romania), a graph file by its absolute path."""
    monkeypatch.chdir(tmp_path)
    words = visitors_args(parse("romania", "-a", "astar", "--serve"))
    assert words[-2:] == ["--", "romania"]
    app_args = parse_options(words)
    assert app_args.graph is not None and app_args.graph.start == "Arad"
    graph = tmp_path / "g.graph"
    graph.write_text("edge A B\nstart A\ngoal B\n")
    words = visitors_args(parse("g.graph", "--serve"))
    assert words[-2:] == ["--", str(graph)]
    assert parse_options(words).graph is not None


@pytest.mark.parametrize("exercise", ["1", "class.toml"])
def test_the_served_apps_get_the_terrain_and_exercise_files_as_absolute_paths(
        tmp_path, monkeypatch, exercise: str) -> None:
    monkeypatch.chdir(tmp_path)
    words = visitors_args(parse("--terrain", "t.txt", "--exercise", exercise, "--serve"))
    app_args = parse(*words)
    assert app_args.terrain == str(tmp_path / "t.txt")
    assert app_args.exercise == (exercise if exercise == "1" else str(tmp_path / exercise))


EXERCISE_FILE = str(Path(__file__).parent / "data" / "exercises" / "greedy-not-optimal.toml")


@pytest.mark.parametrize("argv", [
    ["--exercise", "1"], ["--exercise", "2"], ["--exercise", EXERCISE_FILE],
    ["--compare", "bfs,dfs"], ["--compare", "greedy,astar:manhattan", "--order", "N,E,S,W"],
    [], ["-a", "dfs"], [TUTORIAL],
])
def test_the_served_apps_accept_the_command_line_the_server_gives_them(
        capsys, monkeypatch, argv: list[str]) -> None:
    """Through main, as typed: its checks fill in -a's default, which --exercise and --compare
    refuse; the served app must pass the same checks (the fork server parses them)."""
    import tui_search.serve.web

    started: list[list[str]] = []

    class NoServer:
        def serve(self) -> None:
            pass

    def make_server(app_args: list[str], *_a: object, **_k: object) -> NoServer:
        started.append(app_args)
        return NoServer()

    monkeypatch.setattr(tui_search.serve.web, "make_server", make_server)
    code, _, err = run_cli(capsys, *argv, "--serve", "--theme", "dark")
    assert (code, err) == (0, ""), err
    (app_args,) = started
    visitors = parse_options(app_args)  # no UsageError
    assert visitors.served
    assert visitors.exercise == (argv[1] if "--exercise" in argv else None)


def test_the_web_extra_is_found_without_importing_it() -> None:
    from tui_search.cli.serve_flags import web_extra_installed

    assert web_extra_installed()  # the test extra brings it


def test_the_served_apps_command_line_without_a_save_dir_or_map() -> None:
    assert visitors_args(parse("--serve")) == ["--served"]


def test_a_name_reaches_the_app_as_one_word(tmp_path) -> None:
    name = tmp_path / "$(touch pwned); `touch pwned2` && rm -rf x.txt"
    assert visitors_args(parse(str(name), "--serve"))[-1] == str(name)


# -- where a served app may read and write ---------------------------------------------


def test_a_served_app_without_a_save_dir_touches_no_file(tmp_path) -> None:
    access = FileAccess.served_in(None)
    assert access.off == OFF_MESSAGE
    with pytest.raises(NameRefused, match="off in the served app"):
        access.path_for("map.txt")
    assert not access.may_save_over(tmp_path / "map.txt")


def test_the_terminal_app_takes_any_path() -> None:
    access = FileAccess()
    assert access.off is None
    assert access.path_for("  ~/maps/x.txt ") == Path("~/maps/x.txt").expanduser()
    assert access.path_for("../x") == Path("../x")
    assert access.may_save_over(Path("/anywhere/x.map"))


@pytest.mark.parametrize("typed", [
    "../escape.txt", "..", ".", "/etc/passwd.txt", "sub/x.txt", "sub\\x.txt", "~/x.txt",
    ".hidden.txt", "", "   ", "x.sh", "x.txt.sh", "x" * 81 + ".txt", "a\x00b.txt", "a\nb.txt",
    "x:y.txt", "link-out.txt", "link-in.txt", "a\x7fb.txt", "a\x85b.txt", "\u202etxt.map",
    "a\u2066b.txt", "a\u200fb.txt", "a\u200bb.txt", "a\u2028b.txt",
])
def test_names_that_could_leave_the_folder_are_refused(tmp_path, typed: str) -> None:
    folder = tmp_path / "saves"
    folder.mkdir()
    (tmp_path / "outside.txt").write_text("S.G\n")
    (folder / "link-out.txt").symlink_to(tmp_path / "outside.txt")
    (folder / "inside.txt").write_text("S.G\n")
    (folder / "link-in.txt").symlink_to(folder / "inside.txt")  # a link at all: refused
    access = FileAccess.served_in(folder)
    with pytest.raises(NameRefused) as refused:
        access.path_for(typed)
    assert "\n" not in str(refused.value).replace(repr(typed), "")


def test_a_folder_that_is_a_link_is_used_as_where_it_leads(tmp_path) -> None:
    real = tmp_path / "real"
    real.mkdir()
    (tmp_path / "alias").symlink_to(real)
    access = FileAccess.served_in(tmp_path / "alias")
    assert access.folder == real.resolve()
    assert access.path_for("  My map-2_b.TXT ") == real.resolve() / "My map-2_b.TXT"
    assert access.path_for("den.map") == real.resolve() / "den.map"


def test_ctrl_s_saves_over_only_a_file_in_the_folder(tmp_path) -> None:
    folder = (tmp_path / "saves")
    folder.mkdir()
    access = FileAccess.served_in(folder)
    assert access.may_save_over(folder.resolve() / "mine.txt")
    assert not access.may_save_over(Path(TUTORIAL))  # the map the teacher served
    assert not access.may_save_over(folder.resolve() / ".." / "mine.txt")
    assert access.suggestion(Path(TUTORIAL)) == "tutorial.txt"
    assert access.open_suggestion(Path(TUTORIAL)) == ""


def test_a_served_apps_config_is_never_written(tmp_path) -> None:
    config = Config.in_memory()
    assert config.save_theme("light") is None and config.theme == "light"
    assert not config_path().exists()
    assert Config.load().theme is None


# -- a real server ------------------------------------------------------------------------


def test_the_page_and_its_websocket_deliver_the_apps_first_screen() -> None:
    with served(TUTORIAL, "-a", "dfs") as server:
        assert "visitors cannot save or open files" in server.banner
        assert server.url.startswith("http://127.0.0.1:")
        page, screen = asyncio.run(first_screen(server.url, "Quit"))
        assert f'data-session-websocket-url="ws://{server.url[7:]}ws"' in page
        assert "tui-search: tutorial.txt" in page
        assert "tutorial.txt" in screen and "Stack (LIFO)" in screen  # -a dfs reached the app
        # A second visitor gets an app of their own.
        _, again = asyncio.run(first_screen(server.url, "Quit"))
        assert "(0,0) START" in again
    assert server.process.wait() == 0  # Ctrl+C stops it cleanly


def test_an_exercise_is_served() -> None:
    """``--exercise 1 --serve``: the visitor's app starts with the exercise (no traceback)."""
    with served("--exercise", "1") as server:
        _, screen = asyncio.run(first_screen(server.url, "Exercise 1"))
        assert "Traceback" not in screen
    assert server.process.wait() == 0


def test_keys_typed_in_the_page_reach_the_served_app_which_will_not_save() -> None:
    """ctrl+s, as the page sends it, in the served app: "Not available" (its one line)."""
    with served(TUTORIAL) as server:
        _, (_, saved) = asyncio.run(visit(server.url, [("", "Quit"),
                                                       ("\x13", "Not available")]))
        assert "Saving and opening" in saved


def test_the_page_sends_its_websocket_to_the_address_the_browser_used(tmp_path: Path) -> None:
    """Served on ``localhost``, opened as 127.0.0.1 (as a classroom opens a 0.0.0.0 server by
    the computer's address): the page's websocket goes to 127.0.0.1 too.  (The save folder is
    a temporary one: the visitor's own folder is made in it.)"""
    with served("--host", "localhost", "--save-dir", str(tmp_path)) as server:
        assert server.banner.startswith("Serving tui-search (tutorial (built-in)) on "
                                        "http://localhost:")
        assert f"visitors may save and open maps in {tmp_path.resolve()} only" in server.banner
        page, _ = asyncio.run(first_screen(server.url, "Quit"))
        assert f'data-session-websocket-url="ws://{server.url[7:]}ws"' in page


def test_the_banner_for_every_network_links_each_address_with_the_token_loopback_last() -> None:
    from tui_search.serve.addresses import Address
    from tui_search.serve.web import banner_text

    found = [Address("192.168.1.20", "wlan0"), Address("10.0.0.7", "eth0"),
             Address("127.0.0.1", "lo")]
    assert banner_text("0.0.0.0", 8123, "tutorial.txt", None, True, "T0K",
                       found).splitlines() == [
        ("Serving tui-search (tutorial.txt) on port 8123 of every network this computer is on "
         "— one app per visitor, visitors cannot save or open files."),
        ("Open the link for the class's network in their browsers (and allow the port "
         "through the firewall):"),
        "  http://192.168.1.20:8123/?token=T0K  (wlan0)",
        "  http://10.0.0.7:8123/?token=T0K      (eth0)",
        "  http://127.0.0.1:8123/?token=T0K     (lo: this computer only)",
        ("Warning: every computer on this computer's networks can reach port 8123; only a "
         "browser given the link with its token can open an app."),
        "Press Ctrl+C to stop.",
    ]
    six = banner_text("::", 80, "t", None, True, "T", [Address("fd00::2", "eth0"),
                                                        Address("::1")])
    assert six.splitlines()[2:4] == ["  http://[fd00::2]:80/?token=T  (eth0)",
                                     "  http://[::1]:80/?token=T      (this computer only)"]
    assert banner_text("10.1.2.3", 80, "t", "/s", False, "T").splitlines()[:2] == [
        ("Serving tui-search (t) on http://10.1.2.3:80/?token=T — one app per visitor, "
         "visitors may save and open maps in /s only."),
        ("Warning: every computer that can reach 10.1.2.3 can reach port 80; only a browser "
         "given the link with its token can open an app."),
    ]


def test_this_computers_addresses_are_found_each_once_loopback_last() -> None:
    """The real call: at least the loopback, last; no link-local or repeated address; the
    fallback (the name's and the route's addresses) never fails either."""
    import ipaddress
    import socket

    from tui_search.serve.addresses import Address, _by_name_and_route, loopback_last, own_addresses

    for family, loopback in ((socket.AF_INET, "127.0.0.1"), (socket.AF_INET6, "::1")):
        found = own_addresses(family)
        assert found[-1].ip == loopback, found
        ips = [ipaddress.ip_address(a.ip) for a in found]
        assert len(set(ips)) == len(ips) and not any(ip.is_link_local for ip in ips)
        assert all(ip.version == (4 if family == socket.AF_INET else 6) for ip in ips)
        assert all(isinstance(a, Address) for a in _by_name_and_route(family))
    assert loopback_last([Address("127.0.0.1"), Address("fe80::1"), Address("10.0.0.1"),
                          Address("10.0.0.1", "again")]) == [Address("10.0.0.1"),
                                                             Address("127.0.0.1")]


def test_another_sites_page_may_not_open_an_app() -> None:
    import aiohttp

    with served() as server:
        with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
            asyncio.run(first_screen(server.url, "Quit", origin="http://evil.example"))
        assert refused.value.status == 403
        _, screen = asyncio.run(first_screen(server.url, "tutorial (built-in)",
                                             origin=server.url.rstrip("/")))
        assert "Quit" in screen


def test_a_port_in_use_is_one_line_and_exit_2() -> None:
    import subprocess

    with served() as server:
        port = server.url.rsplit(":", 1)[1].strip("/")
        second = subprocess.run([sys.executable, "-m", "tui_search", "--serve", "--port", port],
                                check=False, capture_output=True, text=True, timeout=60)
    assert second.returncode == EXIT_BAD_INPUT, second
    assert second.stdout == ""
    assert second.stderr.startswith(f"tui-search: error: cannot listen on 127.0.0.1:{port}: ")
    assert second.stderr.count("\n") == 1


# -- the browser check's judgement of a screenshot ---------------------------------------


def png(width: int, height: int, colour_at) -> bytes:
    """An RGB PNG, each row with filter 0 but the second (filter 2: "up"), as Chromium's
    encoder varies its filters."""
    import struct
    import zlib

    raw = bytearray()
    prev = bytes(width * 3)
    for y in range(height):
        line = bytes(c for x in range(width) for c in colour_at(x, y))
        if y == 1:
            raw += b"\x02" + bytes((a - b) & 255 for a, b in zip(line, prev, strict=True))
        else:
            raw += b"\x00" + line
        prev = line

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(
            ">I", zlib.crc32(kind + body))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height,
                                                              8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(bytes(raw))) + chunk(b"IEND", b""))


def test_the_browser_check_tells_the_app_from_a_blank_or_starting_page() -> None:
    from tests.browser_check import BACKGROUND, GOAL, WALL, judge, png_pixels

    starting = png(40, 20, lambda x, y: (0x0C, 0x18, 0x1F))
    assert "not the app's light page: the most common colours are #0c181f 100%" in judge(
        starting)
    assert "no map" in judge(png(40, 20, lambda x, y: BACKGROUND))

    def app(x: int, y: int) -> tuple[int, int, int]:
        return WALL if x < 4 else GOAL if (x, y) == (10, 10) else BACKGROUND

    shot = png(40, 20, app)
    assert png_pixels(shot)[2][:5] == [WALL] * 4 + [BACKGROUND]
    assert judge(shot) is None


def test_past_the_visitor_limit_the_next_visitor_is_told_to_try_later() -> None:
    """In process (the limit is not a flag): with room for none, the websocket gets 503."""
    import aiohttp
    from aiohttp.test_utils import TestClient, TestServer

    from tui_search.serve.web import make_server

    async def visit() -> int:
        server = make_server(["--served"], FORK_COMMAND, "127.0.0.1", 8000, "t",
                             max_visitors=0)
        async with TestClient(TestServer(await server._make_app())) as client:
            with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
                await client.ws_connect("/ws")
            return refused.value.status

    assert asyncio.run(visit()) == 503


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc (Linux)")
def test_a_visitors_app_ends_when_the_server_is_killed() -> None:
    """A server that dies without stopping its apps (SIGKILL, a crash) leaves none running
    5 s later: its fork server ends them, and each app exits once it is re-parented."""
    import signal

    with served(TUTORIAL) as server:
        async def open_app_then_kill_the_server() -> list[int]:
            import aiohttp

            async with aiohttp.ClientSession() as session:
                async with session.get(server.url) as response:
                    page = await response.text()
                ws_url = re.search(r'data-session-websocket-url="([^"]+)"', page).group(1)
                async with session.ws_connect(ws_url + "?width=100&height=32") as ws:
                    await ws.receive(timeout=30)  # the app is up
                    apps = descendants(server.process.pid)
                    server.process.send_signal(signal.SIGKILL)
                    server.process.wait()
                    return apps

        apps = asyncio.run(open_app_then_kill_the_server())
    try:
        assert len(apps) == 2  # the fork server and the app
        assert "tui_search" in Path(f"/proc/{apps[1]}/cmdline").read_text()
        wait_for(lambda: not any(running(pid) for pid in apps), 5)
    finally:  # a failure leaves nothing behind
        for pid in apps:
            if running(pid):
                os.kill(pid, signal.SIGKILL)
