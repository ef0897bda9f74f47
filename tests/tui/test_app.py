"""The app driven by Pilot: every key, the mouse, editing then searching, saving, quitting.

Assertions are on the app's state (the run, its position, the grid, the dirty flag) and on
what is drawn (the map's lines as text, the status lines), so each test fails when the
behaviour it names breaks.
"""

from __future__ import annotations

import asyncio
import functools
import os
import re
import time
from collections.abc import Callable, Coroutine
from pathlib import Path
from typing import Any

import pytest
from textual import events

from tests.helpers import MAPS, TUTORIAL
from tests.textual_internals import composited, notifications, repainted, settle
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.scenarios import load_scenario
from tui_search.engine.maps.write import format_text_map
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.record import CHUNK
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.confirm_quit import ConfirmQuitScreen
from tui_search.tui.dialogs.help import HelpScreen
from tui_search.tui.dialogs.save_as import SaveAsScreen
from tui_search.tui.model import playback
from tui_search.tui.model.session import NEEDS_ENDPOINTS
from tui_search.tui.screens.main import MainScreen
from tui_search.tui.view.cell_codes import START
from tui_search.tui.widgets.cell_style import CURSOR
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar
from tui_search.tui.widgets.search_tree import SearchTreePanel
from tui_search.tui.widgets.stats import Stats

#: Small MovingAI files copied into the repository (see their SOURCES.md).
ARENA = Path(__file__).parents[1] / "data" / "movingai" / "arena.map"
SIZE = (100, 32)


def sync(test: Callable[..., Coroutine[Any, Any, None]]) -> Callable[..., None]:
    """Run an async test with ``asyncio.run`` (the project pins no async pytest plugin)."""

    @functools.wraps(test)
    def wrapper(*args: Any, **kwargs: Any) -> None:
        asyncio.run(test(*args, **kwargs))

    return wrapper


def tutorial_app(algorithm: str = "bfs", path: Path | None = TUTORIAL) -> SearchApp:
    """The app on the tutorial's 6x6 map (start (0,0), goal (5,2))."""
    return SearchApp(load_map(TUTORIAL), path=path, algorithm=algorithm)


def open_grid(width: int, height: int, start=(0, 0), goal=None) -> Grid:
    """A big obstacle-free map, goal in the far corner unless given."""
    return Grid(width, height, start=start, goal=goal or (width - 1, height - 1))


def map_lines(app: SearchApp) -> list[str]:
    """The map as drawn: the text of every visible line of the grid view."""
    view = app.query_one(GridView)
    return [view.render_line(y).text for y in range(view.scrollable_content_region.height)]


def stats(app: SearchApp) -> tuple[str, str]:
    s = app.query_one(Stats)
    return s.status_text, s.narration_text


def screen_state(app: SearchApp) -> tuple:
    """Everything a step changes: position, counts, frontier, map, status lines, and the
    terminal as composited (which shows any line a step forgot to repaint)."""
    run = app.session.run
    assert run is not None
    panel = app.query_one(FrontierPanel)
    screen = re.sub(r"terminal-\d+-", "terminal-", app.export_screenshot())
    return (run.k, run.now.expanded, run.now.generated, run.now.frontier(), tuple(map_lines(app)),
            stats(app), panel.border_title, tuple(panel.lines()),
            tuple(app.query_one(SearchTreePanel).lines()), screen)


async def wait_until(pilot, condition: Callable[[], bool], seconds: float = 20.0) -> None:
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        await pilot.pause(0.02)


async def click_shown(pilot, selector: str) -> None:
    """Click the widget ``selector`` of the screen on top once it is laid out and stays put:
    on a loaded machine a screen just pushed can take longer than a pause to get its regions,
    and a control it shows or hides on mount moves the others a frame later."""
    seen: list[object] = []
    deadline = time.monotonic() + 20.0
    while True:
        await settle(pilot)  # what is queued handled, the layout and the paint done
        found = pilot.app.screen.query(selector)
        where = found.first().region if found else None
        if where is not None and where.area > 0 and seen[-1:] == [where]:
            break
        seen.append(where)
        assert time.monotonic() < deadline, f"{selector} is never laid out in one place"
        await pilot.pause(0.02)
    assert await pilot.click(selector), f"the click meant for {selector} landed elsewhere"


async def screen_shown(pilot, kind: type) -> Any:
    """The screen on top once it is a ``kind``, mounted (its widgets composed): a key that
    pushes a screen returns before the app has handled it on a loaded machine, so keys
    meant for the new screen wait."""
    await wait_until(pilot, lambda: isinstance(pilot.app.screen, kind)
                     and pilot.app.screen.is_mounted)
    return pilot.app.screen


# -- start-up ----------------------------------------------------------------------------


@sync
async def test_starts_paused_at_step_0_with_the_cursor_on_the_start() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert app.session.run is not None
        app.main.playback.tick()  # a playback tick: paused, it moves nothing
        assert app.session.run.k == 0
        assert not app.session.playing
        assert app.session.cursor == (0, 0)
        assert isinstance(app.focused, GridView)
        status, narration = stats(app)
        assert status.startswith("BFS │ step 0/22")
        assert narration == "START (0,0) is on the queue. Press n to expand it."
        lines = map_lines(app)
        row0 = next(line for line in lines if "S◀" in line)
        # the 6x6 map fills the room it has: cells of 8x4 characters, the start's depth 0,
        # the cursor's mark beside the start's glyph and a bar under its cell
        assert row0.strip().startswith("S◀     0" + "█" * 8 + "·       " * 3 + "█" * 8)
        assert lines[lines.index(row0) + 3].strip().startswith("▂" * 8 + "█" * 8)
        view = app.main.views[0]
        start = view.cell_looks().codes[START + CURSOR][1]  # its own colours, not reversed
        assert start.bgcolor == view.get_component_rich_style("grid-view--start").bgcolor
        assert not start.reverse


@sync
async def test_a_map_without_start_and_goal_opens_and_waits_for_them() -> None:
    grid = Grid(8, 5)
    app = SearchApp(grid)
    async with app.run_test(size=SIZE) as pilot:
        assert app.session.run is None
        assert stats(app)[1] == NEEDS_ENDPOINTS
        assert app.main.check_action("next", ()) is None
        await pilot.press("n", "space", "end")  # nothing to do: no crash
        await pilot.press("s", "right", "right", "down", "g")
        assert app.session.run is not None
        assert (grid.start, grid.goal) == ((0, 0), (2, 1))
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        assert app.session.run.path() == [(0, 0), (1, 1), (2, 1)]


# -- the cursor --------------------------------------------------------------------------


@sync
async def test_arrows_and_hjkl_move_the_cursor_and_stop_at_the_edges() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("right", "right", "down")
        assert app.session.cursor == (2, 1)
        await pilot.press("l", "j", "j", "h", "k")
        assert app.session.cursor == (2, 2)
        await pilot.press(*["up"] * 5, *["left"] * 5)
        assert app.session.cursor == (0, 0)
        await pilot.press(*["l"] * 9, *["j"] * 9)
        assert app.session.cursor == (5, 5)
        assert app.query_one(GridView).cursor == (5, 5)


# -- stepping ----------------------------------------------------------------------------


@sync
async def test_n_expands_one_node_and_narrates_it_in_the_tutorials_words() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n")
        assert app.session.run.k == 1
        assert stats(app)[1] == "Expanded START (0,0): added S to the queue"
        await pilot.press("n", "n", "n")
        assert app.session.run.k == 4
        assert stats(app)[1] == "Expanded (1,2): added E, NE to the queue"
        assert "queue 4 (peak 4)" in stats(app)[0]


@sync
async def test_status_lines_too_wide_for_the_terminal_wrap() -> None:
    """At the end, the narration and the path's moves and cost overflow a 60-column terminal:
    the lines wrap (no "…"), every word on screen; a line that fits is drawn whole."""
    app = tutorial_app()
    async with app.run_test(size=(60, 24)) as pilot:
        await pilot.press("end")
        widget = app.query_one(Stats)
        width = widget.content_size.width
        _, narration = stats(app)
        assert len(narration) > width
        rows = widget.shown_lines()
        assert widget.size.height == len(rows) > 2
        assert all(len(row) <= width and "…" not in row for row in rows)
        assert " ".join(" ".join(rows).split()).endswith(narration)
        assert widget.render_line(len(rows) - 1).text.rstrip() == rows[-1]
        await pilot.press("home")
        await pilot.pause()
        _status, narration = stats(app)
        assert len(narration) < width
        rows = widget.shown_lines()
        assert rows[-1] == narration
        assert widget.render_line(len(rows) - 1).text == narration.ljust(width)


@sync
async def test_dfs_narration_says_stack() -> None:
    app = tutorial_app("dfs")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n", "n")
        assert stats(app)[1] == "Expanded (1,2): added SW, S, E, NE to the stack"


@sync
async def test_p_after_n_restores_exactly_what_was_on_screen() -> None:
    for algorithm in ("bfs", "dfs", "iddfs"):
        app = tutorial_app(algorithm)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press("n", "n", "n")
            await pilot.pause()
            before = screen_state(app)
            await pilot.press("n")
            await pilot.pause()
            assert screen_state(app) != before
            await pilot.press("p")
            await pilot.pause()
            assert screen_state(app) == before, algorithm


@sync
async def test_p_at_step_0_and_n_at_the_end_are_greyed_out_and_do_nothing() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        bindings = app.screen.active_bindings
        assert bindings["p"].enabled is False and bindings["home"].enabled is False
        assert bindings["n"].enabled is True
        assert app.main.check_action("prev", ()) is None
        await pilot.press("p")
        assert app.session.run.k == 0
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        await pilot.pause()
        bindings = app.screen.active_bindings
        assert bindings["n"].enabled is False and bindings["end"].enabled is False
        assert bindings["space"].enabled is True  # space plays again from step 0
        assert bindings["p"].enabled is True
        total = app.session.run.k
        await pilot.press("n")
        assert app.session.run.k == total


@sync
async def test_home_and_end_go_to_the_first_and_last_step() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        run = app.session.run
        assert run.k == 22 and run.found
        assert stats(app)[1] == (
            "Goal (5,2) found from (5,1) · path: 7 moves, cost 8.66 (the lowest) · generated 24 of "
            "at most 7⁸ = 5,764,801")
        assert any("◆" in line for line in map_lines(app))
        await pilot.press("home")
        assert run.k == 0
        assert not any("◆" in line for line in map_lines(app))


@sync
async def test_no_path_is_reported_when_the_frontier_empties() -> None:
    app = SearchApp(load_map(MAPS / "no-path.txt"), MAPS / "no-path.txt")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        status, narration = stats(app)
        assert narration.endswith("Frontier empty: no path")
        assert status.endswith("│ speed 5/s")
        assert "path:" not in narration


def post_keys(app: SearchApp, *keys: str) -> None:
    """Queue key presses all at once, so each key after the first is handled before any timer
    the first one starts (``pilot.press`` waits for the app to go idle after each key, which
    lets a seek run slices, or finish, in between)."""
    for key in keys:
        app.post_message(events.Key(key, None))


def slices_of_one_chunk(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Make every slice of ``end`` record exactly one chunk (a time slice of 0 s), so a small
    map still takes a known number of slices whatever the machine's speed; returns the list
    that gets the steps recorded after each slice."""
    monkeypatch.setattr(playback, "SLICE_SECONDS", 0.0)
    recorded: list[int] = []
    record_for = playback.record_for

    def counted(run: Run, seconds: float | None = None) -> bool:
        try:
            return record_for(run, seconds)
        finally:
            recorded.append(run.recorded)

    monkeypatch.setattr(playback, "record_for", counted)
    return recorded


@sync
async def test_end_on_a_big_map_runs_in_slices_and_keys_are_still_answered(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    recorded = slices_of_one_chunk(monkeypatch)
    app = SearchApp(open_grid(30, 30), algorithm="iddfs")  # 67,105 steps: 17 chunks
    seen: list[tuple[bool, str]] = []  # (seeking, narration) when the cursor key was handled
    move = app.main.action_move

    def spy(dx: int, dy: int) -> None:
        seen.append((app.session.seeking, stats(app)[1]))
        move(dx, dy)

    app.main.action_move = spy  # type: ignore[method-assign]
    async with app.run_test(size=SIZE) as pilot:
        first = app.session.run.recorded
        post_keys(app, "end", "right")
        await wait_until(pilot, lambda: seen and not app.session.seeking)
        run = app.session.run
        assert run.at_end and run.found and run.k == run.total == 67_105
        assert "Computing" not in stats(app)[1]
        assert stats(app)[1].startswith("Goal (29,29) found from (28,28) · path")
        assert app.session.cursor == (1, 0)
    assert seen and seen[0][0], "the cursor key waited for the whole seek"
    assert seen[0][1].startswith("Computing the search…")
    # Several slices, each recording one chunk, the last one the end of the search.
    gains = [b - a for a, b in zip([first, *recorded], recorded, strict=False)]
    assert len(gains) > 3 and all(0 < gain <= CHUNK for gain in gains)
    assert recorded[-1] == run.total


@sync
async def test_a_step_key_during_end_stops_the_seek_where_it_is(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    recorded = slices_of_one_chunk(monkeypatch)
    app = SearchApp(open_grid(30, 30), algorithm="iddfs")
    async with app.run_test(size=SIZE) as pilot:
        post_keys(app, "end", "n")
        run = app.session.run
        await wait_until(pilot, lambda: run.k == 1)
        assert recorded, "end started a seek"
        assert not app.session.seeking and not run.at_end and not run.done
        slices, steps = len(recorded), run.recorded
        app.main.playback.seek_slice()  # what the seek's pending timer calls: it records no more
        assert run.k == 1 and run.recorded == steps and len(recorded) == slices
        assert not stats(app)[1].startswith("Computing")


def watch_repaints(view: GridView) -> tuple[list[int], list[tuple]]:
    """From now on, the lines ``view`` is asked to repaint one by one, and the arguments of
    each ``refresh`` (``()``: the whole view)."""
    painted: list[int] = []
    original = view.refresh_line
    view.refresh_line = lambda y: (painted.append(y), original(y))  # type: ignore
    refreshed: list[tuple] = []
    original_refresh = view.refresh
    view.refresh = lambda *a, **k: (refreshed.append(a), original_refresh(*a, **k))  # type: ignore
    return painted, refreshed


@sync
async def test_a_step_repaints_only_the_lines_it_changed() -> None:
    app = SearchApp(open_grid(300, 300, start=(5, 5)))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n", "n")
        painted, refreshed_all = watch_repaints(app.query_one(GridView))
        await pilot.pause()
        app.main.action_next()  # what the step itself repaints (not focus or hover events)
        assert app.session.run.k == 4
        assert painted and set(painted) <= {4, 5, 6, 7}
        assert not any(a == () for a in refreshed_all), "a whole-view refresh"


@pytest.mark.parametrize("algorithm", ["bfs", "dfs", "iddfs"])
@sync
async def test_a_step_repaints_every_line_it_changes(algorithm: str) -> None:
    """A step repaints only the lines whose content changed (and a border line only when its
    title did): whatever it left alone must be what a full repaint draws, at every step of
    the tutorial (to its end, or 25 steps of iterative deepening) forwards and back, and on a
    40x40 map where the panels fill and scroll."""
    for grid, steps in ((load_map(TUTORIAL), 25), (open_grid(40, 40, start=(20, 20)), 12)):
        app = SearchApp(grid, algorithm=algorithm)
        async with app.run_test(size=SIZE) as pilot:
            run = app.session.run
            run.advance()
            steps = min(steps, run.recorded)
            for forward in [True] * steps + [False] * steps:
                app.main.action_next() if forward else app.main.action_prev()
                await settle(pilot)
                assert composited(app) == await repainted(pilot), (forward, run.k)


@sync
async def test_space_plays_and_pauses() -> None:
    app = SearchApp(open_grid(60, 60))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("plus", "plus", "plus")  # 50 steps/s: 2 steps a tick
        assert playback.steps_per_tick(playback.SPEEDS[app.session.speed_index]) == 2
        await pilot.press("space")
        run = app.session.run
        assert app.session.playing
        k = run.k
        app.main.playback.tick()  # what the playback timer calls
        assert run.k == k + 2
        await wait_until(pilot, lambda: run.k > k + 2)  # and the timer calls it by itself
        await pilot.press("space")
        k = run.k
        assert not app.session.playing
        app.main.playback.tick()  # paused: a tick moves nothing
        assert run.k == k


@sync
async def test_playback_at_top_speed_skips_frames_and_stops_at_the_end() -> None:
    app = SearchApp(open_grid(300, 300))
    async with app.run_test(size=SIZE) as pilot:
        for _ in playback.SPEEDS:
            await pilot.press("plus")
        assert playback.SPEEDS[app.session.speed_index] == playback.SPEEDS[-1]
        assert app.main.check_action("faster", ()) is None
        assert playback.steps_per_tick(playback.SPEEDS[-1]) > 1000  # frames are skipped
        run = app.session.run
        # Playing, the timer not started yet: on a loaded machine the timer, started by the
        # key, could reach the end before a tick called here (it failed so, under load).
        assert not app.session.play()
        k = run.k
        app.main.playback.tick()  # what the timer calls
        assert run.k - k > 1 and app.session.playing  # one frame, many steps
        app.session.stop()
        await pilot.press("space")  # the key plays on from there, with the timer
        await wait_until(pilot, lambda: run.at_end, 60)  # a guard against hanging
        assert not app.session.playing


@sync
async def test_plus_and_minus_change_the_speed_within_its_bounds() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        i = app.session.speed_index
        await pilot.press("plus")
        assert app.session.speed_index == i + 1
        assert "speed 10/s" in stats(app)[0]
        for _ in range(len(playback.SPEEDS)):
            await pilot.press("minus")
        assert app.session.speed_index == 0
        assert app.main.check_action("slower", ()) is None
        assert "speed 1/s" in stats(app)[0]


# -- algorithms and runs -----------------------------------------------------------------


@sync
async def test_1_2_3_switch_algorithm_and_restart_on_the_same_map() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        first = app.session.run
        await pilot.press("2")
        assert app.session.algorithm == "dfs" and app.session.run is not first
        assert app.session.run.k == 0
        assert app.query_one(FrontierPanel).border_title.startswith("Stack (LIFO)")
        assert stats(app)[0].startswith("DFS")
        await pilot.press("3")
        assert app.session.run.algorithm == "iddfs"
        assert "depth limit 0" in stats(app)[0]
        await pilot.press("1")
        assert app.session.run.algorithm == "bfs"
        assert app.query_one(FrontierPanel).border_title.startswith("Queue (FIFO)")


@sync
async def test_r_makes_a_fresh_run_at_step_0() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n", "n")
        old = app.session.run
        await pilot.press("r")
        assert app.session.run is not old and app.session.run.k == 0
        assert stats(app)[1].startswith("START (0,0) is on the queue")


# -- editing -----------------------------------------------------------------------------


@sync
async def test_s_and_g_move_start_and_goal_and_restart_the_search() -> None:
    """The keys and the title; the search between them: tests/tui/test_session.py."""
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        await pilot.press("down", "down", "s")
        assert app.session.grid.start == (0, 2) and app.session.dirty
        assert app.session.run.k == 0 and app.session.run.grid.start == (0, 2)
        await pilot.press("right", "g")
        assert app.session.grid.goal == (1, 2)
        assert "modified" in app.query_one(GridView).border_title


@sync
async def test_start_on_an_obstacle_or_on_the_goal_is_refused_with_a_notification() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("right", "s")  # (1,0) is an obstacle
        assert app.session.grid.start == (0, 0) and not app.session.dirty
        await pilot.pause()
        assert any("obstacle" in n.message for n in notifications(app))
        app.session.cursor = (5, 2)  # the goal
        await pilot.press("s")
        assert app.session.grid.start == (0, 0)
        assert any("on the goal" in n.message for n in notifications(app))
        await pilot.press("o")  # an obstacle on the goal
        assert not app.session.grid.is_blocked((5, 2))


@sync
async def test_o_toggles_an_obstacle_at_the_cursor_and_restarts_the_run() -> None:
    """The key; the new run's path round the obstacle: tests/tui/test_session.py."""
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        app.session.cursor = (1, 2)
        await pilot.press("o")
        assert app.session.grid.is_blocked((1, 2)) and app.session.dirty
        assert app.session.run.k == 0 and app.session.run.grid.is_blocked((1, 2))
        await pilot.press("o")
        assert not app.session.grid.is_blocked((1, 2))


def at(view: GridView, x: int, y: int) -> tuple[int, int]:
    """Where to click cell ``(x, y)``: the view has a one-cell border, so content (0,0) is
    the widget's (1,1)."""
    cx, cy = view.screen_offset((x, y))
    return 1 + cx, 1 + cy


@sync
async def test_clicking_a_cell_moves_the_cursor_and_toggles_an_obstacle() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()  # laid out: the cells have their size
        view = app.query_one(GridView)
        await pilot.click(GridView, offset=at(view, 2, 3))
        assert app.session.cursor == (2, 3)
        assert app.session.grid.is_blocked((2, 3)) is False  # (2,3) was an obstacle: erased
        assert app.session.dirty and app.session.run.k == 0
        await pilot.click(GridView, offset=at(view, 2, 3))
        assert app.session.grid.is_blocked((2, 3)) is True
        await pilot.click(GridView, offset=at(view, 0, 0))  # the start: cursor only
        assert app.session.cursor == (0, 0) and not app.session.grid.is_blocked((0, 0))


@sync
async def test_right_click_moves_the_cursor_only() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()  # laid out: the cells have their size
        await pilot.click(GridView, offset=at(app.query_one(GridView), 3, 4), button=3)
        assert app.session.cursor == (3, 4) and not app.session.dirty


@sync
async def test_click_and_drag_draws_then_erases_obstacles() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()  # laid out: the cells have their size
        view = app.query_one(GridView)
        await pilot.mouse_down(GridView, offset=at(view, 0, 5))
        for x in range(1, 5):
            await pilot.hover(GridView, offset=at(view, x, 5))
        await pilot.mouse_up(GridView, offset=at(view, 4, 5))
        assert [app.session.grid.is_blocked((x, 5)) for x in range(6)] == [True] * 5 + [False]
        assert app.session.run.grid.is_blocked((4, 5))
        # starting on an obstacle erases
        await pilot.mouse_down(GridView, offset=at(view, 1, 5))
        await pilot.hover(GridView, offset=at(view, 2, 5))
        await pilot.mouse_up(GridView, offset=at(view, 2, 5))
        assert [app.session.grid.is_blocked((x, 5)) for x in range(6)] == [
            True, False, False, True, True, False]
        # moving without a button down draws nothing
        await pilot.hover(GridView, offset=at(view, 5, 5))
        assert not app.session.grid.is_blocked((5, 5))


# -- the overview ------------------------------------------------------------------------


@sync
async def test_z_switches_to_the_half_block_overview_and_back() -> None:
    app = SearchApp(open_grid(64, 40))
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        assert view.geometry.size == (128, 40)
        await pilot.press("z")
        # 64 columns do not fit the 58 the side column leaves: a character is 2x2 cells
        assert view.overview and view.geometry.block == 2 and view.geometry.size == (32, 10)
        assert set(view.render_line(0).text.strip()) == {"▀"}
        await pilot.press("z")
        assert not view.overview and view.geometry.size == (128, 40)


@sync
async def test_the_view_follows_the_cursor_and_the_node_being_expanded() -> None:
    app = SearchApp(open_grid(200, 200, start=(150, 150), goal=(199, 0)))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        view = app.query_one(GridView)
        region = view.scrollable_content_region

        def visible(cell) -> bool:
            sx, sy = view.scroll_offset
            return sx <= cell[0] * 2 < sx + region.width and sy <= cell[1] < sy + region.height

        assert visible((150, 150))
        await pilot.press("n")
        assert visible(app.session.run.now.current_node())
        app.session.run.goto(5000)
        await pilot.press("n")
        await pilot.pause()
        assert visible(app.session.run.now.current_node())
        for _ in range(30):
            await pilot.press("up")
        await pilot.pause()
        assert visible(app.session.cursor)


# -- files -------------------------------------------------------------------------------


@sync
async def test_ctrl_s_saves_to_the_maps_file_and_clears_dirty(tmp_path: Path) -> None:
    path = tmp_path / "tutorial.txt"
    path.write_text(TUTORIAL.read_text())
    app = SearchApp(load_map(path), path=path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("down", "down", "down", "down", "o")
        assert app.session.dirty
        await pilot.press("ctrl+s")
        await wait_until(pilot, lambda: not app.session.dirty)
        assert path.read_text() == format_text_map(app.session.grid)
        assert load_map(path).is_blocked((0, 4))


@sync
async def test_a_failed_save_leaves_the_old_file_and_says_why(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "tutorial.txt"
    old = TUTORIAL.read_text()
    path.write_text(old)
    app = SearchApp(load_map(path), path=path)

    def refuse(src, dst):
        raise PermissionError(13, "Permission denied")

    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("down", "o")
        monkeypatch.setattr(os, "replace", refuse)
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert path.read_text() == old
        assert app.session.dirty
        assert sorted(p.name for p in tmp_path.iterdir()) == ["tutorial.txt"]
        errors = [n for n in notifications(app) if n.severity == "error"]
        assert errors and "cannot save: permission denied" in errors[-1].message
        assert "\n" not in errors[-1].message


@sync
async def test_ctrl_s_without_a_file_asks_for_a_name(tmp_path: Path) -> None:
    app = tutorial_app(path=None)
    target = tmp_path / "mine.txt"
    async with app.run_test(size=SIZE) as pilot:
        app.session.cursor = (0, 5)
        await pilot.press("o")
        await pilot.press("ctrl+s")
        (await screen_shown(pilot, SaveAsScreen)).query_one("Input").value = str(target)
        await pilot.press("enter")
        await wait_until(pilot, lambda: not isinstance(app.screen, SaveAsScreen))
        assert target.read_text() == format_text_map(app.session.grid)
        assert app.session.map_path == target and not app.session.dirty


# -- help, quitting, small terminals -----------------------------------------------------


@sync
async def test_question_mark_opens_help_and_escape_closes_it() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("question_mark")
        await screen_shown(pilot, HelpScreen)
        await pilot.press("n")  # keys of the main screen do nothing under help
        await pilot.pause()
        assert app.session.run.k == 0
        await pilot.press("escape")
        await wait_until(pilot, lambda: not isinstance(app.screen, HelpScreen))


@sync
async def test_help_names_the_search_core_that_runs(monkeypatch) -> None:
    """Where pip hid the build's warning, the help screen's last line says which core runs."""
    from textual.widgets import Static

    from tui_search.engine.search.loops import compiled

    monkeypatch.setenv(compiled.CORE_ENV, "python")
    compiled.selected.cache_clear()
    try:
        app = tutorial_app()
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press("question_mark")
            await screen_shown(pilot, HelpScreen)
            about = app.screen.query_one("#help-about", Static)
            assert str(about.render()).endswith("(Python search core)")
    finally:
        compiled.selected.cache_clear()


def test_help_lists_every_key_of_the_binding_table() -> None:
    from textual.binding import Binding

    from tui_search.tui.dialogs.help import KEYS

    listed = " ".join(key for key, _ in KEYS).split()
    aliases = {"up": "arrows", "down": "arrows", "left": "arrows", "right": "arrows",
                "plus": "+", "minus": "-", "question_mark": "?", "comma": ",", "escape": "esc",
                "right_square_bracket": "]", "left_square_bracket": "[", "pageup": "pgup",
                "pagedown": "pgdn", "shift+left": "⇧←", "shift+right": "⇧→", "shift+up": "⇧↑",
                "shift+down": "⇧↓"}
    for binding in Binding.make_bindings(MainScreen.BINDINGS):
        assert aliases.get(binding.key, binding.key) in listed, binding.key


@sync
async def test_q_quits_at_once_when_nothing_is_unsaved() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("q")
        await wait_until(pilot, lambda: not app.is_running)
        assert app.return_code == 0


@sync
async def test_q_with_unsaved_edits_asks_first() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("down", "o", "q")
        await screen_shown(pilot, ConfirmQuitScreen)
        await pilot.press("n")  # stay
        await wait_until(pilot, lambda: not isinstance(app.screen, ConfirmQuitScreen))
        assert app.is_running
        await pilot.press("q")
        await screen_shown(pilot, ConfirmQuitScreen)
        await pilot.press("y")  # quit without saving
        await wait_until(pilot, lambda: not app.is_running)


@sync
async def test_save_and_quit_from_the_question(tmp_path: Path) -> None:
    path = tmp_path / "t.txt"
    path.write_text(TUTORIAL.read_text())
    app = SearchApp(load_map(path), path=path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("down", "o", "q")
        await screen_shown(pilot, ConfirmQuitScreen)
        await pilot.press("s")
        await wait_until(pilot, lambda: not app.is_running)
    assert load_map(path).is_blocked((0, 1))


@sync
async def test_a_terminal_too_small_shows_a_message_instead_of_the_layout() -> None:
    app = tutorial_app()
    async with app.run_test(size=(50, 15)) as pilot:
        await pilot.pause()
        message = app.main.small_note
        assert message.is_mounted and message.display and not app.query_one("#panes").display
        assert "need at least 60×20, have 50×15" in str(message.render())
    app = tutorial_app()
    async with app.run_test(size=(60, 20)) as pilot:
        await pilot.pause()
        assert not app.main.small_note.is_mounted  # mounted the first time it shows
        await pilot.resize_terminal(59, 30)
        await pilot.pause()
        assert app.main.small_note.display
        await pilot.resize_terminal(80, 24)
        await pilot.pause()
        assert not app.main.small_note.display and app.query_one("#panes").display


# -- the engine contract the app relies on -----------------------------------------------


def test_step_changes_names_every_cell_a_step_changes() -> None:
    """Repainting only step_changes' cells gives the same picture as repainting everything."""
    for algorithm in ("bfs", "dfs", "iddfs"):
        run = Run(load_map(TUTORIAL), algorithm)
        before = [run.now.row_states(y) for y in range(6)]
        while True:
            old_k, was_end = run.k, run.at_end
            if not run.forward():
                break
            after = [run.now.row_states(y) for y in range(6)]
            changed = playback.step_changes(run, old_k, was_end)
            if changed is not None:
                diff = {(x, y) for y in range(6) for x in range(6) if before[y][x] != after[y][x]}
                assert diff <= set(changed), (algorithm, run.k)
            before = after


@sync
async def test_the_key_bar_dims_keys_that_cannot_act_and_a_click_presses_a_key() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        bar = app.query_one(KeyBar)

        def enabled() -> dict[str, bool]:
            return {key: on for keys, _, _ in bar.hints() for _, key, on in keys}

        hints = bar.hints()
        assert [desc for _, desc, _ in hints][:3] == ["Step", "Play", "BFS/DFS/ID/UCS/GBF/A*"]
        assert [display for display, _, _ in hints[0][0]] == ["n", "p"]
        assert enabled()["n"] and not enabled()["p"]  # step 0: nothing to go back to
        await pilot.click(KeyBar, offset=(1, 0))  # the "n" of "np Step" (after the padding)
        await pilot.pause()
        assert app.session.run.k == 1 and enabled()["p"]
        await pilot.click(KeyBar, offset=(2, 0))  # the "p"
        await pilot.pause()
        assert app.session.run.k == 0
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        await pilot.pause()
        assert not enabled()["n"] and enabled()["p"]


@sync
async def test_a_run_that_reaches_the_step_limit_says_it_gave_up() -> None:
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, algorithm="iddfs", max_steps=30)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        await pilot.pause()
        assert app.session.run.k == 30 and app.session.run.gave_up
        status, narration = stats(app)
        assert "step 30/30" in status
        assert narration.endswith(". Gave up at --max-steps 30")
    # Ending an iteration exactly at the limit: the empty stack does not claim "no path".
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, algorithm="iddfs", max_steps=1)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        await pilot.pause()
        assert app.session.run.gave_up and app.session.run.now.frontier_len() == 0
        assert app.query_one(FrontierPanel).lines() == ["empty — gave up at --max-steps 1"]


@sync
async def test_a_movingai_map_opens_with_its_scenario_and_z_shows_it_whole() -> None:
    """``tui-search arena.map --scen arena.map.scen --scen-row 5``, as the CLI builds it."""
    from tui_search.cli.parse import parse_options

    arena = ARENA
    options = parse_options([str(arena), "--scen", f"{arena}.scen", "--scen-row", "5"])
    grid, path = options.grid, options.path
    scen = load_scenario(f"{arena}.scen", 5)
    app = SearchApp(grid, path=path)
    async with app.run_test(size=(120, 40)) as pilot:
        assert (app.session.grid.width, app.session.grid.height) == (49, 49)
        assert app.session.grid.start == scen.start and app.session.grid.goal == scen.goal
        assert app.session.cursor == scen.start
        assert app.query_one(GridView).border_title == "arena.map"
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        assert app.session.run.found
        assert app.session.run.path()[-1] == scen.goal
        await pilot.press("z")
        await pilot.pause()
        assert app.query_one(GridView).overview
