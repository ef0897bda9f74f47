"""``--replay FILE`` driven by Pilot: the trace and its search in lockstep, the frontier as
added, the first difference marked on both maps and in the status line, and the key that
jumps there and back."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from tests.engine.student_searches import bfs, dfs_recursive
from tests.helpers import TUTORIAL, TUTORIAL_ROWS
from tests.tui.test_app import sync, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.choices import Semantics
from tui_search.engine.traces.read import read_trace
from tui_search.engine.traces.replay import replay_of
from tui_search.tui.app import SearchApp
from tui_search.tui.view.narration import narrate
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.run_pane import RunPane
from tui_search.tui.widgets.stats import Stats

NWSE = Semantics(order=("N", "W", "S", "E"))


def replay_app(bug_at: int | None = 9, theme: str | None = None) -> SearchApp:
    """The app replaying a student's BFS (order N,W,S,E) that takes the newest entry once, at
    step ``bug_at``, beside the app's BFS with that order (in ``theme``: None, the default)."""
    grid = load_map(TUTORIAL)
    trace = read_trace(bfs(TUTORIAL_ROWS, "N,W,S,E", bug_at=bug_at), grid, "trace.jsonl")
    replay = replay_of(trace, grid, "bfs", NWSE)
    return SearchApp(grid, path=TUTORIAL, algorithm="bfs", semantics=NWSE, replay=replay,
                     theme=theme)


def status(app: SearchApp) -> str:
    stats = app.screen.query_one("#stats", Stats)
    return stats.status_text + " " + stats.narration_text


@sync
async def test_replay_steps_both_ways_in_lockstep_and_jumps_to_the_difference() -> None:
    app = replay_app()
    async with app.run_test(size=(120, 40)) as pilot:
        session = app.session
        panes = list(app.screen.query(RunPane))
        assert [p.label for p in panes] == ["your trace", "BFS"]
        trace_run, bfs_run = session.runs
        assert trace_run.algo.short == "your trace"
        # the trace's line names its file, not the moves of the search it is beside
        assert "trace.jsonl" in panes[0].stats.status_text
        assert "moves" not in panes[0].stats.status_text
        assert "moves N,W,S,E" in panes[1].stats.status_text
        # the first difference: in the status line from the start, and marked on both maps
        assert "step 9: your trace expands" in status(app)
        got, expected = session.jumps.replay.marks()
        assert got is not None and expected is not None and got != expected
        assert [p.view.marks for p in panes] == [frozenset({got}), frozenset({expected})]
        # stepping: both runs, both ways
        await pilot.press("n", "n")
        assert (trace_run.k, bfs_run.k) == (2, 2)
        await pilot.press("p")
        assert (trace_run.k, bfs_run.k) == (1, 1)
        # the trace's narration says what its step did in the app's own words
        trace_words = panes[0].stats.narration_text
        assert trace_words.replace("frontier", "queue") == panes[1].stats.narration_text
        # its frontier panel: in the order added, and says the trace gives no discipline
        frontier = panes[0].query_one(FrontierPanel)
        assert "as added" in str(frontier.border_title)
        # d: to the first difference, and back to where it was
        await pilot.press("d")
        await wait_until(pilot, lambda: trace_run.k == 9)
        assert bfs_run.k == 9
        assert trace_run.steps.at(9).node == got and bfs_run.steps.at(9).node == expected
        await pilot.press("d")
        await wait_until(pilot, lambda: trace_run.k == 1)
        assert bfs_run.k == 1


@sync
async def test_a_trace_that_matches_has_no_difference_key_and_an_edit_ends_the_replay() -> None:
    app = replay_app(bug_at=None)
    async with app.run_test(size=(120, 40)) as pilot:
        session = app.session
        assert "your trace matches BFS" in status(app)
        assert session.jumps.difference_step is None
        assert app.screen.check_action("difference", ()) is False
        assert all(not v.marks for v in app.screen.query(GridView))
        await pilot.press("down", "o")  # an obstacle under the trace: the replay is over
        await wait_until(pilot, lambda: session.jumps.replay is None)
        await wait_until(pilot, lambda: [p.label for p in app.screen.query(RunPane)] == ["BFS"])
        assert "replay of your trace is over" in status(app)


def test_the_session_jumps_to_the_difference_and_back_from_anywhere() -> None:
    """Without Textual: d from step 4 goes to step 9, again back to 4; from step 9 itself (no
    step to go back to) it stays; another search ends the replay."""
    session = replay_app().session
    session.goto(4)
    session.jumps.to_difference()
    assert [r.k for r in session.runs] == [9, 9]
    session.jumps.to_difference()
    assert [r.k for r in session.runs] == [4, 4]
    session.goto(9)
    session.jumps.to_difference()
    assert [r.k for r in session.runs] == [9, 9]
    assert session.jumps.lockstep_sentence(80).endswith("· d: to it and back")
    session.choose_algorithm("dfs")
    assert session.jumps.replay is None and session.labels == ["DFS"]
    assert session.jumps.marks() == [None] and session.jumps.difference_step is None


@sync
async def test_a_recursive_dfs_is_replayed_beside_the_recursion_it_is() -> None:
    """A student's recursive DFS (order E,S,W,N) replayed without -a: the search's pane is
    the recursive DFS, named 'DFS (recursive)', its status says so; the line under the panes
    says the trace matches it; the trace's line says the order it inferred; the panes keep in
    step, a cell the same at every step (the recursion's skips of cells visited meanwhile,
    which the trace leaves out, put back)."""
    grid = load_map(TUTORIAL)
    trace = read_trace(dfs_recursive(TUTORIAL_ROWS, "E,S,W,N"), grid, "rec.jsonl")
    app = SearchApp(grid, path=TUTORIAL, replay=replay_of(trace, grid, None, Semantics()))
    async with app.run_test(size=(120, 40)) as pilot:
        panes = list(app.screen.query(RunPane))
        assert [p.label for p in panes] == ["your trace", "DFS (recursive)"]
        said = status(app)
        assert "your trace matches a recursive DFS (order E,S," in said
        assert "rec.jsonl" in panes[0].stats.status_text
        assert "order E,S," in panes[0].stats.status_text
        assert "inferred" in panes[0].stats.status_text
        assert "recursive (a line lists the neighbours)" in panes[1].stats.status_text
        assert app.screen.check_action("difference", ()) is False
        ours, theirs = app.session.runs
        await pilot.press("end")
        await wait_until(pilot, lambda: ours.at_end and theirs.at_end)
        assert ours.k == theirs.k > len(trace.steps)  # the skips put back
        assert [(s.node, s.discarded) for s in ours.steps.all()] == [
            (s.node, s.discarded) for s in theirs.steps.all()]


def test_a_trace_that_stops_with_cells_left_does_not_say_its_frontier_is_empty() -> None:
    """A trace cut short ends with cells on its frontier: its last narration says it stops
    there, not that the frontier is empty, nor that moves it never declared block the way."""
    grid = load_map(TUTORIAL)
    lines = dfs_recursive(TUTORIAL_ROWS, "E,S,W,N").splitlines()
    trace = read_trace("\n".join(lines[:-3]) + "\n", grid, "rec.jsonl")
    ours, _ = replay_of(trace, grid, None, Semantics()).runs(grid)
    ours.advance()
    ours.goto(ours.total)
    said = narrate(ours)
    assert said.endswith(f"It stops here, {ours.now.frontier_len()} still on the frontier: "
                         "no path found")
    assert "empty" not in said and "block" not in said


def test_the_readme_examples_replay_names_no_moves_at_its_end() -> None:
    """The replay example of docs/03-traces.md (examples/student_bfs.py on maps/tutorial.txt)
    finds no path: at its end the trace's pane says its frontier is empty, not that moves block
    the way -- the trace declared none (the moves are the matched search's, inferred).  The
    search beside it keeps its reason: those are its own rules."""
    example = Path(__file__).resolve().parents[2] / "examples" / "student_bfs.py"
    done = subprocess.run([sys.executable, str(example), TUTORIAL], capture_output=True,
                          text=True, check=True, timeout=60)
    grid = load_map(TUTORIAL)
    ours, theirs = replay_of(read_trace(done.stdout, grid, "trace.jsonl"), grid, None,
                             Semantics()).runs(grid)
    for run in (ours, theirs):
        run.advance()
        run.goto(run.total)
    assert narrate(ours).endswith(". Frontier empty: no path")
    assert "block" in narrate(theirs)
