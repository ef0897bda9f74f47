"""Shared test helpers: build grids from rows, and an independent shortest-path oracle."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from tui_search.engine.maps.grid import Grid

ROOT = Path(__file__).resolve().parents[1]
MAPS = ROOT / "maps"
#: The tutorial's map, for the tests of the app and of its Textual-free parts alike.
TUTORIAL = MAPS / "tutorial.txt"
#: Real MovingAI benchmark files copied into the repository (maps byte for byte, big .scen files
#: trimmed to a spread of rows; their origins are in SOURCES.md there), so a fresh clone and CI
#: run every test that reads one.
MOVINGAI = ROOT / "tests" / "data" / "movingai"

TUTORIAL_ROWS = [
    "S#...#",
    ".#.##.",
    "...##G",
    "..#.#.",
    "....##",
    "......",
]


def grid_from_rows(rows: list[str]) -> Grid:
    """A grid from text rows: '#' obstacle, 'S' start, 'G' goal, anything else free."""
    grid = Grid(len(rows[0]), len(rows))
    for y, row in enumerate(rows):
        for x, ch in enumerate(row):
            if ch == "#":
                grid.set_blocked((x, y), True)
            elif ch == "S":
                grid.start = (x, y)
            elif ch == "G":
                grid.goal = (x, y)
    return grid


def reference_distances(
    grid: Grid, corners: str = "always", order: tuple[str, ...] | None = None
) -> dict[tuple[int, int], int]:
    """Fewest moves from the start to every reachable cell, by relaxing all edges until
    nothing changes (Bellman-Ford): deliberately not a queue-based search, so it checks
    BFS independently."""
    return {c: int(d) for c, d in _relaxed(grid, corners, order, lambda move: 1).items()}


def reference_costs(
    grid: Grid, corners: str = "always", order: tuple[str, ...] | None = None
) -> dict[tuple[int, int], float]:
    """The cheapest cost (1 a straight move, sqrt(2) a diagonal) from the start to every
    reachable cell, the same way: no priority queue, so it checks uniform-cost search and A*
    independently."""
    from tui_search.engine.maps.grid import move_cost

    return _relaxed(grid, corners, order, move_cost)


def _relaxed(grid: Grid, corners: str, order: tuple[str, ...] | None,
             cost_of: Callable[[str], float]) -> dict[tuple[int, int], float]:
    """Bellman-Ford from the start: each move costs ``cost_of(move)``; unreachable cells are
    left out."""
    inf = float("inf")
    dist = {(x, y): inf for y in range(grid.height) for x in range(grid.width)}
    dist[grid.start] = 0
    changed = True
    while changed:
        changed = False
        for cell, d in dist.items():
            if d == inf or grid.is_blocked(cell):
                continue
            moves = grid.neighbours(cell, corners=corners) if order is None else (
                grid.neighbours(cell, order, corners))
            for move, nxt in moves:
                if dist[nxt] > d + cost_of(move) + 1e-12:
                    dist[nxt] = d + cost_of(move)
                    changed = True
    return {c: d for c, d in dist.items() if d != inf}


def summary(run) -> dict:
    """A recorded run's whole result as the headless JSON gives it."""
    from tui_search.cli.headless import json_summary

    return json_summary(run.outcome())


def flags_of(*argv: str):
    """The command line's options as typed, nothing read (no map, no exercise): what
    :func:`~tui_search.cli.parse.parse_options` starts from, for tests of the flags alone."""
    from tui_search.cli.options import Options
    from tui_search.cli.parser import build_parser
    from tui_search.engine.search.registry import DEFAULT_ALGORITHM

    args = build_parser().parse_args(list(argv))
    return Options.made(vars(args), maps=tuple(args.maps),
                        algorithm_given=args.algorithm is not None,
                        algorithm=args.algorithm or DEFAULT_ALGORITHM)
