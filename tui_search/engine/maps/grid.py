"""The map model: size, obstacles, each free cell's cost, start and goal; the eight moves
and their order.

Coordinates follow MovingAI: ``x`` is the column counted from 0 at the left, ``y`` the row
counted from 0 at the top.  A move costs its length (1 straight, sqrt(2) diagonal) times the
cost of the cell it enters; a map whose every cell costs 1 keeps no costs at all (``costs``
is None), so the plain maps pay nothing for terrain.  The grid is a plain, mutable value: editing it
never touches a search, because every search copies what it needs when it starts (search state lives
in the run, never on the grid).  A copy shares what is worked out from the cells (the padded arrays
of :mod:`~tui_search.engine.search.problem`: :meth:`Grid.derived`) and its costs, until either grid
is edited: a search started on an unedited map pays neither again.
"""

from __future__ import annotations

import math
from array import array
from collections.abc import Callable
from itertools import compress, pairwise
from typing import TypeVar

from tui_search.engine.maps.source import MapSource

Cell = tuple[int, int]
_T = TypeVar("_T")

#: Every direction the robot can move in, with its (dx, dy).  The tuple's order is only the
#: numbering of direction codes; the order in which successors are generated is ``order``.
DIRECTIONS: tuple[str, ...] = ("N", "NE", "E", "SE", "S", "SW", "W", "NW")
DELTAS: dict[str, Cell] = {
    "N": (0, -1),
    "NE": (1, -1),
    "E": (1, 0),
    "SE": (1, 1),
    "S": (0, 1),
    "SW": (-1, 1),
    "W": (-1, 0),
    "NW": (-1, -1),
}
DIR_CODE: dict[str, int] = {name: i for i, name in enumerate(DIRECTIONS)}

#: Counterclockwise from north: the order the tutorial's narrative implies ("successors are
#: added (SW, S, E, NE) in the order that they are discovered").
DEFAULT_ORDER: tuple[str, ...] = ("N", "NW", "W", "SW", "S", "SE", "E", "NE")

SQRT2 = math.sqrt(2.0)


def parse_order(text: str) -> tuple[str, ...]:
    """Parse ``"N,NE,E,SE,S,SW,W,NW"`` (or any ordered, non-empty subset of the eight
    directions, e.g. ``"N,W,S,E"`` for the 4-connected grid) into a tuple of names.

    Raises ``ValueError`` with a one-line reason when it is not one.
    """
    names = tuple(part.strip().upper() for part in text.split(",") if part.strip())
    unknown = [n for n in names if n not in DELTAS]
    if unknown:
        raise ValueError(f"unknown direction {unknown[0]!r} (use N, NE, E, SE, S, SW, W, NW)")
    if len(set(names)) != len(names):
        dup = next(n for n in names if names.count(n) > 1)
        raise ValueError(f"direction {dup} is given twice")
    if not names:
        raise ValueError("name at least one direction (N, NE, E, SE, S, SW, W, NW)")
    return names


def move_cost(direction: str) -> float:
    """Octile cost of one move: 1 straight, sqrt(2) diagonal."""
    return SQRT2 if len(direction) == 2 else 1.0


def is_diagonal(direction: str) -> bool:
    return len(direction) == 2


class Grid:
    """A ``width`` x ``height`` map; ``blocked[y * width + x]`` is 1 for an obstacle, and
    ``costs[y * width + x]`` (None: all 1) what entering the cell costs (> 0; 1 on an
    obstacle).  An all-1 ``costs`` is stored as None, so two grids of the same map are equal.
    Edit cells with :meth:`set_blocked` and :meth:`set_cost` (or give ``costs`` a new array),
    never by writing into ``blocked`` or ``costs``: :meth:`lowest_cost` and :meth:`derived`
    are remembered until then, and a copy shares ``costs`` until one of the two sets a cost."""

    #: What two grids are compared by (``==``; a grid is mutable, so it has no hash) and
    #: shown by: not the file text, nor what is worked out from the cells.
    COMPARED = ("width", "height", "blocked", "start", "goal", "costs")

    def __init__(self, width: int, height: int, blocked: bytearray | None = None,
                 start: Cell | None = None, goal: Cell | None = None,
                 source: MapSource | None = None, costs: array[float] | None = None) -> None:
        # Written out, not a dataclass (compiled at import: benchmarks/README.md, "startup").
        if width < 1 or height < 1:
            raise ValueError("a grid needs at least one row and one column")
        if blocked is None:
            blocked = bytearray(width * height)  # all open
        elif len(blocked) != width * height:
            raise ValueError("blocked has the wrong size")
        if costs is not None and len(costs) != len(blocked):
            raise ValueError("costs has the wrong size")
        self.width = width
        self.height = height
        self.blocked = blocked
        self.start = start
        self.goal = goal
        #: The file text the grid was read from (None for a grid built in code): saving
        #: writes it back with only the edited cells changed.  Not part of the grid's value.
        self.source = source
        self.costs = costs
        # lowest_cost's answer and the costs it is for: worked out again after an edit
        # (set_cost, set_blocked) or when ``costs`` is another array.
        self._lowest: tuple[array[float], float] | None = None
        # derived()'s answers, shared with this grid's copies: an edit gives the edited grid
        # a new, empty dict (never clears the shared one), so the others keep theirs.
        self._derived: dict[str, tuple[array[float] | None, object]] = {}
        # costs is one array with a copy's (or the grid copied): set_cost copies it before
        # writing.
        self._costs_shared = False
        self._all_ones()

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        return all(getattr(self, name) == getattr(other, name) for name in self.COMPARED)

    __hash__ = None  # type: ignore[assignment]  # mutable: unhashable, as a dataclass with == is

    def __repr__(self) -> str:
        shown = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.COMPARED[:5])
        return f"Grid({shown})"

    # -- queries -------------------------------------------------------------------------
    def in_bounds(self, cell: Cell) -> bool:
        x, y = cell
        return 0 <= x < self.width and 0 <= y < self.height

    def is_blocked(self, cell: Cell) -> bool:
        x, y = cell
        return bool(self.blocked[y * self.width + x])

    def is_free(self, cell: Cell) -> bool:
        return self.in_bounds(cell) and not self.is_blocked(cell)

    def cost(self, cell: Cell) -> float:
        """What entering ``cell`` costs (per unit of a move's length)."""
        if self.costs is None:
            return 1.0
        x, y = cell
        return self.costs[y * self.width + x]

    def lowest_cost(self) -> float:
        """The lowest cost of a free cell (1 on a map without terrain, or with no free cell):
        the factor that keeps the heuristics admissible."""
        costs = self.costs
        if costs is None:
            return 1.0
        if self._lowest is None or self._lowest[0] is not costs:
            free = self.blocked.translate(_FREE)
            self._lowest = costs, min(compress(costs, free), default=1.0)
        return self._lowest[1]

    def derived(self, key: str, make: Callable[[Grid], _T]) -> _T:
        """``make(self)``, remembered under ``key`` until the grid is edited (shared with its
        copies while neither is): what a search works out from the cells alone, such as the
        padded walls and costs of :class:`~tui_search.engine.search.problem.Problem`.  What ``make``
        returns is shared, so no one may change it."""
        found = self._derived.get(key)
        if found is not None and found[0] is self.costs:
            return found[1]  # type: ignore[return-value]
        value = make(self)
        self._derived[key] = (self.costs, value)
        return value

    def path_cost(self, path: list[Cell]) -> float:
        """The cost of ``path``: each move's length times the cost of the cell it enters,
        summed from the start as the searches sum g (the start's own cost is never paid).
        Without terrain, the octile length of its moves (:func:`path_cost`)."""
        if self.costs is None:
            return path_cost(path_moves(path))
        g, costs, w = 0.0, self.costs, self.width
        for (ax, ay), (bx, by) in pairwise(path):
            g = g + (SQRT2 if ax != bx and ay != by else 1.0) * costs[by * w + bx]
        return g

    def row(self, y: int) -> bytes:
        """The obstacle bytes of row ``y`` (fast path for drawing)."""
        w = self.width
        return bytes(self.blocked[y * w : (y + 1) * w])

    def neighbours(
        self, cell: Cell, order: tuple[str, ...] = DEFAULT_ORDER, corners: str = "always"
    ) -> list[tuple[str, Cell]]:
        """Legal moves from ``cell`` in ``order`` under the corner rule ``corners``
        (``always``, ``one`` or ``never``; see :mod:`tui_search.engine.search.choices`), ignoring
        visited state: the reference definition that the fast search loops must agree with."""
        x, y = cell
        out = []
        for name in order:
            dx, dy = DELTAS[name]
            nxt = (x + dx, y + dy)
            if not self.is_free(nxt):
                continue
            if dx and dy and corners != "always":
                a, b = self.is_free((x + dx, y)), self.is_free((x, y + dy))
                if not (a and b if corners == "never" else a or b):
                    continue
            out.append((name, nxt))
        return out

    # -- edits (the app owns the grid and calls these) ----------------------------------
    def set_blocked(self, cell: Cell, value: bool) -> None:
        """Block or free ``cell``; a blocked cell costs 1 (a freed one is plain floor)."""
        x, y = cell
        self.blocked[y * self.width + x] = 1 if value else 0
        self._lowest = None
        self._derived = {}
        if value and self.costs is not None:
            self.set_cost(cell, 1.0)

    def set_cost(self, cell: Cell, value: float) -> None:
        """Make entering ``cell`` cost ``value`` (> 0)."""
        if not (value > 0 and math.isfinite(value)):
            raise ValueError(f"a cell's cost must be a positive number, not {value!r}")
        x, y = cell
        i = y * self.width + x
        known = self._lowest[1] if self._lowest is not None and self.costs is not None \
            and self._lowest[0] is self.costs else None
        if self.costs is None:
            if value == 1.0:
                return
            self.costs = array("d", [1.0]) * (self.width * self.height)
        elif self._costs_shared:  # a copy's too: write into one of its own
            self.costs = array("d", self.costs)
        self._costs_shared = False
        old, self.costs[i] = self.costs[i], value
        self._lowest = None
        self._derived = {}
        # The lowest free cost follows a free cell's edit with no scan of the map
        # (benchmarks/README.md, "terrain"), unless the cell was the lowest and is dearer now
        # (another may be as low).
        if known is not None and not self.blocked[i] and (value <= known or old != known):
            self._lowest = self.costs, min(known, value)
        if value == 1.0:
            self._all_ones()

    def _all_ones(self) -> None:
        """Keep no costs when every cell costs 1."""
        if self.costs is not None and self.costs.count(1.0) == len(self.costs):
            self.costs = None

    def copy(self) -> Grid:
        grid = Grid(
            self.width, self.height, bytearray(self.blocked), self.start, self.goal, self.source
        )
        if self.costs is not None:  # already not all 1: no need to look again
            # shared until either grid sets a cost (set_cost copies it then)
            grid.costs = self.costs
            grid._costs_shared = self._costs_shared = True
            # worked out here once, not once a copy: every search copies the grid it runs on
            grid._lowest = grid.costs, self.lowest_cost()
        grid._derived = self._derived
        return grid

    def free_count(self) -> int:
        return len(self.blocked) - self.blocked.count(1)


#: ``blocked.translate(_FREE)``: 1 for a free cell, 0 for an obstacle.
_FREE = bytes.maketrans(b"\x00\x01", b"\x01\x00")


def path_moves(path: list[Cell]) -> list[str]:
    """Direction names of the moves along ``path``."""
    by_delta = {v: k for k, v in DELTAS.items()}
    return [by_delta[(b[0] - a[0], b[1] - a[1])] for a, b in pairwise(path)]


def path_cost(moves: list[str]) -> float:
    """Octile length of a list of moves."""
    diag = sum(1 for m in moves if len(m) == 2)
    return (len(moves) - diag) + diag * SQRT2
