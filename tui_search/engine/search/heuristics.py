"""The heuristics of informed search, and what a move costs.

A straight move costs 1 and a diagonal sqrt(2) -- the octile cost the app reports for every
path.  A heuristic estimates the cost from a cell to the goal from the two offsets
``dx = |x - gx|`` and ``dy = |y - gy|`` alone:

* ``octile``: ``max + (sqrt(2) - 1) * min`` -- the exact cost on an open 8-connected grid;
* ``euclidean``: the straight line, never more than octile;
* ``chebyshev``: ``max(dx, dy)``, as if diagonals cost 1;
* ``manhattan``: ``dx + dy``, exact on an open 4-connected grid but *not admissible* with
  diagonal moves (it counts a diagonal as 2), so A* with it may return a costlier path -- a
  lesson, not a bug (AIMA's ``GridProblem`` keeps it anyway);
* ``zero``: no estimate at all: A* becomes uniform-cost search.

On a map with terrain every estimate is multiplied by the map's lowest cell cost
(:func:`scaled`): no move costs less than its length times that, so the estimates stay
admissible (and consistent).  The recorded loops and the reference loop call the same function, so a
priority is the same float whichever loop computed it (the frontier's order depends on it, ties and
all).
"""

from __future__ import annotations

from collections.abc import Callable
from math import hypot

from tui_search.engine.maps.grid import SQRT2

#: How much cheaper a new path to a cell must be for the cell to be pushed again.  Costs are
#: floating-point sums of 1 and sqrt(2), so two paths of the same cost summed in another
#: order can differ in the last bit; without this margin the cell would be pushed again (and
#: its first entry go stale) for nothing.  Two different costs on a grid of 10,000 moves differ
#: by far more (about 3e-5 at the least).
CHEAPER_BY = 1e-9

#: sqrt(2) - 1: what a diagonal costs beyond a straight move.
DIAGONAL_EXTRA = SQRT2 - 1

Heuristic = Callable[[int, int], float]


def octile(dx: int, dy: int) -> float:
    return dx + DIAGONAL_EXTRA * dy if dx >= dy else dy + DIAGONAL_EXTRA * dx


def euclidean(dx: int, dy: int) -> float:
    return hypot(dx, dy)


def chebyshev(dx: int, dy: int) -> float:
    return float(max(dx, dy))


def manhattan(dx: int, dy: int) -> float:
    return float(dx + dy)


def zero(dx: int, dy: int) -> float:
    return 0.0


HEURISTICS: dict[str, Heuristic] = {
    "octile": octile,
    "euclidean": euclidean,
    "manhattan": manhattan,
    "chebyshev": chebyshev,
    "zero": zero,
}

DEFAULT_HEURISTIC = "octile"

#: One line per heuristic, for the settings screen and the help.
EXPLAIN_HEURISTIC: dict[str, str] = {
    "octile": "the exact cost on an open grid (straight 1, diagonal √2)",
    "euclidean": "the straight-line distance",
    "manhattan": "dx + dy: counts a diagonal as 2, too much when diagonals are allowed",
    "chebyshev": "max(dx, dy): counts a diagonal as 1",
    "zero": "no estimate: A* becomes uniform-cost search",
}

#: What the app and the command line say when an inadmissible heuristic is in force.
INADMISSIBLE = "inadmissible heuristic: the path may not be optimal"


def admissible(name: str, order: tuple[str, ...]) -> bool:
    """Can ``name`` never overestimate the cost to the goal with these moves?  Every heuristic
    here is, except manhattan when a diagonal move is allowed (a diagonal costs sqrt(2) < 2).
    (With only straight moves manhattan is admissible, and exact on an open grid.)"""
    if name == "manhattan":
        return not any(len(move) == 2 for move in order)
    return True


def scaled(heuristic: Heuristic, lowest: float) -> Heuristic:
    """``heuristic`` times ``lowest``, the map's lowest cell cost (itself when that is 1:
    multiplying by 1 changes no float, and a plain map pays nothing)."""
    if lowest == 1.0:
        return heuristic
    return lambda dx, dy: lowest * heuristic(dx, dy)


def weighted(heuristic: Heuristic, weight: float) -> Heuristic:
    """``heuristic`` times weighted A*'s ``weight`` (itself when that is 1: A* pays nothing,
    and its floats stay A*'s)."""
    if weight == 1.0:
        return heuristic
    return lambda dx, dy: weight * heuristic(dx, dy)


def heuristic_for(name: str, lowest: float = 1.0) -> Heuristic:
    """The heuristic called ``name`` on a map whose lowest cell cost is ``lowest``."""
    return scaled(HEURISTICS[name], lowest)


def priority_of(priority: str, heuristic: Heuristic, goal: tuple[int, int],
                weight: float = 1.0) -> Callable[[float, int, int], float]:
    """The priority of an entry with cost ``g`` at ``(x, y)``: ``g``, ``h`` or ``g + h`` (the
    algorithm's ``priority``); weighted A*'s ``g + weight * h`` when ``weight`` is not 1 (the
    product rounded, then the sum: the compiled core's floats, built with no fused
    multiply-add).  The loops inline nothing of it, so every loop orders alike."""
    gx, gy = goal
    if priority == "g":
        return lambda g, x, y: g
    if priority == "h":
        return lambda g, x, y: heuristic(abs(x - gx), abs(y - gy))
    if weight != 1.0:
        return lambda g, x, y: g + weight * heuristic(abs(x - gx), abs(y - gy))
    return lambda g, x, y: g + heuristic(abs(x - gx), abs(y - gy))


def consistent_order(name: str, order: tuple[str, ...], weight: float = 1.0) -> bool:
    """Does an A* ordered by ``g + weight * h`` never reach a cell it expanded more cheaply
    (so that the loops may close an expanded cell)?  With weight 1 and an admissible heuristic
    here (each is consistent too); never for a weight above 1: W·h overestimates, and a cell
    expanded may be reached more cheaply later (it is re-opened, as the reference loop
    does)."""
    return weight == 1.0 and admissible(name, order)


__all__ = ["CHEAPER_BY", "DEFAULT_HEURISTIC", "EXPLAIN_HEURISTIC", "HEURISTICS", "INADMISSIBLE",
           "admissible", "consistent_order", "heuristic_for", "priority_of", "scaled", "weighted"]
