"""Reading a trace another program wrote, and checking it against one search: every error
message, every kind of difference, and the app's own traces held equal to their searches."""

from __future__ import annotations

import io
import json
from collections.abc import Callable

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.cli.headless import search_headless
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import MapError
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics
from tui_search.engine.traces.check import check_trace
from tui_search.engine.traces.read import read_trace

GRID = grid_from_rows(TUTORIAL_ROWS)
NWSE = Semantics(order=("N", "W", "S", "E"))


def app_trace(grid: Grid, key: str, sem: Semantics, max_steps: int = 10_000) -> str:
    out = io.StringIO()
    search_headless(grid, key, sem, max_steps, out)
    return out.getvalue()


def lines(*objs: object) -> str:
    return "\n".join(json.dumps(o) for o in objs) + "\n"


@pytest.mark.parametrize("text, line, message", [
    ('{"node": [0, 0], "successors": []}\n{"node": [0, 1]\n', 2, "not JSON: Expecting"),
    ("[1, 2]\n", 1, "each line should be a JSON object"),
    (lines({"node": [0, 0], "successors": [[6, 0]]}), 1,
     "successor (6,0) is off the map (6x6: x 0..5, y 0..5)"),
    (lines({"node": [0, 0], "successors": [[1, 0]]}), 1, "successor (1,0) is an obstacle"),
    (lines({"node": [0, 0], "successors": [{"dir": "S"}]}), 1,
     'a successor object needs "node": [x, y]'),
    (lines({"node": [0, 0], "successors": [[0, 1]]}, {"node": [0, 2], "successors": []}), 2,
     "expands (0,2), which no earlier line added (nor is it the start)"),
    (lines({"start": [0, 1], "goal": [5, 2]}, {"node": [0, 1], "successors": []}), 1,
     "the trace starts at (0,1), the map at (0,0)"),
    (lines({"start": [0, 0], "goal": [5, 3]}), 1, "the trace's goal is (5,3), the map's (5,2)"),
    (lines({"node": [0, 0], "successors": []}, {"path": [[0, 0]]},
           {"node": [0, 0], "successors": []}), 2, 'the "path" line should be the last'),
    (lines({"node": ["a", 0], "successors": []}), 1, "node should be [x, y], two whole numbers"),
    (lines({"successors": []}), 1, 'an expansion needs "node": [x, y]'),
])
def test_malformed_traces_are_one_line_errors_with_the_line(text, line, message) -> None:
    with pytest.raises(MapError) as info:
        read_trace(text, GRID, "t.jsonl")
    assert info.value.line == line
    assert info.value.message.startswith(message), info.value.message
    assert str(info.value).startswith(f"t.jsonl:{line}")


def test_an_empty_trace_says_so() -> None:
    with pytest.raises(MapError, match="no expansions"):
        read_trace("\n", GRID, "t.jsonl")


def test_both_successor_forms_start_goal_and_path_are_read() -> None:
    trace = read_trace(lines({"start": [0, 0], "goal": [5, 2]},
                             {"node": [0, 0], "successors": [{"dir": "S", "node": [0, 1]}]},
                             {"node": [0, 1], "successors": [[0, 2], [1, 2]]},
                             {"path": [[0, 0], [0, 1]]}), GRID, "t")
    assert trace.start == (0, 0) and trace.goal == (5, 2)
    assert [s.successors for s in trace.steps] == [((0, 1),), ((0, 2), (1, 2))]
    assert trace.path == ((0, 0), (0, 1))


def check(text: str, key: str = "bfs", sem: Semantics = DEFAULT_SEMANTICS) -> str:
    verdict = check_trace(read_trace(text, GRID, "t"), GRID, key, sem)
    return verdict.text() if verdict.difference is None else verdict.difference.message


def edited(key: str, sem: Semantics, edit) -> str:
    objs = [json.loads(x) for x in app_trace(GRID, key, sem).splitlines()]
    edit(objs)
    return lines(*objs)


def test_the_apps_trace_matches_with_its_choices_named() -> None:
    assert check(app_trace(GRID, "bfs", NWSE), "bfs", NWSE) == (
        "matches BFS (order N,W,S,E; visit on generate; goal test on generate) for all 22 steps")


def test_an_expansion_out_of_turn_names_where_the_search_would_take_it() -> None:
    def swap(objs):
        objs[6], objs[8] = objs[8], objs[6]
    text = edited("bfs", NWSE, swap)
    assert check(text, "bfs", NWSE) == (
        "step 7: BFS expands (1,3) next (the queue's front); your trace expands (0,5), "
        "which BFS would expand at step 9")


def test_the_newest_entry_of_the_queue_taken_is_named_as_a_stacks() -> None:
    """The trace takes the queue's newest entry, one an earlier step than the last added:
    the search's frontier (the trace's too, every step before matching) says it is the
    newest."""
    def swap(objs):
        objs[8], objs[10] = objs[10], objs[8]
    verdict = check_trace(read_trace(edited("bfs", NWSE, swap), GRID, "t"), GRID, "bfs", NWSE)
    assert verdict.difference is not None and verdict.difference.cause == "newest"
    assert verdict.difference.message == (
        "step 9: BFS takes (0,5), the oldest cell on its queue; your trace takes (2,1), the "
        "newest, as a stack does (a DFS: -a dfs)")


def test_a_successor_added_twice_missing_extra_or_out_of_order() -> None:
    def twice(objs):
        objs[1]["successors"].append(objs[1]["successors"][0])
    assert check(edited("bfs", NWSE, twice), "bfs", NWSE) == "step 2: your trace added (0,2) twice"

    assert check(edited("bfs", NWSE, lambda o: None), "bfs") == (
        "step 2: BFS adds (1,2) from (0,1); your trace does not")
    assert check(edited("bfs", Semantics(), lambda o: None), "bfs", NWSE) == (
        "step 2: your trace added (1,2), which BFS does not add from (0,1): "
        "move SE is not in order N,W,S,E")
    order = Semantics(order=("N", "E", "S", "W"))
    assert check(edited("bfs", NWSE, lambda o: None), "bfs", order) == (
        "step 3: your trace added (0,3), (1,2); BFS adds (1,2), (0,3) (order N,E,S,W): "
        "(1,2) before (0,3)")


def test_a_trace_that_stops_early_or_goes_on() -> None:
    def short(objs):
        del objs[-1]
    assert check(edited("bfs", NWSE, short), "bfs", NWSE) == (
        "step 22: your trace ends after step 21; BFS goes on and expands (5,5) "
        "(the queue's front)")

    def longer(objs):
        objs.append({"node": [0, 0], "successors": []})
    assert check(edited("bfs", NWSE, longer), "bfs", NWSE) == (
        "step 23: your trace expands (0,0); BFS has stopped after its step 22 "
        "(its frontier was empty)")  # four moves do not reach the tutorial's goal
    assert check(edited("bfs", Semantics(), longer), "bfs") == (
        "step 23: your trace expands (0,0); BFS has stopped after its step 22 "
        "(it found the goal, tested on generate)")


def test_discarded_pops_may_be_marked_or_left_out() -> None:
    sem = Semantics(visit="expand")
    full = app_trace(GRID, "bfs", sem)
    assert '"discarded": true' in full
    kept = [x for x in full.splitlines() if '"discarded"' not in x]
    assert check(full, "bfs", sem).startswith("matches BFS")
    verdict = check_trace(read_trace("\n".join(kept), GRID, "t"), GRID, "bfs", sem)
    assert verdict.matches and verdict.steps == len(kept) < len(full.splitlines())


def test_json_names_the_choices_and_the_difference() -> None:
    verdict = check_trace(read_trace(app_trace(GRID, "dfs", Semantics()), GRID, "t"), GRID,
                          "bfs", Semantics())
    obj = verdict.as_json()
    assert obj["verdict"] == "difference" and obj["matched_steps"] == 2
    assert obj["choices"]["visit"] == "generate"
    assert obj["first_difference"]["step"] == 3
    assert obj["first_difference"]["kind"] == "expand"


CHOICES = st.builds(
    Semantics,
    order=st.permutations(["N", "NE", "E", "SE", "S", "SW", "W", "NW"]).flatmap(
        lambda p: st.integers(1, 8).map(lambda n: tuple(p[:n]))),
    corners=st.sampled_from(["always", "one", "never"]),
    goal_test=st.sampled_from([None, "generate", "expand"]),
    heuristic=st.sampled_from(["octile", "manhattan", "zero"]),
)


#: The app's own searches and choices, for traces held equal to them: a map, an algorithm,
#: its choices, and "generate", "expand" (the visit rule) or "tree" (tree search).
APP_SEARCHES = (random_grids(max_side=6),
                st.sampled_from(["bfs", "dfs", "iddfs", "ucs", "greedy", "astar"]), CHOICES,
                st.sampled_from(["generate", "expand", "tree"]))


def app_case(grid: Grid, key: str, sem: Semantics, visit: str,
             limit: int) -> tuple[Semantics, str]:
    """``sem`` with the visit rule or tree search of ``visit`` where it applies to ``key``,
    and the app's trace of that search (up to ``limit`` steps; "" when the start is the
    goal: hypothesis drops the case)."""

    from hypothesis import assume

    from tui_search.engine.search.registry import get_algorithm

    algo = get_algorithm(key)
    if visit == "tree":
        sem = sem.replace(tree_search=True)
    elif visit == "expand" and not (algo.iterative or algo.weighted):
        sem = sem.replace(visit="expand")
    text = app_trace(grid, key, sem, limit)
    assume(text)
    return sem, text


def over_app_searches(test: Callable[..., None]) -> Callable[..., None]:
    """``test`` run on :data:`APP_SEARCHES` (150 cases)."""
    return settings(max_examples=150, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])(given(*APP_SEARCHES)(test))


@over_app_searches
def test_the_apps_own_trace_checks_as_a_full_match_of_its_choices(
        grid: Grid, key: str, sem: Semantics, visit: str) -> None:
    limit = 300
    sem, text = app_case(grid, key, sem, visit, limit)
    verdict = check_trace(read_trace(text, grid, "t"), grid, key, sem, max_steps=limit)
    assert verdict.matches, verdict.text()
    assert verdict.matched == len(text.splitlines())
