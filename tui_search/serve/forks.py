"""The served app's fork server: one process that imports Python's modules, Textual and the
app once, then forks a visitor's app for each request, so that a visitor's start-up is only
the app's own first frame (a class of 30 connecting at once shares the imports instead of
paying them 30 times on two cores).

``tui-search --serve`` starts it as ``python -m tui_search.cli.fork_entry SOCKET -- APP-ARGS``
(the app's command line, :func:`tui_search.cli.serve_flags.served_args`; the command line's
entry gives :func:`main` its ways to build and run an app) with textual-serve's environment for
apps (Textual reads its driver from it when imported).  The server asks for an app over the
unix socket ``SOCKET``: one message of JSON (the terminal's size, the visitor's id) carrying the
app's stdin, stdout and stderr (:func:`socket.send_fds`); the reply is the app's process id.
That connection is the app's lease: when the server closes it (the visitor has gone, however
they left) or the server dies, the app is ended -- asked with SIGTERM, killed
:data:`KILL_AFTER` seconds later.  A visitor's app using more than the memory limit (its
resident size, read from ``/proc`` every :data:`WATCH_EVERY` seconds) is killed with one line
on the server's log.  SIGINT or SIGTERM ends every app, then the fork server.
"""

from __future__ import annotations

import json
import os
import selectors
import signal
import socket
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

#: Makes the app of a command line (not run): the command line's way, given to the fork server.
AppBuilder = Callable[[list[str]], Any]
#: Runs the app of a command line to its end: its exit code.
AppMain = Callable[[list[str]], int]

#: How often the fork server looks at its apps' memory and at its own parent (seconds).
WATCH_EVERY = 0.25
#: How long an app asked to end (SIGTERM) has before it is killed.
KILL_AFTER = 1.5
_PAGE = os.sysconf("SC_PAGE_SIZE") if hasattr(os, "sysconf") else 4096


def preload(app_args: list[str], build_app: AppBuilder) -> None:
    """Import what every visitor's app imports, and run the app once, headless, for what it
    builds on its first run and keeps (Textual's parsed CSS, the modules imported late):
    each visitor's app then starts from there.  ``build_app`` makes the app of a command
    line (the command line's own way)."""
    import asyncio
    import threading

    from tui_search.engine.util.collector import collector_paused

    with collector_paused():
        import textual.drivers.web_driver  # noqa: F401  (the served app's driver)

        # What the app imports on first use, not before its first frame (an exercise shown,
        # code shown): imported here once, for every visitor.
        import tui_search.engine.course.grading
        import tui_search.engine.search.pseudocode  # noqa: F401

        app = build_app(app_args)

    async def first_frame() -> None:
        async with app.run_test(size=(120, 36)) as pilot:
            await pilot.pause()

    asyncio.run(first_frame())
    if threading.active_count() != 1:  # forking copies one thread only
        raise RuntimeError("threads left running before the first fork")


def run_app(app_args: list[str], fds: list[int], request: dict[str, object],
            app_main: AppMain) -> int:
    """In the forked child: the visitor's app on the fds given, at the size asked, run by
    ``app_main`` (the command line's ``main``)."""
    for target, fd in enumerate(fds):
        os.dup2(fd, target)
        os.close(fd)
    os.environ["COLUMNS"] = str(request["width"])
    os.environ["ROWS"] = str(request["height"])
    visitor = request.get("visitor")
    args = [*app_args]
    if isinstance(visitor, str):
        args[:0] = ["--visitor", visitor]
    return app_main(args)


class ForkServer:
    """The accept loop, the apps it forked (pid -> lease connection) and their ends."""

    def __init__(self, listener: socket.socket, app_args: list[str], memory_mb: int,
                 app_main: AppMain) -> None:
        self.listener = listener
        self.app_args = app_args
        self.app_main = app_main
        self.memory = memory_mb * 1024 * 1024
        self.memory_mb = memory_mb
        self.parent = os.getppid()
        self.apps: dict[int, socket.socket] = {}
        self.ending: dict[int, float] = {}  # pid -> when to kill it
        self.selector = selectors.DefaultSelector()
        self.selector.register(listener, selectors.EVENT_READ)
        self.stopping = False

    def serve(self) -> None:
        while not self.stopping and os.getppid() == self.parent:
            for key, _ in self.selector.select(WATCH_EVERY):
                if key.fileobj is self.listener:
                    self.accept()
                else:
                    self.lease_ended(key.fileobj, key.data)  # type: ignore[arg-type]
            self.reap()
            self.watch()
        self.end_all()

    def accept(self) -> None:
        try:
            conn, _ = self.listener.accept()
        except OSError:
            return
        try:
            conn.settimeout(5)
            message, fds, _, _ = socket.recv_fds(conn, 4096, 3)
            request = json.loads(message)
            if len(fds) != 3 or not isinstance(request, dict):
                raise ValueError("a request is JSON and three fds")
        except (OSError, ValueError):
            conn.close()
            return
        pid = os.fork()
        if pid == 0:  # the visitor's app
            code = 1
            try:
                self.selector.close()
                self.listener.close()
                conn.close()
                for lease in self.apps.values():
                    lease.close()
                for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGCHLD):
                    signal.signal(sig, signal.SIG_DFL)
                code = run_app(self.app_args, fds, request, self.app_main)
            finally:
                os._exit(code)
        for fd in fds:
            os.close(fd)
        try:
            conn.sendall(f"{pid}\n".encode())
        except OSError:
            pass
        self.apps[pid] = conn
        self.selector.register(conn, selectors.EVENT_READ, pid)

    def lease_ended(self, conn: socket.socket, pid: int) -> None:
        """The server closed the app's connection (or wrote to it: either means end it)."""
        self.selector.unregister(conn)
        self.end(pid)

    def end(self, pid: int) -> None:
        if pid in self.ending:
            return
        self.ending[pid] = time.monotonic() + KILL_AFTER
        _signal(pid, signal.SIGTERM)

    def reap(self) -> None:
        while self.apps:
            try:
                pid, _ = os.waitpid(-1, os.WNOHANG)
            except ChildProcessError:
                return
            if pid == 0:
                break
            self.ending.pop(pid, None)
            conn = self.apps.pop(pid, None)
            if conn is not None:
                try:
                    self.selector.unregister(conn)
                except (KeyError, ValueError):
                    pass
                conn.close()
        now = time.monotonic()
        for pid, deadline in list(self.ending.items()):
            if now >= deadline:
                _signal(pid, signal.SIGKILL)

    def watch(self) -> None:
        """Kill an app over the memory limit, with one line on the log."""
        for pid in list(self.apps):
            if pid in self.ending:
                continue
            try:
                resident = int(Path(f"/proc/{pid}/statm").read_text().split()[1]) * _PAGE
            except (OSError, ValueError, IndexError):
                continue
            if resident > self.memory:
                print(f"tui-search: a visitor's app (process {pid}) used more than "
                      f"{self.memory_mb} MB of memory: ended", file=sys.stderr, flush=True)
                self.ending[pid] = time.monotonic()
                _signal(pid, signal.SIGKILL)

    def end_all(self) -> None:
        """Every app asked to end, killed if it has not within KILL_AFTER, all reaped."""
        for pid in list(self.apps):
            self.end(pid)
        deadline = time.monotonic() + KILL_AFTER + 1
        while self.apps and time.monotonic() < deadline:
            self.reap()
            time.sleep(0.02)
        for pid in list(self.apps):
            _signal(pid, signal.SIGKILL)
        for pid in list(self.apps):
            try:
                os.waitpid(pid, 0)
            except ChildProcessError:
                pass


def _signal(pid: int, sig: int) -> None:
    try:
        os.kill(pid, sig)
    except ProcessLookupError:
        pass


def main(argv: list[str], build_app: AppBuilder, app_main: AppMain) -> int:
    """The fork server's process: ``argv`` is ``SOCKET -- APP-ARGS``; ``build_app`` makes the
    app of a command line (for the preload), ``app_main`` runs one (in each fork)."""
    path, app_args = argv[0], argv[argv.index("--") + 1:]
    from tui_search.serve.web import APP_MEMORY_MB

    memory_mb = int(os.environ.get("TUI_SEARCH_APP_MEMORY_MB", APP_MEMORY_MB))
    preload(app_args, build_app)
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(path)
    listener.listen(64)
    server = ForkServer(listener, app_args, memory_mb, app_main)

    def stop(_sig: int, _frame: object) -> None:
        server.stopping = True

    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGTERM, stop)
    import gc

    gc.freeze()  # what is imported now is shared with every app, not copied by the collector
    print("ready", flush=True)
    server.serve()
    return 0

