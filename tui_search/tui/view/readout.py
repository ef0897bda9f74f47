"""Ask the map: what the run knows of one cell, in a line -- "(12,40): expanded at step 345,
depth 17, reached by NE from (11,41)", "(3,4) costs 5: never reached" (no Textual: the readout
widget shows the string)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.source import LAY
from tui_search.engine.run.position import CellState
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State
from tui_search.engine.util.numbers import group_digits
from tui_search.tui.model.cell_edits import cell_text

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.run.bidirectional import BiRun


def _number(value: float) -> str:
    return f"{value:.2f}".rstrip("0").rstrip(".")


def cell_head(grid: Grid | Graph, cell: State) -> str:
    """``(3,4)``, or ``(3,4) costs 5`` on terrain (a free cell that does not cost 1); on a
    Pacman layout with the course's own (x, y) too, y from the bottom: ``(3,4) course (3,5)``;
    a graph's node by its name."""
    if not isinstance(grid, Grid) or isinstance(cell, str):
        return cell_text(cell)
    head = cell_text(cell)
    if grid.source is not None and grid.source.kind == LAY:  # the course counts y from below
        head += f" course ({cell[0]},{grid.height - 1 - cell[1]})"
    cost = grid.cost(cell)
    if cost == 1.0 or grid.is_blocked(cell):
        return head
    return f"{head} costs {_number(cost)}"


def _blocked(board: Grid | Graph, state: State) -> bool:
    if isinstance(board, Grid):
        return isinstance(state, tuple) and board.is_blocked(state)
    return str(state) in board.closed


def describe(run: Run | None, grid: Grid | Graph, cell: State) -> str:
    """``cell``'s coordinates and what it is: an obstacle, never reached, on the frontier
    since a step, expanded at a step, with its depth, costs and the move that reached it
    (of its latest event at the run's position)."""
    head = cell_head(grid, cell)
    if _blocked(grid, cell):
        return f"{head}: {'obstacle' if isinstance(grid, Grid) else 'closed'}"
    parts = []
    if cell == grid.start:
        parts.append("the start")
    elif cell == grid.goal if isinstance(grid, Grid) else cell in grid.goals:
        parts.append("the goal")
    g = run.now.last_event(cell) if run is not None else None
    if run is None or g is None:
        if run is not None:
            parts.append("not reached in this iteration" if run.steps.iteration_of(run.k)
                         else "never reached")
        return f"{head}: {', '.join(parts) or 'free'}"
    state = run.now.cell_state(cell)
    if state == CellState.PATH:
        parts.append("on the path")
    step = run.nodes.expanded_at(g)
    if step is not None and step <= run.k:
        if run.steps.is_discarded(step):
            parts.append(f"taken off at step {step} and discarded (expanded before)")
        elif step == run.k:
            parts.append(f"being expanded (step {step})")
        else:
            parts.append(f"expanded at step {step}")
    else:
        since = run.nodes.generated_at(g)
        parts.append(f"on the frontier since step {since}")
    parts.append(f"depth {group_digits(run.nodes.depth(g))}")
    costs = run.nodes.costs(g)
    if costs is not None:
        cost, h, priority = costs
        parts.append(f"g {_number(cost)}")
        if run.algo.informed:
            parts.append(f"h {_number(h)}")
            if priority not in (cost, h):
                parts.append(f"f {_number(priority)}")
    parent = run.nodes.parent(g)
    if parent >= 0:
        parts.append(f"reached by {run.nodes.move(g)} from {cell_text(run.nodes.cell(parent))}")
    times = run.now.times_reached(cell)[0]
    if times > 1:
        parts.append(f"reached {times} times")
    return f"{head}: {', '.join(parts)}"


def describe_each(runs: Sequence[Run | BiRun], names: list[str], grid: Grid | Graph,
                  cell: State) -> str:
    """What each run knows of ``cell``, in a line -- "(3,4): BFS expanded at step 5, depth 3 …
    │ DFS never reached"; ``names`` name the runs ("": not named).  An obstacle is said once."""
    if not runs or _blocked(grid, cell):
        first = runs[0] if runs else None
        return describe(first if first is None or isinstance(first, Run) else first.halves[0],
                        grid, cell)
    bodies = [describe(run, grid, cell).partition(": ")[2] if isinstance(run, Run)
              else _two_way(run, grid, cell) for run in runs]
    return f"{cell_head(grid, cell)}: " + " │ ".join(
        f"{name} {body}".lstrip() for name, body in zip(names, bodies, strict=True))


def _two_way(run: BiRun, grid: Grid | Graph, cell: State) -> str:
    """What a bidirectional search's halves know of ``cell``, each counting its own steps:
    "→ expanded at its step 5, depth 3 … ← never reached"."""
    bodies = [describe(half, grid, cell).partition(": ")[2].replace(" at step ", " at its step ")
              for half in run.halves]
    return " ".join(f"{arrow} {body}" for arrow, body in zip("→←", bodies, strict=True))


__all__ = ["cell_head", "describe", "describe_each"]
