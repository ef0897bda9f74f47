"""Reading what someone else wrote (a student's trace, a teacher's exercise, a map from the
web) without trusting it: its text decoded strictly, and its JSON or TOML parsed only once it
is known to be shallow and small enough.

Python's ``json`` and ``tomllib`` recurse into nested arrays (a ``RecursionError`` at ~1,000
levels), ``tomllib`` takes memory quadratic in the parts of a dotted key, and every parser
makes an object of tens of bytes for each ``[]`` of ``[],[],[]``.  So each is given its text only
after :func:`check_nesting` (and for JSON :func:`check_values`) passed it: a pass over the text
that keeps no objects, most often two ``str.count`` calls.

Every problem is a :class:`BadInput`: one line, and the line and column (from 1) where they
apply; a reader puts its file's name on it
(:func:`tui_search.engine.maps.read.bad_file`).  CONTRIBUTING.md, "Untrusted files", says
how a new reader joins the tests of hostile input.
"""

from __future__ import annotations

import re
from typing import Any

__all__ = ["MAX_DEPTH", "BadInput", "check_nesting", "check_values", "decode_text", "load_json",
           "position"]

#: Arrays and objects (tables) nested deeper than this are refused: none of the app's files
#: needs more than four levels.
MAX_DEPTH = 100
#: What a parsed JSON value may cost in memory for each separator, bracket or brace of its
#: text (a list or dict object and the pointer to it; a small string or number and its
#: pointer), in bytes: an upper bound for :func:`check_values`.
VALUE_BYTES = 80


class BadInput(ValueError):
    """What is wrong with an input, in one line, and where: ``line`` and ``col`` from 1."""

    def __init__(self, message: str, line: int | None = None, col: int | None = None) -> None:
        super().__init__(message, line, col)
        self.message, self.line, self.col = message, line, col

    def __str__(self) -> str:
        return self.message


def position(text: str, offset: int) -> tuple[int, int]:
    """The line and column (from 1) of character ``offset`` of ``text``."""
    start = text.rfind("\n", 0, offset) + 1
    return text.count("\n", 0, start) + 1, offset - start + 1


def decode_text(data: bytes, what: str) -> str:
    """``data`` as UTF-8 text with no NUL, or a :class:`BadInput` at the first bad byte
    (``what``: the kind of file, as the message says it: "a map")."""
    nul = data.find(b"\x00")
    if nul >= 0:
        raise BadInput(f"binary file (a NUL byte), not {what}", *_byte_position(data, nul))
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        where = _byte_position(data, exc.start)
        raise BadInput(f"not UTF-8 (byte 0x{data[exc.start]:02x}): {what} is UTF-8 text",
                       *where) from None


def _byte_position(data: bytes, offset: int) -> tuple[int, int]:
    """The line and column (in characters, from 1) of byte ``offset`` of ``data``."""
    start = data.rfind(b"\n", 0, offset) + 1
    before = data[start:offset].decode("utf-8", "replace")
    return data.count(b"\n", 0, start) + 1, len(before) + 1


# What the nesting pass reads: strings and comments (whose brackets do not count), brackets,
# and for TOML the dots of dotted keys and the newlines that end them.  Each string's body is
# one character at a time (``[^"\\]|\\.``): never two ways to match, so never a slow match.
_JSON_TOKENS = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}]', re.DOTALL)
_TOML_TOKENS = re.compile(
    r'"""(?:[^"\\]|\\.|"(?!""))*"""'
    r"|'''(?:[^']|'(?!''))*'''"
    r'|"(?:[^"\\\n]|\\.)*"'
    r"|'[^'\n]*'"
    r"|#[^\n]*"
    r"|[\[\]{}.\n]",
    re.DOTALL,
)


def check_nesting(text: str, depth: int = MAX_DEPTH, *, toml: bool = False) -> None:
    """Refuse ``text`` whose arrays and objects (TOML: arrays and tables) nest more than
    ``depth`` deep, at the bracket that goes too deep; for TOML also a line with more than
    ``depth`` dots outside strings and comments (a dotted key of so many parts: ``tomllib``
    keeps a table for each part's prefix).  Brackets in strings do not count.  Time linear
    in the text; nothing is kept."""
    dots = toml and text.count(".") > depth
    if text.count("[") + text.count("{") <= depth and not dots:
        return  # (most files: nothing can be too deep)
    level = line_dots = 0
    for token in (_TOML_TOKENS if toml else _JSON_TOKENS).finditer(text):
        kind = token.group()
        if kind in ("[", "{"):
            level += 1
            if level > depth:
                raise BadInput(f"nested more than {depth} deep", *position(text, token.start()))
        elif kind in ("]", "}"):
            level = max(0, level - 1)
        elif kind == ".":
            line_dots += 1
            if line_dots > depth:
                raise BadInput(f"more than {depth} dots on one line outside strings (a key "
                               f"of more than {depth} parts)", *position(text, token.start()))
        elif kind == "\n":
            line_dots = 0


def check_values(text: str, budget: int, separators: str = "[{,:") -> None:
    """Refuse JSON ``text`` (TOML's: ``separators`` ``[{,=``) whose parsed value could take
    more than ``budget`` bytes: each bracket, brace and separator stands for at most
    :data:`VALUE_BYTES` of objects (a string's characters count one each).  Separators inside
    strings count too, so the bound is cautious; a trace's line, or an exercise file, is far
    below it."""
    values = sum(map(text.count, separators))
    if values * VALUE_BYTES + len(text) > budget:
        raise BadInput(f"too many values ({values:,} brackets, braces and separators, over "
                       f"{budget // VALUE_BYTES:,} for a file of this size)")


def load_json(text: str, budget: int, depth: int = MAX_DEPTH) -> Any:
    """``json.loads(text)`` once :func:`check_nesting` and :func:`check_values` passed it; a
    :class:`BadInput` (with the line and column of JSON's own errors) if not."""
    import json  # only the readers of JSON need it

    check_nesting(text, depth)
    check_values(text, budget)
    try:
        return json.loads(text)
    except RecursionError:  # (a guard: check_nesting refuses anything this deep)
        raise BadInput(f"nested more than {depth} deep") from None
    except ValueError as exc:
        msg = getattr(exc, "msg", str(exc))
        raise BadInput(f"not JSON: {msg}", getattr(exc, "lineno", None),
                       getattr(exc, "colno", None)) from None
