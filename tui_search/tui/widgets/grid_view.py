"""The map, drawn with Textual's line API: one ``render_line`` per terminal row, never a widget
per cell, so a 512x512 map costs what the visible part costs.

Two modes:

* **cells** -- each map cell is two columns wide and carries a glyph as well as a colour, so the
  picture reads without colour too (see :data:`GLYPHS`, which the legend shows);
* **overview** -- half blocks (``▀`` with a foreground and a background colour): two map rows per
  terminal row and one column per map column, so a whole 512x512 map fits a large terminal.

The widget only draws.  It is told what to show (``show_run``, ``set_cursor``, ``set_grid``) and
reports what the mouse did with messages (``CellClicked``, ``CellDragged``, ``StrokeEnded``);
the app decides what an edit means.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from itertools import groupby

from rich.segment import Segment
from rich.style import Style
from textual import events
from textual.geometry import Region, Size
from textual.message import Message
from textual.scroll_view import ScrollView
from textual.strip import Strip

from tui_search.engine.grid import Cell, Grid
from tui_search.engine.run import Run
from tui_search.tui.widgets.line_panel import CachedStyles, QuietScrollbars, window_strip

# Drawing codes: the search states of a free cell (CellState's values), then what the grid says.
FREE, FRONTIER, EXPANDED, CURRENT, PATH, WALL, START, GOAL = range(8)
COMPONENTS = ("free", "frontier", "expanded", "current", "path", "wall", "start", "goal")
#: Two columns per cell; a distinct glyph per kind so the map reads in monochrome.
GLYPHS = ("· ", "○ ", "● ", "◉ ", "◆ ", "██", "S ", "G ")
NAMES = ("free", "frontier (generated)", "expanded", "being expanded", "path", "obstacle",
         "start", "goal")
CELL_WIDTH = 2
UPPER_HALF = "▀"


class GridView(QuietScrollbars, CachedStyles, ScrollView, can_focus=True, inherit_bindings=False):
    """The map and the search state at the run's position, with a cursor.

    Bindings are the app's (one table, in the Footer), hence ``inherit_bindings=False``: the
    arrow keys move the cursor rather than scroll.
    """

    @dataclass
    class CellClicked(Message):
        """The mouse went down on a map cell (button 1 left, 3 right)."""

        cell: Cell
        button: int

    @dataclass
    class CellDragged(Message):
        """The mouse, still down since a ``CellClicked``, moved onto another cell."""

        cell: Cell

    @dataclass
    class StrokeEnded(Message):
        """The mouse button went up after a click or a drag."""

    COMPONENT_CLASSES = {f"grid-view--{name}" for name in COMPONENTS} | {"grid-view--cursor"}

    DEFAULT_CSS = """
    GridView {
        background: $surface;
        color: $foreground;
        /* The app's theme variables (tui_search/tui/themes.py): a theme recolours the map. */
        & > .grid-view--free { color: $map-free; }
        & > .grid-view--wall { color: $map-wall; }
        & > .grid-view--start { background: $map-start; color: $map-start-text; text-style: bold; }
        & > .grid-view--goal { background: $map-goal; color: $map-goal-text; text-style: bold; }
        & > .grid-view--frontier { background: $map-frontier; color: $map-frontier-text; }
        & > .grid-view--expanded { background: $map-expanded; color: $map-expanded-text; }
        & > .grid-view--current { background: $map-current; color: $map-current-text;
                                  text-style: bold; }
        & > .grid-view--path { background: $map-path; color: $map-path-text; text-style: bold; }
        & > .grid-view--cursor { text-style: reverse; }
    }
    """

    def __init__(self, grid: Grid, *, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.grid = grid
        self.run: Run | None = None
        self.cursor: Cell = grid.start or (0, 0)
        self.overview = False
        self._stroke = False  # the mouse went down on the map and is not up yet
        self._last: Cell | None = None  # the cell the stroke is on
        self._looks: list[tuple[str, Style]] | None = None  # cells mode, code + 8 * cursor
        self._swatches: list[Style] | None = None  # overview mode: a colour per code

    # -- what to show (attributes pushed down by the app) -----------------------------------
    def set_grid(self, grid: Grid) -> None:
        self.grid = grid
        self._update_virtual_size()
        self.refresh()

    def show_run(self, run: Run | None, changed: Iterable[Cell] | None = None) -> None:
        """Draw ``run`` at its position.  ``changed`` names the cells that differ from what is
        on screen (a step's node and successors); ``None`` redraws every visible line."""
        self.run = run
        if changed is None:
            self.refresh()
        else:
            self.refresh_cells(changed)

    def set_cursor(self, cell: Cell) -> None:
        old, self.cursor = self.cursor, cell
        self.refresh_cells((old, cell))
        self.follow(cell)

    def set_overview(self, on: bool) -> None:
        self.overview = on
        self._update_virtual_size()
        self.refresh()
        self.call_after_refresh(self.follow, self.cursor)

    def refresh_cells(self, cells: Iterable[Cell]) -> None:
        """Repaint only the terminal lines holding ``cells``."""
        lines = {self._line_of(cell) for cell in cells}
        for line in lines:
            self.refresh_line(line)

    def follow(self, cell: Cell) -> None:
        """Scroll (without animation) so ``cell`` is in view with a little room around it."""
        if not self.size.area:
            return
        x0, y0, w, h = self._cell_region(cell)
        width, height = self.scrollable_content_region.size
        sx, sy = self.scroll_offset
        margin_x = min(4, max(0, (width - w) // 2))
        margin_y = min(2, max(0, (height - h) // 2))
        new_x, new_y = sx, sy
        if x0 - margin_x < sx or x0 + w + margin_x > sx + width:
            new_x = x0 - (width - w) // 2  # out of view: centre it
        if y0 - margin_y < sy or y0 + h + margin_y > sy + height:
            new_y = y0 - (height - h) // 2
        if (new_x, new_y) != (sx, sy):
            self.scroll_to(max(0, new_x), max(0, new_y), animate=False, immediate=True)

    # -- geometry ---------------------------------------------------------------------------
    def on_mount(self) -> None:
        self._update_virtual_size()

    def on_resize(self) -> None:
        self.follow(self.cursor)

    def _update_virtual_size(self) -> None:
        g = self.grid
        if self.overview:
            self.virtual_size = Size(g.width, (g.height + 1) // 2)
        else:
            self.virtual_size = Size(g.width * CELL_WIDTH, g.height)

    def _line_of(self, cell: Cell) -> int:
        return cell[1] // 2 if self.overview else cell[1]

    def _cell_region(self, cell: Cell) -> Region:
        x, y = cell
        if self.overview:
            return Region(x, y // 2, 1, 1)
        return Region(x * CELL_WIDTH, y, CELL_WIDTH, 1)

    @property
    def pad_x(self) -> int:
        """Blank columns left of the map, which is centred when narrower than the view."""
        return max(0, (self.scrollable_content_region.width - self.virtual_size.width) // 2)

    def cell_at(self, offset_x: int, offset_y: int) -> Cell | None:
        """The map cell under a point of the content area (None when off the map)."""
        sx, sy = self.scroll_offset
        vx, vy = offset_x + sx - self.pad_x, offset_y + sy
        if vx < 0:
            return None
        if self.overview:
            x, y = vx, vy * 2
        else:
            x, y = vx // CELL_WIDTH, vy
        return (x, y) if self.grid.in_bounds((x, y)) else None

    # -- styles (from DEFAULT_CSS, so a theme or a palette is a CSS change) -----------------
    def notify_style_update(self) -> None:
        super().notify_style_update()
        self._looks = None
        self._swatches = None

    def _cell_looks(self) -> list[tuple[str, Style]]:
        """Glyph and style of each drawing code (``code + len(COMPONENTS)``: under the
        cursor)."""
        if self._looks is None:
            cursor = self.get_component_rich_style("grid-view--cursor")
            styles = [self.get_component_rich_style(f"grid-view--{n}") for n in COMPONENTS]
            self._looks = [(GLYPHS[i], styles[i]) for i in range(len(COMPONENTS))] + [
                (GLYPHS[i], styles[i] + cursor) for i in range(len(COMPONENTS))
            ]
        return self._looks

    def swatch(self, code: int) -> Style:
        """The one colour a kind of cell has in the overview (and in the legend)."""
        if self._swatches is None:
            base = self.rich_style
            swatches = []
            for i, name in enumerate(COMPONENTS):
                style = self.get_component_rich_style(f"grid-view--{name}")
                colour = style.bgcolor
                if i in (FREE, WALL) or colour is None or colour == base.bgcolor:
                    colour = style.color if i == WALL else (colour or base.bgcolor)
                swatches.append(Style(color=colour))
            self._swatches = swatches
        return self._swatches[code]

    # -- drawing ----------------------------------------------------------------------------
    def _codes(self, y: int, x0: int, x1: int) -> list[int]:
        """Drawing codes of cells ``x0 .. x1-1`` of map row ``y``."""
        g = self.grid
        run = self.run
        codes = run.row_states(y, x0, x1) if run is not None else [FREE] * (x1 - x0)
        w = g.width
        blocked = g.blocked
        base = y * w
        if blocked.find(1, base + x0, base + x1) >= 0:
            for i in range(x1 - x0):
                if blocked[base + x0 + i]:
                    codes[i] = WALL
        for cell, code in ((g.start, START), (g.goal, GOAL)):
            if cell is not None and cell[1] == y and x0 <= cell[0] < x1:
                codes[cell[0] - x0] = code
        return codes

    def render_line(self, y: int) -> Strip:
        sx, sy = self.scroll_offset
        width = self.scrollable_content_region.width
        line = sy + y
        if self.overview:
            return self._overview_line(line, sx, width)
        background = self.cached_style()
        if line >= self.grid.height:
            return Strip.blank(width, background)
        x0 = min(sx // CELL_WIDTH, self.grid.width)
        x1 = min(self.grid.width, (sx + width) // CELL_WIDTH + 1)
        codes = self._codes(line, x0, x1)
        cx, cy = self.cursor
        if cy == line and x0 <= cx < x1:
            codes[cx - x0] += len(COMPONENTS)
        looks = self._cell_looks()
        # one segment per run of like cells, the padding that centres the map first
        segments = [Segment(" " * self.pad_x, background)]
        for code, run in groupby(codes):
            glyph, style = looks[code]
            segments.append(Segment(glyph * len(list(run)), style))
        return window_strip(segments, sx - x0 * CELL_WIDTH, width, background)

    def _overview_line(self, line: int, sx: int, width: int) -> Strip:
        background = self.cached_style()
        g = self.grid
        top = line * 2
        if top >= g.height:
            return Strip.blank(width, background)
        x0 = min(sx, g.width)
        x1 = min(g.width, sx + width)
        upper = self._codes(top, x0, x1)
        lower = self._codes(top + 1, x0, x1) if top + 1 < g.height else None
        cursor_x = self.cursor[0] - x0 if self.cursor[1] // 2 == line else -1
        cursor_colour = self.get_component_rich_style("grid-view--cursor").color or (
            background.color
        )
        cache: dict[tuple, Style] = {}
        colours = []
        for i in range(x1 - x0):
            a = self.swatch(upper[i]).color
            b = self.swatch(lower[i]).color if lower is not None else background.bgcolor
            if i == cursor_x:
                if self.cursor[1] == top:
                    a = cursor_colour
                else:
                    b = cursor_colour
            colours.append((a, b))
        segments = [Segment(" " * self.pad_x, background)]
        for (a, b), run in groupby(colours):
            style = cache.get((a, b))
            if style is None:
                style = cache[a, b] = Style(color=a, bgcolor=b)
            segments.append(Segment(UPPER_HALF * len(list(run)), style))
        return window_strip(segments, 0, width, background)

    # -- the mouse: report, don't edit ------------------------------------------------------
    def _event_cell(self, event: events.MouseEvent, captured: bool = False) -> Cell | None:
        offset = (event.get_content_offset_capture(self) if captured
                  else event.get_content_offset(self))
        if offset is None:
            return None
        return self.cell_at(offset.x, offset.y)

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
            return
        cell = self._event_cell(event, captured=True)
        if cell is not None and cell != self._last:
            self._last = cell
            self.post_message(self.CellDragged(cell))

    def on_mouse_up(self, event: events.MouseUp) -> None:
        if self._stroke:
            self._stroke = False
            self.release_mouse()
            self.post_message(self.StrokeEnded())
