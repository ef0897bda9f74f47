"""What a bidirectional search's map draws (no Textual or Rich): each cell as its two halves
see it, the forward half's states in their own looks, the backward half's in theirs
(:data:`~tui_search.tui.view.cell_codes.BACK_FRONTIER` ...), a cell both have reached as one
of its own, the best meeting so far marked, and at the end the path through it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.search.state import State, as_cell
from tui_search.tui.view.cell_codes import (
    BACK_CURRENT,
    BACK_EXPANDED,
    BACK_FRONTIER,
    BOTH,
    CURRENT,
    EXPANDED,
    FREE,
    MEETING,
    PATH,
)

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.run.recorded import Run

#: A backward half's state (free, frontier, expanded, being expanded) as a drawing code.
BACKWARD_CODES = (FREE, BACK_FRONTIER, BACK_EXPANDED, BACK_CURRENT)


def combine(ahead: int, behind: int) -> int:
    """The code of a cell the forward half sees as ``ahead`` and the backward as ``behind``
    (each a state: free, frontier, expanded, being expanded): the one being expanded shows
    as such, else a cell both reached is :data:`BOTH`."""
    if not behind:
        return ahead
    if not ahead:
        return BACKWARD_CODES[behind]
    if ahead == CURRENT:
        return CURRENT
    return BACK_CURRENT if behind == CURRENT else BOTH


def two_way_codes(run: BiRun, y: int, x0: int, x1: int) -> list[int]:
    """Drawing codes of cells ``x0 .. x1-1`` of map row ``y`` for ``run`` at its position."""
    ahead, behind = (half.now.row_states(y, x0, x1) for half in run.halves)
    # each half marks the node of its own last step: only the step just taken's is current
    still = behind if run.k and run.direction(run.k) == "forward" else ahead
    for i, state in enumerate(still):
        if state == CURRENT:
            still[i] = EXPANDED
    codes = [combine(a, b) for a, b in zip(ahead, behind, strict=True)]
    if run.at_end:
        for cell in run.path() or ():
            x, y_ = as_cell(cell)
            if y_ == y and x0 <= x < x1:
                codes[x - x0] = PATH
    meeting = run.meeting()
    if meeting is not None:
        mx, my = as_cell(meeting)
        if my == y and x0 <= mx < x1:
            codes[mx - x0] = MEETING
    return codes


def node_code(run: BiRun, node: State) -> int:
    """The drawing code of ``node`` (a graph's, or a cell) for ``run`` at its position."""
    if node == run.meeting():
        return MEETING
    if run.at_end and node in (run.path() or ()):
        return PATH
    ahead, behind = (int(half.now.cell_state(node)) for half in run.halves)
    if run.k and run.direction(run.k) == "forward":
        behind = EXPANDED if behind == CURRENT else behind
    else:
        ahead = EXPANDED if ahead == CURRENT else ahead
    return combine(ahead, behind)


def half_at(run: BiRun, cell: State) -> Run | None:
    """The half whose numbers a cell's label shows: the forward half's where it reached the
    cell, else the backward's where it did (None: neither)."""
    for half in run.halves:
        if half.now.last_event(cell) is not None:
            return half
    return None


__all__ = ["BACKWARD_CODES", "combine", "half_at", "node_code", "two_way_codes"]
