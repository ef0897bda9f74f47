"""What the line-API views share: resizing what they scroll over cheaply, cached styles, and
the panels' look.

Resizing:

Setting ``virtual_size`` through its reactive asks Textual for a layout of the whole screen,
which then re-renders every widget: on a step, that is most of the cost of the step. The
panels change their length on nearly every step, so they set the size without the layout and
update only their scrollbars (showing or hiding a scrollbar still asks for a layout, rarely).
"""

from __future__ import annotations

from rich.style import Style
from textual.geometry import Size
from textual.scroll_view import ScrollView
from textual.widget import Widget


def set_virtual_size(view: ScrollView, size: Size) -> None:
    """Give ``view`` a new virtual size without a layout pass, and refresh its scrollbars."""
    if size != view.virtual_size:
        view.set_reactive(Widget.virtual_size, size)
        view._scroll_update(size)


class CachedStyles:
    """A mixin for line-API widgets: the widget's style and its component styles looked up
    once per style change, not once per line (``rich_style`` walks every ancestor: on a step,
    looking it up for each line redrawn cost more than drawing the line)."""

    _style_cache: dict[str | None, Style] | None = None

    def notify_style_update(self) -> None:
        super().notify_style_update()  # type: ignore[misc]
        self._style_cache = None

    def cached_style(self, component: str | None = None) -> Style:
        """The widget's own style (``None``) or that of one of its component classes."""
        cache = self._style_cache
        if cache is None:
            cache = self._style_cache = {}
        style = cache.get(component)
        if style is None:
            widget: Widget = self  # type: ignore[assignment]
            style = cache[component] = (
                widget.rich_style if component is None
                else widget.get_component_rich_style(component)
            )
        return style


def group_digits(n: int) -> str:
    """``1000000`` -> ``1 000 000`` (digit groups a student can read at a glance)."""
    return f"{n:,}".replace(",", " ")


class LinePanel(CachedStyles, ScrollView, can_focus=True):
    """A bordered, focusable line-API list: the look the frontier and tree panels share."""

    DEFAULT_CSS = """
    LinePanel {
        border: round $border-blurred;
        border-title-align: left;
        border-subtitle-align: right;
        border-title-color: $foreground;
        border-subtitle-color: $text-muted;
        padding: 0 1;
        &:focus { border: round $border; border-title-color: $text-primary; }
    }
    """
