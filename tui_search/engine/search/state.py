"""What a search's states are -- a grid's cells, a graph's nodes' names -- and how a person
reads one.  Plain functions, imported by everything that shows a state (the first frame
too: nothing here is slow to import)."""

from __future__ import annotations

from tui_search.engine.maps.grid import Cell

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


__all__ = ["State", "as_cell", "state_text"]
