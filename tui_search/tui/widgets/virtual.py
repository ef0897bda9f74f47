"""Resizing what a line-API view scrolls over, cheaply.

Setting ``virtual_size`` through its reactive asks Textual for a layout of the whole screen,
which then re-renders every widget: on a step, that is most of the cost of the step. The
panels change their length on nearly every step, so they set the size without the layout and
update only their scrollbars (showing or hiding a scrollbar still asks for a layout, rarely).
"""

from __future__ import annotations

from textual.geometry import Size
from textual.scroll_view import ScrollView
from textual.widget import Widget


def set_virtual_size(view: ScrollView, size: Size) -> None:
    """Give ``view`` a new virtual size without a layout pass, and refresh its scrollbars."""
    if size != view.virtual_size:
        view.set_reactive(Widget.virtual_size, size)
        view._scroll_update(size)
