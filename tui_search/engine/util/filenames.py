"""File names as typed by a person: how to show one safely, and what is wrong with one.

A name typed into a prompt (or sent by a visitor of the served app) may be anything: too long
for the file system, hold a NUL, control characters that move the terminal's cursor, or bidi
controls that make ``evil\\u202etxt.exe`` look like ``evilexe.txt``.  :func:`describe_name`
gives the one-line text to show for any name; :func:`name_problem` says, in one line, why a
name cannot be used (``strict``: the served save folder's rule, which also refuses control
and bidi characters).  Stdlib only, so the server can use them too.
"""

from __future__ import annotations

import os
import unicodedata

__all__ = ["MAX_NAME_BYTES", "MAX_PATH_BYTES", "describe_name", "name_problem",
           "unsafe_character"]

#: The longest name of one file or folder (in bytes, as the file system stores it) and of a
#: whole path that POSIX file systems take; longer ones fail with ENAMETOOLONG.
MAX_NAME_BYTES = 255
MAX_PATH_BYTES = 4095

#: The Unicode categories a name in the served folder may not hold: control characters (C0,
#: DEL, C1), format characters (bidi embeddings, overrides, isolates and marks, zero-width
#: marks) and the line and paragraph separators.
UNSAFE_CATEGORIES = frozenset(("Cc", "Cf", "Zl", "Zp"))


def unsafe_character(c: str) -> bool:
    """A character that moves the terminal's cursor, reorders text or hides itself."""
    return unicodedata.category(c) in UNSAFE_CATEGORIES

def describe_name(name: str) -> str:
    """``name`` as one line that shows every character it holds: what ``repr`` would escape
    (control, bidi and other format characters, separators other than the space, unassigned
    ones) escaped as it writes them (``\\x1b``, ``\\u202e``, ``\\xa0``); the rest as is.
    (No markup escaping: what shows it in a markup language escapes that too.)"""
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii")
                   for c in name)


def name_problem(name: str, *, strict: bool = False) -> str | None:
    """Why ``name`` (a path as typed) cannot be a file's name, in one line; None when it can.

    Refused always: nothing typed, a NUL, characters the file system's encoding cannot hold,
    a part longer than :data:`MAX_NAME_BYTES` or a path longer than :data:`MAX_PATH_BYTES`.
    ``strict`` (the served save folder) also refuses control, bidi and zero-width characters
    (:func:`unsafe_character`), which
    elsewhere are allowed and shown escaped (:func:`describe_name`)."""
    if not name.strip():
        return "type a file name"
    if "\x00" in name:
        return "a file name cannot hold a NUL character (\\x00)"
    try:
        data = os.fsencode(name)
    except UnicodeError:
        return "a file name cannot hold characters this system cannot write in file names"
    if len(data) > MAX_PATH_BYTES:
        return f"the name is too long (at most {MAX_PATH_BYTES} bytes)"
    if any(len(part) > MAX_NAME_BYTES for part in data.split(os.fsencode(os.sep))):
        return f"the name is too long (at most {MAX_NAME_BYTES} bytes between slashes)"
    if strict:
        bad = next((c for c in name if unsafe_character(c)), None)
        if bad is not None:
            return (f"a file name here cannot hold control, bidi or invisible characters "
                    f"({describe_name(bad)})")
    return None
