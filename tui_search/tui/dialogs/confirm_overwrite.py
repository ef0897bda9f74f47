"""Saving onto a file that exists asks first: overwrite it, or choose another name."""

from __future__ import annotations

from pathlib import Path
from typing import ClassVar

from textual.binding import Binding, BindingType

from tui_search.engine.util.filenames import describe_name
from tui_search.tui.dialogs.question import QuestionScreen

#: What the screen dismisses with.
OVERWRITE, ANOTHER = "overwrite", "another"


class ConfirmOverwriteScreen(QuestionScreen):
    """``y`` overwrites, ``n`` or escape goes back to the name (the safe choice is focused)."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("y", "choose('overwrite')", "Overwrite"),
        Binding("n,escape", "choose('another')", "Choose another name"),
    ]
    AUTO_FOCUS = "#another"

    def __init__(self, path: Path, text: str = "") -> None:
        """``text``: the question (by default, that ``path`` exists)."""
        super().__init__(
            "File exists",
            text or f"{describe_name(str(path))} already exists. Replace it with this map?",
            [(OVERWRITE, "Overwrite (y)", "error"),
             (ANOTHER, "Choose another name (n)", "primary")],
        )
        self.path = path
