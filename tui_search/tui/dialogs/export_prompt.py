"""Ask for the file to export the run to: dismisses with the path and whether to replace what
is there (asked first), or None.  The kind is the name's ending, as ``--export``'s."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from tui_search.engine.util.filenames import describe_name
from tui_search.tui.dialogs.confirm_overwrite import OVERWRITE, ConfirmOverwriteScreen
from tui_search.tui.dialogs.path_prompt import PathPrompt

#: The prompt's answer: the file, and whether the files there may be replaced.
Chosen = tuple[Path, bool]


class ExportScreen(PathPrompt[Chosen | None]):
    """Enter exports (asking first before replacing a file), escape cancels."""

    TITLE_TEXT = "Export the run"
    LABEL_TEXT = ("File name, its kind by its ending: .svg an animated picture for a web page "
                  "or a slide, .cast a terminal recording (asciinema), .gif an animated GIF, "
                  ".md a handout (its picture beside it), .trace.json or .trace.yaml a "
                  "Posthoc search trace (its map beside it):")
    HINT_TEXT = "enter to export · escape to cancel"

    def __init__(self, problem: Callable[[str], str | None],
                 targets: Callable[[str], list[str]], suggestion: str,
                 to_path: Callable[[str], Path] | None = None, *, folder: Path | None = None,
                 flat: bool = False) -> None:
        """``problem(name)``: why a name can be no export (None: it can); ``targets(name)``:
        the files an export to it writes; the rest as :class:`PathPrompt`'s."""
        super().__init__(suggestion, to_path, folder=folder, flat=flat)
        self.problem = problem
        self.targets = targets

    def submit(self, path: Path) -> None:
        problem = self.problem(str(path))
        if problem is not None:
            self.show_error(problem)
            return
        if path.is_dir():
            self.show_error(f"{describe_name(str(path))} is a folder: type a file name")
            return
        there = [name for name in self.targets(str(path)) if os.path.lexists(name)]
        if not there:
            self.dismiss((path, False))
            return
        names = " and ".join(describe_name(name) for name in there)
        text = f"{names} already {'exists' if len(there) == 1 else 'exist'}. Replace with the run?"

        def answer(choice: str | None) -> None:
            if choice == OVERWRITE:
                self.dismiss((path, True))
            else:  # another name: the prompt, with the name, is still here
                self.query_one("#filename").focus()

        self.app.push_screen(ConfirmOverwriteScreen(path, text), answer)
