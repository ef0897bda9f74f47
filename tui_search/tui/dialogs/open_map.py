"""Ask for a map file to open (ctrl+o): dismisses with the loaded grid and its path, or None.

The file is read in the prompt, so a file that cannot be a map keeps the prompt open with
the loader's one-line reason (file, line and column).
"""

from __future__ import annotations

from pathlib import Path

from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MapError
from tui_search.tui.dialogs.path_prompt import PathPrompt
from tui_search.tui.model.boards import too_big_for_the_app
from tui_search.tui.model.file_rules import one_line


class OpenMapScreen(PathPrompt[tuple[Grid, Path] | None]):
    """Enter opens, escape cancels."""

    TITLE_TEXT = "Open a map"
    LABEL_TEXT = "File name (a text map .txt, or a MovingAI .map):"
    HINT_TEXT = "enter to open · escape to cancel"

    def submit(self, path: Path) -> None:
        try:
            grid = load_map(path)
        except MapError as exc:
            self.show_error(one_line(exc))
            return
        too_big = too_big_for_the_app(grid)
        if too_big:
            self.show_error(one_line(MapError(str(path), too_big)))
            return
        self.dismiss((grid, path))
