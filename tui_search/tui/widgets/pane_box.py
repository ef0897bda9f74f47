"""The panes' grid, a cell a search's pane (``app.tcss`` lays it out, the screen sets its
columns and rows): it says when its size changes, so the screen fits the panes to the room
it has (the lines around it took a row or gave one back: a second search's readout line, the
lines under the panes saying each search's counts)."""

from __future__ import annotations

from textual import events
from textual.containers import Grid
from textual.message import Message


class PaneBox(Grid):
    """The panes, in a grid that posts :class:`PaneBox.Resized` when its size changes."""

    class Resized(Message):
        """The room for the panes changed."""

    def on_resize(self, event: events.Resize) -> None:
        self.post_message(self.Resized())
