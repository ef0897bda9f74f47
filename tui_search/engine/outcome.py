"""What a whole search came to: the path and the counts, however the search was run.

A recorded :class:`~tui_search.engine.run.Run` and the streaming reference search (the headless
command line) both end in an :class:`Outcome`; the command line turns it into its text and JSON.
"""

from __future__ import annotations

from typing import NamedTuple

from tui_search.engine.grid import Cell, path_cost
from tui_search.engine.semantics import Semantics


class Outcome(NamedTuple):
    algorithm: str
    semantics: Semantics
    path: list[Cell] | None  # start to goal; None when no path was found
    moves: list[str] | None
    expanded: int  # steps that expanded a node
    discarded: int  # steps that took off a cell already expanded (visit on expand)
    generated: int  # pushes, the start (every iteration's root) included
    max_frontier: int
    gave_up: bool  # stopped at the step limit before the search ended

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

    @property
    def cost(self) -> float | None:
        """Octile cost of the path: 1 per straight move, sqrt(2) per diagonal."""
        return None if self.moves is None else path_cost(self.moves)
