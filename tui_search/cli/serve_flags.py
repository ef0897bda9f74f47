"""The flags of ``--serve``: the server's own (where it listens, where visitors may save, how
much memory an app may use), their checks, and the command line each visitor's app is given
(:func:`served_args`: the teacher's flags, made absolute, with the hidden ``--served``).

The server itself is :mod:`tui_search.serve.web`'s; it is given plain values, never these
flags.
"""

from __future__ import annotations

import argparse
import os
import re
from typing import TYPE_CHECKING

from tui_search.cli.flags import UsageError
from tui_search.engine.maps.graph_file import BUILT_IN
from tui_search.serve.web import APP_MEMORY_MB, DEFAULT_HOST, DEFAULT_PORT

if TYPE_CHECKING:
    from tui_search.cli.options import Options

#: The flags that configure the server, not the visitors' apps.
SERVER_FLAGS = ("serve", "host", "port", "save_dir", "shared_save_dir", "app_memory",
                "token_file")
#: Flags whose value is a file: given to the visitors' apps as absolute paths (``--exercise``
#: only when it names a file, not the tutorial's ``1`` or ``2``).
FILE_FLAGS = ("map", "scen", "terrain")
#: What the served app cannot do (the flags it refuses).
NOT_SERVED = {"headless": "--headless", "json": "--json", "trace": "--trace",
              "plain": "--plain"}
#: How the web extra is installed, from a clone of the project (it is not on PyPI).
NEEDS_EXTRA = "--serve needs textual-serve: in the tui-search folder, pip install -e '.[web]'"


def add_serve_arguments(p: argparse.ArgumentParser) -> None:
    """The serving flags, on the command line's parser."""
    p.add_argument("--serve", action="store_true",
                   help="serve the app to web browsers, one app per visitor (needs the web "
                   "extra: pip install -e '.[web]' in the tui-search folder); visitors "
                   "cannot save or open files")
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
    p.add_argument("--token-file", metavar="FILE", default=None,
                   help="with --serve off loopback: the token the link needs, FILE's first "
                   "line (the servers of one class behind one proxy share it; default: a "
                   "random one)")
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


def check_serve_flags(args: argparse.Namespace) -> None:
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
    if args.token_file is not None:
        read_token(args.token_file, args.host or DEFAULT_HOST)
    if os.name != "posix":
        raise UsageError("--serve needs a Unix-like system (it forks each visitor's app)")
    if not web_extra_installed():
        raise UsageError(NEEDS_EXTRA)


#: A shared token: at least this many characters, each a letter, a digit, ``-`` or ``_`` (as
#: ``secrets.token_urlsafe`` writes them, so it goes in a URL as it is).
TOKEN_LENGTH = 16
_TOKEN = re.compile(r"[A-Za-z0-9_-]+")


def read_token(path: str, host: str) -> str:
    """``--token-file``'s token: the file's first line, stripped; a UsageError (one line) for
    a file that cannot be read, a token too short or with other characters, or a server on
    loopback (which needs none)."""
    from tui_search.engine.util.atomic import os_reason
    from tui_search.engine.util.filenames import describe_name
    from tui_search.serve.guard import is_loopback

    where = f"--token-file {describe_name(path)}"
    if is_loopback(host):
        raise UsageError(f"{where}: a server on {host} (this computer only) needs no token: "
                         "give --host too")
    try:
        with open(path, encoding="utf-8") as file:
            token = file.readline().strip()
    except (OSError, UnicodeDecodeError) as err:
        reason = os_reason(err) if isinstance(err, OSError) else "not a text file"
        raise UsageError(f"{where}: cannot read it: {reason}") from None
    if len(token) < TOKEN_LENGTH or not _TOKEN.fullmatch(token):
        raise UsageError(f"{where}: the first line must be a token of at least "
                         f"{TOKEN_LENGTH} letters, digits, - or _ (python3 -c \"import "
                         "secrets; print(secrets.token_urlsafe(18))\" makes one)")
    return token


def web_extra_installed() -> bool:
    """Is textual-serve there (``pip install -e '.[web]'``)?  Found, not imported."""
    from importlib.util import find_spec  # (this module is imported by every run: lazily)

    return find_spec("textual_serve") is not None


def served_args(parser: argparse.ArgumentParser, options: Options,
                save_folder: str | None) -> list[str]:
    """The command line of one visitor's app (after ``python -m tui_search``): the flags given
    as typed (other than the server's own; ``-a`` only when given), file paths made absolute,
    ``--served``, and ``--save-dir`` as the absolute ``save_folder``."""
    words: list[str] = []
    positional: list[str] = []
    # argparse keeps a parser's actions in ``_actions`` (no public list): reading them here
    # means a flag added to the CLI reaches the served app without a change here.
    for action in parser._actions:
        dest = action.dest
        if dest in ("help", "version", "served", "visitor", *SERVER_FLAGS):
            continue
        value = getattr(options, dest, None)
        if dest == "algorithm" and not options.algorithm_given:
            continue
        if value is None or value is False or value == action.default:
            continue
        built_in = dest == "map" and str(value) in BUILT_IN  # ``romania``: no file
        if (dest in FILE_FLAGS and not built_in) or (
                dest == "exercise" and str(value) not in ("1", "2")):
            value = os.path.abspath(value)
        if not action.option_strings:
            positional.append(str(value))
        elif action.nargs == 0:  # a store_true switch
            words.append(action.option_strings[-1])
        else:
            for item in value if isinstance(value, list) else [value]:
                words += [action.option_strings[-1], str(item)]
    words.append("--served")
    if save_folder is not None:
        words += ["--save-dir", save_folder]
    if positional:
        words += ["--", *positional]
    return words
