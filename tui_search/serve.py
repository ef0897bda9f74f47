"""``tui-search --serve``: the app in web browsers, one app per visitor, with textual-serve
(the optional extra ``tui-search[web]``).

textual-serve starts a process per visitor from a command line.  :func:`served_command`
builds it from the command line the teacher typed (the map, the search flags, the theme), as
``python -m tui_search ... --served``, quoted with :mod:`shlex`; the hidden ``--served`` flag
makes that app keep off the server's files (:class:`~tui_search.tui.file_access.FileAccess`:
no saving or opening, or plain names in ``--save-dir`` only) and off the config file
(:meth:`~tui_search.tui.config.Config.in_memory`).

The server listens on 127.0.0.1 unless ``--host`` says otherwise; its page connects its
websocket to the address the browser used (so ``--host 0.0.0.0`` works from other machines);
a websocket opened by another site's page (a different ``Origin``) is refused, and at most
:data:`MAX_VISITORS` apps run at once.  No Textual or textual-serve import until the server
starts: the flags are checked first, with the same one-line errors as the rest of the CLI.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from typing import TYPE_CHECKING, Any

from tui_search.flags import UsageError

if TYPE_CHECKING:
    from aiohttp import web

    from tui_search.tui.file_access import FileAccess

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8000
#: Apps running at once (each is a Python process of some 60 MB): the next visitor is told to
#: try later.  A class fits; a script opening sockets in a loop does not exhaust the machine.
MAX_VISITORS = 60
#: The flags that configure the server, not the visitors' apps.
SERVER_FLAGS = ("serve", "host", "port", "save_dir")
#: Flags whose value is a file: given to the visitors' apps as absolute paths.
FILE_FLAGS = ("map", "scen")
#: What the served app cannot do (the flags it refuses).
NOT_SERVED = {"headless": "--headless", "json": "--json", "trace": "--trace"}
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
                   "nowhere else")
    p.add_argument("--served", action="store_true", help=argparse.SUPPRESS)  # the visitor's app


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
    if not web_extra_installed():
        raise UsageError(NEEDS_EXTRA)


def web_extra_installed() -> bool:
    """Is textual-serve there (``pip install 'tui-search[web]'``)?  Found, not imported."""
    from importlib.util import find_spec  # (this module is imported by every run: lazily)

    return find_spec("textual_serve") is not None


def file_access(args: argparse.Namespace) -> FileAccess:
    """Where the app may read and write maps: anywhere, or the served app's rules."""
    from tui_search.tui.file_access import FileAccess, NameRefused

    if not args.served:
        return FileAccess()
    try:
        return FileAccess.served_in(args.save_dir)
    except NameRefused as exc:
        raise UsageError(str(exc)) from None


def served_command(parser: argparse.ArgumentParser, args: argparse.Namespace,
                   python: str = sys.executable) -> str:
    """The shell command that starts one visitor's app: the flags given (other than the
    server's own), file paths made absolute, ``--served``, and ``--save-dir`` as an absolute
    path; every word quoted."""
    words = [python, "-m", "tui_search"]
    positional: list[str] = []
    # argparse keeps a parser's actions in ``_actions`` (no public list): reading them here
    # means a flag added to the CLI reaches the served app without a change here.
    for action in parser._actions:
        dest = action.dest
        if dest in ("help", "version", "served", *SERVER_FLAGS):
            continue
        value = getattr(args, dest, None)
        if value is None or value is False or value == action.default:
            continue
        if dest in FILE_FLAGS:
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
    if os.name == "nt":  # textual-serve runs it in cmd.exe there, which has its own quoting
        import subprocess

        return subprocess.list2cmdline(words)
    import shlex

    # exec: the app replaces the shell, so it is the server's own child (exit_with_server).
    return "exec " + shlex.join(words)


#: How often a served app checks that its server is still there (seconds).
WATCH_EVERY = 0.5
#: How long it then has to exit by itself before it is ended.
GRACE = 3.0


def exit_with_server(app: Any, every: float = WATCH_EVERY) -> None:
    """End the served ``app`` when the server that started it is gone (killed, crashed):
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
    command = served_command(parser, args)
    host = args.host or DEFAULT_HOST
    port = args.port or DEFAULT_PORT
    folder = file_access(argparse.Namespace(served=True, save_dir=args.save_dir)).folder
    server = make_server(command, host, port, title,
                         saving=str(folder) if folder is not None else None)
    try:
        server.serve()
    except OSError as exc:
        raise UsageError(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None
    return 0


def make_server(command: str, host: str, port: int, title: str, saving: str | None = None,
                max_visitors: int = MAX_VISITORS) -> Any:
    """A textual-serve Server for ``command``, with the classroom's rules (module doc)."""
    from aiohttp import web
    from textual_serve.server import Server

    own_url = f"http://{_url_host(host)}:{port}"

    class ClassroomServer(Server):
        visitors = 0

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
            origin = request.headers.get("Origin")
            if origin is not None and origin.split("://", 1)[-1] != request.host:
                raise web.HTTPForbidden(text="another site's page may not open an app")
            if self.visitors >= max_visitors:
                raise web.HTTPServiceUnavailable(text="too many visitors: try again later")
            ClassroomServer.visitors += 1
            try:
                return await super().handle_websocket(request)
            finally:
                ClassroomServer.visitors -= 1

        def serve(self, debug: bool = False) -> None:
            # textual-serve's own serve(), but the banner once the port is listened on
            # (aiohttp's ``print``), and aiohttp's handling of Ctrl+C and SIGTERM.
            self.debug = debug
            self.initialize_logging()
            web.run_app(self._make_app(), host=self.host, port=self.port,
                        print=self.banner)

        async def on_startup(self, app: web.Application) -> None:
            pass  # not textual-serve's logo and command line: the banner says what matters

        def banner(self, _aiohttp_says: str) -> None:
            files = (f"visitors may save and open maps in {saving} only" if saving
                     else "visitors cannot save or open files")
            if host in ("0.0.0.0", "::"):
                print(f"Serving tui-search ({title}) on port {port} of every network this "
                      f"computer is on — one app per visitor, {files}.", flush=True)
                print(f"Open http://THIS-COMPUTER'S-ADDRESS:{port} in the class's browsers "
                      "(and allow the port through the firewall).", flush=True)
            else:
                print(f"Serving tui-search ({title}) on {own_url} — one app per visitor, "
                      f"{files}.", flush=True)
            print("Press Ctrl+C to stop.", flush=True)

    return ClassroomServer(command, host=host, port=port, title=f"tui-search: {title}")


def _url_host(host: str) -> str:
    return f"[{host}]" if ":" in host else host
