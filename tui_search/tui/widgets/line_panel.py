"""What the line-API views share: cached styles, drawing a window of a line, and the panels'
look and repaint -- all with Textual's public API.  Scrolling them cheaply (their virtual size,
quiet scrollbars) is :mod:`~tui_search.tui.widgets.scrollbars`'.

Titles:

Setting a border title repaints the whole panel (even for the same text), so the panels'
titles say what they show and change only with it (the algorithm, the iteration); the counts
that change on every step are each panel's first line.  Each title and bottom legend comes in
a few wordings, longest first, and a panel shows the longest that fits its border, never one
that Textual would cut with "…".
"""

from __future__ import annotations

from typing import ClassVar

from rich.cells import cell_len
from rich.segment import Segment
from rich.style import Style
from textual.geometry import Offset, Size
from textual.scroll_view import ScrollView
from textual.strip import Strip
from textual.widget import Widget

from tui_search.tui.view.pieces import Parts
from tui_search.tui.widgets.scrollbars import QuietScrollbars, fit_bars, refresh_rows


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


def whole_words(parts: Parts, end: int) -> Parts:
    """``parts`` cut before the word that column ``end`` would cut through (a line longer than
    its panel shows no half number: the scrollbar says there is more)."""
    text = "".join(part for part, _ in parts)
    if cell_len(text) <= end or len(text) != cell_len(text):
        return parts
    if text[end] == " " or text[end - 1] == " ":
        return parts
    keep = text.rfind(" ", 0, end) + 1
    out: Parts = []
    at = 0
    for part, cls in parts:
        if at + len(part) <= keep:
            out.append((part, cls))
        elif at < keep:
            out.append((part[: keep - at], cls))
        at += len(part)
    return out


def words_from(parts: Parts, start: int) -> Parts:
    """``parts`` with the word that column ``start`` would cut through blanked (a line scrolled
    sideways shows no half word at its left edge: a tree's shallower lines under a deep one)."""
    text = "".join(part for part, _ in parts)
    if not 0 < start < len(text) or len(text) != cell_len(text):
        return parts
    if text[start] == " " or text[start - 1] == " ":
        return parts
    end = text.find(" ", start)
    end = len(text) if end < 0 else end
    out: Parts = []
    at = 0
    for part, cls in parts:
        lo, hi = max(start, at) - at, min(end, at + len(part)) - at
        if lo < hi:
            part = part[:lo] + " " * (hi - lo) + part[hi:]
        out.append((part, cls))
        at += len(part)
    return out


class LinePanel(QuietScrollbars, CachedStyles, ScrollView, can_focus=True):
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
           at all: drawn only while it has a thumb (fit_bars). */
        overflow-y: scroll;
        scrollbar-visibility: hidden;
        scrollbar-background: transparent;
        scrollbar-corner-color: $background;
        &:focus { border: round $border; border-title-color: $text-primary; }
    }
    """

    #: The first lines of the list kept at the top of the panel, never scrolled either way
    #: (the tree's count): row y < PINNED shows line y from its first column.
    PINNED: ClassVar[int] = 0

    _painted: tuple[Offset, Size, list[Parts]] | None = None  # what the visible lines show
    _titles: tuple[str, str] | None = None  # the title and the legend shown
    _wordings: tuple[tuple[str, ...], tuple[str, ...]] = ((), ())  # each one's wordings

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

    def pinned_rows(self) -> int:
        """Rows pinned at the top: :attr:`PINNED`, none when that would leave no other."""
        return self.PINNED if self.scrollable_content_region.height > self.PINNED else 0

    def row_line(self, y: int) -> int:
        """The line of the list that row ``y`` of the panel shows."""
        return y if y < self.pinned_rows() else self.scroll_offset.y + y

    def windowed(self, parts: Parts, x: int, width: int) -> tuple[Parts, int]:
        """A line's ``parts`` as a window ``width`` wide from column ``x`` shows them, and
        the column of those parts the window starts at: here no half word at either edge."""
        return words_from(whole_words(parts, x + width), x), x

    def render_line(self, y: int) -> Strip:
        width = self.scrollable_content_region.width
        base = self.cached_style()
        line = self.row_line(y)
        scroll_x = 0 if y < self.pinned_rows() else self.scroll_offset.x
        parts = self.line_parts(line)
        if not parts:
            return Strip.blank(width, base)
        parts, scroll_x = self.windowed(parts, scroll_x, width)
        style = self.cached_style
        band = self.line_band(line)
        if band is None:
            return window_strip([Segment(text, style(cls)) for text, cls in parts], scroll_x,
                                width, base)
        return window_strip([Segment(text, style(cls) + band) for text, cls in parts], scroll_x,
                            width, base + band)

    def show_titles(self, titles: tuple[str, ...], legends: tuple[str, ...]) -> None:
        """Set the border title and the bottom legend, each given as its wordings, longest
        first: the panel shows the first that fits its border whole, none when none does
        (the border would cut it with "…"); chosen anew on a resize."""
        self._wordings = (titles, legends)
        self._set_titles(self._fitting(titles), self._fitting(legends))

    def _fitting(self, wordings: tuple[str, ...]) -> str:
        """Of ``wordings`` the first that fits the border (the first of all before the panel
        is laid out: the resize that follows chooses again)."""
        width = self.outer_size.width
        if not width:
            return wordings[0] if wordings else ""
        room = width - 6  # as the border leaves it: its corners, and more
        return next((text for text in wordings if cell_len(text) <= room), "")

    def on_resize(self) -> None:
        fit_bars(self)
        if self._titles is not None:
            titles, legends = self._wordings
            self._set_titles(self._fitting(titles), self._fitting(legends))

    def _set_titles(self, title: str, subtitle: str) -> None:
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
        rows = [self.line_parts(self.row_line(y)) for y in range(size.height)]
        painted, self._painted = self._painted, (offset, size, rows)
        if painted is None or painted[0] != offset or painted[1] != size:
            self.refresh()
            return
        changed = [new != old for new, old in zip(rows, painted[2], strict=True)]
        refresh_rows(self, changed, size.width)
