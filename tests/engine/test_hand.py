"""A search stepped by hand: each step checked against the search at once, a wrong one named
in the words of a trace's check (its cause's code too), counted once a step, and the steps
made written as a trace that reads back and matches its search."""

from __future__ import annotations

import pytest

from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import Semantics
from tui_search.engine.traces.check import check_trace
from tui_search.engine.traces.hand import HandRun
from tui_search.engine.traces.read import read_trace

GRID = grid_from_rows(TUTORIAL_ROWS)
NESW = Semantics(order=("N", "E", "S", "W"))


def play(hand: HandRun, steps: int) -> None:
    """Make ``steps`` steps right, from the hints."""
    for _ in range(steps):
        assert hand.pick(hand.hint_cell()).ok
        while (cell := hand.hint_cell()) is not None:
            assert hand.mark(cell).ok
        assert hand.end_step().ok


def test_a_whole_run_made_right_has_no_mistake_and_its_trace_matches_the_search() -> None:
    hand = HandRun(GRID, "bfs", Semantics())
    while not hand.finished:
        play(hand, 1)
    assert hand.mistakes == [] and hand.phase == "done" and hand.k == hand.run.k
    trace = read_trace(hand.trace_text(), GRID, "run.jsonl")
    assert trace.path is not None and trace.path[-1] == GRID.goal
    verdict = check_trace(trace, GRID, "bfs", Semantics())
    assert verdict.matches and verdict.steps == hand.k


#: (search, choices, steps made first, the wrong move, its cause, its sentence)
MISTAKES = [
    ("bfs", Semantics(), 2, ("pick", (1, 2)), "newest",
     "step 3: BFS takes (0,2), the oldest cell on its queue; you took (1,2), the newest, as a "
     "stack does (a DFS)"),
    ("bfs", Semantics(), 3, ("pick", (0, 3)), "out-of-turn",
     "step 4: BFS expands (1,2) next (the queue's front); you took (0,3), which BFS would "
     "expand at step 5"),
    ("dfs", Semantics(), 2, ("pick", (0, 2)), "first-listed",
     "step 3: DFS takes (1,2), the last cell step 2 pushed; you took (0,2), the first step 2 "
     "added, as a queue or a recursion does, not a stack"),
    ("dfs", Semantics(), 3, ("pick", (0, 2)), "oldest",
     "step 4: DFS takes (2,1), the top of its stack, the newest; you took (0,2), the oldest, "
     "at its bottom, as a queue does (a BFS)"),
    ("ucs", Semantics(), 5, ("pick", (2, 2)), "tie",
     "step 6: UCS expands (1,3) next; you took (2,2): g ties at 3.41, and you took the newest "
     "entry of the tie; this search takes the oldest entry"),
    ("bfs", Semantics(visit="expand"), 6, ("pick", (0, 3)), "not-dropped",
     "step 7: BFS takes (1,2) off first (the queue's front): it was expanded already (at step "
     "4), so BFS drops it; you took (0,3)"),
    ("bfs", Semantics(), 0, ("mark", (1, 0)), "obstacle",
     "step 1: you added (1,0), an obstacle: no search adds it"),
    ("bfs", Semantics(), 1, ("mark", (0, 0)), "start-again",
     "step 2: you added the start (0,0) again: BFS marks the start reached when it begins; a "
     "search that does not (as some library code) pushes it again"),
    ("bfs", Semantics(), 2, ("mark", (1, 2)), "reached",
     "step 3: you added (1,2), which BFS does not add from (0,2): it was added already, at "
     "step 2; BFS marks a cell visited when it adds it, so it adds it once, and you added it "
     "again, as a search that marks cells visited when it takes them off does"),
    ("bfs", Semantics(), 2, ("mark", (0, 1)), "expanded",
     "step 3: you added (0,1), which BFS does not add from (0,2): it was expanded already, at "
     "step 2, and BFS adds a cell it has visited no more"),
    ("bfs", Semantics(), 1, ("mark", (1, 2)), "order",
     "step 2: you added (1,2); BFS adds (0,2) before (1,2) (order N,NW,W,SW,S,SE,E,NE)"),
    ("bfs", NESW, 1, ("mark", (1, 2)), "move-not-allowed",
     "step 2: you added (1,2), which BFS does not add from (0,1): move SE is not in order "
     "N,E,S,W"),
    ("bfs", Semantics(), 1, ("mark", (3, 3)), "not-a-move",
     "step 2: you added (3,3), which BFS does not add from (0,1): it is not one move away"),
    ("ucs", Semantics(corners="never"), 1, ("mark", (1, 2)), "corner",
     "step 2: you added (1,2), which UCS does not add from (0,1): the move SE passes a blocked "
     "corner, and the corner rule never refuses it"),
    ("ucs", Semantics(), 2, ("mark", (0, 1)), "not-cheaper",
     "step 3: you added (0,1), which UCS does not add from (0,2): it was reached already at g "
     "1.00, and this path costs 3.00, no cheaper (UCS pushes a cell again only when reached "
     "cheaper)"),
    ("bfs", Semantics(), 1, ("end", None), "left-out",
     "step 2: BFS adds (0,2) from (0,1); you did not"),
]


@pytest.mark.parametrize(("key", "sem", "made", "move", "cause", "message"), MISTAKES,
                         ids=[m[4] for m in MISTAKES])
def test_each_kind_of_mistake_is_named_and_not_taken(key: str, sem: Semantics, made: int,
                                                     move: tuple[str, object], cause: str,
                                                     message: str) -> None:
    hand = HandRun(GRID, key, sem)
    play(hand, made)
    kind, cell = move
    if kind != "pick":
        assert hand.pick(hand.hint_cell()).ok
    before = (hand.k, hand.picked, list(hand.marks))
    told = {"pick": hand.pick, "mark": hand.mark}[kind](cell) if cell else hand.end_step()
    assert not told.ok and told.message == message
    assert told.mistake is not None and told.mistake.cause == cause
    assert (hand.k, hand.picked, hand.marks) == before  # not taken
    assert hand.mistakes == [told.mistake] and hand.by_cause() == {cause: 1}


def test_a_step_counts_one_mistake_however_many_tries_and_the_next_step_its_own() -> None:
    hand = HandRun(GRID, "bfs", Semantics())
    play(hand, 2)
    assert hand.pick((1, 2)).mistake is not None
    again = hand.pick((1, 2))
    assert not again.ok and again.mistake is None  # said again, not counted again
    assert hand.pick((0, 2)).ok
    assert hand.mark((0, 1)).mistake is None  # the same step: still one
    assert len(hand.mistakes) == 1 and len(hand.tries) == 3
    while (cell := hand.hint_cell()) is not None:
        hand.mark(cell)
    hand.end_step()
    assert hand.pick((5, 5)).message == "(5,5) is not on the queue: take one of its entries"
    assert len(hand.mistakes) == 1  # no entry at all: no mistake


def test_a_goal_tested_on_generate_ends_the_run_with_the_step_that_adds_it() -> None:
    hand = HandRun(GRID, "bfs", Semantics())
    while not hand.finished:
        e = hand.expected()
        assert e is not None
        if e.found_goal:
            hand.pick(e.node)
            for _, cell in e.successors:
                hand.mark(cell)
            told = hand.mark((4, 0)) if (4, 0) not in [c for _, c in e.successors] else None
            if told is not None:
                assert told.mistake is not None and told.mistake.cause == "after-goal"
            hand.end_step()
        else:
            play(hand, 1)
    assert hand.run.found and hand.phase == "done"


def test_a_goal_tested_on_expand_is_taken_off_and_the_run_stops() -> None:
    hand = HandRun(GRID, "ucs", Semantics())
    while hand.expected() is not None and not hand.expected().found_goal:
        play(hand, 1)
    told = hand.pick(GRID.goal)
    assert told.ok and told.message == "(5,2) is the goal: UCS stops as it takes it off"
    assert hand.finished


def test_a_stale_entry_at_the_front_is_taken_off_and_dropped() -> None:
    hand = HandRun(GRID, "bfs", Semantics(visit="expand"))
    play(hand, 6)
    e = hand.expected()
    assert e is not None and e.discarded
    told = hand.pick(e.node)
    assert told.ok and "was expanded already: BFS takes it off and drops it" in told.message
    assert hand.k == 7 and hand.steps[-1].discarded


def test_undo_puts_the_entry_back_then_the_step_and_the_mistakes_stay() -> None:
    hand = HandRun(GRID, "bfs", Semantics())
    play(hand, 2)
    hand.pick((1, 2))  # a mistake
    hand.pick((0, 2))
    first = hand.hint_cell()
    hand.mark(first)
    assert hand.take_back().message == f"Took back ({first[0]},{first[1]})"
    assert hand.marks == []
    assert hand.undo().message == "Put (0,2) back" and hand.picked is None
    assert hand.undo().message == "Step 2 undone" and hand.k == 1 and len(hand.steps) == 1
    assert len(hand.mistakes) == 1 and hand.undone == 1
    assert hand.frontier_cells() == [(0, 1)]


def test_the_hints_give_the_cell_then_say_why() -> None:
    hand = HandRun(GRID, "dfs", NESW)
    play(hand, 2)
    assert hand.hint_cell() == hand.expected().node
    assert hand.hint_why() == f"DFS takes the stack's top, the newest entry: " \
        f"({hand.hint_cell()[0]},{hand.hint_cell()[1]})"
    hand.pick(hand.hint_cell())
    why = hand.hint_why()
    assert why.startswith(f"DFS adds the cells one move from ({hand.picked[0]},"
                          f"{hand.picked[1]}), in the order N,E,S,W, leaving out obstacles and "
                          "cells added already: next ")


def test_a_map_with_no_path_ends_when_the_frontier_runs_out() -> None:
    grid = Grid(3, 1, start=(0, 0), goal=(2, 0))
    grid.set_blocked((1, 0), True)
    hand = HandRun(grid, "bfs", Semantics())
    play(hand, 1)
    assert hand.finished and hand.run.path() is None
    assert '{"path": null}' in hand.trace_text()
