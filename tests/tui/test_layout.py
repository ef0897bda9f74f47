"""What a person sees at every terminal size: the whole map in every pane whenever it fits at
its smallest cells, in every mode, from 80x24 to 200x60 (tui/layout.py decides, the screen
applies it; these check what is on the screen)."""

from __future__ import annotations

import contextlib
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.textual_internals import nothing_queued, settle
from tests.tui.test_app import TUTORIAL, sync, wait_until
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.view.layout import CODE_MIN_HEIGHT, MAP_MIN_LINES, arrange
from tui_search.tui.widgets.grid_view import GridView

SIZES = [(80, 24), (100, 30), (120, 40), (160, 48), (200, 60)]
#: Each mode: how the app opens, and the keys that put it in that mode.
MODES = {
    "single": ({}, []),
    "compare 2": ({"compare": "bfs,dfs"}, []),
    "compare 3": ({"compare": "bfs,dfs,astar"}, []),
    "compare 4": ({"compare": "bfs,dfs,ucs,astar"}, []),
    "exercise": ({"exercise": 1}, []),
    "compare and exercise": ({"compare": "bfs,dfs", "exercise": 1}, []),
    "quiz": ({}, ["i"]),
    "compare 4 and exercise": ({"compare": "bfs,dfs,ucs,astar", "exercise": 1}, []),
    "compare 3, exercise and quiz": ({"compare": "bfs,dfs,astar", "exercise": 1}, ["i"]),
}


def whole_map_shown(app: SearchApp, view: GridView) -> str | None:
    """None when every cell of ``view``'s map is drawn on the screen, else what is not."""
    grid = app.session.grid
    width, height = view.scrollable_content_region.size
    drawn_w, drawn_h = view.geometry.size
    if view.show_vertical_scrollbar or view.show_horizontal_scrollbar:
        return f"scrollbars at {app.size}"
    if drawn_w > width or drawn_h > height:
        return f"{drawn_w}x{drawn_h} drawn in {width}x{height} at {app.size}"
    screen, content = app.screen.region, view.scrollable_content_region
    for cell in ((0, 0), (grid.width - 1, grid.height - 1), grid.start, grid.goal):
        x, y = view.screen_offset(cell)  # in the view's content area
        x, y = x + content.x, y + content.y
        if not screen.contains(x, y) or not content.contains(x, y):
            return f"cell {cell} off screen at {app.size}"
    return None


@pytest.mark.parametrize("mode", MODES)
@sync
async def test_the_whole_tutorial_map_shows_in_every_pane_at_every_size(mode: str) -> None:
    options, keys = MODES[mode]
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, **options)  # type: ignore[arg-type]
    async with app.run_test(size=SIZES[0]) as pilot:
        await pilot.press(*keys, "end")
        await wait_until(pilot, lambda: app.session.at_end())
        problems: list[str | None] = []
        for size in SIZES:
            await pilot.resize_terminal(*size)
            def shown(problems: list[str | None] = problems) -> bool:
                problems[:] = [whole_map_shown(app, v) for v in app.main.views]
                return not any(problems)

            with contextlib.suppress(AssertionError):  # the panes are fitted after a resize
                await wait_until(pilot, shown)
            assert not any(problems), (mode, problems)
            assert len(app.main.views) == len(app.session.runs), mode


def map_painted(app: SearchApp, view: GridView, screen: list[str]) -> str | None:
    """None when ``screen`` (the terminal as painted, its lines as text) shows ``view``'s
    map box whole: its bottom border row, and the start and the goal inside it (nothing
    drawn over them), else what is not."""
    region = view.region
    rows = [screen[y][region.x:region.right] for y in range(region.y, region.bottom)]
    if not rows or not (rows[-1].startswith("╰") and rows[-1].endswith("╯")):
        return f"the map's bottom border covered at {app.size}: {rows[-1:]}"
    inside = "".join(rows[1:-1])
    if "S" not in inside or "G" not in inside:
        return f"the start or the goal covered at {app.size}: {rows}"
    return None


@sync
async def test_every_lesson_section_shows_its_maps_whole_at_80x24() -> None:
    """A pane's own status lines wrapped to three rows (section 6's two panes, in the room
    the lesson leaves) are measured once laid out: the lists under the maps give up the
    rows, not the maps' bottom rows and borders; and every search's step and nodes expanded
    are on the screen whole (in panes 23 columns wide: they wrap onto another row)."""
    from tests.textual_internals import repainted
    from tests.tui.test_lesson import lesson_app
    from tests.tui.test_text_fits import _counts
    from tests.tui.test_text_fits import problems as text_problems

    app = lesson_app("tutorial")
    async with app.run_test(size=SIZES[0]) as pilot:
        panel = app.main.query_one(".lesson")
        for section in range(1, 11):
            while f" {section}/10" not in str(panel.border_title):
                await pilot.press("pagedown")
                await pilot.pause()
            await wait_until(pilot, lambda: not app.session.seeking)
            problems: list[str | None] = []

            async def shown(problems: list[str | None] = problems) -> bool:
                screen = ["".join(text for text, _ in line) for line in await repainted(pilot)]
                problems[:] = [whole_map_shown(app, view) or map_painted(app, view, screen)
                               for view in app.main.views]
                problems += text_problems(app, screen, _counts(app))
                return not any(problems)

            for _ in range(100):  # the panes are fitted once their lines are laid out
                if await shown():
                    break
                await pilot.pause(0.05)
            assert not any(problems), (section, problems)


@pytest.mark.parametrize("n", [2, 3, 4])
def test_the_table_gives_way_before_the_lists_and_the_lists_before_the_map(n: int) -> None:
    """80x24 leaves 18 lines for the panes and the table (1 key bar, 2 status lines, 1
    readout, 2 legend lines): the tutorial's 6x6 map needs 8 with its border."""
    arrangement = arrange(n, 80, 18, (6, 6), table_height=n + 5)
    assert arrangement.fits and not arrangement.table
    big = arrange(n, 200, 54, (6, 6), table_height=n + 5)
    assert big.fits and big.table and big.lists and big.trees


def test_one_pane_keeps_its_lists_beside_the_map_and_a_narrow_tall_one_under_it() -> None:
    assert arrange(1, 100, 26, (6, 6)).beside
    tall = arrange(1, 60, 50, (6, 6))
    assert not tall.beside and tall.lists and tall.fits
    # a map too big to fit keeps the lists beside it, and says it does not fit
    big = arrange(1, 140, 40, (512, 512))
    assert big.beside and not big.fits


@pytest.mark.parametrize(("n", "width", "height", "map_size"), [
    (1, 120, 30, (40, 16)),   # beside the lists 72 columns are left for its 82
    (4, 160, 40, (30, 12)),
    (4, 200, 52, (30, 12)),
    (2, 120, 30, (28, 10)),
])
def test_a_map_that_fits_under_the_lists_is_not_clipped_beside_them(
        n: int, width: int, height: int, map_size: tuple[int, int]) -> None:
    """A wide pane keeps its lists beside the map only while the whole map fits beside them:
    else they go under it, where it shows whole (it was clipped, with scrollbars, while it
    fitted)."""
    arrangement = arrange(n, width, height, map_size)
    assert arrangement.fits and not arrangement.beside


@given(st.integers(1, 4), st.integers(80, 200), st.integers(10, 60),
       st.tuples(st.integers(1, 120), st.integers(1, 60)))
def test_a_map_said_to_fit_has_the_room_for_its_smallest_cells(
        n: int, width: int, height: int, map_size: tuple[int, int]) -> None:
    """``fits`` is true only when the map's box holds the map at 2 characters by 1 line a
    cell, in a border: beside the lists, or under them."""
    a = arrange(n, width, height, map_size)
    if a.fits:
        box_w = a.pane_width - (a.lists_width if a.beside else 0)
        assert 2 * map_size[0] + 2 <= box_w
        if a.map_height:
            assert map_size[1] + 2 <= a.map_height


def test_a_status_line_that_wraps_takes_the_blank_lines_under_the_map_not_its_place() -> None:
    """One pane at 100x30 beside its lists: two more status rows leave the map's box as tall
    (its cells and place as they were), the map at most two rows less two lines tall so it
    ends above the pane's end; no room to spare under the map: laid out anew."""
    now = arrange(1, 100, 25, (6, 6))
    steady = arrange(1, 100, 23, (6, 6), wrapped=2)
    assert now.beside and now.map_height == 0
    assert steady.map_height == 25 and steady.map_max_height == 21
    assert (*steady[:8], 0, *steady[9:11], 0, now.code) == now
    under = arrange(1, 60, 29, (6, 6), wrapped=2)  # lists under the map: they give the rows
    assert under.map_height == arrange(1, 60, 31, (6, 6)).map_height
    assert under.lists_height == arrange(1, 60, 31, (6, 6)).lists_height - 2
    tight = arrange(1, 100, 9, (6, 6), wrapped=2)  # the map needs the rows
    assert tight == arrange(1, 100, 9, (6, 6)) and tight.fits


@pytest.mark.parametrize("size", [(100, 30), (80, 24)])
@sync
async def test_the_map_stays_put_while_the_status_line_wraps_to_more_rows(
        size: tuple[int, int]) -> None:
    """A* on the tutorial: its status line takes a row more after some steps; the map's
    place on the screen does not change."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, algorithm="astar")
    async with app.run_test(size=size) as pilot:
        view, stats = app.main.views[0], app.main.stats
        await wait_until(pilot, lambda: stats.outer_size.height > 0)
        app.main.fit_panes()  # measured (the first frame's is reckoned)
        await pilot.pause()
        top, rows = view.region.y, {stats.outer_size.height}
        for _ in range(14):
            await pilot.press("n")
            await pilot.pause()
            rows.add(stats.outer_size.height)
            # the panes are fitted after the status lines are laid out: once they are, the
            # map's top is where it was (a map moved a row would not come back)
            await wait_until(pilot, lambda: view.region.y == top, seconds=5)
        assert len(rows) > 1  # the status line did wrap anew


@pytest.mark.parametrize("size", [SIZES[0], (160, 50)])
@sync
async def test_the_first_layouts_classes_are_styled(size: tuple[int, int]) -> None:
    """The first (reckoned) fit sets the panes' classes without restyling them, leaving it to
    the screen's restyle before the first frame (start-up time): the styles follow the
    classes all the same."""
    from tui_search.tui.widgets.run_pane import RunPane

    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL)
    async with app.run_test(size=size) as pilot:
        await pilot.pause()
        pane = app.screen.query_one(RunPane)
        beside = pane.has_class("-beside")
        assert pane.lists.styles.layout is not None
        assert pane.lists.styles.layout.name == ("vertical" if beside else "horizontal")
        assert not pane.code_panel.is_mounted  # folded: mounted the first time it shows
        for panel in (pane.tree_panel,):
            assert panel.styles.display == ("none" if panel.has_class("-folded") else "block")


@pytest.mark.parametrize("no_run", [False, True])
@sync
async def test_every_part_of_a_pane_is_visible_in_its_hidden_boxes(no_run: bool) -> None:
    """The boxes of a pane's lists and map are hidden (app.tcss: they paint nothing, and
    hidden, Textual does not render them) and visibility is inherited: each part they hold
    (the panels, the Code panel, the note, the map) must be made visible again."""
    from tui_search.tui.widgets.run_pane import RunPane

    app = SearchApp(Grid(20, 8)) if no_run else SearchApp(load_map(TUTORIAL), compare="bfs,dfs")
    async with app.run_test(size=(160, 50)) as pilot:
        await pilot.press("v")  # the Code panel mounted too
        panes = list(app.screen.query(RunPane))
        await wait_until(pilot, lambda: all(p.side_note.is_mounted if no_run
                                            else p.code_panel.is_mounted for p in panes))
        for pane in panes:
            assert not pane.lists.visible and not pane.map_box.visible
            parts = [w for w in pane.walk_children() if not w.children]
            assert pane.view in parts and parts
            assert all(w.visible for w in parts), [w for w in parts if not w.visible]


def test_the_code_panel_needs_fewer_lines_than_a_tree() -> None:
    """Two panes at 80x24 on the tutorial: no room for the trees under the maps, but room for
    the Code panel in their place (and with it on, the lists keep CODE_MIN_HEIGHT lines where
    they would need LISTS_MIN_HEIGHT); beside a map too short for it, none."""
    room = arrange(2, 80, 17, (6, 6), stats_height=4)
    # the panes' own lines give way before the lists (issue 42: a queue beside a stack)
    assert room.lists and not room.pane_stats
    code = arrange(2, 80, 17, (6, 6), stats_height=4, code=True)
    assert code.lists_height == CODE_MIN_HEIGHT and code.code and not code.trees
    assert not arrange(1, 80, 6, (60, 40), code=True).code
    assert arrange(1, 100, 25, (6, 6), code=True).code  # beside, in a tall enough pane


@sync
async def test_the_layout_settles_when_the_lines_under_the_panes_depend_on_it() -> None:
    """Four searches, an exercise and the quiz at 80x24 (``c 3 6 x i``): folding the panes'
    own lines makes the lines under them say each search's counts (two rows more).  The
    layout fitted in the room the shorter lines left flipped to one with no map at all once
    the longer ones took it, and back, every refit.  Settled, the views keep their regions
    over more refits, and each map shows whole or says it shows part."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL)
    async with app.run_test(size=SIZES[0]) as pilot:
        await pilot.press("c", "3", "6", "x", "i")
        await wait_until(pilot, lambda: len(app.main.views) == 4 and app.session.quiz.on
                         and app.session.exercise is not None)
        seen: list[object] = []

        def regions() -> tuple[object, ...]:
            return tuple(view.region for view in app.main.views)

        def steady() -> bool:
            seen.append(regions())
            return nothing_queued(app) and seen[-2:-1] == seen[-1:]

        await wait_until(pilot, steady)
        settled = regions()
        for _ in range(6):  # refits, as a status line laid out anew asks for
            app.main.fit_panes()
            await settle(pilot)
            await pilot.pause(0.1)  # more than a frame: a refit it asked for is done
            assert regions() == settled
        for view in app.main.views:
            assert view.region.height >= MAP_MIN_LINES  # its border and rows of the map
            problem = whole_map_shown(app, view)
            assert problem is None or view.border_subtitle.startswith("part of the map"), \
                problem


def test_a_pane_s_own_lines_beside_its_lists_are_fitted_at_the_width_they_get() -> None:
    """Beside the lists a pane's status lines have the map's column only and wrap to more
    rows: the layout counts those rows for that choice (a map that fits under them whole
    beside a 38-column list at 2 rows no longer does at 12, and goes over its lists)."""
    wide = arrange(2, 160, 20, (10, 7), stats_rows=lambda width: 2)
    assert wide.beside and wide.fits
    # 79: the narrower of two panes with a gutter between them in 160 columns
    narrow = arrange(2, 160, 20, (10, 7), stats_rows=lambda width: 2 if width == 79 else 12)
    assert not narrow.beside and narrow.fits and narrow.lists_height


@sync
async def test_a_pane_s_narration_beside_its_lists_is_not_cut() -> None:
    """Compare on a map no pane shows whole, at 80x24: each pane's lines are as tall as they
    wrap to in the map's column (Textual sizes them against the whole pane), and its
    frontier keeps an entry in sight (no tree in a column that short)."""
    big = Path(__file__).parents[1] / "data" / "open-60x40.txt"
    app = SearchApp(load_map(big), path=big, compare="bfs,dfs")
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: all(pane.has_class("-beside") and pane.stats.region.area
                                            for pane in app.main.panes))
        for pane in app.main.panes:
            stats = pane.stats
            assert len(stats.rows(stats.content_size.width)) == stats.content_size.height == 3
            assert "expand it." in stats.shown_lines()[-1]
            assert pane.tree_panel.has_class("-folded") and pane.frontier.size.height >= 4
