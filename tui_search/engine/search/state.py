"""What a search's states are -- a grid's cells, a graph's nodes' names -- and how a person
reads one.  Plain functions, imported by everything that shows a state (the first frame
too: nothing here is slow to import)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import Cell

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.maps.grid import Grid

#: A state of what is searched: a grid's cell ``(x, y)``, a graph's node's name.
State = Cell | str


def state_text(state: State | None) -> str:
    """A cell or a node as a person reads it: ``(2,3)``, ``Sibiu`` (``-``: none)."""
    if state is None:
        return "-"
    if isinstance(state, str):
        return state
    return f"({state[0]},{state[1]})"


def as_cell(state: State) -> Cell:
    """``state`` where only a grid's cell can be (a map's drawing, its moves)."""
    assert isinstance(state, tuple), f"{state!r} is a graph's node, not a cell"
    return state


def state_width(board: Grid | Graph) -> int:
    """The widest a state of ``board`` is written (:func:`state_text`): the map's farthest
    cell's, or the graph's longest name."""
    if hasattr(board, "names"):  # a graph (its module not imported for a grid)
        return max(map(len, board.names))
    return len(f"({board.width - 1},{board.height - 1})")


__all__ = ["State", "as_cell", "state_text", "state_width"]
