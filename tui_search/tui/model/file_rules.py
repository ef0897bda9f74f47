"""Where the app may read and write map files: anywhere (the app in a terminal, run by its
user), nowhere (the app served to browsers: ``tui-search --serve``), or only plain names in
one folder (``tui-search --serve --save-dir DIR``).

A served app is driven by whoever opens its page, so every name typed into its save-as and
open prompts goes through :meth:`FileAccess.path_for` -- the one place that decides -- and
ctrl+s writes the map's own file only when that file is in the folder.  No Textual here: the
rules are tested as plain functions.
"""

# No future import: CONTRIBUTING.md, "Start-up".
import os
import re
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

from tui_search.engine.util.filenames import describe_name, name_problem

#: The endings a name may have in the folder: the two map formats (so a visitor cannot make
#: a script, a dotfile or a web page there).
MAP_ENDINGS = (".txt", ".map")
MAX_NAME = 80
#: A served visitor's id: the name of their own folder in the server's save folder.
VISITOR_ID = re.compile(r"[0-9a-f]{6}")

OFF_MESSAGE = ("Saving and opening files are off in the served app "
               "(the teacher can allow them in one folder: tui-search --serve --save-dir DIR)")


class NameRefused(ValueError):
    """A name that would leave the folder, or is not a map file's name: one line for the
    prompt."""


class FileAccess(NamedTuple):
    """``served`` False: any path, as typed (``~`` expanded).  ``served`` True: none, or,
    with ``folder`` (an absolute, resolved directory), names in that folder only."""

    served: bool = False
    folder: Path | None = None

    @classmethod
    def served_in(cls, folder: str | os.PathLike[str] | None) -> "FileAccess":
        """The served app's access: off, or confined to ``folder`` (which must be a
        directory; a NameRefused says why not)."""
        if folder is None:
            return cls(served=True)
        path = Path(os.path.expanduser(folder))
        if not path.is_dir():
            raise NameRefused(f"--save-dir {os.fspath(folder)!r}: not a folder")
        return cls(served=True, folder=path.resolve())

    @classmethod
    def for_app(cls, served: bool, save_dir: str | None = None,
                visitor: str | None = None) -> "FileAccess":
        """Where an app may read and write maps: anywhere, or the served app's rules (in the
        visitor's own folder ``save_dir/visitor``, made if need be, when the server gave the
        app a visitor's id)."""
        if not served:
            return cls()
        access = cls.served_in(save_dir)
        if visitor is None or access.folder is None:
            return access
        if not VISITOR_ID.fullmatch(visitor):
            raise NameRefused(f"--visitor {visitor!r}: not a visitor's id")
        own = access.folder / visitor
        own.mkdir(mode=0o700, exist_ok=True)
        return cls.served_in(own)

    @property
    def off(self) -> str | None:
        """Why files cannot be saved or opened at all (one line), or None."""
        return OFF_MESSAGE if self.served and self.folder is None else None

    def path_for(self, typed: str) -> Path:
        """The file that the name typed into a prompt stands for, or NameRefused: one that
        no file can have (:func:`~tui_search.engine.util.filenames.name_problem`; served, strictly).

        Served with a folder, only a plain file name is taken: no folder part (``/``, ``\\``),
        no ``..``, not absolute, not hidden (a leading ``.``), ending in .txt or .map, and not
        a symbolic link (nor anything that resolves outside the folder)."""
        name = typed.strip()
        if self.served and self.folder is None:
            raise NameRefused(OFF_MESSAGE)
        where = f"a file name in {self.folder}"
        if self.served and not name:
            raise NameRefused(f"type {where}")
        problem = name_problem(name, strict=self.served)
        if problem is not None:
            raise NameRefused(problem)
        if self.folder is None:  # not served (served without a folder was refused above)
            return Path(os.path.expanduser(name))  # "~nobody-known" stays as typed
        if "/" in name or "\\" in name or os.path.isabs(name) or name in (".", ".."):
            raise NameRefused(f"{name!r}: only {where}, without a folder part")
        if name.startswith((".", "~")):
            raise NameRefused(f"{name!r}: a name may not start with {name[0]!r}")
        if len(name) > MAX_NAME or any(c in ':*?"<>|' for c in name):
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

    def folder_for(self, path: Path | None) -> Path | None:
        """The folder a prompt's file picker shows: the served app's folder (None when files
        are off), else that of ``path`` (the map's file), else the current one."""
        if self.served:
            return self.folder
        try:
            return (path.parent if path is not None else Path.cwd()).resolve()
        except (OSError, ValueError):
            return None

    def open_suggestion(self, path: Path | None) -> str:
        """What the open prompt offers: the map's folder (nothing, served)."""
        if self.served or path is None or str(path.parent) == ".":
            return ""
        return f"{path.parent}/"


def one_line(error: Exception) -> str:
    """What went wrong, as one line showing any name in it safely
    (:func:`~tui_search.engine.util.filenames.describe_name`)."""
    return describe_name(str(error))


def name_or_problem(typed: str, to_path: Callable[[str], Path]) -> Path | str:
    """The file a prompt's ``typed`` name stands for (``to_path``: a FileAccess's
    :meth:`~FileAccess.path_for`), or the one line saying why no file can have it: never
    an exception, whatever was typed."""
    problem = name_problem(typed.strip())
    if problem is not None:
        return problem
    try:
        return to_path(typed)
    except (OSError, ValueError) as exc:  # NameRefused among them
        return one_line(exc)
