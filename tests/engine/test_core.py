"""One search core: the fast recorded loops equal the reference loop, under every choice.

The reference (:mod:`tui_search.engine.search.reference`) is the definition; every loop of
:mod:`tui_search.engine.search.loops` must record exactly what it does -- the same events in the
same order, the same expansions, the same discarded steps, iterations and goal -- on random maps
under random algorithms and choices.  Then the properties the choices promise.
"""

from __future__ import annotations

import itertools
from array import array

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from tests.engine.cores import CORES, using_core
from tests.engine.test_run import snapshot
from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows, reference_distances
from tui_search.engine.maps.grid import DIRECTIONS, Cell, Grid
from tui_search.engine.run.position import CellState
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import CORNER_RULES, GOAL_TESTS, VISIT_RULES, Semantics
from tui_search.engine.search.heuristics import HEURISTICS
from tui_search.engine.search.loops.dispatch import loop_for
from tui_search.engine.search.loops.general import general
from tui_search.engine.search.loops.iddfs import iddfs
from tui_search.engine.search.loops.tree import tree
from tui_search.engine.search.loops.tutorial import bfs, dfs
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import Record
from tui_search.engine.search.reference import ReferenceSearch, stream
from tui_search.engine.search.registry import ALGORITHMS, get_algorithm

#: Tree search is exponential: every comparison stops here (both loops give up alike).
LIMIT = 1500


@st.composite
def semantics(draw, algorithm: str | None = None) -> tuple[str, Semantics]:
    key = algorithm or draw(st.sampled_from(sorted(ALGORITHMS)))
    moves = draw(st.lists(st.sampled_from(DIRECTIONS), min_size=1, max_size=8, unique=True))
    tree = draw(st.booleans())
    algo = get_algorithm(key)
    # (visit on expand, expanded again, is a choice of published code: test_published_choices)
    visit = "generate" if tree or algo.iterative or algo.weighted else draw(
        st.sampled_from(VISIT_RULES[:2]))
    return key, Semantics(
        order=tuple(moves),
        corners=draw(st.sampled_from(CORNER_RULES)),
        visit=visit,
        goal_test=draw(st.sampled_from((None, *GOAL_TESTS))),
        tree_search=tree,
        heuristic=draw(st.sampled_from(sorted(HEURISTICS))),
    )


def reference_arrays(grid: Grid, key: str, sem: Semantics, limit: int) -> dict:
    """What the reference did, in the record's terms (cells, not padded indices), given the
    run's limit (a recursion's calls form lists the calls made by then)."""
    search = ReferenceSearch(grid, get_algorithm(key), sem, limit)
    cells, step_end, step_exp, discarded, costs = [grid.start], [1], [], [], [0.0]
    roots, first_steps = [0], [1]
    gave_up = False
    for step in search:
        if step.index > limit:
            gave_up = True
            break
        if step.new_root is not None:
            roots.append(step.new_root.event)
            first_steps.append(step.index)
            cells.append(step.new_root.cell)
            costs.append(step.new_root.g)  # IDA*'s roots: 0
        assert step.node.event < len(cells) and cells[step.node.event] == step.node.cell
        step_exp.append(step.node.event)
        cells.extend(s.cell for s in step.successors)
        costs.extend(s.g for s in step.successors)
        assert [s.event for s in step.successors] == list(
            range(len(cells) - len(step.successors), len(cells)))
        step_end.append(len(cells))
        if step.discarded:
            discarded.append(step.index)
    goal = -1 if gave_up or search.goal is None else search.goal.event
    return {"cells": cells, "step_end": step_end, "step_exp": step_exp,
            "discarded": discarded, "roots": roots, "first_steps": first_steps, "goal": goal,
            "gave_up": gave_up,
            "costs": [c.hex() for c in costs] if search.algorithm.weighted else None}


def recorded_arrays(run: Run) -> dict:
    run.advance()
    rec = recording_of(run).rec
    return {
        "cells": [run.nodes.cell(g) for g in range(len(rec.gen_node))],
        "step_end": list(rec.step_end),
        "step_exp": [rec.exp(k) for k in range(1, rec.steps + 1)],
        "discarded": list(rec.discarded),
        "roots": list(rec.iter_root),
        "first_steps": list(rec.iter_first_step),
        "goal": rec.goal_gen,
        "gave_up": rec.gave_up,
        # derived from each step's g: the same floats, bit for bit, as the reference's
        "costs": None if rec.step_g is None else [run.nodes.cost(e).hex()
                                                  for e in range(len(rec.gen_node))],
    }


#: 200 examples each (they were 400, which made four of these among the suite's 15 slowest
#: tests, about 2.4 s each on a loaded 2-core machine): the suite stays near a minute.
core = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@pytest.mark.parametrize("core_name", CORES)
@core
@given(random_grids(max_side=8, costs=True), semantics())
def test_every_recorded_loop_equals_the_reference(core_name: str, grid: Grid, choice) -> None:
    """Both cores, the Python loops and the compiled one, array for array."""
    key, sem = choice
    with using_core(core_name):
        recorded = recorded_arrays(Run(grid, key, sem, LIMIT))
    assert recorded == reference_arrays(grid, key, sem, LIMIT)


@core
@given(random_grids(max_side=8, costs=True), semantics())
def test_the_streamed_outcome_equals_the_recorded_one(grid: Grid, choice) -> None:
    """The headless command line streams the reference: same path and counts as the app."""
    key, sem = choice
    assert stream(grid, get_algorithm(key), sem, LIMIT) == Run(grid, key, sem, LIMIT).outcome()


def _record(grid: Grid, key: str, sem: Semantics, chunk: int) -> tuple:
    rec = Record()
    algorithm = get_algorithm(key)
    loop = loop_for(algorithm, sem)(Problem(grid, sem, sem.goal_test_for(algorithm)), rec, chunk)
    for pause, steps in enumerate(loop, 1):
        # the loop pauses every `chunk` steps, and the record is whole up to there
        assert rec.steps == steps == pause * chunk and len(rec.gen_node) == rec.step_end[-1]
        assert not isinstance(rec.step_exp, array) or len(rec.step_exp) == steps + 1
    return (list(rec.gen_node), list(rec.step_end), [rec.exp(k) for k in range(1, rec.steps + 1)],
            list(rec.discarded), rec.goal_gen, rec.done)


@pytest.mark.parametrize("core_name", CORES)
@core
@given(random_grids(max_side=8, costs=True), semantics(), st.integers(1, 4))
def test_the_loops_record_the_same_in_chunks_of_any_size(core_name: str, grid: Grid, choice,
                                                         chunk: int) -> None:
    """The loops keep a chunk's events in lists (the compiled core in buffers) and write them
    to the record at each pause: the record is whole at every pause, and tiny chunks (a pause
    every step or few) record exactly what one long chunk does."""
    key, sem = choice
    assume(not sem.tree_search)  # exponential: compared with the reference under a limit above
    with using_core(core_name):
        assert _record(grid, key, sem, chunk) == _record(grid, key, sem, 10_000)


@pytest.mark.parametrize(
    ("key", "sem", "loop"),
    [
        ("bfs", Semantics(), bfs),
        ("dfs", Semantics(corners="never", order=("N", "W", "S", "E")), dfs),  # no diagonal
        ("bfs", Semantics(corners="one"), general),
        ("bfs", Semantics(visit="expand"), general),
        ("dfs", Semantics(goal_test="expand"), general),
        ("dfs", Semantics(tree_search=True), tree),
        ("iddfs", Semantics(tree_search=True, goal_test="expand"), iddfs),
    ],
)
def test_the_tutorial_rules_take_the_fast_loops(key, sem, loop) -> None:
    """The hot loops serve the tutorial's rules under no corner rule (any order); the general
    loop every other choice -- the equality test above covers each of them."""
    with using_core("python"):
        chosen = loop_for(get_algorithm(key), sem)
    assert getattr(chosen, "func", chosen) is loop


# -- what the choices promise ------------------------------------------------------------------


@core
@given(random_grids(max_side=8, costs=True), semantics(algorithm="bfs"))
def test_bfs_finds_the_fewest_moves_under_every_choice(grid: Grid, choice) -> None:
    _, sem = choice
    out = Run(grid, "bfs", sem, LIMIT).outcome()
    dist = reference_distances(grid, sem.corners, sem.order)
    if not out.gave_up:
        assert out.found == (grid.goal in dist)
    if out.found:
        assert out.length == dist[grid.goal]


@core
@given(random_grids(max_side=8, costs=True), semantics())
def test_every_path_is_legal_under_its_rules(grid: Grid, choice) -> None:
    """Each move of the path is one of the order's moves, allowed by the corner rule; a
    tree-search path never repeats a cell (graph searches' paths cannot either)."""
    key, sem = choice
    out = Run(grid, key, sem, LIMIT).outcome()
    if not out.found:
        return
    path = out.path
    assert path[0] == grid.start and path[-1] == grid.goal
    assert len(set(path)) == len(path)
    for (a, b), move in zip(itertools.pairwise(path), out.moves, strict=True):
        assert (move, b) in grid.neighbours(a, sem.order, sem.corners)


@core
@given(random_grids(max_side=8, costs=True), semantics())
def test_a_four_direction_order_never_moves_diagonally(grid: Grid, choice) -> None:
    key, sem = choice
    sem = sem.replace(order=("N", "W", "S", "E"))
    out = Run(grid, key, sem, LIMIT).outcome()
    assert all(len(m) == 1 for m in out.moves or [])


@pytest.mark.parametrize("corners", ["one", "never"])
@pytest.mark.parametrize("key", sorted(ALGORITHMS))
def test_the_tutorial_path_squeezes_between_two_obstacles(corners: str, key: str) -> None:
    """The tutorial's path passes a diagonal between two blocked cells: under the corner rules
    ``one`` and ``never`` its map has no path at all."""
    grid = grid_from_rows(TUTORIAL_ROWS)
    assert Run(grid, key).outcome().found
    out = Run(grid, key, Semantics(corners=corners)).outcome()
    assert not out.found and not out.gave_up


def test_visit_on_expand_lists_duplicates_and_discards_them() -> None:
    """Under visit on expand a cell can be pushed twice; taking off the second copy expands
    nothing: the step is discarded, counted apart, and generates nothing."""
    grid = grid_from_rows(TUTORIAL_ROWS)
    run = Run(grid, "bfs", Semantics(visit="expand"))
    run.advance()
    cells = [run.nodes.cell(g) for g in range(len(recording_of(run).rec.gen_node))]
    assert len(cells) > len(set(cells))
    out = run.outcome()
    assert out.discarded > 0 and out.discarded == len(recording_of(run).discarded_steps())
    k = recording_of(run).discarded_steps()[0]
    step = run.steps.at(k)
    assert step.discarded and step.successors == ()
    run.goto(k)
    assert run.now.expanded == k - 1 - (run.now.discarded - 1)
    assert out.found and out.length == 7  # still the fewest moves


def test_goal_test_on_expand_stops_when_the_goal_is_taken_off() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    on_push = Run(grid, "bfs").outcome()
    on_pop = Run(grid, "bfs", Semantics(goal_test="expand"))
    out = on_pop.outcome()
    assert out.length == on_push.length and out.expanded > on_push.expanded
    last = on_pop.steps.at(on_pop.recorded)
    assert last.node == grid.goal and last.found_goal and last.successors == ()


def test_refused_combinations() -> None:
    with pytest.raises(ValueError, match="visit"):
        Semantics(visit="expand", tree_search=True)
    with pytest.raises(ValueError, match="IDDFS"):
        Run(grid_from_rows(TUTORIAL_ROWS), "iddfs", Semantics(visit="expand"))
    with pytest.raises(ValueError):
        Semantics(order=())
    with pytest.raises(ValueError):
        Semantics(corners="sometimes")


def test_tree_search_gives_up_at_the_step_limit() -> None:
    """Tree search is exponential: on an open map without the goal in reach it stops at the
    limit and says so."""
    grid = grid_from_rows(["S....", ".....", ".....", "####.", "...#G"])
    grid.set_blocked((4, 3), True)  # the goal is walled in: no path
    out = Run(grid, "bfs", Semantics(tree_search=True), max_steps=500).outcome()
    assert out.gave_up and not out.found and out.steps == 500


def test_the_bound_is_the_tutorials() -> None:
    assert Semantics().bound(7) == 7 ** 8
    assert Semantics(order=("N", "W", "S", "E")).bound(3) == 3 ** 4


# -- the position under every choice -----------------------------------------------------------


@settings(max_examples=200, deadline=None)
@given(random_grids(max_side=6, costs=True), semantics(),
       st.lists(st.integers(0, 400), min_size=1, max_size=5), st.sampled_from([0, 3, 10**9]))
def test_moving_to_step_k_works_the_same_for_every_choice(grid, choice, targets, rebuild) -> None:
    """The run's frontier model and counters: a jump (stepping either way, or a bulk rebuild)
    lands on exactly the state that stepping forwards from 0 reaches -- duplicates on the
    frontier, discarded steps and tree search included."""
    key, sem = choice
    run = Run(grid, key, sem, 400)
    run.REBUILD_AFTER = rebuild
    run.advance()
    for t in targets:
        k = t % (run.total + 1)
        run.goto(k)
        fresh = Run(grid, key, sem, 400)
        fresh.advance()
        for _ in range(k):
            fresh.forward()
        assert snapshot(run) == snapshot(fresh)
        assert ((run.now.discarded, run.now.frontier_len())
                == (fresh.now.discarded, fresh.now.frontier_len()))


def reference_expanded(grid: Grid, key: str, sem: Semantics, limit: int) -> list[set[Cell]]:
    """For each k, the cells the reference's non-discarded steps among the first k expanded
    (in step k's iteration: iterative deepening begins each one afresh)."""
    sets: list[set[Cell]] = [set()]
    for step in ReferenceSearch(grid, get_algorithm(key), sem, limit):
        if step.index > limit:
            break
        cells = set() if step.new_root is not None else set(sets[-1])
        if not step.discarded:
            cells.add(step.node.cell)
        sets.append(cells)
    return sets


def assert_expanded_as_the_reference(grid: Grid, key: str, sem: Semantics, targets: list[int],
                                     rebuild: int) -> None:
    """At each of ``targets`` (mod the run's steps), in turn, then at every step forwards and
    backwards: the cells the run counts and colours expanded are those the reference
    expanded by then."""
    run = Run(grid, key, sem, 400)
    run.REBUILD_AFTER = rebuild
    run.advance()
    expanded = reference_expanded(grid, key, sem, 400)
    n = run.total + 1
    assert len(expanded) == n
    for k in itertools.chain((t % n for t in targets), range(n), reversed(range(n))):
        run.goto(k)
        cells = [(x, y) for y in range(grid.height) for x in range(grid.width)]
        assert {c for c in cells if run.now.times_reached(c)[1]} == expanded[k]
        coloured = {(x, y) for y in range(grid.height)
                    for x, state in enumerate(run.now.row_states(y)) if state == CellState.EXPANDED}
        shown_apart = {run.now.current_node()} | set(run.path() or () if run.at_end else ())
        assert coloured == expanded[k] - shown_apart


@settings(max_examples=200, deadline=None)
@given(random_grids(max_side=6, costs=True), semantics(),
       st.lists(st.integers(0, 400), min_size=1, max_size=6), st.sampled_from([0, 3, 10**9]))
def test_a_cell_is_expanded_from_its_real_expansion_at_any_step(grid, choice, targets,
                                                                 rebuild) -> None:
    """The cells the run counts and colours expanded at step k, reached either way, are those
    of the reference's expansions in its first k steps: a discarded step expands nothing (a
    greedy search's stale entry can come off before its cell is ever expanded)."""
    assert_expanded_as_the_reference(grid, *choice, targets, rebuild)


@pytest.mark.parametrize("core_name", CORES)
@core
@given(random_grids(max_side=7, costs=True), semantics(), st.integers(1, 12))
def test_a_small_step_limit_gives_up_alike(core_name, grid, choice, limit) -> None:
    """Tiny limits make tiny chunks (a chunk is at most the limit): the recorded loops of
    both cores still equal the reference, and give up at exactly the limit."""
    key, sem = choice
    with using_core(core_name):
        recorded = recorded_arrays(Run(grid, key, sem, limit))
    assert recorded == reference_arrays(grid, key, sem, limit)
