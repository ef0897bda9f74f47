"""A grid prepared for the fast loops: padded walls, padded start and goal, the moves.

Cells are indices into a copy of the map padded with a border of walls, so the loops need no
bounds checks: ``p = (y + 1) * (width + 2) + (x + 1)``.  The move order and the corner rule live
here too, so no loop of :mod:`tui_search.engine.search.loops` tests corners: a cell's legal moves
are ``moves[mask[p]]``.  A map with terrain gives its costs padded alike (``terrain[p]``; None on a
map whose every cell costs 1, which the loops then never read) and its lowest cell cost.
"""

from __future__ import annotations

from array import array
from collections.abc import MutableSequence, Sequence
from functools import cached_property
from typing import Any, cast

from tui_search.engine.maps.grid import DELTAS, DIR_CODE, DIRECTIONS, SQRT2, Cell, Grid
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics
from tui_search.engine.search.state import State


class Problem:
    """A grid prepared for the loops: padded walls, padded start/goal, neighbour offsets.

    ``moves[mask[p]]`` is the tuple of offsets to try from padded cell ``p``, in the neighbour
    order.  With corners ``always`` (the default) every mask is 0 and ``moves[0]`` holds every
    move of the order; otherwise ``mask[p]`` has a bit set for each diagonal the corner rule
    refuses from ``p``, and ``moves[mask]`` leaves those diagonals out -- so the hot loops never
    test corners.
    """

    def __init__(self, grid: Grid, semantics: Semantics = DEFAULT_SEMANTICS,
                 goal_test: str | None = None) -> None:
        """``goal_test`` is the one in force (the algorithm's own when the semantics leave it
        open: :meth:`~tui_search.engine.search.choices.Semantics.goal_test_for`)."""
        if grid.start is None or grid.goal is None:
            raise ValueError("the map needs a start and a goal")
        for name, cell in (("start", grid.start), ("goal", grid.goal)):
            if not grid.in_bounds(cell):
                raise ValueError(f"the {name} {cell} is outside the map")
            if grid.is_blocked(cell):
                raise ValueError(f"the {name} {cell} is on an obstacle")
        w, h = grid.width, grid.height
        self.grid = grid  # the map itself, for the loop that records the reference's steps
        self.board: Grid = grid  # (a graph's problem has its graph there)
        #: Where the run stops (None: not said): a recursion's calls form lists the calls
        #: made by then (:mod:`~tui_search.engine.search.recursion`).
        self.max_steps: int | None = None
        self.width, self.height = w, h
        self.stride = stride = w + 2
        # Shared with every search of this map until it is edited (Grid.derived): never written.
        self.walls, self.terrain = grid.derived("padded", padded)
        self.lowest = grid.lowest_cost()
        self.start = self.pad(grid.start)
        self.goal = self.pad(grid.goal)
        self.semantics = semantics
        self.goal_test = goal_test or semantics.goal_test or "generate"
        order = semantics.order
        offsets = [DELTAS[name][1] * stride + DELTAS[name][0] for name in order]
        self.dir_of_offset = {off: DIR_CODE[name] for name, off in zip(order, offsets, strict=True)}
        self.offsets = offsets

    @cached_property
    def _masks(self) -> tuple[bytes, list[tuple[int, ...]]]:
        """``mask`` and ``moves``, worked out when a loop first asks: the corner masks cost
        a pass over the whole map (benchmarks/README.md, "core"), which a loop that checks corners
        itself (the priority queue's, which may expand a handful of cells) never pays."""
        order, offsets = self.semantics.order, self.offsets
        if corner_free(self.semantics):
            return bytes(len(self.walls)), [tuple(offsets)]
        return self._corner_masks(order, offsets, self.semantics.corners)

    @property
    def plain_moves(self) -> tuple[int, ...]:
        """The offsets every cell tries, for the loops that serve only searches no corner rule
        touches (:func:`corner_free`): they skip the per-cell ``mask`` and ``moves`` lookups."""
        if not corner_free(self.semantics):
            raise ValueError("a corner rule is in force: the moves depend on the cell")
        return tuple(self.offsets)

    @property
    def mask(self) -> bytes:
        return self._masks[0]

    @property
    def moves(self) -> list[tuple[int, ...]]:
        return self._masks[1]

    def _corner_masks(
        self, order: tuple[str, ...], offsets: list[int], corners: str
    ) -> tuple[bytes, list[tuple[int, ...]]]:
        """Per cell, a bit per diagonal the corner rule refuses (whole-array operations):
        ``never`` refuses it when either side cell is blocked, ``one`` when both are."""
        walls, size = bytes(self.walls), len(self.walls)
        mask = 0
        diagonals = [i for i, name in enumerate(order) if len(name) == 2]
        for bit, i in enumerate(diagonals):
            dx, dy = DELTAS[order[i]]
            side_a = int.from_bytes(_shifted(walls, dx), "little")
            side_b = int.from_bytes(_shifted(walls, dy * self.stride), "little")
            refused = side_a | side_b if corners == "never" else side_a & side_b
            mask |= refused << bit  # each byte is 0 or 1, so bit << bit stays in its byte
        table = []
        for m in range(1 << len(diagonals)):
            banned = {diagonals[b] for b in range(len(diagonals)) if m >> b & 1}
            table.append(tuple(off for i, off in enumerate(offsets) if i not in banned))
        return mask.to_bytes(size, "little"), table

    def pad(self, cell: State) -> int:
        x, y = cast(Cell, cell)  # a grid's state is its cell
        return (y + 1) * self.stride + x + 1

    def unpad(self, p: int) -> tuple[int, int]:
        y, x = divmod(p, self.stride)
        return (x - 1, y - 1)

    # -- what a run's queries ask of a move (a graph's problem answers the same) -------------
    @property
    def size(self) -> int:
        """How many numbers a state may have: the padded cells."""
        return len(self.walls)

    def move_name(self, parent: int, child: int) -> str:
        """The direction of the move from padded cell ``parent`` to ``child``."""
        return DIRECTIONS[self.dir_of_offset[child - parent]]

    def step_cost(self, parent: int, child: int) -> float:
        """The move's length times the cost of the cell it enters: the float the loops add."""
        length = SQRT2 if len(self.move_name(parent, child)) == 2 else 1.0
        return length if self.terrain is None else length * self.terrain[child]

    def is_goal(self, p: int) -> bool:
        return p == self.goal

    def path_cost(self, path: list[State] | None) -> float | None:
        from tui_search.engine.search.outcome import cost_of

        return cost_of(self.grid, cast("list[Cell] | None", path))


def padded(grid: Grid) -> tuple[bytes, array[float] | None]:
    """``grid``'s walls with a border of walls, and its costs (None: all 1) with a border of 1.

    The walls' rows are joined by the two border cells between them, a block of rows at a
    time, or for a narrow map copied a column at a time (a strided slice): never an object
    a row alive at once, which cost a map of millions of one-cell rows many times its file
    (benchmarks/README.md, "big_map")."""
    w, h = grid.width, grid.height
    stride = w + 2
    if w < _NARROW:
        walls = bytearray(b"\x01") * (stride * (h + 2))
        _copy_columns(walls, grid.blocked, w, h)
        walls_bytes = bytes(walls)
    else:
        edge = b"\x01" * (w + 1)  # with the separator: the top border row and a left border
        cells = memoryview(grid.blocked)
        block = max(1, _BLOCK_BYTES // w)
        blocks = (b"\x01\x01".join([cells[y * w : (y + 1) * w]
                                    for y in range(lo, min(lo + block, h))])
                  for lo in range(0, h, block))
        walls_bytes = b"\x01\x01".join([edge, *blocks, edge])
    if grid.costs is None:
        return walls_bytes, None
    costs = grid.costs
    terrain = array("d", [1.0]) * len(walls_bytes)
    if w < _NARROW:
        _copy_columns(terrain, costs, w, h)
    else:
        for y in range(h):
            terrain[(y + 1) * stride + 1 : (y + 1) * stride + 1 + w] = costs[y * w : (y + 1) * w]
    return walls_bytes, terrain


#: Maps narrower than this are copied a column at a time; wider ones in blocks of rows of
#: about this many bytes.
_NARROW = 16
_BLOCK_BYTES = 1 << 16


def _copy_columns(out: MutableSequence[Any], cells: Sequence[Any], w: int, h: int) -> None:
    """Put the ``w`` x ``h`` ``cells`` (row by row) inside ``out``'s border of one cell, a
    column at a time (a strided copy: slow for wide maps, one pass for a narrow one)."""
    stride = w + 2
    for x in range(w):  # column x: every w-th cell, every stride-th place
        out[stride + 1 + x : stride * (h + 1) : stride] = cells[x :: w]


def corner_free(semantics: Semantics) -> bool:
    """Does every cell try the same moves: no corner rule, or no diagonal in the order?"""
    return semantics.corners == "always" or not any(len(name) == 2 for name in semantics.order)


def _shifted(data: bytes, offset: int) -> bytes:
    """``out[p] == data[p + offset]`` (1 = wall outside the array)."""
    n = len(data)
    if offset >= 0:
        return data[offset:] + b"\x01" * offset
    return b"\x01" * -offset + data[: n + offset]
