"""What a grid shares with its copies (its costs, the padded arrays of a search's Problem)
until either is edited: every search sees exactly the cells of the grid it was started on."""

from __future__ import annotations

from array import array

from hypothesis import given
from hypothesis import strategies as st

from tests.engine.test_search import random_grids
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.problem import Problem


def reference_padding(grid: Grid) -> tuple[bytes, list[float] | None]:
    """The padded walls and costs, cell by cell."""
    w, h = grid.width, grid.height
    walls, costs = [], []
    for y in range(-1, h + 1):
        for x in range(-1, w + 1):
            inside = 0 <= x < w and 0 <= y < h
            walls.append(grid.is_blocked((x, y)) if inside else True)
            costs.append(grid.cost((x, y)) if inside else 1.0)
    return bytes(walls), None if grid.costs is None else costs


def _check(grid: Grid) -> None:
    problem = Problem(grid)
    walls, costs = reference_padding(grid)
    assert bytes(problem.walls) == walls
    assert (None if problem.terrain is None else list(problem.terrain)) == costs
    free = [grid.cost((x, y)) for y in range(grid.height) for x in range(grid.width)
            if not grid.is_blocked((x, y))]
    assert problem.lowest == grid.lowest_cost() == min(free, default=1.0)


# an edit: which grid of the ones made so far, a cell (as fractions of the sides), what
edits = st.lists(st.tuples(st.integers(0, 7), st.floats(0, 0.999), st.floats(0, 0.999),
                           st.sampled_from(["wall", "free", 1.0, 0.5, 3.0, 9.0, "copy", "low"])),
                 max_size=12)


@given(random_grids(max_side=7, walls_one_in=3, costs=True), edits)
def test_copies_and_edits_in_any_order_pad_each_grid_as_it_is(grid: Grid, steps) -> None:
    grids = [grid]
    _check(grid)
    for which, fx, fy, what in steps:
        g = grids[which % len(grids)]
        cell = (int(fx * g.width), int(fy * g.height))
        if what == "copy":
            grids.append(g.copy())
        elif what == "low":  # worked out, then followed through the edits after
            g.lowest_cost()
        elif what in ("wall", "free"):
            if cell not in (g.start, g.goal):
                g.set_blocked(cell, what == "wall")
        elif not g.is_blocked(cell):
            g.set_cost(cell, what)
        for each in grids:  # every grid, edited or not, pads as it is now
            _check(each)


def test_a_copy_shares_the_costs_until_either_sets_one() -> None:
    grid = Grid(3, 2, start=(0, 0), goal=(2, 1))
    grid.set_cost((1, 0), 5.0)
    copy = grid.copy()
    assert copy.costs is grid.costs
    copy.set_cost((1, 1), 7.0)
    assert copy.costs is not grid.costs
    assert (grid.cost((1, 1)), copy.cost((1, 1))) == (1.0, 7.0)
    grid.set_cost((1, 0), 2.0)
    assert (grid.cost((1, 0)), copy.cost((1, 0))) == (2.0, 5.0)


def test_a_run_keeps_its_cells_when_the_map_is_edited_after_it() -> None:
    grid = Grid(4, 1, start=(0, 0), goal=(3, 0))
    grid.set_cost((2, 0), 9.0)
    before = Run(grid, "ucs")
    again = Run(grid, "ucs")  # an unedited map: the padded arrays are worked out once
    assert recording_of(again).problem.walls is recording_of(before).problem.walls
    grid.set_cost((2, 0), 3.0)
    grid.set_blocked((1, 0), True)
    after = Run(grid, "ucs")
    assert before.outcome().cost == 11.0 and not before.grid.is_blocked((1, 0))
    assert after.outcome().found is False
    grid.set_blocked((1, 0), False)
    assert Run(grid, "ucs").outcome().cost == 5.0


def test_costs_given_as_a_new_array_are_padded_anew() -> None:
    grid = Grid(3, 1, start=(0, 0), goal=(2, 0))
    grid.set_cost((1, 0), 4.0)
    _check(grid)
    grid.costs = array("d", [1.0, 6.0, 2.0])
    _check(grid)
    assert Run(grid, "ucs").outcome().cost == 8.0


def test_a_grid_is_a_mutable_value() -> None:
    """Grid is written out (not a dataclass, for the start's sake): equal by its size, cells,
    ends and costs (not by the file it came from, nor by what is worked out from it), with no
    hash, shown by its size, cells and ends, and checked when made."""
    import pytest

    from tui_search.engine.maps.source import MapSource

    grid = Grid(3, 2, bytearray([0, 1, 0, 0, 0, 0]), (0, 0), (2, 1),
                costs=array("d", [1.0, 1.0, 2.0, 1.0, 1.0, 1.0]))
    copy = grid.copy()
    assert copy == grid and copy is not grid and copy.source is None
    copy.lowest_cost()
    assert Grid(3, 2, bytearray(grid.blocked), (0, 0), (2, 1), source=object(),  # type: ignore[arg-type]
                costs=array("d", grid.costs or [])) == grid
    assert Grid(2, 1, costs=array("d", [1.0, 1.0])).costs is None  # all 1: no costs kept
    for other in (Grid(3, 2, bytearray(grid.blocked), (0, 0), (2, 0), costs=grid.costs),
                  Grid(3, 2, bytearray(6), (0, 0), (2, 1), costs=grid.costs),
                  Grid(3, 2, bytearray(grid.blocked), (0, 0), (2, 1))):
        assert other != grid
    assert grid != (3, 2) and not isinstance(MapSource, Grid)
    with pytest.raises(TypeError):
        hash(grid)
    assert repr(Grid(2, 1, start=(0, 0))) == (
        "Grid(width=2, height=1, blocked=bytearray(b'\\x00\\x00'), start=(0, 0), goal=None)")
    for bad in (lambda: Grid(0, 1), lambda: Grid(2, 2, bytearray(3)),
                lambda: Grid(2, 1, costs=array("d", [1.0]))):
        with pytest.raises(ValueError):
            bad()
