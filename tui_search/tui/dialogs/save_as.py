"""Ask for a file name to save the map as: dismisses with the Path it was saved to, or None.

The prompt saves by itself (through the ``save`` it is given) so that a failed save keeps it
open with the reason and the name typed; a file that exists, other than the map's own, is not
replaced before the overwrite question says so.  The save may ask questions of its own (the
file changed on disk, has hard links) before it answers.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from tui_search.engine.util.filenames import describe_name
from tui_search.tui.dialogs.confirm_overwrite import OVERWRITE, ConfirmOverwriteScreen
from tui_search.tui.dialogs.path_prompt import PathPrompt


class SaveAsScreen(PathPrompt[Path | None]):
    """Enter saves (asking first before replacing another file), escape cancels."""

    TITLE_TEXT = "Save the map as"
    LABEL_TEXT = "File name (.txt: text map with S and G; .map: MovingAI, no start or goal):"
    HINT_TEXT = "enter to save · escape to cancel"

    def __init__(
        self,
        save: Callable[[Path, Callable[[str | None], None]], None],
        suggestion: str = "map.txt",
        own: Path | None = None,
        to_path: Callable[[str], Path] | None = None,
        *,
        folder: Path | None = None,
        flat: bool = False,
        error: str = "",
    ) -> None:
        """``save(path, answer)`` writes the map, then calls ``answer(None)``, or
        ``answer(reason)`` with the one line saying why it could not (or never, when a
        question it asked was cancelled: the prompt is then still here); ``own`` is the
        map's own file, saved over without asking; the rest as :class:`PathPrompt`'s."""
        super().__init__(suggestion, to_path, folder=folder, flat=flat, error=error)
        self.save = save
        self.own = own

    def submit(self, path: Path) -> None:
        if path.is_dir():
            self.show_error(f"{describe_name(str(path))} is a folder: type a file name")
        elif path.exists() and not self._is_own(path):
            self.app.push_screen(ConfirmOverwriteScreen(path), self._overwrite_answer(path))
        else:
            self._save(path)

    def _is_own(self, path: Path) -> bool:
        try:
            return self.own is not None and os.path.samefile(path, self.own)
        except OSError:
            return False

    def _overwrite_answer(self, path: Path) -> Callable[[str | None], None]:
        def answer(choice: str | None) -> None:
            if choice == OVERWRITE:
                self._save(path)
            else:  # choose another name: the prompt, with the name, is still here
                self.query_one("#filename").focus()

        return answer

    def _save(self, path: Path) -> None:
        def answer(error: str | None) -> None:
            if error is None:
                self.dismiss(path)
            else:
                self.show_error(error)

        self.save(path, answer)
