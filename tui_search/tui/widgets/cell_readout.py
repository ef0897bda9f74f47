"""The line under the map that answers "what is this cell?" for the cell under the cursor, or
under the mouse while it hovers over the map (the text is :func:`~tui_search.tui.view.readout.
describe`'s).  Drawn with the line API, repainted only when its text changes (the app tells it
on every step), and wrapped to the width: in compare mode each search's part starts a row when
it does not fit on the one before."""

from __future__ import annotations

from typing import ClassVar

from tui_search.tui.view.pieces import Line, Piece
from tui_search.tui.widgets.wrapped_lines import PartsLines


class CellReadout(PartsLines):
    """``Cursor (12,40): expanded at step 345, …`` (``Mouse`` while hovering)."""

    COMPONENT_CLASSES: ClassVar[set[str]] = {"cell-readout--label", "cell-readout--text"}

    DEFAULT_CSS = """
    CellReadout {
        height: auto;
        padding: 0 1;
        & > .cell-readout--label { color: $text-muted; }
        & > .cell-readout--text { color: $text; }
    }
    """

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.label = ""
        self.text = ""

    def show(self, label: str, text: str) -> None:
        if (label, text) == (self.label, self.text):
            return
        self.label, self.text = label, text
        first, *others = text.split(" │ ")  # compare mode: a part a search
        pieces = [Piece([(f"{label} ", "cell-readout--label"), (first, "cell-readout--text")])]
        pieces += [Piece([(other, "cell-readout--text")], 0, (" │ ", "cell-readout--label"))
                   for other in others]
        self.set_lines([Line(pieces)])
