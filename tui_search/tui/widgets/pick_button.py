"""The settings' radio button: a dot (``●``) in its box when picked, the box empty when not --
Textual's draws the same dot either way, only dimmer when off, which a projector washes out.

It keeps the ``RadioButton.Changed`` message and works in a ``RadioSet``; only the mark inside
the box follows the value.
"""

from __future__ import annotations

from textual.widgets import RadioButton

from tui_search.tui.widgets.tick_box import EMPTY


class PickButton(RadioButton):
    """A radio button that holds a dot when picked, and is empty when not."""

    DOT = "●"

    DEFAULT_CSS = """
    PickButton.-on > .toggle--button { color: $text-success; text-style: bold; }
    """

    def on_mount(self) -> None:
        self._show_mark()

    def watch_value(self) -> None:
        self._show_mark()
        super().watch_value()

    def _show_mark(self) -> None:
        self.BUTTON_INNER = self.DOT if self.value else EMPTY
        self.refresh()


__all__ = ["PickButton"]
