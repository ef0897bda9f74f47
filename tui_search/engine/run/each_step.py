"""A whole search at once, each step handed on as it happens (:func:`search_each_step`): what
the headless trace and a Posthoc trace's export are written from.

Graph BFS and DFS take at most a few steps per cell, so they run on the fast recorded loops
(the record is bounded by the map); iterative deepening and tree search can take billions of
steps on a small map, so they stream the reference loop, which keeps only the frontier and
the parents it points to; so do the bidirectional searches, which no run records.  The two
are held equal by a property test.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, Step
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.registry import get_algorithm

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.search.reference import Expansion


def as_step(step: Expansion) -> Step:
    """A step of the reference loop as a recorded run's step."""
    return Step(step.index, step.node.cell, tuple((s.move or "", s.cell) for s in step.successors),
                step.depth_limit, step.found, step.discarded, step.f_limit, step.direction)


def search_each_step(grid: Grid | Graph, key: str, semantics: Semantics, max_steps: int,
                     on_step: Callable[[Step], object] | None = None) -> Outcome:
    """Search ``grid`` (or a graph) with ``key`` under ``semantics``, at most ``max_steps``
    steps, giving each step to ``on_step`` as it happens; the outcome."""
    algorithm = get_algorithm(key)
    if algorithm.iterative or semantics.tree_search or algorithm.bidirectional:
        from tui_search.engine.search.reference import stream  # not imported at start-up

        write = None if on_step is None else (lambda step: on_step(as_step(step)))
        return stream(grid, algorithm, semantics, max_steps, write)
    run = Run(grid, key, semantics, max_steps)
    if on_step is not None:
        for step in run.steps.all():
            on_step(step)
    return run.outcome()
