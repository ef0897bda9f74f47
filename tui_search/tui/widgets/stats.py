"""The status lines under the map, and a pane's own: the counts, and what the search just did
in the tutorial's words; what they say is :mod:`tui_search.tui.view.status_lines`'s.

Redrawn on every step, so they are drawn with the line API (a ``Static`` rebuilt its content
through Textual's markup and visual pipeline on every step: a tenth of a step), wrapped to the
widget's width by :class:`~tui_search.tui.widgets.wrapped_lines.PartsLines`: a count is never
split from its label, and when the rows run out the figures a student can do without go first
(the playing speed, the frontier's peak, ...), never the narration or the bound.
"""

from __future__ import annotations

from typing import ClassVar

from textual import events
from textual.message import Message

from tui_search.tui.view.pieces import Line, line_text, text_of
from tui_search.tui.view.status_lines import MAX_ROWS
from tui_search.tui.widgets.wrapped_lines import PartsLines


class Stats(PartsLines):
    """``BFS │ step 4/18 │ expanded 4 │ …`` then the narration, which ends with the path's
    moves and cost and the tutorial's bound once found (or says "no path"), each wrapped to
    as many rows as it needs (at most :attr:`MAX_ROWS` while some count can go).

    The screen and the panes call :meth:`show` after every change, with the lines
    :mod:`~tui_search.tui.view.status_lines` builds.
    """

    MAX_ROWS: int | None = MAX_ROWS

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "stats--label", "stats--value", "stats--result", "stats--no-path", "stats--narration",
        "stats--note", "stats--play",
    }

    DEFAULT_CSS = """
    Stats {
        height: auto;
        padding: 0 1;
        background: $panel;
        & > .stats--label { color: $text-muted; }
        & > .stats--value { color: $text; text-style: bold; }
        & > .stats--result { color: $text-success; text-style: bold; }
        & > .stats--no-path { color: $text-error; text-style: bold; }
        & > .stats--narration { color: $text; }
        & > .stats--note { color: $text-warning; }
        & > .stats--play { color: $text-accent; text-style: bold; }
    }
    """

    def __init__(self, *, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.status_text = ""
        self.narration_text = ""
        self.short_text = ""  # each piece alone, and its short form: what may show (tests)
        self._height: int | None = None  # the rows laid out last
        #: Columns the lists beside it take of its container (a pane's, beside the map):
        #: Textual sizes a split widget against its whole container, not the room the
        #: splits before it left, so its height is worked out at the width it really gets.
        self.beside = 0
        #: The lines of the panes beside (a pane's own lines, the others' included): each
        #: takes as many rows as the tallest would in the narrowest pane (``level_width``
        #: columns, its padding included), so the maps under them start on one row and
        #: their cells' rows are level.
        self.peers: list[Stats] = []
        self.level_width = 0

    def show(self, lines: list[Line], max_rows: int) -> None:
        """Show ``lines`` (:mod:`tui_search.tui.view.status_lines`): the counts, then the
        narration; at most ``max_rows`` rows while some piece can go."""
        self.MAX_ROWS = max_rows
        before = self._level_rows()
        if self.set_lines(lines):
            if self.peers and self._level_rows() != before:
                for peer in self.peers:  # they take as many rows as the tallest
                    if peer is not self and peer.display:
                        peer.refresh(layout=True)
            *counts, narration = lines
            self.status_text = " ".join(line_text(line.pieces) for line in counts)
            self.narration_text = line_text(narration.pieces)
            self.short_text = " ".join(text_of(parts) for line in lines
                                       for piece in line.pieces
                                       for parts in (piece.parts, piece.short) if parts)

    def set_room(self, beside: int, level_width: int) -> None:
        """The columns the lists beside it take, and the narrowest pane's width (0: no
        peers to be level with): laid out anew when they changed."""
        if (beside, level_width) != (self.beside, self.level_width):
            self.beside, self.level_width = beside, level_width
            self.refresh(layout=True)

    def _level_rows(self) -> int:
        """The rows its lines take in the narrowest pane (0: no peers)."""
        if not self.peers or not self.level_width:
            return 0
        return self.height_at(self.level_width - self.styles.gutter.width - self.beside)

    def get_content_height(self, container: object, viewport: object, width: int) -> int:
        return max([len(self.rows(max(1, width - self.beside))),
                    *(peer._level_rows() for peer in self.peers if peer.display)])

    @property
    def wrapped(self) -> int:
        """The rows the lines take beyond a row each (they wrapped)."""
        return max(0, self.outer_size.height - len(self._lines or ()))

    class HeightChanged(Message):
        """The lines took a row more or less: the room around them changed."""

    def on_resize(self, event: events.Resize) -> None:
        # the first height too: a pane's lines shown (or mounted) anew were reckoned, not
        # measured, by the layout (the screen refits only when the heights differ)
        if event.size.height != self._height:
            self._height = event.size.height
            self.post_message(self.HeightChanged())
