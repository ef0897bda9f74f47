"""The recorded run: the state at step k is the same however k was reached."""

from __future__ import annotations

import itertools
from array import array
from unittest.mock import patch

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows, summary
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.peak import PeakTable, _largest_size
from tui_search.engine.run.position import CellState
from tui_search.engine.run.recorded import MAX_STEPS, Run, recording_of
from tui_search.engine.search.record import CHUNK


def snapshot(run: Run) -> tuple:
    """Everything the app shows at the position: cells, frontier, tree, counts."""
    g = run.grid
    cells = tuple(run.now.cell_state((x, y)) for y in range(g.height) for x in range(g.width))
    rows = tuple(tuple(run.now.row_states(y)) for y in range(g.height))
    frontier = tuple((run.nodes.cell(e), run.nodes.move(e)) for e in run.now.frontier())
    root = run.now.tree_root()
    tree = []
    todo = [root]
    while todo:
        e = todo.pop()
        kids = list(run.now.children(e))
        tree.append((run.nodes.cell(e), tuple(run.nodes.cell(c) for c in kids)))
        todo.extend(kids)
    return (run.k, cells, rows, frontier, tuple(tree), run.now.expanded, run.now.generated,
            run.steps.peak_frontier(), run.steps.depth_limit(), tuple(run.now.added_now()))


def fresh_at(grid: Grid, algo: str, k: int) -> tuple:
    """What a new run stepped forwards to ``k`` shows (recorded only as far as that: the whole
    of iterative deepening on an open 60x60 map is a million steps)."""
    run = Run(grid, algo)
    run.advance(k)
    for _ in range(k):
        run.forward()
    return snapshot(run)


@settings(max_examples=150, deadline=None)
@given(random_grids(max_side=7), st.sampled_from(["bfs", "dfs", "iddfs"]),
       st.lists(st.integers(0, 400), min_size=1, max_size=6), st.sampled_from([0, 3, 10**9]))
def test_goto_from_any_direction_gives_the_same_state(grid, algo, targets, rebuild) -> None:
    """Whether a jump steps (forwards or backwards) or rebuilds the state in bulk."""
    run = Run(grid, algo)
    run.REBUILD_AFTER = rebuild
    run.advance()
    for t in targets:
        k = t % (run.total + 1)
        run.goto(k)
        assert snapshot(run) == fresh_at(grid, algo, k)


@settings(max_examples=60, deadline=None)
@given(random_grids(max_side=7), st.sampled_from(["bfs", "dfs", "iddfs"]))
def test_backward_undoes_forward_exactly(grid, algo) -> None:
    run = Run(grid, algo)
    run.advance()
    states = [snapshot(run)]
    while run.forward():
        states.append(snapshot(run))
    assert len(states) == run.total + 1
    for expected in reversed(states[:-1]):
        assert run.backward()
        assert snapshot(run) == expected
    assert not run.backward()


def test_tutorial_states_by_step() -> None:
    run = Run(grid_from_rows(TUTORIAL_ROWS), "bfs")
    assert run.now.cell_state((0, 0)) == CellState.FRONTIER and run.now.frontier_len() == 1
    run.goto(2)
    assert run.now.cell_state((0, 1)) == CellState.CURRENT
    assert run.now.cell_state((0, 0)) == CellState.EXPANDED
    assert [run.nodes.cell(e) for e in run.now.frontier()] == [(0, 2), (1, 2)]
    assert [run.nodes.move(e) for e in run.now.added_now()] == ["S", "SE"]
    run.goto(run.total)
    assert run.at_end and run.found
    assert run.now.cell_state((4, 0)) == CellState.PATH
    assert run.now.cell_state((5, 3)) == CellState.UNSEEN


def test_dfs_frontier_is_listed_top_first() -> None:
    run = Run(grid_from_rows(TUTORIAL_ROWS), "dfs")
    run.goto(3)
    assert [run.nodes.move(e) for e in run.now.frontier()] == ["NE", "E", "S", "SW", "S"]


def test_the_run_owns_a_copy_of_the_grid() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    run = Run(grid, "bfs")
    grid.set_blocked((0, 1), True)  # the app edits its map...
    assert summary(run)["found"]  # ...and the old run is unaffected
    assert summary(Run(grid, "bfs"))["found"] is False  # a new run sees the edit


def test_lazy_recording_advances_in_chunks() -> None:
    grid = Grid(300, 300)
    grid.start, grid.goal = (0, 0), (299, 299)
    run = Run(grid, "bfs")
    assert not run.done and run.recorded < 90_000
    run.goto(5)
    assert run.k == 5 and not run.done
    run.advance()
    assert run.done and run.found and run.total == run.recorded


def test_memory_grows_with_steps_not_steps_times_map() -> None:
    grid = Grid(200, 200)
    grid.start, grid.goal = (0, 0), (199, 199)
    run = Run(grid, "dfs")
    run.advance()
    assert recording_of(run).rec.nbytes() < 40 * (run.total + 1)


@pytest.mark.parametrize("algorithm", ["bfs", "dfs", "iddfs"])
def test_a_run_gives_up_exactly_at_its_step_limit(algorithm) -> None:
    grid = Grid(40, 40, start=(0, 0), goal=(39, 39))
    full = Run(grid, algorithm)
    full.advance()
    limit = min(full.recorded // 2, 1000)  # exact for limits up to a chunk (and multiples)
    run = Run(grid, algorithm, max_steps=limit)
    run.goto(10**9)
    assert run.gave_up and run.done and not run.found and run.at_end
    assert run.k == run.total == limit
    # what it did record is the same as the full run's first steps
    ends = recording_of(full).rec.step_end
    assert list(recording_of(run).rec.step_end) == list(ends[: limit + 1])
    assert summary(run)["gave_up"] and not summary(full)["gave_up"]


def test_iddfs_on_a_big_map_gives_up_at_its_step_limit_not_the_memory() -> None:
    """Iterative deepening on a big map takes many millions of steps (~75 million on a
    512x512 maze): the step limit stops it, and what it keeps grows with the steps allowed.
    (A smaller limit than the default here, for speed: the mechanism is the same.)"""
    grid = Grid(300, 300, start=(0, 0), goal=(299, 299))
    assert Run(grid, "iddfs").max_steps == MAX_STEPS  # the default limit a run is given
    run = Run(grid, "iddfs", max_steps=5 * CHUNK)
    run.advance()
    assert run.gave_up and run.done and not run.found and run.recorded == 5 * CHUNK
    assert recording_of(run).rec.nbytes() <= 64 * run.recorded
    run.goto(10**9)
    assert run.k == 5 * CHUNK and run.at_end


@pytest.mark.parametrize("algorithm", ["bfs", "dfs", "iddfs"])
@pytest.mark.parametrize("limit", [CHUNK + 1000, 2 * CHUNK + 7])
def test_a_limit_of_more_than_a_chunk_is_exact_too(algorithm, limit) -> None:
    """The record of the last chunk is cut back to the limit."""
    grid = Grid(150, 150, start=(0, 0), goal=(149, 149))
    for cell in ((148, 149), (148, 148), (149, 148)):  # the goal walled in: a long search
        grid.set_blocked(cell, True)
    full = Run(grid, algorithm)
    full.advance(3 * CHUNK)
    run = Run(grid, algorithm, max_steps=limit)
    run.advance()
    assert run.gave_up and run.recorded == limit and not run.found
    ends = recording_of(full).rec.step_end
    assert list(recording_of(run).rec.step_end) == list(ends[: limit + 1])
    assert len(recording_of(run).rec.gen_node) == recording_of(run).rec.step_end[limit]
    run.goto(limit)
    assert run.at_end and run.now.frontier_len() > 0
    assert summary(run)["expanded"] == limit


def test_a_goal_found_past_the_limit_is_not_found() -> None:
    """On a 1-row corridor BFS generates the goal while expanding its neighbour, at step 99
    (the start's expansion is step 1).  A limit of 98 stops it one step short."""
    grid = Grid(100, 1, start=(0, 0), goal=(99, 0))
    assert summary(Run(grid, "bfs"))["expanded"] == 99
    run = Run(grid, "bfs", max_steps=99)  # exactly what the search needs: found
    assert summary(run)["found"] and not run.gave_up
    run = Run(grid, "bfs", max_steps=98)
    assert summary(run)["gave_up"] and not run.found and run.recorded == 98


def test_iddfs_that_ends_exactly_at_the_limit_has_not_given_up() -> None:
    """No path, found out on the very step the limit allows: that is "no path", not a give-up."""
    grid = grid_from_rows(["S#G"])
    steps = summary(Run(grid, "iddfs"))["expanded"]
    run = Run(grid, "iddfs", max_steps=steps)
    result = summary(run)
    assert not result["gave_up"] and not result["found"] and result["expanded"] == steps


def test_a_goal_found_in_the_chunk_past_the_limit_is_cut_off_too() -> None:
    width = CHUNK + 1000  # the goal is generated at step width - 1, in the second chunk
    grid = Grid(width, 1, start=(0, 0), goal=(width - 1, 0))
    run = Run(grid, "bfs", max_steps=CHUNK + 500)
    result = summary(run)
    assert result["gave_up"] and not result["found"] and result["path"] is None
    assert result["expanded"] == CHUNK + 500 and result["generated"] == CHUNK + 501  # +start


@settings(max_examples=120, deadline=None)
@given(random_grids(max_side=7), st.sampled_from(["bfs", "dfs", "iddfs"]),
       st.integers(0, 400), st.integers(0, 400), st.sampled_from([1, 2, 5, 1 << 15]),
       st.sampled_from([7, 1 << 20]))
def test_a_rebuild_in_pieces_gives_the_state_stepping_gives(grid, algo, a, b, piece,
                                                            cells) -> None:
    """The sliced rebuild (``end`` in the app) leaves the run as stepping there would, and
    until its last piece the run is untouched at its old position."""
    run = Run(grid, algo)
    run.REBUILD_PIECE, run.REBUILD_CELLS = piece, cells
    run.advance()
    start, target = a % (run.total + 1), b % (run.total + 1)
    run.goto(start)
    before = snapshot(run)
    pieces = run.rebuild_pieces(target)
    fractions = []
    for fraction in pieces:
        assert snapshot(run) == before  # not yet moved: whole at the old position
        fractions.append(fraction)
    assert snapshot(run) == fresh_at(grid, algo, target)
    assert fractions == sorted(fractions) and 0 < fractions[-1] <= 1


def test_a_rebuild_in_pieces_does_a_bounded_amount_per_piece_and_can_be_dropped() -> None:
    grid = Grid(60, 60, start=(0, 0), goal=(59, 59))
    for algo in ("bfs", "dfs", "iddfs"):
        run = Run(grid, algo)
        run.REBUILD_PIECE, run.REBUILD_CELLS = 100, 500
        run.advance(3000)
        k = run.recorded
        rec = recording_of(run).rec
        events = rec.step_end[k] - rec.iter_root[run.steps.iteration_of(k)]
        pieces = run.rebuild_pieces(k)
        next(pieces)
        next(pieces)
        pieces.close()  # dropped half-way (a key pressed during `end`)
        assert run.k == 0 and run.now.frontier_len() == 1 and run.now.cell_state((1, 1)) == 0
        n = sum(1 for _ in run.rebuild_pieces(k))
        # No piece handles more than REBUILD_PIECE events or allocates REBUILD_CELLS counters.
        assert n >= events // 100 + 2 * (62 * 62 // 500)
        assert run.k == k and snapshot(run) == fresh_at(grid, algo, k)


@settings(max_examples=60, deadline=None)
@given(random_grids(max_side=7), st.sampled_from(["bfs", "dfs", "iddfs"]))
def test_the_peak_frontier_is_kept_while_recording(grid, algo) -> None:
    """Recording fills the block maxima (so ``end`` on a big map scans at most one block),
    and the peak is the largest frontier stepping meets, over every iteration of iterative
    deepening."""
    # several blocks even on a small map, and pieces of blocks bounded before they are read
    with patch.object(PeakTable, "PEAK_BLOCK", 3), patch.object(PeakTable, "PEAK_PIECE", 2):
        run = Run(grid, algo)
        run.advance()
        # every whole block before the last step, with no peak asked for
        assert len(recording_of(run)._peak) == run.recorded // 3
        stepper = Run(grid, algo)
        peak = stepper.now.frontier_len()
        assert run.steps.peak_frontier(0) == peak
        while stepper.forward():
            peak = max(peak, stepper.now.frontier_len())
            assert run.steps.peak_frontier(stepper.k) == peak


@settings(max_examples=80, deadline=None)
@given(random_grids(max_side=7), st.sampled_from(["bfs", "dfs", "iddfs"]),
       st.lists(st.integers(0, 400), min_size=1, max_size=12))
def test_the_peak_frontier_in_any_order_of_asking(grid, algo, asks) -> None:
    """The last answer is remembered to make a step forwards cheap; asked backwards, across
    blocks or again, the peak is still the largest frontier over steps 0..k."""
    with patch.object(PeakTable, "PEAK_BLOCK", 5), patch.object(PeakTable, "PEAK_PIECE", 2):
        run = Run(grid, algo)
        run.advance()
        sizes = [recording_of(run).frontier_size_at(j) for j in range(run.recorded + 1)]
        for a in asks:
            k = a % (run.total + 1)
            assert run.steps.peak_frontier(k) == max(sizes[: k + 1]), k


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(0, 8), min_size=1, max_size=600), st.integers(0, 2**31 - 6000),
       st.data())
def test_the_largest_size_packed_in_one_int(steps, base, data) -> None:
    """The peak table reads a block's sizes ``ends[j] - j - c`` as fields of one int: the
    same largest size as the plain ``max``, for any block, up to sizes near 2**31."""
    ends = array("i", itertools.accumulate(steps, initial=base + len(steps)))
    lo = data.draw(st.integers(0, len(ends) - 1))
    hi = data.draw(st.integers(lo + 1, len(ends)))
    c = data.draw(st.integers(0, base))  # every size stays >= 0
    assert _largest_size(ends, lo, hi, c) == max(ends[j] - j - c for j in range(lo, hi))


def public_names(obj: object) -> set[str]:
    return {name for name in dir(obj) if not name.startswith("_")}


#: Run's own names: what it is, how much is recorded, where it stands, the answer, the facets.
RUN_NAMES = {
    "grid", "board", "graph", "start", "goal", "algorithm", "algo", "semantics", "max_steps",
    "known_lowest",
    "advance", "advance_some", "done", "found", "gave_up", "recorded", "total", "goal_test",
    "differences", "estimate_warning", "replayed", "k", "goto", "forward", "backward", "reset",
    "at_end",
    "rebuild_pieces",
    "REBUILD_AFTER", "REBUILD_PIECE", "REBUILD_CELLS",
    "outcome", "outcome_so_far", "path", "path_cost", "moves", "admissible",
    "nodes", "steps", "now",
}
FACET_NAMES = {
    "nodes": {"cell", "move", "parent", "depth", "cheap_depth", "cost", "costs",
              "generated_at", "expanded_at", "ancestors", "goal", "path"},
    "steps": {"at", "all", "expanded_event", "succ_range", "expansions", "is_discarded",
              "iteration_of", "first_of_iteration", "depth_limit", "f_limits", "is_cut_off",
              "peak_frontier"},
    "now": {"cell_state", "row_states", "current_node", "changed_cells", "times_reached",
            "last_event", "is_stale", "frontier_len", "frontier", "added_now", "children",
            "tree_root", "tree_size", "expanded", "discarded", "generated"},
}


def test_the_run_surface_is_small_and_named() -> None:
    """Run's public names and its facets' are exactly these: a new query goes in a facet (and
    here) on purpose, never onto Run by accident; the recording stays behind
    ``recording_of``."""
    run = Run(grid_from_rows(TUTORIAL_ROWS), "bfs")
    assert public_names(run) == RUN_NAMES
    for facet, names in FACET_NAMES.items():
        assert public_names(getattr(run, facet)) == names, facet
    assert recording_of(run).rec.steps == run.recorded


def test_a_step_is_a_value() -> None:
    """Step is written out (not a dataclass, for the start's sake): equal and hashed by its
    fields, keyword or positional, immutable, and shown with them."""
    from dataclasses import FrozenInstanceError

    from tui_search.engine.run.recorded import Step

    run = Run(grid_from_rows(TUTORIAL_ROWS), "bfs")
    first = run.steps.at(1)
    again = Step(1, first.node, first.successors)
    assert first == again and hash(first) == hash(again) and first != run.steps.at(2)
    assert first != (1, first.node, first.successors)
    assert repr(first).startswith(f"Step(index=1, node={first.node!r}, ")
    for change in (lambda: setattr(first, "index", 2), lambda: delattr(first, "node"),
                   lambda: setattr(first, "other", 1)):
        with pytest.raises(FrozenInstanceError):
            change()


def test_a_record_names_every_array_it_keeps() -> None:
    """Record is written out (not a dataclass, for the start's sake): FIELDS, which the tests
    compare two records by, is every attribute it has, before a search and after one."""
    from tui_search.engine.run.recorded import recording_of
    from tui_search.engine.search.record import Record

    assert tuple(vars(Record())) == Record.FIELDS
    for key in ("bfs", "iddfs", "astar"):
        run = Run(grid_from_rows(TUTORIAL_ROWS), key)
        run.advance()
        rec = recording_of(run).rec
        assert set(vars(rec)) == set(Record.FIELDS) and repr(rec).startswith("Record(steps=")
