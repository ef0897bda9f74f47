"""What a trace may leave out or add (the goal's pop, successors, ``{"path": null}``), the
messages a student can act on (one cause each; swapped coordinates; never "reached already, or
the corner rule refuses it"), the ranking when nothing matches, and the property: the app's own
trace of every search under every choice of published code matches exactly those choices, and
matches with the goal's line removed too."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from tests.engine.test_published_choices import published_semantics
from tests.engine.test_search import random_grids
from tests.engine.test_trace import app_trace, lines
from tests.helpers import grid_from_rows
from tests.students import dfs_recursive_neighbours
from tui_search.engine.maps.generate import generated_text, make_recipe
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import parse_map_text
from tui_search.engine.maps.read import MapError
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import ALGORITHMS
from tui_search.engine.traces.check import (
    EXPANSIONS_ONLY,
    GOAL_LEFT_OUT,
    GOAL_LISTED,
    check_trace,
)
from tui_search.engine.traces.diagnose import diagnose
from tui_search.engine.traces.read import read_trace

ROOT = Path(__file__).resolve().parents[2]
ROWS = ["S.....", ".##.#.", "...#..", ".#...#", "...#.G", "......"]
GRID = grid_from_rows(ROWS)
NESW = ("N", "E", "S", "W")


def objs(text: str) -> list[dict]:
    return [json.loads(line) for line in text.splitlines()]


def test_the_goal_s_pop_may_be_left_out_or_listed() -> None:
    """A search that tests the goal when it takes it off ends with the goal's pop: a trace
    without that line matches, and says so; one that tests it when it adds it stops before the
    pop: a trace that lists it matches too."""
    on_pop = Semantics(order=NESW, goal_test="expand")
    trace = objs(app_trace(GRID, "bfs", on_pop))
    assert trace[-1]["node"] == list(GRID.goal) and trace[-1]["successors"] == []
    verdict = check_trace(read_trace(lines(*trace[:-1]), GRID, "t"), GRID, "bfs", on_pop)
    assert verdict.matches and verdict.notes == (GOAL_LEFT_OUT,)
    on_push = Semantics(order=NESW)
    pushed = objs(app_trace(GRID, "bfs", on_push)) + [{"node": list(GRID.goal)}]
    verdict = check_trace(read_trace(lines(*pushed), GRID, "t"), GRID, "bfs", on_push)
    assert verdict.matches and verdict.notes == (GOAL_LISTED,)
    # the goal's pop listed with successors is not a pop: the search stopped
    wrong = pushed[:-1] + [{"node": list(GRID.goal), "successors": [[5, 5]]}]
    assert not check_trace(read_trace(lines(*wrong), GRID, "t"), GRID, "bfs", on_push).matches


def test_a_trace_of_expansions_only_is_checked_on_their_order_and_says_so() -> None:
    sem = Semantics(order=NESW)
    nodes = [{"node": o["node"]} for o in objs(app_trace(GRID, "dfs", sem))]
    trace = read_trace(lines(*nodes), GRID, "t")
    assert all(not t.listed for t in trace.steps)
    verdict = check_trace(trace, GRID, "dfs", sem)
    assert verdict.matches and EXPANSIONS_ONLY in verdict.notes
    assert "note: your trace lists no successors" in verdict.text()
    out_of_turn = [nodes[0], nodes[2], nodes[1], *nodes[3:]]
    verdict = check_trace(read_trace(lines(*out_of_turn), GRID, "t"), GRID, "dfs", sem)
    assert verdict.difference is not None and verdict.difference.step == 2


def test_a_path_of_null_says_no_path_was_found() -> None:
    text = app_trace(GRID, "bfs", Semantics(order=NESW)) + '{"path": null}\n'
    trace = read_trace(text, GRID, "t")
    assert trace.path == ()
    with pytest.raises(MapError, match='"path" should be a list of'):
        read_trace('{"node": [0, 0]}\n{"path": 3}\n', GRID, "t")


def test_swapped_coordinates_are_named_where_a_cell_is_refused() -> None:
    """x is the column, y the row: a student who writes [row, column] names an obstacle (or a
    cell off the map) where the swapped cell is free."""
    with pytest.raises(MapError) as raised:
        read_trace('{"node": [0, 0], "successors": [[1, 1]]}\n', GRID, "t.jsonl")
    assert "x is the column" not in raised.value.message  # (1,1) and its swap: obstacles
    grid = grid_from_rows(["S#", "..", ".G"])
    with pytest.raises(MapError) as raised:
        read_trace('{"node": [0, 0], "successors": [[1, 0]]}\n', grid, "t.jsonl")
    assert raised.value.message == ("successor (1,0) is an obstacle; x is the column, y the "
                                    "row: swapped?")
    with pytest.raises(MapError, match="off the map .*: swapped?"):
        read_trace('{"node": [0, 0], "successors": [[2, 0]]}\n', grid, "t.jsonl")


def test_no_message_hedges_between_two_causes() -> None:
    """"reached already, or the corner rule refuses it" is gone: the app knows which."""
    for path in (ROOT / "tui_search").rglob("*.py"):
        text = path.read_text()
        assert "or the corner rule" not in text, path
        assert "reached already, or" not in text, path


def test_the_corner_rule_is_named_when_it_refuses_a_successor() -> None:
    grid = grid_from_rows(["S#.", ".#.", "..G"])
    sem = Semantics(corners="never")
    text = lines({"node": [0, 0], "successors": [[0, 1], [1, 1]]})
    with pytest.raises(MapError):  # (1,1) is an obstacle: read refuses it first
        read_trace(text, grid, "t")
    grid = grid_from_rows(["S#.", "...", "..G"])
    verdict = check_trace(read_trace(lines({"node": [0, 0], "successors": [[0, 1], [1, 1]]}),
                                     grid, "t"), grid, "bfs", sem)
    assert verdict.difference is not None
    assert verdict.difference.message.endswith(
        "the move SE passes a blocked corner, and the corner rule never refuses it")


def test_when_nothing_matches_no_bfs_or_dfs_is_above_an_a_star_that_matched_longer() -> None:
    """An A* trace with its last steps changed: the closest are listed by steps matched, an
    A* first, every one of them with where it parts."""
    trace = objs(app_trace(GRID, "astar", Semantics(order=NESW, heuristic="manhattan")))
    trace[-3]["successors"] = list(reversed(trace[-3]["successors"])) + [[5, 5]]
    diagnosis = diagnose(read_trace(lines(*trace), GRID, "t"), GRID)
    assert not diagnosis.matches
    matched = [v.matched for v in diagnosis.best]
    assert matched == sorted(matched, reverse=True)
    assert diagnosis.best[0].algorithm == "astar" and matched[0] >= len(trace) - 3
    assert diagnosis.text().splitlines()[1].startswith("  A* (manhattan; ")


def test_a_recursive_dfs_on_a_generated_perfect_maze_is_named_a_recursive_dfs() -> None:
    """The issue's case: on a generated perfect maze a recursive DFS was reported as
    greedy best-first for all its steps."""
    recipe = make_recipe("maze", "9x9", "4")
    text = generated_text(recipe)
    grid = parse_map_text(text, "maze")
    rows = [line for line in text.splitlines() if line and not line.startswith(";")]
    diagnosis = diagnose(read_trace(dfs_recursive_neighbours.search(rows), grid, "t"), grid)
    assert diagnosis.matches
    assert diagnosis.best[0].semantics.recursive and diagnosis.best[0].algorithm == "dfs"


published = settings(max_examples=60, deadline=None,
                     suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


def _goal_line_removed(text: str, grid: Grid) -> str | None:
    """The trace without its last line when that is the goal's pop (None: it is not)."""
    rows = objs(text)
    if rows and rows[-1]["node"] == list(grid.goal) and not rows[-1]["successors"]:
        return lines(*rows[:-1]) if len(rows) > 1 else None
    return None


@published
@given(random_grids(max_side=6), st.one_of(published_semantics(), st.tuples(
    st.sampled_from(sorted(ALGORITHMS)), st.builds(Semantics, order=st.just(NESW)))))
def test_the_apps_own_trace_matches_exactly_its_choices(grid: Grid, choice) -> None:
    """The app's own --trace of every search, under every choice of published code, checks
    as a full match of exactly those choices -- and so does the trace with the goal's line
    removed (the goal's pop is optional)."""
    key, sem = choice
    assume(not sem.refusal(ALGORITHMS[key]))
    text = app_trace(grid, key, sem, max_steps=300)
    assume(text)  # the start is the goal: no step
    verdict = check_trace(read_trace(text, grid, "t"), grid, key, sem, max_steps=300)
    assert verdict.matches, verdict.text()
    shorter = _goal_line_removed(text, grid)
    if shorter is not None:
        verdict = check_trace(read_trace(shorter, grid, "t"), grid, key, sem, max_steps=300)
        assert verdict.matches and verdict.notes == (GOAL_LEFT_OUT,), verdict.text()


@settings(max_examples=40, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(random_grids(max_side=5), published_semantics())
def test_the_diagnosis_finds_a_full_match_of_the_apps_own_trace(grid: Grid, choice) -> None:
    """Without -a: the choices of published code are tried where a candidate parts for
    their reason, so the app's own trace under them is matched all through by some search.
    An order reversed on every other cell is tried as a shape of its own (where the trace
    reads so), with the others' choices as variants: it is held to it alone, not beside
    other choices of published code at once."""
    key, sem = choice
    assume(not sem.flip_even or sem.replace(flip_even=False).plain)
    text = app_trace(grid, key, sem, max_steps=200)
    assume(text and len(text.splitlines()) < 200)  # not cut short at the limit
    diagnosis = diagnose(read_trace(text, grid, "t"), grid)
    assert diagnosis.matches, (key, sem, diagnosis.text())


def test_a_recursions_first_call_tells_which_move_comes_first() -> None:
    """The property's rare example: a recursive DFS listing its calls, where the trace's
    lines say only which cell each call recursed into first.  From (1,2) it called NE, with W
    free, and from (2,1) E, with NE (the goal) free: E, then NE, then W, which no single line
    shows.  The diagnosis moves the trace's call before the search's where a candidate parts
    there, and so finds it."""
    grid = grid_from_rows(["...G#", ".....", "..S#."])
    sem = Semantics(order=("SE", "E", "NE", "W", "N", "S", "SW", "NW"), corners="never",
                    recursive="calls")
    text = app_trace(grid, "dfs", sem, max_steps=200)
    diagnosis = diagnose(read_trace(text, grid, "t"), grid)
    assert diagnosis.matches, diagnosis.text()
    first = diagnosis.text().splitlines()[0]
    assert first.startswith("your trace is a recursive DFS (order E,NE,W,"), first
