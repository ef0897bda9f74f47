"""The settings' checkbox: a tick (``✓``) in its box when checked, the box empty when not --
Textual's draws the same ``X`` either way, only dimmer when off, which a projector washes out.

It keeps the ``Checkbox.Changed`` message; only the mark inside the box follows the value.
"""

from __future__ import annotations

from textual.widgets import Checkbox

#: What a box holds when off: nothing (the settings' radio buttons' too).
EMPTY = " "


class TickBox(Checkbox):
    """A checkbox that holds a tick when checked, and is empty when not."""

    TICK = "✓"

    DEFAULT_CSS = """
    TickBox.-on > .toggle--button { color: $text-success; text-style: bold; }
    """

    def on_mount(self) -> None:
        self._show_mark()

    def watch_value(self) -> None:
        self._show_mark()
        super().watch_value()

    def _show_mark(self) -> None:
        self.BUTTON_INNER = self.TICK if self.value else EMPTY
        self.refresh()


__all__ = ["EMPTY", "TickBox"]
