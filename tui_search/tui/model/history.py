"""The map's edit history: undo and redo, and whether the map differs from its file.

An :class:`Edit` is what one key or one mouse stroke changed: each obstacle cell with what it
was and became, each cell the terrain brush painted with its cost before and after, and the
start and goal before and after.  :class:`History` keeps the last
:data:`MAX_EDITS` of them and where the map stands among them, so undo and redo re-apply the
changes to the grid, and "modified" is a comparison of two positions (where the map is, and
where it was read or last saved) rather than of two grids: a mouse stroke on a big map is an
edit a cell, and comparing millions of cells after each would cost more than the edit.

It never draws and never imports Textual: the session
(:class:`~tui_search.tui.model.session.Session`) records each edit here, and the screen groups a
mouse stroke into one edit (:meth:`History.begin_stroke`, :meth:`History.end_stroke`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.search.state import State

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph

#: The edits kept: older ones can no longer be undone.
MAX_EDITS = 1000

#: The start and the goal (None: not on the map).
Ends = tuple[Cell | None, Cell | None]


class Change(Protocol):
    """What the history keeps of one edit: a grid's (:class:`Edit`) or a graph's
    (:class:`~tui_search.tui.model.graph_edits.GraphEdit`, which paints no cells)."""

    walls: list[tuple[Cell, bool, bool]]
    costs: list[tuple[Cell, float, float]]

    def apply(self, board: Grid | Graph, undo: bool) -> State:
        """Put the board as it was before the edit (``undo``) or after it; the state the
        edit is about, for the cursor."""
        ...


class Edit:
    """One edit: ``walls`` lists ``(cell, blocked before, blocked after)`` in the order the
    cells changed, ``costs`` ``(cell, cost before, cost after)`` (the terrain brush); ``ends``
    is the start and goal before and after (None: they stayed)."""

    # Not a dataclass, which compiles its methods when the app starts.
    def __init__(self, walls: list[tuple[Cell, bool, bool]] | None = None,
                 ends: tuple[Ends, Ends] | None = None,
                 costs: list[tuple[Cell, float, float]] | None = None) -> None:
        self.walls = walls if walls is not None else []
        self.ends = ends
        self.costs = costs if costs is not None else []

    def apply(self, board: Grid | Graph, undo: bool) -> State:
        """Put ``board`` (a grid) as it was before this edit (``undo``) or after it; the cell
        the edit is about, for the cursor: its first obstacle (or painted) cell, else where the
        end that moved is now (or was, when it left the map)."""
        grid = board
        assert isinstance(grid, Grid), "a grid's edit"
        for cell, before, after in reversed(self.walls) if undo else self.walls:
            grid.set_blocked(cell, before if undo else after)
        for cell, cost_before, cost_after in reversed(self.costs) if undo else self.costs:
            grid.set_cost(cell, cost_before if undo else cost_after)
        if self.ends is not None:
            now, then = self.ends if undo else self.ends[::-1]
            grid.start, grid.goal = now
            moved = [c for pair in zip(now, then, strict=True) if pair[0] != pair[1]
                     for c in pair if c is not None]
            if moved:
                return moved[0]
        if self.walls:
            return self.walls[0][0]
        return self.costs[0][0] if self.costs else grid.start or (0, 0)


class History:
    """The edits made to one map, the ones undone after them (redo's), and the position the
    map's file holds.  A new edit after an undo drops the edits undone."""

    def __init__(self, limit: int = MAX_EDITS) -> None:
        self.limit = limit
        self._edits: list[Change] = []
        self._done = 0  # the first _done edits are on the map; the rest were undone
        self._saved: int | None = 0  # _done when read or last saved; None: no longer reachable
        self._stroke = False  # a mouse stroke is under way: its cells are one edit
        self._stroke_edit: Change | None = None  # that edit, once its first cell changed

    @property
    def modified(self) -> bool:
        """True when the map differs from its file (as read, or as last saved)."""
        return self._done != self._saved

    def can_undo(self) -> bool:
        return self._done > 0

    def can_redo(self) -> bool:
        return self._done < len(self._edits)

    def add(self, edit: Change) -> None:
        """Record ``edit``, just made: a new edit, or the next cell of the mouse stroke."""
        if self._stroke_edit is not None:
            self._stroke_edit.walls.extend(edit.walls)
            self._stroke_edit.costs.extend(edit.costs)
            return
        del self._edits[self._done:]  # what was undone can't be redone after a new edit
        if self._saved is not None and self._saved > self._done:
            self._saved = None  # the file's state was among them
        self._edits.append(edit)
        if len(self._edits) > self.limit:
            del self._edits[0]
            self._saved = self._saved - 1 if self._saved else None
        self._done = len(self._edits)
        if self._stroke:
            self._stroke_edit = edit

    def begin_stroke(self) -> None:
        """The mouse button went down: the cells it changes until :meth:`end_stroke` are
        one edit."""
        self._stroke, self._stroke_edit = True, None

    def end_stroke(self) -> None:
        self._stroke, self._stroke_edit = False, None

    def undo(self, grid: Grid | Graph) -> State | None:
        """Undo the last edit on ``grid`` (or a graph): the cell (the node) it was about; None
        when there is none."""
        if not self.can_undo():
            return None
        self._stroke_edit = None  # a stroke going on after this is a new edit
        self._done -= 1
        return self._edits[self._done].apply(grid, undo=True)

    def redo(self, grid: Grid | Graph) -> State | None:
        """Make the last edit undone again on ``grid``: the cell it is about; None when
        there is none."""
        if not self.can_redo():
            return None
        self._stroke_edit = None
        self._done += 1
        return self._edits[self._done - 1].apply(grid, undo=False)

    def saved(self) -> None:
        """The map was saved: this is what its file holds now."""
        self._saved = self._done
        self._stroke_edit = None  # cells painted after the save are a new edit


__all__ = ["MAX_EDITS", "Change", "Edit", "Ends", "History"]
