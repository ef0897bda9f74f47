"""``tui-search --serve``: the app in web browsers, one app per visitor, with textual-serve
(the optional extra ``tui-search[web]``).

:func:`served_args` builds a visitor's app's command line from the one the teacher typed (the
map, the search flags, the theme) with the hidden ``--served`` flag, which makes that app keep
off the server's files (:class:`~tui_search.tui.model.file_rules.FileAccess`: no saving or opening,
or plain names in ``--save-dir`` only -- in a folder of the visitor's own unless
``--shared-save-dir``) and off the config file (:meth:`~tui_search.tui.config.Config.in_memory`).
The apps are forked by one process that has imported the app once (:mod:`tui_search.serve.forks`);
each visitor's websocket and app are :mod:`tui_search.serve.visit`'s; who may connect at all
is :mod:`tui_search.serve.guard`'s (the host names, the token off loopback).

The server listens on 127.0.0.1 unless ``--host`` says otherwise; its page connects its
websocket to the address the browser used (so ``--host 0.0.0.0`` works from other machines),
and at most :data:`MAX_VISITORS` apps run at once.  No Textual or textual-serve import until
the server starts: the flags are checked first, with the same one-line errors as the rest of
the CLI.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import re
import sys
from typing import TYPE_CHECKING, Any

from tui_search.cli.flags import UsageError

if TYPE_CHECKING:
    from aiohttp import web

    from tui_search.serve.guard import Guard
    from tui_search.tui.model.file_rules import FileAccess

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8000
#: Apps running at once (each is a Python process of some 60 MB): the next visitor is told to
#: try later.  A class fits; a script opening sockets in a loop does not exhaust the machine.
MAX_VISITORS = 60
#: The flags that configure the server, not the visitors' apps.
SERVER_FLAGS = ("serve", "host", "port", "save_dir", "shared_save_dir", "app_memory")
#: Flags whose value is a file: given to the visitors' apps as absolute paths (``--exercise``
#: only when it names a file, not the tutorial's ``1`` or ``2``).
FILE_FLAGS = ("map", "scen", "terrain")
#: What the served app cannot do (the flags it refuses).
NOT_SERVED = {"headless": "--headless", "json": "--json", "trace": "--trace"}
#: A visitor's app using more memory than this (MB) is ended: the tutorial's uses ~40, and a
#: record of 20 million steps (--max-steps' default) some 400.
APP_MEMORY_MB = 1000
#: A visitor's id: the name of their own folder in --save-dir.
VISITOR_ID = re.compile(r"[0-9a-f]{6}")
NEEDS_EXTRA = "--serve needs textual-serve: pip install 'tui-search[web]'"
HOST_HEADER = re.compile(r"^[A-Za-z0-9.\-]+(:[0-9]+)?$|^\[[0-9A-Fa-f:.]+\](:[0-9]+)?$")


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The serving flags, on the CLI's parser."""
    p.add_argument("--serve", action="store_true",
                   help="serve the app to web browsers, one app per visitor (needs "
                   "pip install 'tui-search[web]'); visitors cannot save or open files")
    p.add_argument("--host", default=None,
                   help=f"with --serve: the address to listen on (default {DEFAULT_HOST}: this "
                   "computer only; 0.0.0.0: every network it is on)")
    p.add_argument("--port", type=_port, default=None,
                   help=f"with --serve: the port to listen on (default {DEFAULT_PORT})")
    p.add_argument("--save-dir", metavar="DIR", default=None,
                   help="with --serve: let visitors save and open maps by name in DIR, and "
                   "nowhere else: each visitor in a folder of their own, DIR/ID, the ID shown "
                   "in their app")
    p.add_argument("--shared-save-dir", action="store_true", default=None,
                   help="with --save-dir: every visitor saves in DIR itself (they can "
                   "overwrite each other's maps)")
    p.add_argument("--app-memory", metavar="MB", type=_positive_mb, default=None,
                   help=f"with --serve: end a visitor's app that uses more than MB megabytes "
                   f"(default {APP_MEMORY_MB})")
    p.add_argument("--served", action="store_true", help=argparse.SUPPRESS)  # the visitor's app
    p.add_argument("--visitor", default=None, help=argparse.SUPPRESS)  # the visitor's id


def _positive_mb(text: str) -> int:
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of megabytes")
    return int(text)


def _port(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = 0
    if not 0 < n < 65536:
        raise argparse.ArgumentTypeError(f"{text!r} is not a port (1 to 65535)")
    return n


def check_args(args: argparse.Namespace) -> None:
    """Refuse what makes no sense with --serve (or the server's flags without it)."""
    if not args.serve:
        given = [f"--{f.replace('_', '-')}" for f in SERVER_FLAGS[1:]
                 if getattr(args, f) is not None and not (args.served and f == "save_dir")]
        if given:
            raise UsageError(f"{', '.join(given)} go{'es' if len(given) == 1 else ''} with "
                             "--serve")
        return
    for dest, flag in NOT_SERVED.items():
        if getattr(args, dest):
            raise UsageError(f"--serve serves the app: {flag} is for a search without it")
    if args.served:
        raise UsageError("--served is what --serve gives the visitors' apps: leave it out")
    if args.shared_save_dir and args.save_dir is None:
        raise UsageError("--shared-save-dir goes with --save-dir")
    if os.name != "posix":
        raise UsageError("--serve needs a Unix-like system (it forks each visitor's app)")
    if not web_extra_installed():
        raise UsageError(NEEDS_EXTRA)


def web_extra_installed() -> bool:
    """Is textual-serve there (``pip install 'tui-search[web]'``)?  Found, not imported."""
    from importlib.util import find_spec  # (this module is imported by every run: lazily)

    return find_spec("textual_serve") is not None


def file_access(args: argparse.Namespace) -> FileAccess:
    """Where the app may read and write maps: anywhere, or the served app's rules (in the
    visitor's own folder ``DIR/ID`` when the server gave the app a visitor's id)."""
    from tui_search.tui.model.file_rules import FileAccess, NameRefused

    if not args.served:
        return FileAccess()
    try:
        access = FileAccess.served_in(args.save_dir)
        visitor = getattr(args, "visitor", None)
        if visitor is None or access.folder is None:
            return access
        if not VISITOR_ID.fullmatch(visitor):
            raise NameRefused(f"--visitor {visitor!r}: not a visitor's id")
        own = access.folder / visitor
        own.mkdir(mode=0o700, exist_ok=True)
        return FileAccess.served_in(own)
    except NameRefused as exc:
        raise UsageError(str(exc)) from None


def served_args(parser: argparse.ArgumentParser, args: argparse.Namespace) -> list[str]:
    """The command line of one visitor's app (after ``python -m tui_search``): the flags given
    (other than the server's own), file paths made absolute, ``--served``, and ``--save-dir``
    as an absolute path."""
    words: list[str] = []
    positional: list[str] = []
    # argparse keeps a parser's actions in ``_actions`` (no public list): reading them here
    # means a flag added to the CLI reaches the served app without a change here.
    for action in parser._actions:
        dest = action.dest
        if dest in ("help", "version", "served", "visitor", *SERVER_FLAGS):
            continue
        value = getattr(args, dest, None)
        if value is None or value is False or value == action.default:
            continue
        if dest in FILE_FLAGS or (dest == "exercise" and str(value) not in ("1", "2")):
            value = os.path.abspath(value)
        if not action.option_strings:
            positional.append(str(value))
        elif action.nargs == 0:  # a store_true switch
            words.append(action.option_strings[-1])
        else:
            for item in value if isinstance(value, list) else [value]:
                words += [action.option_strings[-1], str(item)]
    words.append("--served")
    access = file_access(argparse.Namespace(served=True, save_dir=args.save_dir))
    if access.folder is not None:
        words += ["--save-dir", str(access.folder)]
    if positional:
        words += ["--", *positional]
    return words


def greet_visitor(app: Any, args: argparse.Namespace) -> None:
    """Tell a visitor with a folder of their own its name (their id), once the app is up."""
    if args.visitor is not None and args.save_dir is not None:
        app.call_later(app.notify, f"You are visitor {args.visitor}: your maps are saved in "
                       f"a folder of your own, {args.visitor}.", title="Welcome", timeout=20)


#: How often a served app checks that its server is still there (seconds).
WATCH_EVERY = 0.5
#: How long it then has to exit by itself before it is ended.
GRACE = 3.0


def exit_with_server(app: Any, every: float = WATCH_EVERY) -> None:
    """End the served ``app`` when the process that started it is gone (killed, crashed):
    else it would run on with no visitor, and a Textual app whose output pipe is gone can
    spin on a core (seen: 37 % of one for 40 minutes).  A daemon thread watches the parent
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


def serve(parser: argparse.ArgumentParser, args: argparse.Namespace, title: str) -> int:
    """Serve until Ctrl+C; 0, or 2 when the address cannot be listened on."""
    if args.theme is None:  # the teacher's remembered theme, for every visitor
        from tui_search.tui.config import Config

        args.theme = Config.load().theme
    host = args.host or DEFAULT_HOST
    port = args.port or DEFAULT_PORT
    folder = file_access(argparse.Namespace(served=True, save_dir=args.save_dir)).folder
    from tui_search.serve.guard import Guard

    server = make_server(served_args(parser, args), host, port, title,
                         saving=str(folder) if folder is not None else None,
                         own_folders=not args.shared_save_dir,
                         memory_mb=args.app_memory or APP_MEMORY_MB,
                         guard=Guard.for_host(host))
    try:
        server.serve()
    except OSError as exc:
        raise UsageError(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None
    return 0
def make_server(app_args: list[str], host: str, port: int, title: str,
                saving: str | None = None, *, own_folders: bool = True,
                memory_mb: int = APP_MEMORY_MB, guard: Guard | None = None,
                max_visitors: int = MAX_VISITORS) -> Any:
    """A textual-serve Server for the app ``app_args`` (after ``python -m tui_search``), with
    the classroom's rules (module doc)."""
    import logging
    import secrets

    import aiohttp_jinja2
    import jinja2
    from aiohttp import web
    from textual_serve.server import Server

    from tui_search.serve.guard import Guard
    from tui_search.serve.visit import Forks, visit

    rules = guard or Guard.for_host(host)
    own_url = f"http://{_url_host(host)}:{port}"
    forks = Forks(app_args, memory_mb)

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
            print(banner_text(host, port, title, saving, own_folders, rules.token),
                  flush=True)

    visits: set[asyncio.Task[Any]] = set()
    return ClassroomServer(" ".join(app_args), host=host, port=port,
                           title=f"tui-search: {title}")


def banner_text(host: str, port: int, title: str, saving: str | None, own_folders: bool,
                token: str | None) -> str:
    """What the server prints once it listens: where, who can reach it, what visitors may
    do with files, how to stop it."""
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
        lines.append(f"Open http://THIS-COMPUTER'S-ADDRESS:{port}{query} in the class's "
                     "browsers (and allow the port through the firewall).")
    if token:
        who = ("every computer on this computer's networks" if every
               else f"every computer that can reach {host}")
        lines.append(f"Warning: {who} can reach port {port}; only a browser given the link "
                     "with its token can open an app.")
    lines.append("Press Ctrl+C to stop.")
    return "\n".join(lines)


def _url_host(host: str) -> str:
    return f"[{host}]" if ":" in host else host
