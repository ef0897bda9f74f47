"""The search semantics, exactly: the tutorial's narrative, optimality, completeness, counts."""

from __future__ import annotations

import itertools
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.helpers import TUTORIAL_ROWS, grid_from_rows, reference_distances, summary
from tui_search.engine.maps.grid import DELTAS, Grid, parse_order
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics


def succ_dirs(step) -> list[str]:
    return [d for d, _ in step.successors]


# -- the tutorial's narrative on maps/tutorial.txt ---------------------------------------


def test_tutorial_bfs_narrative() -> None:
    """START's only successor is S; then S (S, SE), S again (S, SE), SE (E, NE)."""
    steps = list(Run(grid_from_rows(TUTORIAL_ROWS), "bfs").steps.all())
    assert [s.node for s in steps[:4]] == [(0, 0), (0, 1), (0, 2), (1, 2)]
    assert [succ_dirs(s) for s in steps[:4]] == [["S"], ["S", "SE"], ["S", "SE"], ["E", "NE"]]


def test_tutorial_dfs_narrative() -> None:
    """DFS expands S (S, SE), then SE (SW, S, E, NE), then NE (the last pushed)."""
    steps = list(Run(grid_from_rows(TUTORIAL_ROWS), "dfs").steps.all())
    assert [succ_dirs(s) for s in steps[:3]] == [["S"], ["S", "SE"], ["SW", "S", "E", "NE"]]
    ne = steps[2].successors[-1][1]
    assert steps[3].node == ne


def test_tutorial_ne_successor_passes_a_blocked_corner() -> None:
    """The tutorial's SE node has an NE successor although the cell north of SE is blocked:
    diagonal moves may pass blocked corners by default."""
    grid = grid_from_rows(TUTORIAL_ROWS)
    step4 = Run(grid, "bfs").steps.at(4)
    (x, y), (nx, ny) = step4.node, step4.successors[-1][1]
    assert step4.successors[-1][0] == "NE"
    assert grid.is_blocked((x, ny)) or grid.is_blocked((nx, y))


def test_tutorial_bfs_and_dfs_agree_on_a_shortest_path_and_dfs_is_cheaper() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    bfs, dfs = summary(Run(grid, "bfs")), summary(Run(grid, "dfs"))
    assert bfs["found"] and dfs["found"]
    assert bfs["path"] == dfs["path"]
    assert bfs["length"] == reference_distances(grid)[grid.goal]
    assert dfs["expanded"] * 2 <= bfs["expanded"]
    assert bfs["moves"][:3] == ["S", "SE", "NE"]


def test_tutorial_exact_counts() -> None:
    """Pinned counts for the tutorial map (what the README and the app show)."""
    grid = grid_from_rows(TUTORIAL_ROWS)
    bfs, dfs = summary(Run(grid, "bfs")), summary(Run(grid, "dfs"))
    assert (bfs["expanded"], bfs["generated"], bfs["max_frontier"]) == (22, 24, 8)
    assert (dfs["expanded"], dfs["generated"], dfs["max_frontier"]) == (7, 13, 6)
    assert bfs["moves"] == ["S", "SE", "NE", "NE", "E", "SE", "S"]
    assert bfs["cost"] == pytest.approx(3 + 4 * math.sqrt(2))


# -- goal test at generation; counts -----------------------------------------------------


def test_goal_test_on_generation_stops_the_expansion_at_once() -> None:
    # Start (1,1); goal north of it: generated first, so no other successor is generated.
    grid = grid_from_rows(["...", ".S.", "..."])
    grid.goal = (1, 0)
    run = Run(grid, "bfs")
    result = summary(run)
    assert result["expanded"] == 1
    assert result["generated"] == 2
    assert run.steps.at(1).successors == (("N", (1, 0)),)
    assert run.steps.at(1).found_goal


def test_start_equal_to_goal_is_a_path_of_one_cell() -> None:
    grid = grid_from_rows(["S.", ".."])
    grid.goal = grid.start
    for algo in ("bfs", "dfs", "iddfs"):
        result = summary(Run(grid, algo))
        assert result["found"] and result["path"] == [[0, 0]] and result["length"] == 0
        assert result["expanded"] == 0 and result["generated"] == 1


def test_no_path_empties_the_frontier() -> None:
    grid = grid_from_rows(["S#.", "##.", "..G"])
    for algo in ("bfs", "dfs", "iddfs"):
        run = Run(grid, algo)
        result = summary(run)
        assert not result["found"] and result["path"] is None and result["moves"] is None
        run.goto(run.total)
        assert run.now.frontier_len() == 0


def test_dfs_pushes_in_order_so_the_last_pushed_is_expanded_next() -> None:
    grid = grid_from_rows([".....", ".....", "..S..", ".....", "....G"])
    run = Run(grid, "dfs")
    first = run.steps.at(1)
    assert succ_dirs(first) == ["N", "NW", "W", "SW", "S", "SE", "E", "NE"]
    assert run.steps.at(2).node == first.successors[-1][1]


def test_bfs_expands_in_generation_order() -> None:
    grid = grid_from_rows([".....", ".....", "..S..", ".....", "....G"])
    run = Run(grid, "bfs")
    first = run.steps.at(1)
    assert [run.steps.at(k).node for k in range(2, 6)] == [c for _, c in first.successors[:4]]


def test_custom_order_changes_the_successor_order() -> None:
    grid = grid_from_rows(["...", ".S.", "..G"])
    order = parse_order("N,NE,E,SE,S,SW,W,NW")
    run = Run(grid, "bfs", Semantics(order=order))
    assert succ_dirs(run.steps.at(1)) == ["N", "NE", "E", "SE"]  # SE is the goal: stop there


@pytest.mark.parametrize("bad", ["N,UP", "N,N,E,SE,S,SW,W,NW", "N,NE,E,SE,S,SW,W,UP", ""])
def test_parse_order_rejects_non_permutations(bad: str) -> None:
    with pytest.raises(ValueError):
        parse_order(bad)


def test_no_corner_cutting_forbids_squeezing_past_a_blocked_corner() -> None:
    grid = grid_from_rows(["S#", ".G"])
    assert summary(Run(grid, "bfs"))["moves"] == ["SE"]
    strict = summary(Run(grid, "bfs", Semantics(corners="never")))
    assert strict["moves"] == ["S", "E"]


def test_iddfs_steps_carry_the_depth_limit_and_restart_from_the_root() -> None:
    run = Run(grid_from_rows(TUTORIAL_ROWS), "iddfs")
    steps = list(run.steps.all())
    limits = [s.depth_limit for s in steps]
    assert limits[0] == 0 and limits == sorted(limits)
    assert limits[-1] == summary(run)["length"]
    firsts = [s for prev, s in itertools.pairwise(steps) if s.depth_limit != prev.depth_limit]
    assert all(s.node == (0, 0) for s in firsts)


# -- properties on random maps -----------------------------------------------------------


#: The cell costs random terrain draws from: below 1, whole, fractional, large.
TERRAIN_COSTS = (0.5, 1.0, 1.0, 1.5, 2.0, 3.0, 5.0, 9.0, 0.25, 12.0)


@st.composite
def random_grids(draw, max_side: int = 9, walls_one_in: int = 2, min_side: int = 1,
                 costs: bool = False) -> Grid:
    """A map of ``min_side`` to ``max_side`` a side, about one cell in ``walls_one_in`` an
    obstacle; with ``costs``, as often as not, random terrain (every cell a random cost)."""
    w = draw(st.integers(min_side, max_side))
    h = draw(st.integers(min_side, max_side))
    cell = (st.booleans() if walls_one_in == 2
            else st.integers(0, walls_one_in - 1).map(lambda v: v == walls_one_in - 1))
    cells = draw(st.lists(cell, min_size=w * h, max_size=w * h))
    grid = Grid(w, h, bytearray(1 if c else 0 for c in cells))
    sx, sy = draw(st.integers(0, w - 1)), draw(st.integers(0, h - 1))
    gx, gy = draw(st.integers(0, w - 1)), draw(st.integers(0, h - 1))
    grid.set_blocked((sx, sy), False)
    grid.set_blocked((gx, gy), False)
    grid.start, grid.goal = (sx, sy), (gx, gy)
    if costs and draw(st.booleans()):
        values = draw(st.lists(st.sampled_from(TERRAIN_COSTS), min_size=w * h, max_size=w * h))
        for i, value in enumerate(values):
            if not grid.blocked[i]:
                grid.set_cost((i % w, i // w), value)
    return grid


def assert_valid_path(grid: Grid, result: dict, corners: str = "always") -> None:
    path = [tuple(c) for c in result["path"]]
    assert path[0] == grid.start and path[-1] == grid.goal
    assert len(set(path)) == len(path), "a cell twice on the path"
    for (a, b), move in zip(itertools.pairwise(path), result["moves"], strict=True):
        legal = {c: d for d, c in grid.neighbours(a, corners=corners)}
        assert legal.get(b) == move
    assert result["length"] == len(path) - 1


CORNERS = ("always", "one", "never")
props = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@props
@given(random_grids(), st.sampled_from(CORNERS))
def test_bfs_finds_a_path_with_the_fewest_moves(grid: Grid, corners: str) -> None:
    dist = reference_distances(grid, corners)
    result = summary(Run(grid, "bfs", Semantics(corners=corners)))
    assert result["found"] == (grid.goal in dist)
    if result["found"]:
        assert result["length"] == dist[grid.goal]
        assert_valid_path(grid, result, corners)


@props
@given(random_grids(), st.sampled_from(CORNERS))
def test_dfs_paths_are_valid_and_complete_on_finite_maps(grid: Grid, corners: str) -> None:
    dist = reference_distances(grid, corners)
    result = summary(Run(grid, "dfs", Semantics(corners=corners)))
    assert result["found"] == (grid.goal in dist)
    if result["found"]:
        assert result["length"] >= dist[grid.goal]
        assert_valid_path(grid, result, corners)


@props
@given(random_grids(max_side=7), st.sampled_from(CORNERS))
def test_iddfs_is_complete_and_as_short_as_bfs(grid: Grid, corners: str) -> None:
    dist = reference_distances(grid, corners)
    result = summary(Run(grid, "iddfs", Semantics(corners=corners)))
    assert result["found"] == (grid.goal in dist)
    if result["found"]:
        assert result["length"] == dist[grid.goal]
        assert_valid_path(grid, result, corners)


@props
@given(random_grids(), st.sampled_from(["bfs", "dfs"]))
def test_every_successor_is_a_legal_unvisited_move(grid: Grid, algo: str) -> None:
    """Steps as data: each successor is a legal move from the expanded node and was never
    generated before; each expanded node was generated before."""
    run = Run(grid, algo)
    generated = {grid.start}
    for step in run.steps.all():
        assert step.node in generated
        legal = grid.neighbours(step.node)
        for d, cell in step.successors:
            assert (d, cell) in legal
            assert cell not in generated
            generated.add(cell)
        names = [d for d, _ in step.successors]
        assert names == [d for d, _ in legal if d in names], "not in neighbour order"
    assert len(generated) == summary(run)["generated"]


def test_deltas_are_unit_moves() -> None:
    assert sorted(DELTAS.values()) == sorted(
        (dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if (dx, dy) != (0, 0)
    )


def test_the_choices_are_a_value() -> None:
    """Semantics is written out (not a frozen dataclass, for the start's sake): checked when
    made, equal and hashed by its choices, changed only by a copy (``replace``), and pickled
    and copied as made."""
    import copy
    import pickle
    from dataclasses import FrozenInstanceError

    sem = Semantics(visit="expand")
    assert sem == Semantics(visit="expand") and hash(sem) == hash(Semantics(visit="expand"))
    assert sem != Semantics() and not sem.is_default and Semantics().is_default
    changed = sem.replace(corners="never")
    assert (changed.corners, changed.visit, sem.corners) == ("never", "expand", "always")
    for again in (pickle.loads(pickle.dumps(changed)), copy.deepcopy(changed), copy.copy(changed)):
        assert again == changed and type(again) is Semantics
    assert repr(sem).startswith("Semantics(order=(") and "visit='expand'" in repr(sem)
    with pytest.raises(FrozenInstanceError):
        sem.visit = "generate"  # type: ignore[misc]
    with pytest.raises(ValueError, match="tree search has no visited set"):
        sem.replace(tree_search=True)
    with pytest.raises(ValueError, match="corners 'some'"):
        Semantics(corners="some")
