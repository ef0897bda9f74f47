"""The classroom view (issue 12), driven by Pilot: cells that fill the space, zooming, the
overview that shows all of a big map, labels, scrolling by whole cells, and asking the map
what a cell is (the cursor's, the mouse's), with the keys that move the cursor far."""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from rich.style import Style

from tests.tui.test_app import SIZE, open_grid, sync, tutorial_app, wait_until, watch_repaints
from tests.tui.test_snapshots import patterned_grid
from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.run.recorded import Run
from tui_search.tui.app import SearchApp
from tui_search.tui.view.cell_codes import (
    CURRENT,
    CURSOR_BAR,
    CURSOR_MARK,
    EXPANDED,
    FREE,
    FRONTIER,
    PATH,
    RANK,
    START,
    UPPER_HALF,
    WALL,
)
from tui_search.tui.view.geometry import MAX_LEVEL, Geometry
from tui_search.tui.widgets.cell_readout import CellReadout
from tui_search.tui.widgets.cell_style import block_codes
from tui_search.tui.widgets.grid_view import GridView


def in_view(view: GridView, cell) -> bool:
    """Is all of ``cell`` on screen?"""
    x, y, w, h = view.geometry.cell_region(cell)
    sx, sy = view.scroll_offset
    width, height = view.scrollable_content_region.size
    return sx <= x and x + w <= sx + width and sy <= y and y + h <= sy + height


@contextlib.asynccontextmanager
async def tutorial_in_big_cells(algorithm: str = "bfs") -> AsyncIterator[tuple]:
    """The tutorial at 160x48 (cells of 12x6), laid out: the app, its pilot, its map."""
    app = tutorial_app(algorithm)
    async with app.run_test(size=(160, 48)) as pilot:
        await pilot.pause()
        yield app, pilot, app.query_one(GridView)


def readout(app: SearchApp) -> str:
    r = app.query_one(CellReadout)
    return f"{r.label} {r.text}"


@sync
async def test_the_tutorial_fills_the_map_area_with_the_largest_cells_that_fit() -> None:
    async with tutorial_in_big_cells() as (app, _pilot, view):
        g = view.geometry
        width, height = view.scrollable_content_region.size
        assert g.level == 6 and (g.cell_width, g.cell_height) == (12, 6)
        assert g.size == (width, height) == (72, 36)  # the view hugs the map
        # one size bigger would not fit the room the side column and the lines below leave
        assert view.geometry.zoomed(1).size[1] > app.screen.size.height - 12
        assert not view.show_vertical_scrollbar and not view.show_horizontal_scrollbar


@sync
async def test_a_resize_fits_the_cells_again_until_the_user_zooms() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        view = app.query_one(GridView)
        small = view.geometry.level
        await pilot.resize_terminal(160, 48)
        await pilot.pause()
        assert view.geometry.level > small
        await pilot.press("left_square_bracket")
        chosen = view.geometry.level
        await pilot.resize_terminal(*SIZE)
        await pilot.pause()
        assert view.geometry.level == chosen  # zoomed: the user's size stays


@sync
async def test_zoom_in_and_out_changes_the_cell_size_and_keeps_the_cursor_cell_on_screen() -> None:
    app = SearchApp(open_grid(120, 90, start=(100, 70)))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        view = app.query_one(GridView)
        assert view.geometry.level == 1 and in_view(view, (100, 70))
        sizes = []
        for _ in range(5):
            await pilot.press("right_square_bracket")
            await pilot.pause()
            sizes.append((view.geometry.cell_width, view.geometry.cell_height))
            assert in_view(view, app.session.cursor)
        assert sizes == [(4, 2), (6, 3), (8, 4), (10, 5), (12, 6)]
        await pilot.press("left", "left", "up")  # the cursor moves; the view follows it
        for _ in range(5):
            await pilot.press("left_square_bracket")
            await pilot.pause()
            assert in_view(view, app.session.cursor)
        assert view.geometry.level == 1 and not view.overview
        await pilot.press("left_square_bracket")  # out of the smallest: the whole map
        await pilot.pause()
        assert view.overview and view.scroll_offset == (0, 0)
        await pilot.press("right_square_bracket")
        await pilot.pause()
        assert not view.overview and view.geometry.level == 1
        assert in_view(view, app.session.cursor)


#: A click: (zoom, scroll x, scroll y, where across, where down).  Zoom 0 is the overview, then
#: cell sizes 1 .. MAX_LEVEL (2x1 .. 24x12); "where" is taken modulo the map's part in view.
clicks = st.tuples(st.integers(0, MAX_LEVEL), st.integers(0, 4000), st.integers(0, 4000),
                   st.integers(0, 10_000), st.integers(0, 10_000))
CLICK_MAP = (150, 110)


def drawn_chars(view: GridView) -> list[list[Style]]:
    """The style of every character of the map's lines as drawn."""
    lines = []
    for y in range(view.scrollable_content_region.height):
        lines.append([seg.style or Style() for seg in view.render_line(y)
                      for _ in range(seg.cell_length)])
    return lines


async def check_click(app: SearchApp, pilot, view: GridView, zoom: int, scroll_x: int,
                      scroll_y: int, where_x: int, where_y: int) -> None:
    """Zoom, scroll, right-click (it only moves the cursor) a point of the map; the expected
    cell comes from arithmetic written here and from the picture, never from the widget's
    geometry; after the click the cursor is drawn where that cell is."""
    columns, rows = CLICK_MAP
    view.set_overview(zoom == 0)
    if zoom:
        view.zoom(zoom - view.geometry.cell_height)  # one call: from 2x1 to 24x12 at once
    await pilot.pause()
    view.scroll_to(scroll_x, scroll_y, animate=False, immediate=True)
    width, height = view.scrollable_content_region.size
    ox, oy = view.scroll_offset
    if zoom:  # a cell: 2 * zoom characters by zoom lines; the map is wider than the view
        cell_w, cell_h = 2 * zoom, zoom
        assert ox % cell_w == 0 and oy % cell_h == 0  # scrolled by whole cells
        drawn_w, drawn_h = columns * cell_w - ox, rows * cell_h - oy
        pad = 0
    else:  # the whole map in view, a character a block; how big, the picture says
        assert (ox, oy) == (0, 0)
        text = [view.render_line(y).text for y in range(height)]
        pad = text[0].index(UPPER_HALF)
        drawn_w = text[0].count(UPPER_HALF)
        drawn_h = sum(UPPER_HALF in line for line in text)
        block = min(b for b in range(1, columns + 1)
                    if -(-columns // b) == drawn_w and -(-rows // (2 * b)) == drawn_h)
    x = pad + where_x % min(width - pad, drawn_w)
    y = where_y % min(height, drawn_h)
    if zoom:
        expected = ((x + ox) // cell_w, (y + oy) // cell_h)
    else:
        expected = ((x - pad) * block, y * 2 * block)  # the block's top-left cell
    await pilot.click(GridView, offset=(1 + x, 1 + y), button=3)  # 1: the view's border
    assert app.session.cursor == expected
    after = drawn_chars(view)
    if zoom:  # the cursor's cell marked (its mark beside its glyph, a bar under a big
        # cell), in its own colours, and nothing else
        ox, oy = view.scroll_offset  # the view may have followed the cursor
        left, top = expected[0] * cell_w - ox, expected[1] * cell_h - oy
        text = [view.render_line(y).text for y in range(height)]
        marks = {(i, j) for j, line in enumerate(text) for i, c in enumerate(line)
                 if c == CURSOR_MARK}
        assert marks == ({(left + 1, top)} if 0 <= left + 1 < width and 0 <= top < height
                         else set())
        bar = top + cell_h - 1
        barred = {(i, j) for j, line in enumerate(text) for i, c in enumerate(line)
                  if c == CURSOR_BAR}
        assert barred == ({(i, bar) for i in range(max(0, left), min(width, left + cell_w))}
                          if cell_h > 1 and 0 <= bar < height else set())
        assert not any(s.reverse for line in after for s in line)
    else:  # the cursor's colour: in the clicked character's upper half, and only there
        cursor = view.get_component_rich_style("grid-view--cursor").color or (
            view.rich_style.color)
        assert {(i, j) for j, line in enumerate(after) for i, s in enumerate(line)
                if s.color == cursor} == {(x, y)}


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(clicks, min_size=1, max_size=3))
@example([(level, 4000 * (level % 2), 4000 * (level % 3 == 0), 9999, 9999)
          for level in range(MAX_LEVEL + 1)])  # every size, scrolled to the far edges too
def test_a_click_hits_the_cell_drawn_there_at_every_size_and_offset(sequence) -> None:
    """The overview and every cell size 2x1 .. 24x12, scrolled anywhere: a click anywhere in
    the map's content moves the cursor to the cell drawn under it (in the overview, the
    block's first cell)."""

    async def check() -> None:
        app = SearchApp(open_grid(*CLICK_MAP, start=(3, 3)))
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            view = app.query_one(GridView)
            for click in sequence:
                await check_click(app, pilot, view, *click)

    asyncio.run(check())


@sync
async def test_the_overview_of_a_512_map_shows_every_row_and_column() -> None:
    app = SearchApp(patterned_grid(512, 512, start=(256, 256), goal=(2, 2)))
    async with app.run_test(size=(140, 45)) as pilot:
        await pilot.press("z")
        await pilot.pause()
        view = app.query_one(GridView)
        g = view.geometry
        assert g.overview and g.block == 7
        width, height = view.scrollable_content_region.size
        assert g.size[0] <= width and g.size[1] <= height and view.scroll_offset == (0, 0)
        assert not view.show_vertical_scrollbar and not view.show_horizontal_scrollbar
        # the drawing covers columns 0..511 and rows 0..511
        assert g.cell_at(g.size[0] - 1, g.size[1] - 1) is not None
        assert g.visible_columns(0, width) == range(512)
        assert view.render_line(g.size[1] - 1).text.strip()


@sync
async def test_a_block_of_the_overview_shows_its_most_important_state() -> None:
    """A 20x20 map in blocks of 5: one frontier cell among expanded ones draws its block as
    frontier; the start's block as the start; a wall among free cells as a wall."""
    app = SearchApp(open_grid(20, 20, start=(2, 2), goal=(19, 19)))
    app.session.grid.set_blocked((12, 2), True)
    app.session.new_runs()
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        view.set_overview(True)
        await pilot.pause()
        view.geometry = Geometry(20, 20, 1, 5)  # the fit would choose 1; blocks of 5 here
        codes = block_codes(view.grid, view.run, range(5), 0, 20, view.geometry.across)
        assert codes == [6, 0, 5, 0]  # START, FREE, WALL, FREE
        run = app.session.run
        for k in (3, 9, 20, 40):
            run.goto(k)
            expected = []
            for bx in range(4):  # the block's most important cell, asked cell by cell
                looks = []
                for x in range(5 * bx, 5 * bx + 5):
                    for y in range(5):
                        cell = (x, y)
                        looks.append(START if cell == app.session.grid.start
                                     else WALL if app.session.grid.is_blocked(cell)
                                     else int(run.now.cell_state(cell)))
                expected.append(max(looks, key=RANK.__getitem__))
            assert block_codes(view.grid, view.run, range(5), 0, 20,
                               view.geometry.across) == expected
        assert FRONTIER in expected and EXPANDED not in expected  # the frontier hides it


#: What a block of the overview holding two kinds of cell shows, written out pair by pair from
#: the issue's order "path > node being expanded > frontier > expanded > obstacle > free" (not
#: derived from the code's RANK).
SHOWS = {
    ("path", "being expanded"): "path",
    ("path", "frontier"): "path",
    ("path", "expanded"): "path",
    ("path", "obstacle"): "path",
    ("path", "free"): "path",
    ("being expanded", "frontier"): "being expanded",
    ("being expanded", "expanded"): "being expanded",
    ("being expanded", "obstacle"): "being expanded",
    ("being expanded", "free"): "being expanded",
    ("frontier", "expanded"): "frontier",
    ("frontier", "obstacle"): "frontier",
    ("frontier", "free"): "frontier",
    ("expanded", "obstacle"): "expanded",
    ("expanded", "free"): "expanded",
    ("obstacle", "free"): "obstacle",
}
KIND = {"path": PATH, "being expanded": CURRENT, "frontier": FRONTIER, "expanded": EXPANDED,
        "obstacle": WALL, "free": FREE}


class PaintedRun(Run):
    """A one-way run (the map draws a bidirectional one otherwise) with just what the
    overview asks of it: the search state of each cell of a row (its ``run.now.row_states``)."""

    def __init__(self, states: dict[Cell, int]) -> None:  # no search: no Run.__init__
        self.states = states
        self.now = self  # type: ignore[assignment]

    def row_states(self, y: int, x0: int, x1: int) -> list[int]:
        return [self.states.get((x, y), FREE) for x in range(x0, x1)]


@sync
async def test_each_pair_of_states_in_a_block_shows_the_more_important_one() -> None:
    """Blocks of 2x2 cells, each holding two kinds of cell (the more important one once, in
    its first cell or in its last, the other in the rest): each draws as the table says, in
    its code and in its colour."""
    pairs = [(pair, first) for pair in SHOWS for first in (True, False)]
    width = 2 * len(pairs) + 2  # a last block for the start and the goal, out of the way
    grid = Grid(width, 2, start=(width - 2, 0), goal=(width - 1, 1))
    states: dict[Cell, int] = {}
    for i, ((a, b), first) in enumerate(pairs):
        block = [(2 * i, 0), (2 * i + 1, 0), (2 * i, 1), (2 * i + 1, 1)]
        one = block[0] if first else block[-1]
        for cell in block:
            kind = KIND[a if cell == one else b]
            if kind == WALL:
                grid.set_blocked(cell, True)
            else:
                states[cell] = kind
    app = SearchApp(grid)
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        view.set_overview(True)
        await pilot.pause()
        view.geometry = Geometry(width, 2, 1, 2)  # blocks of 2, one line: upper halves only
        view.run = PaintedRun(states)  # type: ignore[assignment]  # (a stand-in Run)
        codes = block_codes(view.grid, view.run, range(2), 0, width, view.geometry.across)
        assert codes is not None
        assert [codes[i] for i in range(len(pairs))] == [KIND[SHOWS[p]] for p, _ in pairs]
        line = view.render_line(0)
        colours = [seg.style.color for seg in line if seg.style
                   for _ in range(seg.cell_length)][view.pad_x:]
        assert colours[: len(pairs)] == [view.swatch(KIND[SHOWS[p]]).color for p, _ in pairs]


@sync
async def test_labels_show_arrows_and_depths_and_cycle() -> None:
    async with tutorial_in_big_cells() as (_app, pilot, view):
        await pilot.press(*["n"] * 4)
        g = view.geometry
        # (0,1) reached from the start by S: ↓ in its middle line, depth 1 top right
        _, y, _, h = g.cell_region((0, 1))
        top, middle = view.render_line(y).text, view.render_line(y + h // 2).text
        assert top[: g.cell_width] == "●" + " " * (g.cell_width - 2) + "1"
        assert "↓" in middle[: g.cell_width]
        _, y2, _, _ = g.cell_region((2, 1))  # (2,1) reached NE from (1,2)
        assert "↗" in view.render_line(y2 + h // 2).text[2 * g.cell_width : 3 * g.cell_width]
        await pilot.press("a")  # depth only: no arrows
        assert "↓" not in view.render_line(y + h // 2).text
        assert view.render_line(y).text[: g.cell_width].endswith("1")
        await pilot.press("a")  # none
        assert view.render_line(y).text[: g.cell_width].strip() == "●"
        await pilot.press("a")
        assert view.labels == "arrows"


@sync
async def test_an_informed_search_labels_cells_with_g_and_f() -> None:
    async with tutorial_in_big_cells("astar") as (app, pilot, view):
        await pilot.press(*["n"] * 3)
        g = view.geometry
        run = app.session.run
        e = run.now.last_event((0, 1))
        cost, _, f = run.nodes.costs(e)
        _, y, _, h = g.cell_region((0, 1))
        assert view.render_line(y).text[: g.cell_width].endswith(f"{cost:.0f}")
        last = view.render_line(y + h - 1).text[: g.cell_width]
        assert last.endswith(f"{f:.1f}")


@sync
async def test_a_step_in_big_cells_repaints_only_the_lines_of_the_cells_it_changed() -> None:
    async with tutorial_in_big_cells() as (app, pilot, view):
        await pilot.press("n", "n")
        painted, whole = watch_repaints(view)
        await pilot.pause()
        run = app.session.run
        app.main.action_next()
        before = run.nodes.cell(run.steps.expanded_event(run.k - 1))
        changed = run.now.changed_cells(run.k) + [before]
        lines = {line for cell in changed for line in view.geometry.lines_of(cell)}
        assert painted and set(painted) == lines
        assert not any(a == () for a in whole), "a whole-view refresh"


@sync
async def test_the_wheel_scrolls_by_whole_cells() -> None:
    app = SearchApp(open_grid(200, 200))
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        view.zoom(2)  # 6x3 cells
        await pilot.pause()
        for _ in range(3):
            view.scroll_relative(y=1, animate=False)  # a wheel turn: one line
            await pilot.pause()
            assert view.scroll_y % 3 == 0
        assert view.scroll_y > 0
        view.scroll_to(x=7, y=None, animate=False, immediate=True)
        await pilot.pause()
        assert view.scroll_x % 6 == 0 and view.scroll_x > 0


# -- ask the map ----------------------------------------------------------------------------


@sync
async def test_the_readout_says_what_the_cursor_cell_is() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert readout(app) == "Cursor (0,0): the start, on the frontier since step 0, depth 0"
        await pilot.press(*["n"] * 5, "down", "down")
        assert readout(app) == (
            "Cursor (0,2): expanded at step 3, depth 2, reached by S from (0,1)")
        await pilot.press("down")
        assert readout(app) == (
            "Cursor (0,3): being expanded (step 5), depth 3, reached by S from (0,2)")
        await pilot.press("down")
        assert readout(app) == (
            "Cursor (0,4): on the frontier since step 5, depth 4, reached by S from (0,3)")
        await pilot.press("right")
        assert readout(app).startswith("Cursor (1,4): on the frontier since step 5")
        await pilot.press("up")
        assert readout(app) == "Cursor (1,3): on the frontier since step 3, depth 3, " \
            "reached by SE from (0,2)"
        await pilot.press("right")
        assert readout(app) == "Cursor (2,3): obstacle"
        app.session.cursor = (4, 5)
        await pilot.press("right")
        assert readout(app) == "Cursor (5,5): never reached"
        await pilot.press("n")  # the cursor's cell does not change: the readout follows
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        assert (0, 1) in app.session.run.path()
        app.session.cursor = (0, 0)
        await pilot.press("down")
        assert readout(app).startswith("Cursor (0,1): on the path, expanded at step 2")


@sync
async def test_the_readout_follows_the_mouse_and_gives_back_to_the_cursor() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        view = app.query_one(GridView)
        x, y = view.screen_offset((0, 1))
        await pilot.hover(GridView, offset=(1 + x, 1 + y))
        await pilot.pause()
        assert readout(app) == (
            "Mouse (0,1): being expanded (step 2), depth 1, reached by S from (0,0)")
        await pilot.hover("#stats")
        await pilot.pause()
        assert readout(app).startswith("Cursor (0,0): the start")


@sync
async def test_the_readout_of_a_cost_ordered_search_gives_g_h_and_f() -> None:
    app = tutorial_app("astar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "down")
        text = readout(app)
        run = app.session.run
        cost, _, _ = run.nodes.costs(run.now.last_event((0, 1)))
        assert text.startswith("Cursor (0,1): on the frontier since step 1, depth 1, ")
        assert f"g {cost:g}, h " in text and "f " in text and "reached by S from (0,0)" in text


@sync
async def test_keys_jump_the_cursor_to_start_goal_and_the_node_being_expanded() -> None:
    app = SearchApp(open_grid(150, 150, start=(100, 120), goal=(5, 5)))
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        await pilot.pause()
        await pilot.press("G")
        assert app.session.cursor == (5, 5) and in_view(view, (5, 5))
        await pilot.press("e")  # step 0: none yet
        assert app.session.cursor == (5, 5)
        await pilot.press("n", "n", "n", "e")
        assert app.session.cursor == app.session.run.now.current_node()
        await pilot.press("S")
        await pilot.pause()
        assert app.session.cursor == (100, 120) and in_view(view, (100, 120))
        assert readout(app).startswith("Cursor (100,120): the start")


@sync
async def test_page_keys_move_the_cursor_a_screenful() -> None:
    app = SearchApp(open_grid(60, 200))
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        await pilot.pause()
        rows = view.scrollable_content_region.height
        await pilot.press("pagedown")
        assert app.session.cursor == (0, rows - 1) and in_view(view, app.session.cursor)
        await pilot.press("pagedown", "pagedown", "pagedown", "pagedown", "pagedown",
                          "pagedown", "pagedown", "pagedown", "pagedown")
        assert app.session.cursor == (0, 199)
        await pilot.press("pageup")
        assert app.session.cursor == (0, 199 - (rows - 1))


@sync
async def test_a_readout_too_long_for_its_line_wraps() -> None:
    app = tutorial_app()
    async with app.run_test(size=(60, 24)) as pilot:
        await pilot.pause()
        readout = app.query_one(CellReadout)
        rows = readout.shown_lines()
        assert len(rows) == readout.size.height > 1
        assert rows[0].startswith("Cursor (0,0): the start") and "…" not in "".join(rows)
        assert " ".join(rows) == f"{readout.label} {readout.text}"


@sync
async def test_the_palette_zooms_and_cycles_the_labels() -> None:
    from tests.tui.test_themes import palette_run

    async with tutorial_in_big_cells() as (_app, pilot, view):
        level = view.geometry.level
        await palette_run(pilot, "zoom out")
        assert view.geometry.level == level - 1
        await palette_run(pilot, "zoom in")
        assert view.geometry.level == level
        await palette_run(pilot, "cell labels")
        assert view.labels == "depth/cost"


@sync
async def test_a_new_map_is_fitted_again_even_after_a_zoom() -> None:
    async with tutorial_in_big_cells() as (app, pilot, view):
        await pilot.press("left_square_bracket", "left_square_bracket")
        assert view.geometry.level == 4 and not view.fitted
        app.main.files._use_map(open_grid(60, 60), None)  # what opening a map does
        await pilot.pause()
        assert view.fitted and view.geometry == Geometry(60, 60, 1)
        app.main.files._use_map(open_grid(3, 3), None)
        await pilot.pause()
        assert view.geometry.level == 12  # the largest: 3 cells of 24x12 fit easily
