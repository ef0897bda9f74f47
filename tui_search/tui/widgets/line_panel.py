"""What the line-API views share: repainting only the rows that changed, cached styles, and
the panels' look.

Everything here is Textual's public API.  The panels set ``virtual_size`` through its reactive
(a layout of the screen, and Textual's own repaint of their scrollbars, whenever the length of
a list changes: most steps); Textual draws the scrollbars.  Their border titles name what the
panel shows and change only with it (the algorithm, the iteration); the counts that change on
every step are in the panel's first line, so a step repaints the lines that changed and not the
whole panel (setting a border title repaints all of it).
"""

from __future__ import annotations

from rich.cells import cell_len
from rich.segment import Segment
from rich.style import Style
from textual.geometry import Offset, Region, Size
from textual.scroll_view import ScrollView
from textual.strip import Strip
from textual.widget import Widget


def refresh_rows(widget: Widget, changed: list[bool], width: int) -> None:
    """Repaint the rows of ``widget`` flagged in ``changed``: one region a run of them (a
    refresh costs about as much as drawing a short line)."""
    regions: list[Region] = []
    y, rows = 0, len(changed)
    while y < rows:
        if not changed[y]:
            y += 1
            continue
        end = y + 1
        while end < rows and changed[end]:
            end += 1
        regions.append(Region(0, y, width, end - y))
        y = end
    if regions:
        widget.refresh(*regions)


def window_strip(segments: list[Segment], x: int, width: int, fill: Style) -> Strip:
    """Columns ``x`` to ``x + width`` of the line ``segments`` make, padded with ``fill``: what
    ``Strip(segments).crop_extend(x, x + width, fill)`` gives, made as one Strip (each Strip
    Textual makes on the way costs a set of caches; on a step that was a third of drawing a
    panel's line)."""
    out: list[Segment] = []
    end = x + width
    at = 0
    for segment in segments:
        if at >= end:
            break
        length = cell_len(segment.text)
        if length and at + length > x:
            if at < x:
                segment = segment.split_cells(x - at)[1]
                length -= x - at
                at = x
            if at + length > end:
                segment = segment.split_cells(end - at)[0]
                length = end - at
            if length:
                out.append(segment)
        at += length
    shown = max(0, min(at, end) - x)
    if shown < width:
        out.append(Segment(" " * (width - shown), fill))
    return Strip(out, width)


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


Parts = list[tuple[str, str]]


class LinePanel(CachedStyles, ScrollView, can_focus=True):
    """A bordered, focusable line-API list: the look the frontier and tree panels share, and
    their repaint after a step: only the lines that changed.

    A subclass draws line ``y`` of its whole list from :meth:`line_parts` (text and component
    class pieces), which says everything about how the line looks, and calls
    :meth:`show_titles` and :meth:`refresh_changed` instead of setting the titles and calling
    ``refresh()``: those repaint the whole panel (Textual's title setters do, even for the same
    text), which on a step was most of the lines a step redrew.  So the titles say what the
    panel shows, and what changes on every step (the counts) is in its first line.
    """

    DEFAULT_CSS = """
    LinePanel {
        border: round $border-blurred;
        border-title-align: left;
        border-subtitle-align: right;
        border-title-color: $foreground;
        border-subtitle-color: $text-muted;
        padding: 0 1;
        /* Always there, so that the lines do not jump sideways when a list grows past the
           panel; its track is the panel's own background, so a list that fits shows no bar
           at all. */
        overflow-y: scroll;
        scrollbar-background: transparent;
        scrollbar-corner-color: $background;
        &:focus { border: round $border; border-title-color: $text-primary; }
    }
    """

    _painted: tuple[Offset, Size, list[Parts]] | None = None  # what the visible lines show
    _titles: tuple[str, str] | None = None

    def line_parts(self, y: int) -> Parts:
        """Line ``y`` of the whole list as (text, component class) pieces; ``[]`` past it."""
        raise NotImplementedError

    def line_band(self, y: int) -> Style | None:
        """A style laid over the whole of line ``y`` (a highlight), or None."""
        return None

    def line_text(self, y: int) -> str:
        """The plain text of line ``y`` of the whole list (not of the screen)."""
        return "".join(text for text, _ in self.line_parts(y)).rstrip()

    def lines(self) -> list[str]:
        """Every line's text (tests and small lists only: O(lines))."""
        return [self.line_text(y) for y in range(self.virtual_size.height)]

    def render_line(self, y: int) -> Strip:
        scroll_x, scroll_y = self.scroll_offset
        width = self.scrollable_content_region.width
        base = self.cached_style()
        parts = self.line_parts(scroll_y + y)
        if not parts:
            return Strip.blank(width, base)
        style = self.cached_style
        band = self.line_band(scroll_y + y)
        if band is None:
            return window_strip([Segment(text, style(cls)) for text, cls in parts], scroll_x,
                                width, base)
        return window_strip([Segment(text, style(cls) + band) for text, cls in parts], scroll_x,
                            width, base + band)

    def show_titles(self, title: str, subtitle: str) -> None:
        """Set the border title and subtitle, each only when its text changed (the setter
        repaints the whole panel, even for the same text)."""
        old_title, old_subtitle = self._titles or (None, None)
        self._titles = (title, subtitle)
        if title != old_title:
            self.border_title = title
        if subtitle != old_subtitle:
            self.border_subtitle = subtitle

    def refresh_changed(self) -> None:
        """Repaint the visible lines whose parts differ from what they show (all of them
        after a scroll or a resize: those repaint everything anyway)."""
        offset = self.scroll_offset
        size = self.scrollable_content_region.size
        rows = [self.line_parts(offset.y + y) for y in range(size.height)]
        painted, self._painted = self._painted, (offset, size, rows)
        if painted is None or painted[0] != offset or painted[1] != size:
            self.refresh()
            return
        refresh_rows(self, [new != old for new, old in zip(rows, painted[2])], size.width)
