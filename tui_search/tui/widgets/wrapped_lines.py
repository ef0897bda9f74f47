"""Lines of pieces (:mod:`tui_search.tui.view.pieces`) drawn with the line API, wrapped to the
widget's width: the status lines, the readout and the comparison table.

A widget may show at most ``MAX_ROWS`` rows: past that the pieces ranked least important go
first (see :func:`~tui_search.tui.view.pieces.lay_out`).  Redrawn on every step, so the rows are
laid out once per text and width; a ``Static`` rebuilt its content through Textual's markup and
visual pipeline on every step (a tenth of a step).
"""

from __future__ import annotations

from rich.segment import Segment
from textual.strip import Strip
from textual.widget import Widget

from tui_search.tui.view.pieces import Line, Parts, lay_out, text_of
from tui_search.tui.widgets.line_panel import CachedStyles


class PartsLines(CachedStyles, Widget):
    """Lines of pieces drawn with the line API, wrapped to the widget's width, as tall as
    they need (``height: auto``): the status lines, the readout and the comparison table."""

    #: At most this many rows when dropping the least important pieces gets there.
    MAX_ROWS: int | None = None

    _lines: list[Line] | None = None
    _rows: tuple[int, list[Parts]] | None = None  # (width, rows) last laid out

    def set_lines(self, lines: list[Line]) -> bool:
        """Show ``lines``; True (and a repaint) when they differ from what is shown."""
        if lines == self._lines:
            return False
        old = self._rows
        self._lines, self._rows = lines, None
        width = self.content_size.width
        if old is not None and width and len(self.rows(width)) != len(old[1]):
            self.refresh(layout=True)
        else:
            self.refresh(layout=old is None)
        return True

    def rows(self, width: int) -> list[Parts]:
        """The rows the lines take at ``width`` (laid out once per text and width)."""
        if self._rows is None or self._rows[0] != width:
            self._rows = (width, lay_out(self._lines or [], width, self.MAX_ROWS))
        return self._rows[1]

    def height_at(self, width: int) -> int:
        """The rows the lines would take ``width`` cells wide (laid out anew: the layout
        asks at widths the widget does not have)."""
        return len(lay_out(self._lines or [], max(1, width), self.MAX_ROWS))

    def shown_lines(self) -> list[str]:
        """The rows on screen, as text (tests)."""
        return [text_of(row) for row in self.rows(self.content_size.width)]

    def get_content_height(self, container: object, viewport: object, width: int) -> int:
        return len(self.rows(width))

    def render_line(self, y: int) -> Strip:
        width = self.content_size.width
        base = self.cached_style()
        rows = self.rows(width)
        parts = rows[y] if 0 <= y < len(rows) else []
        style = self.cached_style
        return Strip([Segment(text, style(cls)) for text, cls in parts]).crop_extend(
            0, width, base)
