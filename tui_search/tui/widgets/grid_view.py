"""The map, drawn with Textual's line API (:mod:`~tui_search.tui.widgets.map_lines` says what
each terminal row shows: cells at a zoom, or the overview's blocks).

Where each cell goes is one :class:`~tui_search.tui.view.geometry.Geometry`, which the drawing, the
mouse, the scrolling and the overview share.  By default cells are the largest at which the
whole map fits; ``zoom`` changes their size, and out of the smallest is the overview.

The widget only draws what it is told (``show_run``, ``set_cursor``, ``set_grid``) and posts
what the mouse did (``CellClicked``, ...); the screen decides what an edit means.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, cast

from rich.style import Style
from textual import events
from textual.geometry import Offset, Size
from textual.message import Message
from textual.scroll_view import ScrollView
from textual.strip import Strip

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State, as_cell
from tui_search.tui.view.cell_codes import COMPONENTS
from tui_search.tui.view.cell_labels import LABEL_MODES
from tui_search.tui.view.geometry import Geometry, snapped
from tui_search.tui.widgets.cell_style import RAMP_COMPONENTS, CellLooks, swatches
from tui_search.tui.widgets.line_panel import CachedStyles
from tui_search.tui.widgets.map_lines import map_line
from tui_search.tui.widgets.scrollbars import QuietScrollbars

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun


class GridView(QuietScrollbars, CachedStyles, ScrollView, can_focus=True, inherit_bindings=False):
    """The map and the search state at the run's position, with a cursor.

    Bindings are the app's (one table, in the Footer), hence ``inherit_bindings=False``: the
    arrow keys move the cursor rather than scroll.
    """

    # The messages write their __init__ rather than being dataclasses: a dataclass compiles
    # its methods at import, on every start (benchmarks/README.md, "startup").
    class CellClicked(Message):
        """The mouse went down on a map cell (button 1 left, 3 right)."""

        def __init__(self, cell: Cell, button: int) -> None:
            super().__init__()
            self.cell, self.button = cell, button

    class CellDragged(Message):
        """The mouse, still down since a ``CellClicked``, moved onto another cell."""

        def __init__(self, cell: Cell) -> None:
            super().__init__()
            self.cell = cell

    class StrokeEnded(Message):
        """The mouse button went up after a click or a drag."""

    class CellHovered(Message):
        """The mouse, no button down, moved onto another cell (None: off the map)."""

        def __init__(self, cell: Cell | None) -> None:
            super().__init__()
            self.cell = cell

    COMPONENT_CLASSES = {f"grid-view--{name}" for name in COMPONENTS + RAMP_COMPONENTS} | {
        "grid-view--cursor", "grid-view--marked"}

    DEFAULT_CSS = """
    GridView {
        background: $surface;
        color: $foreground;
        /* The app's theme variables (tui_search/tui/view/themes.py): a theme recolours the map. */
        & > .grid-view--free { color: $map-free; }
        & > .grid-view--wall { color: $map-wall; }
        & > .grid-view--start { background: $map-start; color: $map-start-text; text-style: bold; }
        & > .grid-view--goal { background: $map-goal; color: $map-goal-text; text-style: bold; }
        & > .grid-view--frontier { background: $map-frontier; color: $map-frontier-text; }
        & > .grid-view--expanded { background: $map-expanded; color: $map-expanded-text; }
        & > .grid-view--current { background: $map-current; color: $map-current-text;
                                  text-style: bold; }
        & > .grid-view--path { background: $map-path; color: $map-path-text; text-style: bold; }
        /* A bidirectional search's backward half, a cell both halves reached, the best
           meeting (tui_search/tui/view/two_way/cells.py). */
        & > .grid-view--back-frontier { background: $map-back-frontier;
                                       color: $map-back-frontier-text; }
        & > .grid-view--back-expanded { background: $map-back-expanded;
                                       color: $map-back-expanded-text; }
        & > .grid-view--back-current { background: $map-back-current;
                                      color: $map-back-current-text;
                                      text-style: bold; }
        & > .grid-view--both { background: $map-both; color: $map-both-text; }
        & > .grid-view--meeting { background: $map-meeting; color: $map-meeting-text;
                                  text-style: bold; }
        /* The cursor keeps the cell's colours: its mark beside the glyph, bold; this is a
           free cell's mark's colour (tui_search/tui/widgets/cell_style.py). */
        & > .grid-view--cursor { color: $foreground; text-style: bold; }
        /* A replay's first difference: the cell each run expands where they part, filled
           with a colour of its own (no state's, no obstacle's), its glyph kept. */
        & > .grid-view--marked { background: $map-mark; color: $map-mark-text;
                                 text-style: bold underline; }
        /* Terrain: a free cell's cost, light to dark (tui_search/tui/widgets/cell_style.py). */
        & > .grid-view--cost-1 { background: $map-cost-1; color: $map-cost-text; }
        & > .grid-view--cost-2 { background: $map-cost-2; color: $map-cost-text; }
        & > .grid-view--cost-3 { background: $map-cost-3; color: $map-cost-text; }
        & > .grid-view--cost-4 { background: $map-cost-4; color: $map-cost-text; }
    }
    """

    def __init__(self, grid: Grid, *, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.grid = grid
        self.run: Run | BiRun | None = None
        self.cursor: Cell = grid.start or (0, 0)
        #: Cells drawn marked (a replay's first difference; by hand, the entry taken off, the
        #: successors added and a hint's cell).
        self.marks: frozenset[Cell] = frozenset()
        self.hover: Cell | None = None  # the cell under the mouse, no button down
        #: Where each cell is on screen; until the user zooms, the largest size that fits.
        self.geometry = Geometry(grid.width, grid.height)
        self.fitted = True  # False once zoomed: the size stays what the user chose
        self._level = 1  # the cell size to come back to from the overview
        self._overview = False
        self._area: tuple[int, int] | None = None  # the room the layout offers the map
        self.labels = LABEL_MODES[0]
        self._stroke = False  # the mouse went down on the map and is not up yet
        self._last: Cell | None = None  # the cell the stroke is on
        self._looks: CellLooks | None = None  # cells: code + 8 * cursor, and terrain
        self._swatches: list[Style] | None = None  # the overview's: a colour per code
        self.whole = True  #: the whole map shows (else a part, and the view scrolls)

    # -- what to show (attributes pushed down by the screen) --------------------------------
    def set_grid(self, grid: Grid) -> None:
        self.grid = grid
        self.fitted = True
        self._refit()

    def show_run(self, run: Run | BiRun | None, changed: Iterable[Cell] | None = None
                 ) -> None:
        """Draw ``run`` at its position.  ``changed`` names the cells that differ from what is
        on screen (a step's node and successors); ``None`` redraws every visible line."""
        self.run = run
        if changed is None:
            self.refresh()
        else:
            self.refresh_cells(changed)
        self.call_after_refresh(self.place_terminal_cursor)

    def set_marks(self, cells: tuple[Cell, ...] | frozenset[Cell]) -> None:
        """Draw ``cells`` marked (and no other)."""
        marks = frozenset(cells)
        if marks != self.marks:
            old, self.marks = self.marks, marks
            self.refresh_cells(old ^ marks)

    def set_cursor(self, at: State) -> None:
        cell = as_cell(at)
        old, self.cursor = self.cursor, cell
        self.refresh_cells((old, cell))
        self.follow(cell)
        self.call_after_refresh(self.place_terminal_cursor)

    def place_terminal_cursor(self) -> None:
        """Put the terminal's own cursor on the cursor's cell while the map has the focus
        (Textual's public ``App.cursor_position``, where the terminal's cursor goes after
        every update; Textual keeps it hidden): a braille display, and a screen reader's
        review, follow it there."""
        if not self.has_focus or not self.size.area:
            return
        x, y = self.screen_offset(self.cursor)
        view = self.scrollable_content_region
        if 0 <= x < view.width and 0 <= y < view.height:
            self.app.cursor_position = Offset(view.x + x, view.y + y)

    def on_focus(self) -> None:
        self.call_after_refresh(self.place_terminal_cursor)

    @property
    def overview(self) -> bool:
        """True while the whole map shows at once, in blocks of cells."""
        return self._overview

    def set_overview(self, on: bool) -> None:
        self._overview = on
        self._refit()

    def zoom(self, steps: int) -> None:
        """Cells ``steps`` sizes bigger (smaller when negative); out of the smallest is the
        overview, in from the overview the smallest cells.  The cursor's cell stays in view."""
        if self._overview:
            if steps > 0:
                self._overview = False
                self._level = 1
                self.fitted = False
        elif steps < 0 and self.geometry.level == 1:
            self._overview = True
        else:
            self._level = self.geometry.zoomed(steps).level
            self.fitted = False
        self._refit()

    def view_state(self) -> tuple[bool, int, bool, str]:
        """How the map is looked at (fitted, cell size, overview, labels), to carry over to
        another view of the same map (compare mode's new panes)."""
        return self.fitted, self._level, self._overview, self.labels

    def set_view_state(self, state: object) -> None:
        """``state``: another view's :meth:`view_state` (a graph's view's is not a grid's)."""
        if not isinstance(state, tuple) or state == self.view_state():
            return
        self.fitted, self._level, self._overview, self.labels = cast(
            "tuple[bool, int, bool, str]", state)
        self._refit()

    def cycle_labels(self) -> str:
        """The next label mode (arrows, depth/cost, none); returns it."""
        self.labels = LABEL_MODES[(LABEL_MODES.index(self.labels) + 1) % len(LABEL_MODES)]
        self.refresh()
        return self.labels

    def refresh_cells(self, cells: Iterable[Cell]) -> None:
        """Repaint only the terminal lines holding ``cells``."""
        lines_of = self.geometry.lines_of
        lines = {line for cell in cells for line in lines_of(cell)}
        for line in lines:
            self.refresh_line(line)

    def follow(self, cell: Cell) -> None:
        """Scroll (without animation, by whole cells) so ``cell`` is in view with a little room
        around it."""
        if not self.size.area:
            return
        view = self.scrollable_content_region.size
        x, y = self.geometry.follow(cell, (int(self.scroll_x), int(self.scroll_y)), view)
        if (x, y) != self.scroll_offset:
            self.scroll_to(x, y, animate=False, immediate=True)
            self.call_after_refresh(self.place_terminal_cursor)

    # -- geometry ---------------------------------------------------------------------------
    def on_mount(self) -> None:
        self._refit()

    def on_resize(self) -> None:
        self._update_virtual_size()
        self.follow(self.cursor)
        self.call_after_refresh(self.place_terminal_cursor)

    def get_content_width(self, container: Size, viewport: Size) -> int:
        """The layout offers the map ``container`` (the room the other widgets leave, less
        the border): fit the cells to it, then ask for the map's width."""
        area = (container.width, container.height)
        if area != self._area:
            first, self._area = self._area is None, area
            if self._fit():
                self._update_virtual_size(layout=False)
                # Textual keeps the size a widget took in each room it was offered, and
                # offered one of them again takes it without asking here: a layout to come
                # asks anew (else the cells fitted to the rooms since stayed: a map at 2x1
                # in a box sized for 4x2, after a resize and back)
                self.refresh(layout=not first)
                self.call_after_refresh(self.follow, self.cursor)
        return self.virtual_size.width

    def get_content_height(self, container: Size, viewport: Size, width: int) -> int:
        return self.virtual_size.height

    def _fit(self) -> bool:
        """Choose the geometry for the room there is; True when it changed."""
        g = self.grid
        width, height = self._area or (g.width * 2, g.height)
        if self._overview:
            new = Geometry.overview_fit(g.width, g.height, width, height)
        elif self.fitted:
            new = Geometry.fit(g.width, g.height, width, height)
            self._level = new.level
        else:
            new = Geometry(g.width, g.height, self._level)
        # Scrollbars only for a map bigger than the room (one that fits exactly would keep
        # bars an earlier size called for: a bar takes room, so the map no longer fits).
        self.styles.overflow_x = "hidden" if new.size[0] <= width else "auto"
        self.styles.overflow_y = "hidden" if new.size[1] <= height else "auto"
        whole = new.size[0] <= width and new.size[1] <= height  # else it says so, and how
        self.whole = whole
        self.border_subtitle = "" if whole else "part of the map · z: all of it"
        old, self.geometry = self.geometry, new
        return new != old

    def _refit(self) -> None:
        """A new map, mode or size: the geometry again, a layout and a full repaint, the
        cursor's cell brought into view."""
        self._fit()
        self._update_virtual_size()
        self.refresh(layout=True)
        self.call_after_refresh(self.follow, self.cursor)

    def _update_virtual_size(self, layout: bool = True) -> None:
        """The map's drawing, grown so that the last scroll offset starts at a whole cell."""
        view = self.scrollable_content_region.size if self.size.area else Size(0, 0)
        if view.area:
            size = Size(*self.geometry.scroll_room(view.width, view.height))
        else:
            size = Size(*self.geometry.size)
        if layout:
            self.virtual_size = size
        else:  # inside a layout: no second one
            self.set_reactive(ScrollView.virtual_size, size)

    def validate_scroll_x(self, value: float) -> float:
        value = super().validate_scroll_x(value)
        return snapped(value, self.scroll_x, self.geometry.cell_width, self.max_scroll_x)

    def validate_scroll_y(self, value: float) -> float:
        value = super().validate_scroll_y(value)
        return snapped(value, self.scroll_y, self.geometry.cell_height, self.max_scroll_y)

    @property
    def pad_x(self) -> int:
        """Blank columns left of the map, which is centred when narrower than the view."""
        return max(0, (self.scrollable_content_region.width - self.geometry.size[0]) // 2)

    def cell_at(self, offset_x: int, offset_y: int) -> Cell | None:
        """The map cell under a point of the content area (None when off the map)."""
        sx, sy = self.scroll_offset
        return self.geometry.cell_at(offset_x + sx - self.pad_x, offset_y + sy)

    def screen_offset(self, cell: Cell) -> tuple[int, int]:
        """Where ``cell`` begins in the content area at the scroll offset (tests click
        there; the inverse of :meth:`cell_at`)."""
        x, y, _, _ = self.geometry.cell_region(cell)
        sx, sy = self.scroll_offset
        return x - sx + self.pad_x, y - sy

    # -- styles (from DEFAULT_CSS, so a theme or a palette is a CSS change) -----------------
    def notify_style_update(self) -> None:
        super().notify_style_update()
        self._looks = None
        self._swatches = None

    def cell_looks(self) -> CellLooks:
        """Glyph and style of each drawing code and terrain (see :class:`CellLooks`), read once
        a restyle (the legend shows the same)."""
        if self._looks is None:
            self._looks = CellLooks(self.get_component_rich_style)
        return self._looks

    def swatch(self, code: int) -> Style:
        """The one colour a kind of cell has in the overview (and in the legend)."""
        if self._swatches is None:
            self._swatches = swatches(self.get_component_rich_style, self.rich_style)
        return self._swatches[code]

    # -- drawing (map_lines.py) ----------------------------------------------------------
    def render_line(self, y: int) -> Strip:
        return map_line(self, y)

    # -- the mouse: report, don't edit ------------------------------------------------------
    def _event_cell(self, event: events.MouseEvent, captured: bool = False) -> Cell | None:
        at = event.get_content_offset_capture(self) if captured else event.get_content_offset(self)
        return None if at is None else self.cell_at(at.x, at.y)

    def on_mouse_down(self, event: events.MouseDown) -> None:
        cell = self._event_cell(event)
        if cell is None:
            return
        event.stop()
        self.focus()
        self._stroke = True
        self._last = cell
        self.capture_mouse()
        self.post_message(self.CellClicked(cell, event.button))

    def on_mouse_move(self, event: events.MouseMove) -> None:
        if not self._stroke:
            self._hovered(self._event_cell(event))
            return
        cell = self._event_cell(event, captured=True)
        if cell is not None and cell != self._last:
            self._last = cell
            self.post_message(self.CellDragged(cell))

    def on_leave(self, event: events.Leave) -> None:
        self._hovered(None)

    def _hovered(self, cell: Cell | None) -> None:
        if cell != self.hover:
            self.hover = cell
            self.post_message(self.CellHovered(cell))

    def on_mouse_up(self, event: events.MouseUp) -> None:
        if self._stroke:
            self._stroke = False
            self.release_mouse()
            self.post_message(self.StrokeEnded())
