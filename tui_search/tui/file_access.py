"""Where the app may read and write map files: anywhere (the app in a terminal, run by its
user), nowhere (the app served to browsers: ``tui-search --serve``), or only plain names in
one folder (``tui-search --serve --save-dir DIR``).

A served app is driven by whoever opens its page, so every name typed into its save-as and
open prompts goes through :meth:`FileAccess.path_for` -- the one place that decides -- and
ctrl+s writes the map's own file only when that file is in the folder.  No Textual here: the
rules are tested as plain functions.
"""

from __future__ import annotations

import os
import unicodedata
from pathlib import Path
from typing import NamedTuple

#: The endings a name may have in the folder: the two map formats (so a visitor cannot make
#: a script, a dotfile or a web page there).
MAP_ENDINGS = (".txt", ".map")
MAX_NAME = 80

OFF_MESSAGE = ("Saving and opening files are off in the served app "
               "(the teacher can allow them in one folder: tui-search --serve --save-dir DIR)")


def unsafe_character(c: str) -> bool:
    """A character a name in the served folder may not have: a control character (C0, DEL,
    C1) or one that reorders or hides text (bidi controls, zero-width marks)."""
    return unicodedata.category(c) in ("Cc", "Cf", "Zl", "Zp")


class NameRefused(ValueError):
    """A name that would leave the folder, or is not a map file's name: one line for the
    prompt."""


class FileAccess(NamedTuple):
    """``served`` False: any path, as typed (``~`` expanded).  ``served`` True: none, or,
    with ``folder`` (an absolute, resolved directory), names in that folder only."""

    served: bool = False
    folder: Path | None = None

    @classmethod
    def served_in(cls, folder: str | os.PathLike[str] | None) -> FileAccess:
        """The served app's access: off, or confined to ``folder`` (which must be a
        directory; a NameRefused says why not)."""
        if folder is None:
            return cls(served=True)
        path = Path(folder).expanduser()
        if not path.is_dir():
            raise NameRefused(f"--save-dir {os.fspath(folder)!r}: not a folder")
        return cls(served=True, folder=path.resolve())

    @property
    def off(self) -> str | None:
        """Why files cannot be saved or opened at all (one line), or None."""
        return OFF_MESSAGE if self.served and self.folder is None else None

    def path_for(self, typed: str) -> Path:
        """The file that the name typed into a prompt stands for, or NameRefused.

        Served with a folder, only a plain file name is taken: no folder part (``/``, ``\\``),
        no ``..``, not absolute, not hidden (a leading ``.``), ending in .txt or .map, and not
        a symbolic link (nor anything that resolves outside the folder)."""
        name = typed.strip()
        if not self.served:
            return Path(name).expanduser()
        if self.folder is None:
            raise NameRefused(OFF_MESSAGE)
        where = f"a file name in {self.folder}"
        if not name:
            raise NameRefused(f"type {where}")
        if "/" in name or "\\" in name or os.path.isabs(name) or name in (".", ".."):
            raise NameRefused(f"{name!r}: only {where}, without a folder part")
        if name.startswith((".", "~")):
            raise NameRefused(f"{name!r}: a name may not start with {name[0]!r}")
        if len(name) > MAX_NAME or any(unsafe_character(c) or c in ':*?"<>|' for c in name):
            raise NameRefused(f"{name!r}: use letters, digits, spaces and - _ . "
                              f"(at most {MAX_NAME} characters)")
        if not name.lower().endswith(MAP_ENDINGS):
            raise NameRefused(f"{name!r}: a map's name ends in .txt or .map")
        path = self.folder / name
        if path.is_symlink() or path.resolve().parent != self.folder:
            raise NameRefused(f"{name!r}: a link out of {self.folder}: not followed")
        return path

    def may_save_over(self, path: Path) -> bool:
        """May ctrl+s write ``path`` (the map's own file) without asking for a name?"""
        if not self.served:
            return True
        try:
            return self.path_for(path.name) == path
        except NameRefused:
            return False

    def suggestion(self, path: Path | None, default: str = "map.txt") -> str:
        """What the save-as prompt offers for a map read from ``path``."""
        if path is None:
            return default
        if self.served:
            return path.with_suffix(".txt").name
        return str(path.with_suffix(".txt"))

    def open_suggestion(self, path: Path | None) -> str:
        """What the open prompt offers: the map's folder (nothing, served)."""
        if self.served or path is None or str(path.parent) == ".":
            return ""
        return f"{path.parent}/"
