"""Terrain costs in the searches: what each algorithm promises on random maps with random cell
costs, and that a map whose every cell costs 1 runs exactly as a plain map does."""

from __future__ import annotations

import heapq
import itertools
from array import array

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.test_search import random_grids
from tests.helpers import MAPS, reference_distances
from tui_search.cli.headless import json_summary
from tui_search.engine.maps.grid import SQRT2, Cell, Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import CORNER_RULES, Semantics
from tui_search.engine.search.heuristics import HEURISTICS, admissible
from tui_search.engine.search.outcome import Outcome

EIGHT = ("N", "NW", "W", "SW", "S", "SE", "E", "NE")
FOUR = ("N", "W", "S", "E")
LIMIT = 5000

prop = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def dijkstra(grid: Grid, order: tuple[str, ...], corners: str) -> dict[Cell, float]:
    """The cheapest cost from the start to every reachable cell, written from the rule alone
    (a move costs its length times the cost of the cell it enters; the corner rules from
    their definitions), with none of the engine's search code."""
    deltas = {"N": (0, -1), "NE": (1, -1), "E": (1, 0), "SE": (1, 1), "S": (0, 1),
              "SW": (-1, 1), "W": (-1, 0), "NW": (-1, -1)}

    def free(x: int, y: int) -> bool:
        return 0 <= x < grid.width and 0 <= y < grid.height and not grid.blocked[
            y * grid.width + x]

    assert grid.start is not None
    best = {grid.start: 0.0}
    heap = [(0.0, grid.start)]
    done: set[Cell] = set()
    while heap:
        d, (x, y) = heapq.heappop(heap)
        if (x, y) in done:
            continue
        done.add((x, y))
        for name in order:
            dx, dy = deltas[name]
            if not free(x + dx, y + dy):
                continue
            if dx and dy:
                a, b = free(x + dx, y), free(x, y + dy)
                if corners == "never" and not (a and b) or corners == "one" and not (a or b):
                    continue
            cost = (SQRT2 if dx and dy else 1.0) * grid.cost((x + dx, y + dy))
            if d + cost < best.get((x + dx, y + dy), float("inf")) - 1e-12:
                best[(x + dx, y + dy)] = d + cost
                heapq.heappush(heap, (d + cost, (x + dx, y + dy)))
    return best


@st.composite
def terrains(draw) -> tuple[Grid, Semantics]:
    """A random map with random costs (always some), 4- or 8-connected, any corner rule."""
    grid = draw(random_grids(max_side=9, walls_one_in=3, costs=True))
    if grid.costs is None:  # random_grids leaves half its maps plain: cost one cell here
        free = [(x, y) for y in range(grid.height) for x in range(grid.width)
                if grid.is_free((x, y))]
        grid.set_cost(draw(st.sampled_from(free)), draw(st.sampled_from([0.5, 3.0, 7.0])))
    order = draw(st.sampled_from([EIGHT, FOUR]))
    return grid, Semantics(order=order, corners=draw(st.sampled_from(CORNER_RULES)))


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


def _run(grid: Grid, key: str, sem: Semantics, reached: dict[Cell, float]) -> Outcome:
    """``key``'s outcome, found exactly when ``reached`` (an independent search's) has the
    goal."""
    out = Run(grid, key, sem, LIMIT).outcome()
    assert out.found == (grid.goal in reached)
    return out


@prop
@given(terrains())
def test_uniform_cost_search_finds_the_cheapest_cost(problem) -> None:
    grid, sem = problem
    best = dijkstra(grid, sem.order, sem.corners)
    out = _run(grid, "ucs", sem, best)
    if out.found:
        assert _close(out.cost, best[grid.goal])


@prop
@given(terrains(), st.sampled_from(sorted(HEURISTICS)))
def test_a_star_with_an_admissible_heuristic_finds_the_same_cost(problem, name: str) -> None:
    grid, sem = problem
    sem = Semantics(order=sem.order, corners=sem.corners, heuristic=name)
    if not admissible(name, sem.order):
        return
    out = Run(grid, "astar", sem, LIMIT).outcome()
    ucs = Run(grid, "ucs", sem, LIMIT).outcome()
    assert out.found == ucs.found
    if out.found:
        assert _close(out.cost, ucs.cost)


@prop
@given(terrains())
def test_bfs_finds_the_fewest_moves_and_reports_their_cost(problem) -> None:
    grid, sem = problem
    moves = reference_distances(grid, sem.corners, sem.order)
    out = _run(grid, "bfs", sem, moves)
    if out.found:
        assert out.length == moves[grid.goal]
        assert out.cost == grid.path_cost(out.path)
        assert out.cost >= dijkstra(grid, sem.order, sem.corners)[grid.goal] - 1e-9


@prop
@given(terrains(), st.sampled_from(sorted(HEURISTICS)))
def test_greedy_paths_are_legal_and_never_cheaper_than_ucs(problem, name: str) -> None:
    grid, sem = problem
    sem = Semantics(order=sem.order, corners=sem.corners, heuristic=name)
    out = Run(grid, "greedy", sem, LIMIT).outcome()
    ucs = Run(grid, "ucs", sem, LIMIT).outcome()
    assert out.found == ucs.found
    if out.found:
        path = out.path
        assert path[0] == grid.start and path[-1] == grid.goal
        for (a, b), move in zip(itertools.pairwise(path), out.moves, strict=True):
            assert (move, b) in grid.neighbours(a, sem.order, sem.corners)
        assert out.cost >= ucs.cost - 1e-9


def test_the_path_cost_pays_each_entered_cell_never_the_start() -> None:
    grid = Grid(3, 2, start=(0, 0), goal=(2, 1))
    grid.set_cost((0, 0), 9.0)  # the start's own: never paid
    grid.set_cost((1, 0), 5.0)
    grid.set_cost((2, 1), 2.0)
    assert grid.path_cost([(0, 0), (1, 0), (2, 1)]) == 5.0 + SQRT2 * 2.0
    out = Run(grid, "ucs").outcome()  # round the cost-5 cell: SE (cost 1), E (cost 2)
    assert out.moves == ["SE", "E"] and out.cost == SQRT2 * 1.0 + 2.0
    assert grid.lowest_cost() == 1.0


def test_the_heuristics_are_scaled_by_the_lowest_cost() -> None:
    """A map of cells of cost 2 and 3: A*'s h is twice the octile estimate."""
    grid = Grid(4, 1, start=(0, 0), goal=(3, 0))
    for x in range(4):
        grid.set_cost((x, 0), 3.0 if x == 1 else 2.0)
    run = Run(grid, "astar")
    run.advance()
    assert grid.lowest_cost() == 2.0
    assert run.nodes.costs(0) == (0.0, 6.0, 6.0)


# -- a map of cost 1 everywhere is a plain map ---------------------------------------------------


def _all_ones(grid: Grid) -> Grid:
    """``grid`` with a costs array of 1s given to it (which the grid drops: None)."""
    ones = grid.copy()
    ones.costs = array("d", [1.0]) * (grid.width * grid.height)
    return Grid(ones.width, ones.height, ones.blocked, ones.start, ones.goal, None, ones.costs)


@pytest.mark.parametrize("key", ["bfs", "dfs", "iddfs", "ucs", "greedy", "astar"])
@pytest.mark.parametrize("name", ["tutorial.txt", "exercise1-bfs-wins.txt"])
def test_all_one_terrain_gives_todays_records_and_json(key: str, name: str, tmp_path) -> None:
    plain = load_map(MAPS / name)
    costed = _all_ones(plain)
    assert costed.costs is None and costed == plain
    rows = (MAPS / name).read_text().replace(".", "1")  # every free cell a digit 1
    digits = tmp_path / "ones.txt"
    digits.write_text(rows)
    for other in (costed, load_map(digits)):
        a, b = Run(plain, key), Run(other, key)
        a.advance(), b.advance()
        assert _record(a) == _record(b)
        assert json_summary(a.outcome()) == json_summary(b.outcome())


def _record(run: Run) -> dict:
    rec = recording_of(run).rec
    out = {name: getattr(rec, name) for name in rec.FIELDS}
    out["step_exp"] = [rec.exp(k) for k in range(1, rec.steps + 1)]
    out["step_g"] = None if rec.step_g is None else [g.hex() for g in rec.step_g]
    return out


def test_a_table_or_comments_give_the_same_run_and_json(tmp_path) -> None:
    from tui_search.engine.maps.terrain import parse_terrain

    rows = "S.ff.\n.ww..\n..f.G\n"
    inline = tmp_path / "inline.txt"
    inline.write_text("; terrain f 5\n; terrain w 12\n" + rows)
    plain = tmp_path / "plain.txt"
    plain.write_text(rows)
    table = parse_terrain("f 5\nw 12\n", "t.terrain")
    for key in ("bfs", "ucs", "astar", "greedy"):
        a = Run(load_map(inline), key).outcome()
        b = Run(load_map(plain, terrain=table), key).outcome()
        assert json_summary(a) == json_summary(b)


def test_a_start_on_a_costed_cell_keeps_its_cost_and_a_wall_costs_1() -> None:
    grid = Grid(3, 3, start=(1, 1), goal=(0, 0))
    grid.set_cost((1, 1), 7.0)
    assert grid.cost(grid.start) == 7.0 and grid.copy().cost((1, 1)) == 7.0
    grid.set_blocked((1, 1), True)
    assert grid.costs is None  # all 1 again: nothing kept
