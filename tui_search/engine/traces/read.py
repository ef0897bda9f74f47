"""Reading a search trace that another program wrote: the format of the app's own ``--trace``.

One JSON object a line, one line an expansion: ``{"node": [x, y], "successors": [...]}``, each
successor ``[x, y]`` or ``{"node": [x, y]}`` (``step``, ``dir`` and ``depth_limit`` are
allowed and not needed; ``"discarded": true`` marks a pop that did nothing).  An optional first
line ``{"start": [x, y], "goal": [x, y]}`` and an optional last line ``{"path": [...]}`` (or
``{"path": null}``: no path found).  A trace none of whose lines has ``successors`` is of
expansions only.  Coordinates are (column, row) from the top left.  Blank lines are skipped.

A malformed trace is a :class:`~tui_search.engine.maps.read.MapError` naming the file and the
line: bad JSON, a cell off the map or on an obstacle, a node expanded that was never added, a
start (or goal) that is not the map's.
"""

from __future__ import annotations

import json
from dataclasses import dataclass

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import MapError


@dataclass(frozen=True)
class TraceStep:
    """One expansion of the trace: the line it is on, the cell taken off, the cells added (in
    order, repeats kept: the check reports them), whether it says it was discarded, and
    whether it lists its successors at all (a trace of expansions only lists none)."""

    line: int
    node: Cell
    successors: tuple[Cell, ...]
    discarded: bool = False
    listed: bool = True


@dataclass(frozen=True)
class Trace:
    """A whole trace: its expansions, and the start, goal and path when it gives them."""

    name: str
    steps: tuple[TraceStep, ...]
    start: Cell | None = None
    goal: Cell | None = None
    path: tuple[Cell, ...] | None = None


def show(cell: Cell) -> str:
    """A cell as the messages write it: ``(2,3)``."""
    return f"({cell[0]},{cell[1]})"


class _Reader:
    """Reads a trace line by line against a grid; :meth:`fail` raises the one-line error."""

    def __init__(self, grid: Grid, name: str) -> None:
        self.grid, self.name = grid, name
        self.line = 0

    def fail(self, message: str) -> MapError:
        return MapError(self.name, message, self.line)

    def cell(self, value: object, what: str) -> Cell:
        """``[x, y]`` as a free cell of the map."""
        if (not isinstance(value, list) or len(value) != 2
                or not all(isinstance(v, int) and not isinstance(v, bool) for v in value)):
            raise self.fail(f"{what} should be [x, y], two whole numbers, not "
                            f"{json.dumps(value)[:40]}")
        x, y = value
        grid = self.grid
        hint = "; x is the column, y the row: swapped?" if grid.is_free((y, x)) else ""
        if not (0 <= x < grid.width and 0 <= y < grid.height):
            raise self.fail(f"{what} ({x},{y}) is off the map "
                            f"({grid.width}x{grid.height}: x 0..{grid.width - 1}, "
                            f"y 0..{grid.height - 1}){hint}")
        if grid.blocked[y * grid.width + x]:
            raise self.fail(f"{what} ({x},{y}) is an obstacle{hint}")
        return (x, y)

    def successor(self, value: object) -> Cell:
        if isinstance(value, dict):
            if "node" not in value:
                raise self.fail('a successor object needs "node": [x, y]')
            return self.cell(value["node"], "successor")
        return self.cell(value, "successor")

    def endpoints(self, obj: dict[str, object]) -> tuple[Cell | None, Cell | None]:
        """The first line's ``start`` and ``goal`` (None where it gives none): the map's."""
        grid = self.grid
        assert grid.start is not None  # as read_trace holds
        start = goal = None
        if "start" in obj:
            start = self.cell(obj["start"], "start")
            if start != grid.start:
                raise self.fail(f"the trace starts at {show(start)}, the map at "
                                f"{show(grid.start)}")
        if "goal" in obj:
            goal = self.cell(obj["goal"], "goal")
            if grid.goal is not None and goal != grid.goal:
                raise self.fail(f"the trace's goal is {show(goal)}, the map's "
                                f"{show(grid.goal)}")
        return start, goal

    def obj(self, text: str) -> dict[str, object]:
        try:
            value = json.loads(text)
        except ValueError as exc:
            msg = getattr(exc, "msg", str(exc))
            col = getattr(exc, "colno", None)
            raise MapError(self.name, f"not JSON: {msg}", self.line, col) from None
        if not isinstance(value, dict):
            raise self.fail("each line should be a JSON object ({...})")
        return value


def read_trace(text: str, grid: Grid, name: str) -> Trace:
    """The trace in ``text`` (the contents of file ``name``), checked against ``grid``."""
    reader = _Reader(grid, name)
    steps: list[TraceStep] = []
    start = goal = None
    path: tuple[Cell, ...] | None = None
    assert grid.start is not None
    added: set[Cell] = {grid.start}
    path_line = 0
    unadded: MapError | None = None  # the first node no earlier line added
    listed = False  # does any line list successors (else the trace is of expansions only)?
    for number, raw in enumerate(text.split("\n"), 1):
        reader.line = number
        if not raw.strip():
            continue
        if path_line:
            reader.line = path_line
            raise reader.fail('the "path" line should be the last')
        obj = reader.obj(raw)
        if "start" in obj or "goal" in obj:
            if steps or start is not None or goal is not None:
                raise reader.fail('"start" and "goal" belong on the first line only')
            start, goal = reader.endpoints(obj)
            continue
        if "path" in obj and "node" not in obj:
            cells = obj["path"]
            if cells is not None and not isinstance(cells, list):
                raise reader.fail('"path" should be a list of [x, y], or null (no path)')
            path = () if cells is None else tuple(reader.cell(c, "path cell") for c in cells)
            path_line = number
            continue
        if "node" not in obj:
            raise reader.fail('an expansion needs "node": [x, y] (or the first line "start", '
                              'the last "path")')
        node = reader.cell(obj["node"], "node")
        if node not in added and unadded is None:  # an error unless no line lists successors
            hint = ("; x is the column, y the row: swapped?" if (node[1], node[0]) in added
                    else "")
            unadded = MapError(name, f"expands {show(node)}, which no earlier line added "
                               f"(nor is it the start){hint}", number)
        successors = obj.get("successors", [])
        if not isinstance(successors, list):
            raise reader.fail('"successors" should be a list')
        cells = tuple(reader.successor(s) for s in successors)
        added.update(cells)
        listed |= "successors" in obj
        steps.append(TraceStep(number, node, cells, obj.get("discarded") is True,
                               "successors" in obj))
    if not steps:
        raise MapError(name, "the trace has no expansions (lines with \"node\")")
    if unadded is not None and listed:
        raise unadded
    if not listed:  # expansions only: nothing says a line lists no successors
        steps = [TraceStep(t.line, t.node, (), t.discarded, False) for t in steps]
    return Trace(name, tuple(steps), start, goal, path)


def load_trace(path: str, grid: Grid) -> Trace:
    """:func:`read_trace` of a file; a file that cannot be read is a one-line error."""
    try:
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
    except OSError as exc:
        raise MapError(path, f"cannot read the trace: {exc.strerror}") from None
    except UnicodeDecodeError:
        raise MapError(path, "the trace is not UTF-8 text") from None
    return read_trace(text, grid, path)


__all__ = ["Trace", "TraceStep", "load_trace", "read_trace", "show"]
