"""Scrolling the line-API views cheaply, with Textual's public API: resizing what they scroll
over without a layout, and repainting a scrollbar only where its cells change.

Resizing:

Setting ``virtual_size`` through its reactive asks Textual for a layout of the whole screen,
and the layout repaints every scrollbar on it: the panels change their length on nearly every
step, and that was most of a step (benchmarks/README.md, "step").  So :func:`set_virtual_size`
sets the size without the layout and updates the panels' scrollbars itself; it asks for the
layout only when a scrollbar must come or go.

Scrollbars:

Textual repaints a scrollbar whenever its length, window or position changes, though a queue
of 2,000 entries that grows by one moves no glyph of it: on a step, repainting the two
panels' scrollbars was a good part of the step (benchmarks/README.md, "step").
:func:`update_scrollbar` sets the same values and repaints only the rows whose cells change
(Textual draws them).  A scrollbar is drawn at all only while it has a thumb (:func:`fit_bars`).
"""

from __future__ import annotations

from math import ceil

from textual.geometry import Region, Size
from textual.scroll_view import ScrollView
from textual.scrollbar import ScrollBar, ScrollBarRender
from textual.widget import Widget

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
    refresh_rows(bar, [new != old for new, old in zip(after, before, strict=True)], bar.size.width)


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
    composites all the same (benchmarks/README.md, "startup").  Their room stays
    (``overflow: scroll``).  Before its first layout the view is left as its CSS has it
    (hidden); its first Resize decides."""
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

