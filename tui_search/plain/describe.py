"""The map in words, for plain mode: the whole map row by row, one row or column, one cell,
or the cells around the cursor -- each cell as what it is now ("free", "obstacle", "goal",
"on the queue", "expanded", "being expanded", "path"), its terrain cost where it has one.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import DELTAS, Cell, Grid
from tui_search.engine.run.position import CellState
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import as_cell
from tui_search.tui.model.session import Session
from tui_search.tui.view.narration import cell_text
from tui_search.tui.view.readout import describe_each

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun

#: The neighbours said around a cell, clockwise from north.
AROUND = ("N", "NE", "E", "SE", "S", "SW", "W", "NW")
#: A run of this many cells alike or more is said once, counted ("5 free").
RUN_SAID = 3


def cell_word(session: Session, cell: Cell, run: Run | None = None) -> str:
    """What ``cell`` is now, in a word or three (``run``: whose state; the first pane's; a
    bidirectional search's: both halves', :func:`two_way_word`)."""
    grid = session.grid
    if grid.is_blocked(cell):
        return "obstacle"
    shown = run or session.run
    if shown is not None and not isinstance(shown, Run):
        return two_way_word(shown, grid, cell)
    run = shown
    state = run.now.cell_state(cell) if run is not None else CellState.UNSEEN
    if cell == grid.start:
        word = "start"
    elif cell == grid.goal:
        word = "goal" + (", found" if state == CellState.PATH else "")
    else:
        word = {CellState.UNSEEN: "free",
                CellState.FRONTIER: f"on the {run.algo.frontier.noun}" if run else "free",
                CellState.EXPANDED: "expanded", CellState.CURRENT: "being expanded",
                CellState.PATH: "path"}[state]
    cost = grid.cost(cell)
    return f"{word} cost {cost:g}" if cost != 1.0 else word


def two_way_word(run: BiRun, grid: Grid, cell: Cell) -> str:
    """What ``cell`` is to a bidirectional search: "start", "goal", "path", "meeting", or
    each half's word ("forward expanded, backward on the queue")."""
    if run.at_end and cell in (run.path() or ()):
        word = "path"
    elif cell == run.meeting():
        word = "best meeting"
    elif cell in (grid.start, grid.goal):
        word = "start" if cell == grid.start else "goal"
    else:
        noun = run.algo.frontier.noun
        words = {CellState.FRONTIER: f"on the {noun}", CellState.EXPANDED: "expanded",
                 CellState.CURRENT: "being expanded"}
        said = [f"{d} {words[state]}" for d, half in zip(("forward", "backward"), run.halves,
                                                          strict=True)
                if (state := half.now.cell_state(cell)) in words]
        word = ", ".join(said) or "free"
    cost = grid.cost(cell)
    return f"{word} cost {cost:g}" if cost != 1.0 else word


def _said(words: list[str]) -> str:
    """Words in order, a run of :data:`RUN_SAID` or more alike said once, counted."""
    out: list[str] = []
    i = 0
    while i < len(words):
        j = i
        while j < len(words) and words[j] == words[i]:
            j += 1
        n = j - i
        out += [f"{n} {words[i]}"] if n >= RUN_SAID else words[i:j]
        i = j
    return ", ".join(out)


def _mark_cursor(session: Session, cells: list[Cell], words: list[str]) -> list[str]:
    return [w + " (cursor)" if c == session.cursor else w for c, w in zip(cells, words,
                                                                            strict=True)]


def describe_row(session: Session, y: int) -> str:
    """"Row 3: free, free, obstacle, goal, 2 free" (from x 0)."""
    grid = session.grid
    if not 0 <= y < grid.height:
        return f"There is no row {y}: rows go from 0 to {grid.height - 1}."
    cells = [(x, y) for x in range(grid.width)]
    words = _mark_cursor(session, cells, [cell_word(session, c) for c in cells])
    return f"Row {y}: {_said(words)}."


def describe_column(session: Session, x: int) -> str:
    """"Column 2: obstacle, free, ..." (from y 0, the top)."""
    grid = session.grid
    if not 0 <= x < grid.width:
        return f"There is no column {x}: columns go from 0 to {grid.width - 1}."
    cells = [(x, y) for y in range(grid.height)]
    words = _mark_cursor(session, cells, [cell_word(session, c) for c in cells])
    return f"Column {x}: {_said(words)}."


def describe_map(session: Session) -> list[str]:
    """The map: its size, ends and obstacles, then each row."""
    grid = session.grid
    walls = sum(grid.is_blocked((x, y)) for y in range(grid.height) for x in range(grid.width))
    ends = ", ".join(f"{name} {cell_text(cell)}" if cell is not None else f"no {name}"
                     for name, cell in (("start", grid.start), ("goal", grid.goal)))
    head = (f"Map {session.map_name}: {grid.width} columns by {grid.height} rows, x from 0 "
            f"at the left, y from 0 at the top; {ends}; {walls} obstacles; the cursor on "
            f"{cell_text(session.cursor)}.")
    return [head, *(describe_row(session, y) for y in range(grid.height))]


def describe_cell(session: Session, cell: Cell) -> str:
    """What every search shown knows of ``cell`` (the app's readout line)."""
    if not session.grid.in_bounds(cell):
        return f"{cell_text(cell)} is off the map."
    return describe_each(session.runs, session.names, session.grid, cell) + "."


def describe_around(session: Session) -> str:
    """The cursor's cell and its eight neighbours, clockwise from north."""
    x, y = cursor = as_cell(session.cursor)  # plain mode shows grids
    grid = session.grid
    parts = []
    for move in AROUND:
        dx, dy = DELTAS[move]
        cell = (x + dx, y + dy)
        word = cell_word(session, cell) if grid.in_bounds(cell) else "off the map"
        parts.append(f"{move} {cell_text(cell)} {word}")
    return (f"Around {cell_text(cursor)}, {cell_word(session, cursor)}: "
            f"{', '.join(parts)}.")
