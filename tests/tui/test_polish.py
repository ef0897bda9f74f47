"""Nothing lost, nothing confusing: ``end`` on a big map never holds the keys up (and esc stops
it), keys do nothing behind the "too small" message, the key bar says Pause and keeps help and
quit, and small things: one digit grouping, the built-in map's title, space at the end, the
stack's columns."""

from __future__ import annotations

import re

import pytest

from tests.tui.test_app import SIZE, TUTORIAL, open_grid, stats, sync, tutorial_app, wait_until
from tui_search.cli import main as cli
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run
from tui_search.tui.app import SearchApp
from tui_search.tui.model import playback
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar
from tui_search.tui.widgets.search_tree import SearchTreePanel


def walled_goal(side: int) -> Grid:
    """An open map whose goal, in the far corner, is walled off: a search sees every cell."""
    grid = open_grid(side, side)
    for cell in ((side - 2, side - 2), (side - 1, side - 2), (side - 2, side - 1)):
        grid.set_blocked(cell, True)
    return grid


def shown(app: SearchApp) -> list[str]:
    """The descriptions of the key bar's hints as drawn (those that fit)."""
    return [description for _, description, _ in app.query_one(KeyBar).shown_hints()]


# -- item 8 and 9: `end` in slices, esc, keys act at once ----------------------------------


@pytest.fixture
def one_slice(monkeypatch: pytest.MonkeyPatch) -> None:
    """``end`` does one small piece of work and then waits (an hour) for its next slice: what
    a key pressed meanwhile does is then certain, not a race against the clock."""
    monkeypatch.setattr(Run, "REBUILD_PIECE", 64)
    monkeypatch.setattr(playback, "SLICE_SECONDS", 0.0)
    monkeypatch.setattr(playback, "SLICE_PAUSE", 3600.0)


@sync
async def test_a_key_pressed_while_end_moves_to_the_last_step_acts_at_once(one_slice) -> None:
    """The move to the last step (the bulk rebuild, which blocked for seconds on a big map)
    is done in slices too: the status line says how to stop it, the key bar shows esc, and a
    step key stops it where it is and steps."""
    app = SearchApp(open_grid(120, 120))
    app.session.run.advance()  # recorded: `end` goes straight to moving there
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        run = app.session.run
        assert app.session.seeking and run.k == 0  # whole at step 0 until the move is done
        narration = stats(app)[1]
        assert narration.startswith(f"Moving to step {run.recorded:,}… ") and narration.endswith(
            " — esc to stop")
        assert "Stop" in shown(app)
        await pilot.press("n")
        assert not app.session.seeking and run.k == 1 and not run.at_end
        assert "esc" not in stats(app)[1] and "Stop" not in shown(app)


@sync
async def test_esc_stops_end_while_it_records(one_slice) -> None:
    app = SearchApp(open_grid(80, 80), algorithm="iddfs")  # 3.4 M steps to record
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        run = app.session.run
        assert app.session.seeking
        assert stats(app)[1].startswith("Computing the search… ")
        assert stats(app)[1].endswith(" steps recorded — esc to stop")
        await pilot.press("escape")
        assert not app.session.seeking and run.k == 0 and not run.done
        assert stats(app)[1].startswith("START (0,0) is on the stack")
        assert "Stop" not in shown(app)
        await pilot.press("escape")  # nothing to stop: nothing happens
        assert run.k == 0 and not app.session.seeking


@sync
async def test_esc_stops_end_while_it_moves_and_leaves_the_run_where_it_was(one_slice) -> None:
    app = SearchApp(walled_goal(120), algorithm="dfs")
    app.session.run.advance()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        before = (app.session.run.k, app.session.run.now.frontier(), stats(app))
        await pilot.press("end")
        assert app.session.seeking and stats(app)[1].startswith("Moving to step")
        await pilot.press("escape")
        run = app.session.run
        assert not app.session.seeking
        assert (run.k, run.now.frontier(), stats(app)) == before


@sync
async def test_end_left_alone_gets_there_in_many_slices(monkeypatch: pytest.MonkeyPatch) -> None:
    calls: list[float | None] = []
    rebuild_for = playback.rebuild_for

    def counted(pieces, seconds=None):
        calls.append(result := rebuild_for(pieces, seconds))
        return result

    monkeypatch.setattr(Run, "REBUILD_PIECE", 512)
    monkeypatch.setattr(playback, "SLICE_SECONDS", 0.0)
    monkeypatch.setattr(playback, "rebuild_for", counted)
    app = SearchApp(walled_goal(120), algorithm="dfs")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: not app.session.seeking, 60)
        run = app.session.run
        assert run.at_end and not run.found and run.k > 14_000
        assert stats(app)[1].endswith("Frontier empty: no path")
        stepped = Run(walled_goal(120), "dfs")
        stepped.advance()
        while stepped.forward():
            pass
        assert run.now.frontier() == stepped.now.frontier() and run.k == stepped.k
        assert run.steps.peak_frontier() == stepped.steps.peak_frontier()
    assert len(calls) > 10 and calls[-1] is None and all(c is not None for c in calls[:-1])


@sync
async def test_home_from_far_moves_in_slices_too(monkeypatch: pytest.MonkeyPatch) -> None:
    app = SearchApp(open_grid(120, 120))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: not app.session.seeking, 60)
        run = app.session.run
        total = run.k
        monkeypatch.setattr(Run, "REBUILD_PIECE", 64)
        monkeypatch.setattr(playback, "SLICE_SECONDS", 0.0)
        monkeypatch.setattr(playback, "SLICE_PAUSE", 3600.0)
        await pilot.press("home")
        assert app.session.seeking and run.k == total
        assert stats(app)[1].startswith("Moving to step 0… ")
        await pilot.press("escape")
        assert not app.session.seeking and run.k == total and run.at_end
        monkeypatch.setattr(playback, "SLICE_PAUSE", 0.01)
        await pilot.press("home")
        await wait_until(pilot, lambda: not app.session.seeking, 60)
        assert run.k == 0 and stats(app)[1].startswith("START (0,0) is on the queue")


# -- item 11: behind "terminal too small" only q acts --------------------------------------


@sync
async def test_keys_do_nothing_behind_the_too_small_message() -> None:
    app = tutorial_app()
    async with app.run_test(size=(40, 12)) as pilot:
        assert app.screen.has_class("-too-small")
        walls = app.session.grid.copy()
        await pilot.press("n", "n", "n", "end", "space", "o", "right", "3", "z", "question_mark")
        await pilot.pause()
        run = app.session.run
        assert run is not None and run.k == 0
        assert not app.session.playing and not app.session.seeking
        assert app.session.run is run and app.session.algorithm == "bfs"  # no new run either
        assert app.session.grid == walls and not app.session.dirty and app.session.cursor == (0, 0)
        assert not app.query_one(GridView).overview and len(app.screen_stack) == 1
        await pilot.resize_terminal(*SIZE)  # big enough again: the keys act
        await wait_until(pilot, lambda: not app.screen.has_class("-too-small"))
        await pilot.press("n")
        await wait_until(pilot, lambda: app.session.run.k == 1)
        await pilot.resize_terminal(40, 12)
        await wait_until(pilot, lambda: app.screen.has_class("-too-small"))
        await pilot.press("q")
        await wait_until(pilot, lambda: not app.is_running)
    assert app.return_code == 0


# -- item 12: Play / Pause, and the key bar keeps help and quit ------------------------------


@sync
async def test_the_key_bar_says_pause_while_playing() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        assert "Play" in shown(app) and "Pause" not in shown(app)
        await pilot.press("space")
        assert app.session.playing
        await pilot.pause()
        assert "Pause" in shown(app) and "Play" not in shown(app)
        await pilot.press("space")
        assert not app.session.playing
        await pilot.pause()
        assert "Play" in shown(app) and "Pause" not in shown(app)


@sync
async def test_a_narrow_key_bar_drops_the_least_important_hints_never_help_and_quit() -> None:
    app = tutorial_app()
    async with app.run_test(size=(60, 20)) as pilot:
        bar = app.query_one(KeyBar)
        hints = shown(app)
        assert hints[-2:] == ["Help", "Quit"] and hints[:2] == ["Step", "Play"]
        assert len(hints) < len(bar.hints())  # not all fit: Zoom, Save, Reset went
        assert "Zoom" not in hints and "Reset" not in hints
        assert "? Help  q Quit" in bar.render_line(0).text
        await pilot.press("space")
        await pilot.pause()
        assert "Pause" in shown(app) and shown(app)[-2:] == ["Help", "Quit"]
    # Wide enough (150 columns), nothing is dropped.
    app = tutorial_app()
    async with app.run_test(size=(150, 32)):
        assert shown(app) == [desc for _, desc, _ in app.query_one(KeyBar).hints()]


@sync
async def test_a_hint_wider_than_the_bar_ends_in_an_ellipsis() -> None:
    from typing import ClassVar

    from textual.app import App, ComposeResult
    from textual.binding import BindingType

    class OneKey(App[None]):
        BINDINGS: ClassVar[list[BindingType]] = [("q", "quit", "Quit the app")]

        def compose(self) -> ComposeResult:
            yield KeyBar(id="keys")

    app = OneKey()
    async with app.run_test(size=(9, 3)) as pilot:  # 7 columns inside the bar's padding
        bar = app.query_one(KeyBar)
        await pilot.pause()
        line = bar.render_line(0)
        assert line.text == "q Quit…" and line.cell_length == 7
        await pilot.click(KeyBar, offset=(1, 0))  # its key still presses it
        await pilot.pause()
    assert app.return_code == 0


# -- item 13: small things -----------------------------------------------------------------


@sync
async def test_counts_are_grouped_with_commas_everywhere() -> None:
    app = SearchApp(open_grid(300, 300, start=(150, 150)))
    app.session.run.advance()
    async with app.run_test(size=SIZE) as pilot:
        app.session.run.goto(70_000)
        app.main.present()
        await pilot.pause()
        run = app.session.run
        n, size = run.now.frontier_len(), run.now.tree_size()
        assert n > 999 and size > 999
        assert app.query_one(FrontierPanel).line_text(0) == f"{n:,} in the queue"
        assert f"{size:,} nodes" in app.query_one(SearchTreePanel).line_text(0)
        assert f"generated {run.now.generated:,}" in stats(app)[0]
        assert f"step 70,000/{run.total:,}" in stats(app)[0]


@sync
async def test_a_path_of_thousands_of_moves_is_grouped_and_the_end_expands_nothing() -> None:
    """``path: 1,200 moves`` beside ``generated 1,201``, as every count; and at the end the
    tree's last node expanded no longer says "◀ expanding" (the search is over)."""
    app = SearchApp(Grid(1, 1201, start=(0, 0), goal=(0, 1200)))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n")
        tree = app.query_one(SearchTreePanel)
        await wait_until(pilot, lambda: "◀ expanding" in "".join(
            tree.line_text(y) for y in range(4)))
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        app.main.present()
        await pilot.pause()
        status, narration = stats(app)
        assert "path: 1,200 moves" in narration and "generated 1,201" in status
        shown = [tree.line_text(y) for y in range(tree.model.line_count())]
        assert not any("◀ expanding" in line for line in shown)


@sync
async def test_the_built_in_map_is_titled_tutorial_built_in(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    started: list[SearchApp] = []
    monkeypatch.setattr(SearchApp, "run", lambda self: started.append(self))
    assert cli.main([]) == 0  # `tui-search` with no map
    (app,) = started
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        assert view.border_title == "tutorial (built-in)"
        await pilot.press("right", "o")  # an edit
        assert view.border_title == "tutorial (built-in) · modified"
    # A map from a file keeps its file's name.
    started.clear()
    assert cli.main([str(TUTORIAL)]) == 0
    async with started[0].run_test(size=SIZE):
        assert started[0].query_one(GridView).border_title == "tutorial.txt"


@sync
async def test_space_at_the_last_step_plays_again_from_step_0() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        total = app.session.run.k
        await pilot.press("space")
        assert app.session.playing and app.session.run.k < total
        assert app.main.check_action("play", ()) is False
        assert app.main.check_action("pause", ()) is True


@sync
async def test_space_at_the_last_step_of_a_big_run_slides_back_then_plays() -> None:
    app = SearchApp(open_grid(120, 120))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: not app.session.seeking, 60)
        total = app.session.run.k
        assert total > app.session.run.REBUILD_AFTER
        await pilot.press("space")
        await wait_until(pilot, lambda: not app.session.seeking, 60)
        assert app.session.playing and app.session.run.k < 100 < total


@sync
async def test_stack_columns_stand_in_the_same_place_for_start_and_moves() -> None:
    """``d=0 START`` and ``d=1 S``: one space between columns, the move in the same column
    whatever its label (it comes last, after the depth)."""
    app = tutorial_app("iddfs")
    async with app.run_test(size=SIZE) as pilot:
        panel = app.query_one(FrontierPanel)
        entry = re.compile(r"\(\d+,\d+\) (d=\d+) (\S+)")
        assert "(0,0) d=0 START" in panel.lines()[1]  # under the count line
        columns, labels = set(), set()
        for _ in range(8):
            for line in panel.lines():
                if match := entry.search(line):
                    columns.add(match.start(2))
                    labels.add(match.group(2))
            await pilot.press("n")
        assert {"START", "S", "SE"} <= labels and len(columns) == 1, (labels, columns)



@sync
async def test_a_slice_of_end_due_after_the_app_closed_does_nothing(one_slice) -> None:
    """Seen: leaving the app while `end` computed, the next slice came due as it closed and
    found no screen to show the run on (a traceback on the way out)."""
    app = SearchApp(open_grid(120, 120))
    app.session.run.advance()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        assert app.session.seeking
    app.main.playback.seek_slice()  # what the pending timer would do
    assert app.session.run.k == 0
