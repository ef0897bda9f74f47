"""Reading a search trace that another program wrote: the format of the app's own ``--trace``.

One JSON object a line, one line an expansion: ``{"node": [x, y], "successors": [...]}``, each
successor ``[x, y]`` or ``{"node": [x, y]}`` (``step``, ``dir`` and ``depth_limit`` are
allowed and not needed; ``"discarded": true`` marks a pop that did nothing).  An optional first
line ``{"start": [x, y], "goal": [x, y]}`` and an optional last line ``{"path": [...]}`` (or
``{"path": null}``: no path found).  A trace none of whose lines has ``successors`` is of
expansions only.  Coordinates are (column, row) from the top left.  Blank lines are skipped.

:func:`trace_line` writes a step in it (``--trace``, and a run stepped by hand).

A malformed trace is a :class:`~tui_search.engine.maps.read.MapError` naming the file and the
line: bad JSON, a cell off the map or on an obstacle, a node expanded that was never added, a
start (or goal) that is not the map's.  A trace is a student's, so untrusted
(:mod:`~tui_search.engine.util.untrusted`): at most :data:`MAX_TRACE_BYTES`, UTF-8 without
NUL, each line's JSON checked before it is parsed; its steps are kept in flat arrays
(:class:`TraceSteps`), a few bytes a step.
"""

# No future import: CONTRIBUTING.md, "Start-up".
import json
from array import array
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import NamedTuple, overload

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import MapError, each_line, read_text
from tui_search.engine.run.recording import Step
from tui_search.engine.util.untrusted import BadInput, load_json

#: Bigger traces are refused before reading (each line an expansion: a search of a 512x512
#: map writes a few MB).
MAX_TRACE_BYTES = 64 * 1024 * 1024
#: What a line's JSON may take in memory beyond this many times the whole trace's size
#: (:func:`~tui_search.engine.util.untrusted.check_values`).
LINE_BUDGET = 8
LINE_ALLOWANCE = 256 * 1024


class TraceStep(NamedTuple):
    """One expansion of the trace: the line it is on, the cell taken off, the cells added (in
    order, repeats kept: the check reports them), whether it says it was discarded, and
    whether it lists its successors at all (a trace of expansions only lists none).  (A
    tuple: made each time a step is read from :class:`TraceSteps`, it must be quick.)"""

    line: int
    node: Cell
    successors: tuple[Cell, ...]
    discarded: bool = False
    listed: bool = True


class TraceSteps(Sequence[TraceStep]):
    """A trace's expansions in a few flat arrays: each step's line, its node and where its
    successors end, each cell as ``y * width + x``.  A :class:`TraceStep` is made when asked
    for, so a trace of millions of lines costs a few bytes a step, not objects."""

    __slots__ = ("_discarded", "_lines", "_listed", "_nodes", "_succ", "_succ_end", "_width")

    def __init__(self, width: int) -> None:
        self._width = width
        self._lines, self._nodes = array("I"), array("i")
        self._succ_end, self._succ = array("I"), array("i")
        self._discarded = bytearray()
        self._listed = bytearray()

    def add(self, line: int, node: Cell, successors: Sequence[Cell], discarded: bool,
            listed: bool = True) -> None:
        w = self._width
        self._lines.append(line)
        self._nodes.append(node[1] * w + node[0])
        self._succ.extend(y * w + x for x, y in successors)
        self._succ_end.append(len(self._succ))
        self._discarded.append(discarded)
        self._listed.append(listed)

    def __len__(self) -> int:
        return len(self._lines)

    @overload
    def __getitem__(self, index: int) -> TraceStep: ...
    @overload
    def __getitem__(self, index: slice) -> list[TraceStep]: ...
    def __getitem__(self, index: int | slice) -> TraceStep | list[TraceStep]:
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        if index < 0:
            index += len(self)
        if not 0 <= index < len(self):
            raise IndexError("trace step out of range")
        w = self._width
        begin = self._succ_end[index - 1] if index else 0
        successors = tuple((c % w, c // w) for c in self._succ[begin:self._succ_end[index]])
        node = self._nodes[index]
        return TraceStep(self._lines[index], (node % w, node // w), successors,
                         bool(self._discarded[index]), bool(self._listed[index]))

    def __iter__(self) -> Iterator[TraceStep]:
        w, lines, nodes, succ, discarded, listed = (
            self._width, self._lines, self._nodes, self._succ, self._discarded, self._listed)
        begin = 0
        for i, end in enumerate(self._succ_end):
            node = nodes[i]
            yield TraceStep(lines[i], (node % w, node // w),
                            tuple([(c % w, c // w) for c in succ[begin:end]]),
                            bool(discarded[i]), bool(listed[i]))
            begin = end

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Sequence):
            return NotImplemented
        return len(self) == len(other) and all(a == b for a, b in zip(self, other, strict=True))

    __hash__ = None  # type: ignore[assignment]  # (equal to a list of its steps)

    def __repr__(self) -> str:
        return f"TraceSteps({len(self)} steps)"


@dataclass(frozen=True)
class Trace:
    """A whole trace: its expansions, and the start, goal and path when it gives them."""

    name: str
    steps: Sequence[TraceStep]  # TraceSteps as read; a tuple where a check remade them
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

    def obj(self, text: str, budget: int) -> dict[str, object]:
        try:
            value = load_json(text, budget)
        except BadInput as err:
            raise MapError(self.name, err.message, self.line, err.col) from None
        if not isinstance(value, dict):
            raise self.fail("each line should be a JSON object ({...})")
        return value


def read_trace(text: str, grid: Grid, name: str) -> Trace:
    """The trace in ``text`` (the contents of file ``name``), checked against ``grid``."""
    reader = _Reader(grid, name)
    steps = TraceSteps(grid.width)
    start = goal = None
    path: tuple[Cell, ...] | None = None
    assert grid.start is not None
    added = bytearray(grid.width * grid.height)  # 1: a cell some line added (or the start)
    added[grid.start[1] * grid.width + grid.start[0]] = 1
    budget = LINE_BUDGET * len(text) + LINE_ALLOWANCE
    path_line = 0
    unadded: MapError | None = None  # the first node no earlier line added
    listed = False  # does any line list successors (else the trace is of expansions only)?
    for number, raw in enumerate(each_line(text), 1):
        reader.line = number
        if not raw.strip():
            continue
        if path_line:
            reader.line = path_line
            raise reader.fail('the "path" line should be the last')
        obj = reader.obj(raw, budget)
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
        width = grid.width
        if not added[node[1] * width + node[0]] and unadded is None:  # unless none lists any
            sx, sy = node[1], node[0]  # the cell with x and y swapped
            swapped = (0 <= sx < width and 0 <= sy < grid.height and added[sy * width + sx])
            hint = "; x is the column, y the row: swapped?" if swapped else ""
            unadded = MapError(name, f"expands {show(node)}, which no earlier line added "
                               f"(nor is it the start){hint}", number)
        successors = obj.get("successors", [])
        if not isinstance(successors, list):
            raise reader.fail('"successors" should be a list')
        cells = [reader.successor(s) for s in successors]
        for x, y in cells:
            added[y * width + x] = 1
        listed |= "successors" in obj
        steps.add(number, node, cells, obj.get("discarded") is True, "successors" in obj)
    if not steps:
        raise MapError(name, "the trace has no expansions (lines with \"node\")")
    if unadded is not None and listed:
        raise unadded
    return Trace(name, steps, start, goal, path)


def trace_line(step: Step) -> str:
    """A step in this format, the line ``--trace`` writes: the node taken off and exactly the
    successors it added, in order; iterative deepening adds the depth limit, a discarded step
    says so."""
    obj: dict[str, object] = {
        "step": step.index,
        "node": list(step.node),
        "successors": [{"dir": d, "node": list(c)} for d, c in step.successors],
    }
    if step.depth_limit is not None:
        obj["depth_limit"] = step.depth_limit
    if step.discarded:
        obj["discarded"] = True
    return json.dumps(obj, separators=(", ", ": ")) + "\n"


def load_trace(path: str, grid: Grid) -> Trace:
    """:func:`read_trace` of a file; a file that cannot be read is a one-line error."""
    return read_trace(read_text(path, "a trace", MAX_TRACE_BYTES), grid, path)


__all__ = ["MAX_TRACE_BYTES", "Trace", "TraceStep", "TraceSteps", "load_trace", "read_trace",
           "show", "trace_line"]
