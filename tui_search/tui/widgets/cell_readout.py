"""The line under the map that answers "what is this cell?" for the cell under the cursor, or
under the mouse while it hovers over the map (the text is :func:`~tui_search.tui.readout.
describe`'s).  One line with the line API, repainted only when its text changes: the app tells
it on every step."""

from __future__ import annotations

from typing import ClassVar

from rich.segment import Segment
from textual.strip import Strip
from textual.widget import Widget

from tui_search.tui.widgets.line_panel import ELLIPSIS, CachedStyles


class CellReadout(CachedStyles, Widget):
    """``Cursor (12,40): expanded at step 345, …`` (``Mouse`` while hovering)."""

    COMPONENT_CLASSES: ClassVar[set[str]] = {"cell-readout--label", "cell-readout--text"}

    DEFAULT_CSS = """
    CellReadout {
        height: 1;
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
        if (label, text) != (self.label, self.text):
            self.label, self.text = label, text
            self.refresh()

    def render_line(self, y: int) -> Strip:
        width = self.content_size.width
        base = self.cached_style()
        if y:
            return Strip.blank(width, base)
        label = f"{self.label} "
        text = self.text
        if len(label) + len(text) > width > len(label):  # too long: it ends in an ellipsis
            text = text[: width - len(label) - 1] + ELLIPSIS
        segments = [Segment(label, self.cached_style("cell-readout--label")),
                    Segment(text, self.cached_style("cell-readout--text"))]
        return Strip(segments).crop_extend(0, width, base)
