"""Where a key, or a character of the ``solved`` string, is in an exercise's TOML text (its
line and column, for the errors), and a TOML error as a one-line
:class:`~tui_search.engine.maps.read.MapError`."""

from __future__ import annotations

import re

from tui_search.engine.maps.read import MapError


def key_position(text: str, key: str) -> tuple[int | None, int | None]:
    """The line and column (from 1) of ``key``'s value in the TOML ``text`` (None: not
    written at the start of a line)."""
    m = re.search(rf"^[ \t]*{re.escape(key)}[ \t]*=[ \t]*", text, re.MULTILINE)
    if m is None:
        return None, None
    line = text.count("\n", 0, m.end()) + 1
    return line, m.end() - (text.rfind("\n", 0, m.end()) + 1) + 1


def condition_position(text: str, offset: int) -> tuple[int | None, int | None]:
    """Where character ``offset`` of the ``solved`` string is in the file: through a basic
    string's escapes (``\\"`` is one character of the value, two of the file), past a
    multi-line string's first newline and a line-ending backslash's whitespace; a literal
    string (``'...'``) has no escapes."""
    line, col = key_position(text, "solved")
    if line is None or col is None:
        return None, None
    i = sum(len(row) + 1 for row in text.split("\n")[:line - 1]) + col - 1  # the quote
    quote = text[i:i + 3] if text[i:i + 3] in ('"""', "'''") else text[i:i + 1]
    i += len(quote)
    multi = len(quote) == 3
    if multi and text[i:i + 1] == "\n":  # the string starts on the next line
        i += 1
    while i < len(text):
        escape = quote[0] == '"' and text[i] == "\\"
        if escape and multi and text[i + 1:i + 2] in (" ", "\t", "\n"):
            i += 1  # a line-ending backslash: it and the whitespace after it are no character
            while i < len(text) and text[i] in " \t\n":
                i += 1
            continue
        if offset == 0:
            break
        i += {"u": 6, "U": 10}.get(text[i + 1:i + 2], 2) if escape else 1
        offset -= 1
    return text.count("\n", 0, i) + 1, i - (text.rfind("\n", 0, i) + 1) + 1


def toml_error(path: str, exc: Exception) -> MapError:
    message = str(exc)
    m = re.search(r"\s*\(at line (\d+), column (\d+)\)$", message)
    if m is None:
        return MapError(path, f"not TOML: {message}")
    return MapError(path, f"not TOML: {message[:m.start()]}", int(m.group(1)), int(m.group(2)))
