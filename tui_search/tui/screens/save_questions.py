"""What the file commands ask when a save is refused for a reason the user may overrule:
the file changed on disk since it was read or saved, or it has other names (hard links).

Each question's answer carries the save on (:meth:`FileCommands.write_map
<tui_search.tui.screens.file_commands.FileCommands.write_map>` again, with ``overwrite`` or
``in_place``), or reloads the file, or goes to another name; cancel leaves the map and the file as
they were.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from tui_search.engine.maps.read import MapError
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from textual.screen import Screen

#: What a save calls when it is over: with None once saved, else with why not.
Done = Callable[[MapError | None], None]


class SaveCommands(Protocol):
    """What the questions call back: the file commands
    (:class:`tui_search.tui.screens.file_commands.FileCommands`, which import this module, not the
    reverse)."""

    @property
    def dirty(self) -> bool:
        """True while the map has edits not saved."""

    def write_map(self, path: Path, kind: str, done: Done, *, in_prompt: bool = False,
                  overwrite: bool = False, in_place: bool = False) -> None: ...

    def ask_save_as(self, then: Callable[[], None] | None = None, error: str = "") -> None: ...

    def reload(self, path: Path) -> None: ...

    def push_screen(self, screen: Screen[Any], callback: Callable[[Any], None]) -> None: ...


def changed_on_ctrl_s(files: SaveCommands, path: Path, kind: str, done: Done, *,
                      in_place: bool = False) -> None:
    """ctrl+s found the file changed on disk: overwrite it, reload it (asking again before
    the app's edits are dropped), save as another name, or cancel."""
    from tui_search.tui.dialogs.save_refused import OVERWRITE, RELOAD, SAVE_AS, ChangedOnDiskScreen

    def answer(choice: str | None) -> None:
        if choice == OVERWRITE:
            files.write_map(path, kind, done, overwrite=True, in_place=in_place)
        elif choice == RELOAD:
            confirm_reload(files, path)
        elif choice == SAVE_AS:
            files.ask_save_as(lambda: done(None))

    files.push_screen(ChangedOnDiskScreen(describe_name(str(path))), answer)


def confirm_reload(files: SaveCommands, path: Path) -> None:
    """Read ``path`` again; with unsaved edits, only once the user says to drop them."""
    if not files.dirty:
        files.reload(path)
        return
    from tui_search.tui.dialogs.save_refused import YES, DropEditsScreen

    def answer(choice: str | None) -> None:
        if choice == YES:
            files.reload(path)

    files.push_screen(DropEditsScreen(describe_name(str(path))), answer)


def changed_in_prompt(files: SaveCommands, path: Path, kind: str, done: Done, *,
                      in_place: bool = False) -> None:
    """Save-as onto the map's own file, which changed on disk: replace it, or back to the
    prompt for another name."""
    from tui_search.tui.dialogs.confirm_overwrite import OVERWRITE, ConfirmOverwriteScreen

    def answer(choice: str | None) -> None:
        if choice == OVERWRITE:
            files.write_map(path, kind, done, in_prompt=True, overwrite=True, in_place=in_place)

    text = (f"{describe_name(str(path))} changed on disk since it was opened or saved. "
            "Replace it with this map?")
    files.push_screen(ConfirmOverwriteScreen(path, text), answer)


def other_names(path: Path) -> int:
    """How many other names (hard links) the file ``path`` has (0 when it can't be told)."""
    try:
        return max(os.stat(path).st_nlink - 1, 0)
    except (OSError, ValueError):
        return 0


def ask_in_place(files: SaveCommands, path: Path, kind: str, done: Done, *,
                 in_prompt: bool = False, overwrite: bool = False) -> None:
    """The file has hard links: write it in place (all its names change), or don't save."""
    from tui_search.tui.dialogs.save_refused import YES, InPlaceScreen

    def answer(choice: str | None) -> None:
        if choice == YES:
            files.write_map(path, kind, done, in_prompt=in_prompt, overwrite=overwrite,
                            in_place=True)

    files.push_screen(InPlaceScreen(describe_name(str(path)), other_names(path)), answer)
