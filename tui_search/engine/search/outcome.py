"""What a whole search came to: the path and the counts, however the search was run.

A recorded :class:`~tui_search.engine.run.recorded.Run` and the streaming reference search (the
headless command line) both end in an :class:`Outcome`; the command line turns it into its text and
JSON.
"""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import Any, NamedTuple

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.search.choices import Semantics


class Outcome(NamedTuple):
    algorithm: str
    semantics: Semantics
    #: Start to goal (None when no path was found): cells (x, y) on a grid, nodes' names on a
    #: graph.
    path: list[Any] | None
    moves: list[str] | None
    expanded: int  # steps that expanded a node
    discarded: int  # steps that took off a cell already expanded (visit on expand)
    generated: int  # pushes, the start (every iteration's root) included
    max_frontier: int
    gave_up: bool  # stopped at the step limit before the search ended
    #: The path's cost: each move's length (1 straight, sqrt(2) diagonal) times the cost of
    #: the cell it enters (:meth:`Grid.path_cost <tui_search.engine.maps.grid.Grid.path_cost>`).
    cost: float | None
    #: A bidirectional search's: why it stopped, in a sentence ("" for the others).
    stopped: str = ""
    #: A bidirectional search's meeting cell, its path's (None: none, or a search one way).
    meeting: Any = None

    @property
    def found(self) -> bool:
        return self.path is not None

    @property
    def steps(self) -> int:
        """Steps taken: one per ``n`` press, discarded ones included."""
        return self.expanded + self.discarded

    @property
    def length(self) -> int | None:
        """Moves on the path."""
        return None if self.moves is None else len(self.moves)


def cost_of(grid: Grid, path: list[Cell] | None) -> float | None:
    """:attr:`Outcome.cost` of ``path`` on ``grid`` (None: no path)."""
    return None if path is None else grid.path_cost(path)
