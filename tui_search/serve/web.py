"""``tui-search --serve``: the app in web browsers, one app per visitor, with textual-serve
(the optional extra ``web``: ``pip install -e '.[web]'`` in the project's folder).

The server is given plain values: each visitor's app's command line (the command line's
:func:`~tui_search.cli.serve_flags.served_args` makes it from the one the teacher typed, with
the hidden ``--served`` flag, which makes that app keep off the server's files
(:class:`~tui_search.tui.model.file_rules.FileAccess`: no saving or opening, or plain names in
``--save-dir`` only -- in a folder of the visitor's own unless ``--shared-save-dir``) and off
the config file (:meth:`~tui_search.tui.config.Config.in_memory`)), where to listen, and where
visitors may save.  The apps are forked by one process that has imported the app once
(:mod:`tui_search.serve.forks`);
each visitor's websocket and app are :mod:`tui_search.serve.visit`'s; who may connect at all
is :mod:`tui_search.serve.guard`'s (the host names, the token off loopback).

The server listens on 127.0.0.1 unless ``--host`` says otherwise; its page connects its
websocket to the address the browser used (so ``--host 0.0.0.0`` works from other machines),
and at most :data:`MAX_VISITORS` apps run at once.  No Textual or textual-serve import until
the server starts: the flags are checked first, with the same one-line errors as the rest of
the CLI.
"""

from __future__ import annotations

import asyncio
import os
import re
import sys
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Sequence

    from aiohttp import web

    from tui_search.serve.addresses import Address
    from tui_search.serve.guard import Guard

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8000
#: Apps running at once (each is a Python process; benchmarks/README.md, "limits"): the next
#: visitor is told to try later.  A class fits; a script opening sockets in a loop does not
#: exhaust the machine.
MAX_VISITORS = 60
#: A visitor's app using more memory than this (MB) is ended: far above the tutorial's, and
#: above a record of --max-steps' default (benchmarks/README.md, "limits").
APP_MEMORY_MB = 1000
HOST_HEADER = re.compile(r"^[A-Za-z0-9.\-]+(:[0-9]+)?$|^\[[0-9A-Fa-f:.]+\](:[0-9]+)?$")


class ServeError(Exception):
    """The server could not start (the address cannot be listened on): one line, exit 2."""


def greet_visitor(app: Any, visitor: str | None, save_dir: str | None) -> None:
    """Tell a visitor with a folder of their own its name (their id), once the app is up."""
    if visitor is not None and save_dir is not None:
        app.call_later(app.notify, f"You are visitor {visitor}: your maps are saved in "
                       f"a folder of your own, {visitor}.", title="Welcome", timeout=20)


#: How often a served app checks that its server is still there (seconds).
WATCH_EVERY = 0.5
#: How long it then has to exit by itself before it is ended.
GRACE = 3.0


def exit_with_server(app: Any, every: float = WATCH_EVERY) -> None:
    """End the served ``app`` when the process that started it is gone (killed, crashed):
    else it would run on with no visitor, and a Textual app whose output pipe is gone can
    spin on a core (seen: a third of one, for most of an hour).  A daemon thread watches the parent
    process; once this process is re-parented it asks the app to exit and, should it not
    within :data:`GRACE` seconds, ends the process."""
    import threading
    import time

    parent = os.getppid()

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(every)
        threading.Timer(GRACE, os._exit, (0,)).start()
        app.call_from_thread(app.exit)

    threading.Thread(target=watch, name="exit-with-server", daemon=True).start()


def serve(app_args: list[str], fork_command: list[str], *, host: str | None,
          port: int | None, title: str, save_folder: str | None, own_folders: bool,
          memory_mb: int | None, token: str | None = None, records: str | None = None) -> int:
    """Serve the app ``app_args`` until Ctrl+C, each visitor's app forked by the process
    ``fork_command`` starts; 0, or a ServeError when the address cannot be listened on.
    ``token``: the one the links need off loopback (None: a random one); ``records``: the
    records folder, shown on the teacher's page."""
    from tui_search.serve.guard import Guard

    host = host or DEFAULT_HOST
    port = port or DEFAULT_PORT
    server = make_server(app_args, fork_command, host, port, title, saving=save_folder,
                         own_folders=own_folders, memory_mb=memory_mb or APP_MEMORY_MB,
                         guard=Guard.for_host(host, token), records=records)
    try:
        server.serve()
    except OSError as exc:
        raise ServeError(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None
    return 0


def make_server(app_args: list[str], fork_command: list[str], host: str, port: int, title: str,
                saving: str | None = None, *, own_folders: bool = True,
                memory_mb: int = APP_MEMORY_MB, guard: Guard | None = None,
                max_visitors: int = MAX_VISITORS, records: str | None = None,
                teacher: str | None = None) -> Any:
    """A textual-serve Server for the app ``app_args`` (after ``python -m tui_search``), with
    the classroom's rules (module doc); with ``records``, the teacher's page
    (:mod:`tui_search.serve.teacher`), its token ``teacher`` (None: a random one)."""
    import logging
    import secrets

    import aiohttp_jinja2
    import jinja2
    from aiohttp import web
    from textual_serve.server import Server

    from tui_search.serve.guard import Guard
    from tui_search.serve.teacher import teacher_routes_of
    from tui_search.serve.visit import Forks, visit

    rules, teacher_key, teacher_routes = teacher_routes_of(
        guard or Guard.for_host(host), records, teacher, title)
    own_url = f"http://{_url_host(host)}:{port}"
    forks = Forks(fork_command, app_args, memory_mb)

    class ClassroomServer(Server):
        visitors = 0

        def initialize_logging(self) -> None:
            # One line a record: not textual-serve's rich tracebacks with local variables.
            logging.basicConfig(level="INFO", format="%(message)s", stream=sys.stdout)

        async def _make_app(self) -> web.Application:
            # textual-serve's routes, behind the guard, and no listing of the static folder.
            app = web.Application(middlewares=[rules.middleware()])
            aiohttp_jinja2.setup(app, loader=jinja2.FileSystemLoader(self.templates_path))
            app.add_routes([
                web.get("/", self.handle_index, name="index"),
                web.get("/ws", self.handle_websocket, name="websocket"),
                web.get("/download/{key}", self.handle_download, name="download"),
                *teacher_routes,
                web.static("/static", self.statics_path, show_index=False, name="static"),
            ])
            app.on_shutdown.append(self.on_shutdown)
            return app

        async def handle_index(self, request: web.Request) -> web.StreamResponse:
            # textual-serve writes its public URL into the page as the websocket's address;
            # the one the browser used is the one that reaches this server from there.  (No
            # await between setting it and the page using it: no other request sees it.)
            if HOST_HEADER.match(request.host):
                self.public_url = f"{request.scheme}://{request.host}"
            else:  # not an address: the one listened on
                self.public_url = own_url
            return await super().handle_index(request)

        async def handle_websocket(self, request: web.Request) -> web.WebSocketResponse:
            if self.visitors >= max_visitors:
                raise web.HTTPServiceUnavailable(text="too many visitors: try again later")
            ClassroomServer.visitors += 1
            task = asyncio.current_task()
            if task is not None:
                visits.add(task)
            try:
                visitor = secrets.token_hex(3) if saving and own_folders else None
                return await visit(request, forks, visitor, self.download_manager)
            finally:
                if task is not None:
                    visits.discard(task)
                ClassroomServer.visitors -= 1

        async def on_shutdown(self, app: web.Application) -> None:
            for task in list(visits):  # every visit ends, its app with it
                task.cancel()

        def serve(self, debug: bool = False) -> None:
            # textual-serve's own serve(), but the banner once the port is listened on
            # (aiohttp's ``print``), aiohttp's handling of Ctrl+C and SIGTERM, and the fork
            # server around it.
            self.debug = debug
            self.initialize_logging()
            forks.start()
            try:
                web.run_app(self._make_app(), host=self.host, port=self.port,
                            print=self.banner, shutdown_timeout=1.0)
            finally:
                forks.stop()

        async def on_startup(self, app: web.Application) -> None:
            pass  # not textual-serve's logo and command line: the banner says what matters

        def banner(self, _aiohttp_says: str) -> None:
            print(banner_text(host, port, title, saving, own_folders, rules.token,
                              teacher=teacher_key), flush=True)

    visits: set[asyncio.Task[Any]] = set()
    return ClassroomServer(" ".join(app_args), host=host, port=port,
                           title=f"tui-search: {title}")


def banner_text(host: str, port: int, title: str, saving: str | None, own_folders: bool,
                token: str | None, addresses: Sequence[Address] | None = None,
                teacher: str | None = None) -> str:
    """What the server prints once it listens: where, who can reach it, what visitors may
    do with files, the teacher's page (``teacher``: its token; None: no page), how to stop
    it.  Served on every network, a link for each of this computer's ``addresses`` (found
    when not given), the loopback last."""
    files = "visitors cannot save or open files"
    if saving:
        files = (f"visitors may save and open maps in {saving} only"
                 + (", each in a folder of their own" if own_folders else ""))
    query = f"/?token={token}" if token else ""
    every = host in ("0.0.0.0", "::")
    where = (f"port {port} of every network this computer is on" if every
             else f"http://{_url_host(host)}:{port}{query}")
    lines = [f"Serving tui-search ({title}) on {where} — one app per visitor, {files}."]
    if every:
        if addresses is None:
            import socket

            from tui_search.serve.addresses import own_addresses

            addresses = own_addresses(socket.AF_INET6 if ":" in host else socket.AF_INET)
        lines.append("Open the link for the class's network in their browsers (and allow the "
                     "port through the firewall):")
        links = [f"http://{_url_host(a.ip)}:{port}{query}" for a in addresses]
        wide = max(map(len, links), default=0)
        for a, link in zip(addresses, links, strict=True):
            on = "this computer only" if a.is_loopback else ""
            said = ": ".join(part for part in (a.interface, on) if part)
            lines.append(f"  {link:<{wide}}  ({said})" if said else f"  {link}")
    if teacher is not None:
        from tui_search.serve.teacher import teacher_url

        base = (f"http://{_url_host(addresses[0].ip)}:{port}" if every and addresses
                else f"http://{_url_host('127.0.0.1' if every else host)}:{port}")
        lines.append("The teacher's page, the class's records live (this link is printed "
                     "once: keep it to yourself, it is not the class's):")
        lines.append(teacher_url(base, teacher))
    if token:
        who = ("every computer on this computer's networks" if every
               else f"every computer that can reach {host}")
        lines.append(f"Warning: {who} can reach port {port}; only a browser given the link "
                     "with its token can open an app.")
    lines.append("Press Ctrl+C to stop.")
    return "\n".join(lines)


def _url_host(host: str) -> str:
    return f"[{host}]" if ":" in host else host
