"""Reading a search trace that another program wrote: the format of the app's own ``--trace``.

One JSON object a line, one line an expansion: ``{"node": [x, y], "successors": [...]}``, each
successor ``[x, y]`` or ``{"node": [x, y]}`` (``step``, ``dir``, ``depth_limit`` and
``f_limit`` are allowed and not needed; ``"discarded": true`` marks a pop that did nothing).
An optional first line ``{"start": [x, y], "goal": [x, y]}`` and an optional last line
``{"path": [...]}`` (or ``{"path": null}``: no path found).  A trace none of whose lines has
``successors`` is of expansions only.  Coordinates are (column, row) from the top left.
Blank lines are skipped.

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
from functools import cached_property
from typing import NamedTuple, overload

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import MapError, each_line, read_text
from tui_search.engine.run.recording import Step
from tui_search.engine.search.state import State, as_cell, state_json, state_text
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
    node: State  # a cell (x, y) on a grid, a node's name on a graph
    successors: tuple[State, ...]
    discarded: bool = False
    listed: bool = True


class TraceSteps(Sequence[TraceStep]):
    """A trace's expansions in a few flat arrays: each step's line, its node and where its
    successors end, each cell as ``y * width + x``.  A :class:`TraceStep` is made when asked
    for, so a trace of millions of lines costs a few bytes a step, not objects."""

    __slots__ = ("_board", "_discarded", "_lines", "_listed", "_nodes", "_succ", "_succ_end")

    def __init__(self, board: Grid | Graph) -> None:
        self._board = board
        self._lines, self._nodes = array("I"), array("i")
        self._succ_end, self._succ = array("I"), array("i")
        self._discarded = bytearray()
        self._listed = bytearray()

    def _number(self, state: State) -> int:
        board = self._board
        if isinstance(board, Graph):
            return board.index[str(state)]
        x, y = as_cell(state)
        return y * board.width + x

    def _state(self, n: int) -> State:
        board = self._board
        if isinstance(board, Graph):
            return board.names[n]
        return n % board.width, n // board.width

    def add(self, line: int, node: State, successors: Sequence[State], discarded: bool,
            listed: bool = True) -> None:
        self._lines.append(line)
        self._nodes.append(self._number(node))
        self._succ.extend(self._number(s) for s in successors)
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
        state = self._state
        begin = self._succ_end[index - 1] if index else 0
        successors = tuple(state(c) for c in self._succ[begin:self._succ_end[index]])
        return TraceStep(self._lines[index], state(self._nodes[index]), successors,
                         bool(self._discarded[index]), bool(self._listed[index]))

    def __iter__(self) -> Iterator[TraceStep]:
        lines, nodes, succ, discarded, listed = (
            self._lines, self._nodes, self._succ, self._discarded, self._listed)
        board = self._board
        if isinstance(board, Graph):
            names = board.names

            def state(n: int) -> State:
                return names[n]
        else:
            w = board.width

            def state(n: int) -> State:
                return n % w, n // w
        begin = 0
        for i, end in enumerate(self._succ_end):
            yield TraceStep(lines[i], state(nodes[i]),
                            tuple([state(c) for c in succ[begin:end]]),
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
    start: State | None = None
    goal: State | None = None
    path: tuple[State, ...] | None = None
    #: Read as a bidirectional search's (:func:`read_trace`'s ``both_ways`` None): a line
    #: says ``"dir": "backward"``, or one expands a goal no earlier line added.
    bidirectional: bool = False

    @cached_property
    def expansions_only(self) -> bool:
        """Does no step list its successors (an autograder's trace: the order of its
        expansions alone)?  Asked by every check of a diagnosis: worked out once a trace."""
        return all(not step.listed for step in self.steps)


def show(state: State) -> str:
    """A cell or a node as the messages write it: ``(2,3)``, ``Sibiu``."""
    return state_text(state)


class _Reader:
    """Reads a trace line by line against a grid or a graph; :meth:`fail` raises the
    one-line error."""

    def __init__(self, board: Grid | Graph, name: str) -> None:
        self.board, self.name = board, name
        self.line = 0

    def fail(self, message: str) -> MapError:
        return MapError(self.name, message, self.line)

    def cell(self, value: object, what: str) -> State:
        """``[x, y]`` as a free cell of the map; on a graph, a node's name."""
        if isinstance(self.board, Graph):
            return self.node(value, what)
        if (not isinstance(value, list) or len(value) != 2
                or not all(isinstance(v, int) and not isinstance(v, bool) for v in value)):
            raise self.fail(f"{what} should be [x, y], two whole numbers, not "
                            f"{json.dumps(value)[:40]}")
        x, y = value
        grid = self.board
        hint = "; x is the column, y the row: swapped?" if grid.is_free((y, x)) else ""
        if not (0 <= x < grid.width and 0 <= y < grid.height):
            raise self.fail(f"{what} ({x},{y}) is off the map "
                            f"({grid.width}x{grid.height}: x 0..{grid.width - 1}, "
                            f"y 0..{grid.height - 1}){hint}")
        if grid.blocked[y * grid.width + x]:
            raise self.fail(f"{what} ({x},{y}) is an obstacle{hint}")
        return (x, y)

    def node(self, value: object, what: str) -> str:
        """A graph's node, by its name."""
        graph = self.board
        assert isinstance(graph, Graph)
        if not isinstance(value, str):
            raise self.fail(f"{what} should be a node's name (a string), not "
                            f"{json.dumps(value)[:40]}")
        if value not in graph.index:
            raise self.fail(f"{what} {value[:40]!r} is not a node of {graph.name}")
        if value in graph.closed:
            raise self.fail(f"{what} {value!r} is closed")
        return value

    def successor(self, value: object) -> State:
        if isinstance(value, dict):
            if "node" not in value:
                raise self.fail('a successor object needs "node": [x, y]')
            return self.cell(value["node"], "successor")
        return self.cell(value, "successor")

    def path(self, cells: object) -> tuple[State, ...]:
        """The path line's cells (none: no path found)."""
        if cells is not None and not isinstance(cells, list):
            raise self.fail('"path" should be a list of [x, y], or null (no path)')
        return () if cells is None else tuple(self.cell(c, "path cell") for c in cells)

    def endpoints(self, obj: dict[str, object]) -> tuple[State | None, State | None]:
        """The first line's ``start`` and ``goal`` (None where it gives none): the map's."""
        board = self.board
        ends = _ends(board)
        assert ends[0] is not None  # as read_trace holds
        start = goal = None
        if "start" in obj:
            start = self.cell(obj["start"], "start")
            if start != ends[0]:
                raise self.fail(f"the trace starts at {show(start)}, the map at "
                                f"{show(ends[0])}")
        if "goal" in obj:
            goal = self.cell(obj["goal"], "goal")
            if ends[1] and goal not in ends[1]:
                raise self.fail(f"the trace's goal is {show(goal)}, the map's "
                                f"{' or '.join(map(show, ends[1]))}")
        return start, goal

    def obj(self, text: str, budget: int) -> dict[str, object]:
        try:
            value = load_json(text, budget)
        except BadInput as err:
            raise MapError(self.name, err.message, self.line, err.col) from None
        if not isinstance(value, dict):
            raise self.fail("each line should be a JSON object ({...})")
        return value


def _ends(board: Grid | Graph) -> tuple[State | None, tuple[State, ...]]:
    """The board's start and goals."""
    if isinstance(board, Graph):
        return board.start, board.goals
    return board.start, () if board.goal is None else (board.goal,)


def read_trace(text: str, grid: Grid | Graph, name: str, both_ways: bool | None = False
               ) -> Trace:
    """The trace in ``text`` (the contents of file ``name``), checked against ``grid`` (or
    a graph, whose trace names its nodes); ``both_ways``: a bidirectional search's, whose
    backward search expands the goal unadded; None: either, as the trace reads (a goal
    expanded unadded is the backward root: the trace is then :attr:`Trace.bidirectional`,
    as one whose line says ``"dir": "backward"`` is)."""
    reader = _Reader(grid, name)
    steps = TraceSteps(grid)
    start = goal = None
    path: tuple[State, ...] | None = None
    begin = _ends(grid)[0]
    assert begin is not None
    added: set[State] | bytearray = set() if isinstance(grid, Graph) else bytearray(
        grid.width * grid.height)  # a cell some line added (or the start)
    _add(added, grid, begin)
    roots = _ends(grid)[1]
    for root in roots if both_ways else ():
        _add(added, grid, root)
    from_goal = backward = False  # a goal expanded unadded (both_ways None); "dir" backward
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
            path, path_line = reader.path(obj["path"]), number
            continue
        if "node" not in obj:
            raise reader.fail('an expansion needs "node": [x, y] (or the first line "start", '
                              'the last "path")')
        node = reader.cell(obj["node"], "node")
        backward |= obj.get("dir") == "backward"
        if both_ways is None and node in roots and not _was_added(added, grid, node):
            from_goal = True  # the backward search's root
            _add(added, grid, node)
        elif not _was_added(added, grid, node) and unadded is None:  # unless none lists any
            unadded = _unadded(name, number, added, grid, node, bool(both_ways or from_goal))
        successors = obj.get("successors", [])
        if not isinstance(successors, list):
            raise reader.fail('"successors" should be a list')
        cells = [reader.successor(s) for s in successors]
        for cell in cells:
            _add(added, grid, cell)
        listed |= "successors" in obj
        steps.add(number, node, cells, obj.get("discarded") is True, "successors" in obj)
    if not steps:
        raise MapError(name, "the trace has no expansions (lines with \"node\")")
    if unadded is not None and listed:
        raise unadded
    return Trace(name, steps, start, goal, path, backward or (from_goal and listed))


def _unadded(name: str, number: int, added: set[State] | bytearray, board: Grid | Graph,
             node: State, goal: bool) -> MapError:
    """The error of a node expanded that no earlier line added (``goal``: nor is it the
    goal, a bidirectional search's backward root)."""
    swapped = isinstance(node, tuple) and _was_added(added, board, (node[1], node[0]))
    hint = "; x is the column, y the row: swapped?" if swapped else ""
    return MapError(name, f"expands {show(node)}, which no earlier line added (nor is it the "
                    f"start{' or the goal' * goal}){hint}", number)


def _add(added: set[State] | bytearray, board: Grid | Graph, state: State) -> None:
    if isinstance(added, set):
        added.add(state)
    else:
        x, y = as_cell(state)
        added[y * as_grid(board).width + x] = 1


def _was_added(added: set[State] | bytearray, board: Grid | Graph, state: State) -> bool:
    if isinstance(added, set):
        return state in added
    x, y = as_cell(state)
    grid = as_grid(board)
    return 0 <= x < grid.width and 0 <= y < grid.height and bool(added[y * grid.width + x])


def as_grid(board: Grid | Graph) -> Grid:
    assert isinstance(board, Grid)
    return board


def trace_line(step: Step) -> str:
    """A step in this format, the line ``--trace`` writes: the node taken off and exactly the
    successors it added, in order (a graph's: the nodes' names); iterative deepening adds the
    depth limit, IDA* its limit on f (rounded to 6 places), a discarded step says so; a
    bidirectional search's names its direction (``"dir": "forward"`` or ``"backward"``)."""
    node = step.node
    obj: dict[str, object] = {"step": step.index, "node": state_json(node)}
    if step.direction:  # a bidirectional search's: which search took the step
        obj["dir"] = step.direction
    if isinstance(node, str):  # a graph's: the nodes reached, by name
        obj["successors"] = [s for _, s in step.successors]
    else:
        obj["successors"] = [{"dir": d, "node": state_json(c)} for d, c in step.successors]
    if step.depth_limit is not None:
        obj["depth_limit"] = step.depth_limit
    if step.f_limit is not None:
        obj["f_limit"] = round(step.f_limit, 6)
    if step.discarded:
        obj["discarded"] = True
    return json.dumps(obj, separators=(", ", ": ")) + "\n"


def load_trace(path: str, grid: Grid | Graph, both_ways: bool | None = False) -> Trace:
    """:func:`read_trace` of a file; a file that cannot be read is a one-line error."""
    return read_trace(read_text(path, "a trace", MAX_TRACE_BYTES), grid, path, both_ways)


__all__ = ["MAX_TRACE_BYTES", "Trace", "TraceStep", "TraceSteps", "load_trace", "read_trace",
           "show", "trace_line"]
