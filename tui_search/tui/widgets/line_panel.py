"""What the line-API views share: resizing what they scroll over cheaply, quiet scrollbars,
repainting only the rows that changed, cached styles, and the panels' look -- all with Textual's
public API.

Resizing:

Setting ``virtual_size`` through its reactive asks Textual for a layout of the whole screen,
and the layout repaints every scrollbar on it: the panels change their length on nearly every
step, and that was two thirds of a step (measured: 16 ms more a step, on maze512 and on the
tutorial alike).  So :func:`set_virtual_size` sets the size without the layout and updates the
panels' scrollbars itself; it asks for the layout only when a scrollbar must come or go.

Scrollbars:

Textual repaints a scrollbar whenever its length, window or position changes, though a queue
of 2,000 entries that grows by one moves no glyph of it: on a step, repainting the two
panels' scrollbars (some 45 lines) was a quarter of the step.  :func:`update_scrollbar` sets
the same values and repaints only the rows whose cells change (Textual draws them).

Titles:

Setting a border title repaints the whole panel (even for the same text), so the panels'
titles say what they show and change only with it (the algorithm, the iteration); the counts
that change on every step are each panel's first line.  Each title and bottom legend comes in
a few wordings, longest first, and a panel shows the longest that fits its border, never one
that Textual would cut with "…".
"""

from __future__ import annotations

from math import ceil
from typing import ClassVar

from rich.cells import cell_len
from rich.segment import Segment
from rich.style import Style
from textual.geometry import Offset, Region, Size
from textual.scroll_view import ScrollView
from textual.scrollbar import ScrollBar, ScrollBarRender
from textual.strip import Strip
from textual.widget import Widget

from tui_search.tui.pieces import Parts

#: A scrollbar cell as :meth:`ScrollBarRender.render_bar` draws it: glyph, drawn reversed,
#: and what a click on it does.
BarCell = tuple[str, bool, "str | None"]
_UP: BarCell = (" ", False, "scroll_up")
_DOWN: BarCell = (" ", False, "scroll_down")
_THUMB: BarCell = (" ", True, "grab")
_EMPTY: BarCell = (" ", False, None)


def scrollbar_cells(bar: ScrollBar) -> list[BarCell]:
    """What each cell along ``bar`` draws, computed as
    :meth:`~textual.scrollbar.ScrollBarRender.render_bar` computes it in textual 8.2.8 (the
    same steps, on cells instead of segments; a test holds them equal)."""
    size = bar.size.height if bar.vertical else bar.size.width
    virtual = ceil(bar.window_virtual_size)
    window = ceil(bar.window_size if bar.window_size < bar.window_virtual_size else 0)
    if not (window and size and virtual and size != virtual):
        return [_EMPTY] * size
    bars = ScrollBarRender.VERTICAL_BARS if bar.vertical else ScrollBarRender.HORIZONTAL_BARS
    eighths = len(bars)
    thumb = max(1, window / (virtual / size))
    position = (size - thumb) * (bar.position / (virtual - window))
    start = int(position * eighths)
    end = start + ceil(thumb * eighths)
    start_index, start_bar = divmod(max(0, start), eighths)
    end_index, end_bar = divmod(max(0, end), eighths)
    cells = [_UP] * size
    cells[end_index:] = [_DOWN] * (size - end_index)
    cells[start_index:end_index] = [_THUMB] * (end_index - start_index)
    if start_index < len(cells) and bars[eighths - 1 - start_bar] != " ":
        cells[start_index] = (bars[eighths - 1 - start_bar], not bar.vertical, "grab")
    if end_index < len(cells) and bars[eighths - 1 - end_bar] != " ":
        cells[end_index] = (bars[eighths - 1 - end_bar], bar.vertical, "grab")
    return cells[:size]


def update_scrollbar(bar: ScrollBar, **values: float) -> None:
    """Set ``bar``'s ``window_virtual_size``, ``window_size`` or ``position``, and repaint
    only what that changes: nothing, the rows of a vertical bar whose cells changed (a thumb
    that moves repaints the rows it leaves and enters), or the whole bar."""
    before = scrollbar_cells(bar)
    if "position" in values:
        values["position"] = bar.validate_position(values["position"])
    for name, value in values.items():
        bar.set_reactive(getattr(ScrollBar, name), value)
    after = scrollbar_cells(bar)
    if after == before:
        return
    if not bar.vertical or len(after) != len(before):
        bar.refresh()
        return
    refresh_rows(bar, [new != old for new, old in zip(after, before)], bar.size.width)


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


def set_virtual_size(view: ScrollView, size: Size) -> None:
    """Give ``view`` a new virtual size without a layout of the screen, and update its
    scrollbars, repainting only what changes (what the layout would do for it, in public
    calls).  When a scrollbar may have to come or go (``overflow: auto``: Textual shows one
    when the size passes the view's, a second look when both are auto), or before the view
    is laid out, the size goes through the reactive, whose layout decides."""
    if size == view.virtual_size:
        return
    width, height = view.container_size
    styles = view.styles
    wide, tall = size.width > width, size.height > height
    if (not view.container_size
            or styles.overflow_x == "auto" and view.show_horizontal_scrollbar != wide
            or styles.overflow_y == "auto" and view.show_vertical_scrollbar != tall):
        view.virtual_size = size
        fit_bars(view)
        return
    bar_w, bar_h = view.scrollbar_size_vertical, view.scrollbar_size_horizontal
    view.set_reactive(Widget.virtual_size, size)
    if view.show_vertical_scrollbar and bar_w:
        update_scrollbar(view.vertical_scrollbar, window_virtual_size=size.height,
                         window_size=height - bar_h)
    if view.show_horizontal_scrollbar and bar_h:
        update_scrollbar(view.horizontal_scrollbar, window_virtual_size=size.width,
                         window_size=width - bar_w)
    view.scroll_x = view.validate_scroll_x(view.scroll_x)
    view.scroll_y = view.validate_scroll_y(view.scroll_y)
    fit_bars(view)


def fit_bars(view: ScrollView) -> None:
    """Draw ``view``'s scrollbars only while one has a thumb (its lines overflow it): one
    without is a blank track of the panel's own background, which Textual renders and
    composites all the same (~27 M instructions of the tutorial's first frame;
    benchmarks/README.md, session 13).  Their room stays (``overflow: scroll``).  Before
    its first layout the view is left as its CSS has it (hidden); its first Resize decides."""
    if not view.container_size:
        return
    window, virtual = view.scrollable_content_region.size, view.virtual_size
    thumb = (view.show_vertical_scrollbar and virtual.height > window.height
             or view.show_horizontal_scrollbar and virtual.width > window.width)
    shown = "visible" if thumb else "hidden"
    if view.styles.scrollbar_visibility != shown:
        view.styles.scrollbar_visibility = shown  # a layout: the bars come or go


class QuietScrollbars:
    """A mixin for :class:`ScrollView` subclasses: scrolling repaints a scrollbar only where
    its thumb moves on screen (``ScrollView.watch_scroll_x/y``, with
    :func:`update_scrollbar`)."""

    def watch_scroll_x(self, old_value: float, new_value: float) -> None:
        view: ScrollView = self  # type: ignore[assignment]
        self._scrolled(view.show_horizontal_scrollbar and view.horizontal_scrollbar,
                       old_value, new_value)

    def watch_scroll_y(self, old_value: float, new_value: float) -> None:
        view: ScrollView = self  # type: ignore[assignment]
        self._scrolled(view.show_vertical_scrollbar and view.vertical_scrollbar,
                       old_value, new_value)

    def _scrolled(self, bar: ScrollBar | bool, old_value: float, new_value: float) -> None:
        """What ``ScrollView.watch_scroll_x/y`` do, the bar moved by :func:`update_scrollbar`."""
        view: ScrollView = self  # type: ignore[assignment]
        if isinstance(bar, ScrollBar):
            update_scrollbar(bar, position=new_value)
        if round(old_value) != round(new_value):
            view.refresh(view.size.region)


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

    def render_line(self, y: int) -> Strip:
        width = self.scrollable_content_region.width
        base = self.cached_style()
        line = self.row_line(y)
        scroll_x = 0 if y < self.pinned_rows() else self.scroll_offset.x
        parts = self.line_parts(line)
        if not parts:
            return Strip.blank(width, base)
        parts = words_from(whole_words(parts, scroll_x + width), scroll_x)
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
        refresh_rows(self, [new != old for new, old in zip(rows, painted[2])], size.width)
