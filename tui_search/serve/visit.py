"""One visitor of ``tui-search --serve``: their websocket and their app, from the moment the
page connects to the moment the app has ended.

textual-serve's :class:`~textual_serve.app_service.AppService` relays between the websocket and
an app process; here the process comes from the fork server (:mod:`tui_search.serve.forks`,
started and asked by :class:`Forks`) instead of a shell command, and the websocket's handler
(:func:`visit`) differs from textual-serve's in what a visitor cannot do to the server:

* a terminal size (the page's ``?width=&height=``, a ``["resize", ...]``) is clamped to
  :data:`MAX_WIDTH` x :data:`MAX_HEIGHT`;
* a malformed message is one line in the log (the first of each visitor; the rest are
  ignored), never a traceback;
* however the visit ends (the page closed, the connection dropped -- a heartbeat every
  :data:`HEARTBEAT` seconds notices a silent one -- the server stopping), the app is asked to
  quit and, :data:`QUIT_WAIT` seconds later, ended by the fork server (closing its lease).
"""

from __future__ import annotations

import asyncio
import json
import logging
import os
import signal
import socket
import subprocess
import tempfile
from pathlib import Path
from types import SimpleNamespace
from typing import TYPE_CHECKING, Any, cast

from textual_serve.app_service import AppService

if TYPE_CHECKING:
    from aiohttp import web
    from textual_serve.download_manager import DownloadManager

log = logging.getLogger("textual-serve")

MAX_WIDTH = 500
MAX_HEIGHT = 200
#: Seconds between the server's pings; a visitor who has not answered within half of it is
#: gone (aiohttp closes the websocket).
HEARTBEAT = 2.0
#: Seconds an app asked to quit has before the fork server ends it.
QUIT_WAIT = 1.0
#: Apps starting at once, one a CPU; the next visitors wait their turn (without it, 30 apps
#: starting together share the CPUs and every visitor waits as long as the last).
STARTING = os.cpu_count() or 1
#: An output of this many bytes is the first frame: the app's turn to start is over.
FIRST_FRAME_BYTES = 2048
#: Seconds a starting app may keep its turn, first frame or not.
TURN = 2.0


def clamp(width: object, height: object) -> tuple[int, int]:
    """A terminal size the server accepts: whole numbers within 1..MAX (TypeError or
    ValueError for what is not a number)."""
    if isinstance(width, bool) or isinstance(height, bool):
        raise TypeError("a size is a number")
    w, h = int(cast(Any, width)), int(cast(Any, height))
    return max(1, min(MAX_WIDTH, w)), max(1, min(MAX_HEIGHT, h))


class Forks:
    """The fork server process, and asking it for apps."""

    def __init__(self, command: list[str], app_args: list[str], memory_mb: int) -> None:
        self.command = command  # starts the fork server: SOCKET -- APP-ARGS follow
        self.app_args = app_args
        self.memory_mb = memory_mb
        self.folder = Path(tempfile.mkdtemp(prefix="tui-search-"))
        self.path = str(self.folder / "forks")
        self.process: subprocess.Popen[str] | None = None
        self.turns = asyncio.Semaphore(STARTING)

    def start(self) -> None:
        """Start the fork server; return once it has imported the app and listens."""
        # The environment textual-serve gives an app (its driver, colours...): Textual reads
        # it when imported, which is once, in the fork server.
        env = AppService._build_environment(cast(AppService, SimpleNamespace(debug=False)))
        env["TUI_SEARCH_APP_MEMORY_MB"] = str(self.memory_mb)
        self.process = subprocess.Popen(
            [*self.command, self.path, "--", *self.app_args],
            env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, text=True)
        assert self.process.stdout is not None
        if self.process.stdout.readline() != "ready\n":
            self.process.wait()
            raise RuntimeError("the served app's fork server did not start")

    def stop(self) -> None:
        """End the fork server, which ends every app first."""
        if self.process is not None:
            stop_process(self.process, signal.SIGTERM, 4)
        for leftover in self.folder.iterdir():
            leftover.unlink()
        self.folder.rmdir()

    async def open_app(self, width: int, height: int, visitor: str | None) -> ForkedApp:
        """A new app at this size, with its pipes as asyncio streams."""
        loop = asyncio.get_running_loop()
        (stdin_r, stdin_w), (out_r, out_w), (err_r, err_w) = os.pipe(), os.pipe(), os.pipe()
        lease = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            lease.setblocking(False)
            await loop.sock_connect(lease, self.path)
            request = json.dumps({"width": width, "height": height, "visitor": visitor})
            socket.send_fds(lease, [request.encode()], [stdin_r, out_w, err_w])
            reply = b""
            while not reply.endswith(b"\n"):
                chunk = await loop.sock_recv(lease, 64)
                if not chunk:
                    raise OSError("the fork server did not start an app")
                reply += chunk
        except BaseException:
            lease.close()
            for fd in (stdin_w, out_r, err_r):
                os.close(fd)
            raise
        finally:
            for fd in (stdin_r, out_w, err_w):
                os.close(fd)
        return ForkedApp(int(reply), lease, await _writer(stdin_w), await _reader(out_r),
                         await _reader(err_r))


def stop_process(process: subprocess.Popen[Any], sig: int, timeout: float) -> None:
    """Send ``sig`` to ``process`` if it runs, and wait for it; kill it after ``timeout``."""
    if process.poll() is None:
        process.send_signal(sig)
        try:
            process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


class ForkedApp:
    """What AppService reads of an asyncio subprocess (its pipes), and the lease: closing
    it has the fork server end the app."""

    def __init__(self, pid: int, lease: socket.socket, stdin: asyncio.StreamWriter,
                 stdout: asyncio.StreamReader, stderr: asyncio.StreamReader) -> None:
        self.pid, self.lease = pid, lease
        self.stdin, self.stdout, self.stderr = stdin, stdout, stderr

    def end(self) -> None:
        self.lease.close()
        self.stdin.close()


async def _reader(fd: int) -> asyncio.StreamReader:
    loop = asyncio.get_running_loop()
    reader = asyncio.StreamReader(limit=2**20)
    await loop.connect_read_pipe(lambda: asyncio.StreamReaderProtocol(reader),
                                 os.fdopen(fd, "rb", 0))
    return reader


async def _writer(fd: int) -> asyncio.StreamWriter:
    loop = asyncio.get_running_loop()
    transport, protocol = await loop.connect_write_pipe(
        lambda: asyncio.StreamReaderProtocol(asyncio.StreamReader()), os.fdopen(fd, "wb", 0))
    return asyncio.StreamWriter(transport, protocol, None, loop)


class VisitorApp(AppService):
    """textual-serve's relay, its app from the fork server."""

    def __init__(self, forks: Forks, visitor: str | None, websocket: web.WebSocketResponse,
                 downloads: DownloadManager) -> None:
        super().__init__("(forked)", write_bytes=websocket.send_bytes,
                         write_str=websocket.send_str, close=cast(Any, websocket.close),
                         download_manager=downloads)
        self.forks, self.visitor = forks, visitor
        self.forked: ForkedApp | None = None
        self._turn: asyncio.TimerHandle | None = None

    async def _open_app_process(self, width: int = 80, height: int = 24) -> Any:
        await self.forks.turns.acquire()  # the app's turn to start (STARTING)
        self._turn = asyncio.get_running_loop().call_later(TURN, self._turn_over)
        try:
            self.forked = await self.forks.open_app(width, height, self.visitor)
        except BaseException:
            self._turn_over()
            raise
        self._process = cast(Any, self.forked)
        self._stdin = self.forked.stdin
        return self.forked

    def _turn_over(self) -> None:
        if self._turn is not None:
            self._turn.cancel()
            self._turn = None
            self.forks.turns.release()

    async def on_data(self, payload: bytes) -> None:
        if len(payload) >= FIRST_FRAME_BYTES:
            self._turn_over()
        await super().on_data(payload)

    async def end(self) -> None:
        """Ask the app to quit; end it QUIT_WAIT seconds later if it has not (and at once if
        this is cancelled)."""
        try:
            if self._task is not None:
                await self._download_manager.cancel_app_downloads(
                    app_service_id=self.app_service_id)
                await self.send_meta({"type": "quit"})
                await asyncio.wait_for(asyncio.shield(self._task), QUIT_WAIT)
        except (asyncio.TimeoutError, OSError):
            pass
        finally:
            self._turn_over()
            if self.forked is not None:
                self.forked.end()


async def visit(request: web.Request, forks: Forks, visitor: str | None,
                downloads: DownloadManager) -> web.WebSocketResponse:
    """The websocket of one visitor, relaying to an app of their own (module doc)."""
    from aiohttp import web

    websocket = web.WebSocketResponse(heartbeat=HEARTBEAT)
    try:
        width, height = clamp(request.query.get("width", 80), request.query.get("height", 24))
    except (TypeError, ValueError):
        width, height = 80, 24
    await websocket.prepare(request)
    app = VisitorApp(forks, visitor, websocket, downloads)
    try:
        await app.start(width, height)
        if app._task is not None:  # the app gone (ended, killed): the visit is over
            app._task.add_done_callback(lambda _: asyncio.ensure_future(websocket.close()))
        await relay(websocket, app)
    except asyncio.CancelledError:
        pass
    except Exception as exc:  # noqa: BLE001  (one line, not a traceback with its locals)
        log.error("visitor %s: %s: %s", visitor or "-", type(exc).__name__, exc)
    finally:
        await app.end()
        await websocket.close()
    return websocket


async def relay(websocket: web.WebSocketResponse, app: VisitorApp) -> None:
    """The page's messages to the app, as textual-serve's ``_process_messages`` does, sizes
    clamped and malformed messages logged once."""
    from aiohttp import WSMsgType

    malformed = False
    async for message in websocket:
        if message.type != WSMsgType.TEXT:
            continue
        try:
            envelope = json.loads(message.data)
            if not isinstance(envelope, list):
                raise TypeError("a message is a list")
            kind = envelope[0]
            if kind == "stdin":
                await app.send_bytes(str(envelope[1]).encode("utf-8"))
            elif kind == "resize":
                await app.set_terminal_size(*clamp(envelope[1]["width"],
                                                   envelope[1]["height"]))
            elif kind == "ping":
                await websocket.send_json(["pong", envelope[1]])
            elif kind == "blur":
                await app.blur()
            elif kind == "focus":
                await app.focus()
        except (ValueError, TypeError, KeyError, IndexError) as exc:
            if not malformed:
                malformed = True
                log.warning("visitor %s: a malformed message ignored (%s), and any more: %.60r",
                            app.visitor or "-", type(exc).__name__, message.data)
