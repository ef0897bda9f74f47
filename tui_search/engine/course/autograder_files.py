"""The CS188 autograder's ``.test`` and ``.solution`` files, read as a graph or a layout with
its search and choices.

The format: ``key: "value"`` lines, ``key: \"\"\"`` blocks closed by a line ``\"\"\"``, and
``#`` comment lines.  A ``GraphSearchTest`` gives ``algorithm`` and ``graph``::

    start_state: A
    goal_states: G
    A 0:A->B B 1.0        (from, action, to, an optional cost: in successor order)

and, for A*, a ``heuristic`` block of ``state value`` lines (a state left out is 0).  A
``PacmanSearchTest`` gives ``algorithm``, ``layoutName``, a ``layout`` block (a Pacman layout:
:mod:`~tui_search.engine.maps.layouts`), and may give ``heuristic`` (``manhattanHeuristic``,
``euclideanHeuristic``, ``nullHeuristic``) and ``costFn``.  ``costFn`` is a lambda: never
evaluated; the three the course uses (cost 1, ``.5 ** x``, ``2 ** x`` of the x the move
enters) are recognised as text, any other is refused.  Every error is one line naming the
file, the line and the column (:class:`~tui_search.engine.maps.read.MapError`).  The files are
untrusted: read within :data:`MAX_TEST_BYTES`, as UTF-8 without NUL bytes.
"""

from __future__ import annotations

import math
import os
import re
from array import array

from tui_search.engine.maps.graph import Edge, Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import MapError, read_text
from tui_search.engine.util.frozen import Frozen

__all__ = ["ALGORITHM_NAMES", "MAX_TEST_BYTES", "CourseTest", "read_course_test",
           "is_course_test", "read_solution", "solution_path"]

#: The largest test or solution file read: the course's are a few KB (a big maze's layout is
#: under 2 KB); a test's graph costs a few hundred bytes a road once read.
MAX_TEST_BYTES = 16 * 1024
#: The course's names of its searches (and their short forms), as the app's keys.
ALGORITHM_NAMES = {
    "depthFirstSearch": "dfs", "dfs": "dfs", "breadthFirstSearch": "bfs", "bfs": "bfs",
    "uniformCostSearch": "ucs", "ucs": "ucs", "aStarSearch": "astar", "astar": "astar",
}
#: A layout test's heuristic by the course's name, as the app's.
HEURISTIC_NAMES = {"manhattanHeuristic": "manhattan", "euclideanHeuristic": "euclidean",
                   "nullHeuristic": "zero"}
#: The cost functions the course uses, as text without spaces (``x`` the lambda's argument).
COST_FUNCTIONS = {"1": "1", ".5**x[0]": "0.5 ** x", "0.5**x[0]": "0.5 ** x",
                  "2**x[0]": "2 ** x"}
_KEY = re.compile(r"([A-Za-z_][A-Za-z_0-9]*):[ \t]*")
_LAMBDA = re.compile(r"lambda([A-Za-z_][A-Za-z_0-9]*):(.*)")
_NUMBER = re.compile(r"[0-9]+(?:\.[0-9]*)?|\.[0-9]+")
MAX_NAME = 100


def is_course_test(name: str | None) -> bool:
    return name is not None and name.endswith(".test")


def solution_path(path: str) -> str:
    """The ``.solution`` beside a ``.test``."""
    return path.removesuffix(".test") + ".solution"


class Field(Frozen):
    """A value of a test file and where it is: the line of its key, the column of its value
    (a block's value starts on the line after)."""

    __slots__ = _FIELDS = ("text", "line", "col", "block")

    text: str
    line: int
    col: int
    block: bool

    def __init__(self, text: str, line: int, col: int, block: bool) -> None:
        self._assign(text=text, line=line, col=col, block=block)


def parse_fields(text: str, path: str) -> dict[str, Field]:
    """The file's keys and their values, each where it is."""
    fields: dict[str, Field] = {}
    lines = text.removeprefix("\ufeff").split("\n")
    i = 0
    while i < len(lines):
        number, line = i + 1, lines[i].rstrip("\r")
        i += 1
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        match = _KEY.match(line)
        if not match:
            raise MapError(path, 'expected key: "value" or key: """ (a block)', number, 1)
        key, rest = match.group(1), line[match.end():].rstrip()
        if key in fields:
            raise MapError(path, f"a second {key!r} (the first is at line {fields[key].line})",
                           number, 1)
        col = match.end() + 1
        if rest == '"""':
            body: list[str] = []
            while i < len(lines) and lines[i].rstrip("\r").strip() != '"""':
                body.append(lines[i].rstrip("\r"))
                i += 1
            if i == len(lines):
                raise MapError(path, f'the """ block of {key!r} is never closed', number, col)
            i += 1
            fields[key] = Field("\n".join(body), number, 1, True)
        elif len(rest) >= 2 and rest[0] == rest[-1] == '"':
            fields[key] = Field(rest[1:-1], number, col + 1, False)
        else:
            raise MapError(path, f'the value of {key!r} is not in quotes: "..."', number, col)
    return fields


class CourseTest(Frozen):
    """A ``.test`` file read: its class, the app's search key, the graph or the grid, the
    heuristic (the app's name; None: the search's own), the cost function (``1``, ``0.5 **
    x``, ``2 ** x``), the layout's name, and the ``.solution``'s fields (empty: none)."""

    __slots__ = _FIELDS = ("path", "kind", "algorithm", "course_name", "graph", "grid",
                           "heuristic", "cost_fn", "layout_name", "actions", "solution")

    path: str
    kind: str  # "GraphSearchTest" or "PacmanSearchTest"
    algorithm: str
    course_name: str  # the course's name of the search (breadthFirstSearch)
    graph: Graph | None
    grid: Grid | None
    heuristic: str | None
    cost_fn: str
    layout_name: str
    actions: dict[tuple[str, str], str]  # a graph's (from, to): the action's name
    solution: dict[str, str]

    def __init__(self, **fields: object) -> None:
        self._assign(**fields)


def _need(fields: dict[str, Field], key: str, path: str) -> Field:
    if key not in fields:
        raise MapError(path, f"no {key!r}: the test needs one")
    return fields[key]


def read_course_test(path: str) -> CourseTest:
    """The ``.test`` file at ``path``, and the ``.solution`` beside it when there is one."""
    fields = parse_fields(read_text(path, "a course test", MAX_TEST_BYTES), path)
    kind = fields["class"].text if "class" in fields else (
        "PacmanSearchTest" if "layout" in fields else "GraphSearchTest")
    if kind not in ("GraphSearchTest", "PacmanSearchTest"):
        f = fields["class"]
        raise MapError(path, f"class {kind!r}: this reads GraphSearchTest and PacmanSearchTest",
                       f.line, f.col)
    algo = _need(fields, "algorithm", path)
    if algo.text not in ALGORITHM_NAMES:
        raise MapError(path, f"algorithm {algo.text!r}: use depthFirstSearch, "
                       "breadthFirstSearch, uniformCostSearch or aStarSearch", algo.line,
                       algo.col)
    graph = grid = None
    heuristic: str | None = None
    actions: dict[tuple[str, str], str] = {}
    cost_fn, layout_name = "1", ""
    if kind == "GraphSearchTest":
        graph, actions = _graph(_need(fields, "graph", path), fields.get("heuristic"), path)
        heuristic = "table" if "heuristic" in fields else "zero"
    else:
        grid = _layout(_need(fields, "layout", path), path)
        layout_name = fields["layoutName"].text if "layoutName" in fields else ""
        if "heuristic" in fields:
            h = fields["heuristic"]
            if h.text not in HEURISTIC_NAMES:
                raise MapError(path, f"heuristic {h.text!r}: use "
                               f"{', '.join(HEURISTIC_NAMES)}", h.line, h.col)
            heuristic = HEURISTIC_NAMES[h.text]
        elif ALGORITHM_NAMES[algo.text] == "astar":
            heuristic = "zero"  # the course's aStarSearch defaults to nullHeuristic
        if "costFn" in fields:
            cost_fn = _cost_fn(fields["costFn"], path)
            grid.costs = _costs(grid, cost_fn)
    answer = solution_path(path)
    solution = read_solution(answer) if os.path.exists(answer) else {}
    return CourseTest(path=path, kind=kind, algorithm=ALGORITHM_NAMES[algo.text],
                      course_name=algo.text, graph=graph, grid=grid, heuristic=heuristic,
                      cost_fn=cost_fn, layout_name=layout_name, actions=actions,
                      solution=solution)


def read_solution(path: str) -> dict[str, str]:
    """A ``.solution`` file's fields (as text)."""
    return {k: f.text for k, f in parse_fields(
        read_text(path, "a course solution", MAX_TEST_BYTES), path).items()}


def _cost_fn(field: Field, path: str) -> str:
    """The course's cost function named by its text (``lambda pos: .5 ** pos[0]``)."""
    flat = "".join(field.text.split())
    match = _LAMBDA.fullmatch(flat)
    body = match.group(2).replace(match.group(1), "x") if match else ""
    if body not in COST_FUNCTIONS:
        raise MapError(path, f"costFn {field.text[:60]!r} is not one the course uses (lambda "
                       "pos: 1, .5 ** pos[0], 2 ** pos[0]): it is never run", field.line,
                       field.col)
    return COST_FUNCTIONS[body]


def _costs(grid: Grid, cost_fn: str) -> array[float] | None:
    """What entering each cell costs under the cost function (x is the same in the course's
    coordinates as in the app's)."""
    if cost_fn == "1":
        return None
    base = 0.5 if cost_fn.startswith("0.5") else 2.0
    return array("d", [base ** x for _ in range(grid.height) for x in range(grid.width)])


def _layout(field: Field, path: str) -> Grid:
    from tui_search.engine.maps.layouts import parse_layout

    return parse_layout(field.text + "\n", path, first_line=field.line + 1)


def _graph(field: Field, h_field: Field | None, path: str
           ) -> tuple[Graph, dict[tuple[str, str], str]]:
    """The graph block: its start, goals and edges (in successor order), directed."""
    rows = [(field.line + 1 + i, line) for i, line in enumerate(field.text.split("\n"))
            if line.strip()]
    if len(rows) < 2:
        raise MapError(path, "the graph block needs start_state: and goal_states: lines",
                       field.line)
    names: dict[str, int] = {}
    edges: list[Edge] = []
    actions: dict[tuple[str, str], str] = {}

    def node(name: str, line: int, col: int) -> int:
        if len(name) > MAX_NAME:
            raise MapError(path, f"a state's name is at most {MAX_NAME} characters", line, col)
        return names.setdefault(name, len(names))

    (n1, first), (n2, second) = rows[0], rows[1]
    w1, w2 = _words(first), _words(second)
    if w1[0][1] != "start_state:" or len(w1) != 2:
        raise MapError(path, "the graph's first line is start_state: STATE", n1, w1[0][0])
    if w2[0][1] != "goal_states:" or len(w2) < 2:
        raise MapError(path, "the graph's second line is goal_states: STATE ...", n2, w2[0][0])
    start = w1[1][1]
    node(start, n1, w1[1][0])
    goals = tuple(name for _, name in w2[1:])
    for col, name in w2[1:]:
        node(name, n2, col)
    for number, line in rows[2:]:
        w = _words(line)
        if len(w) not in (3, 4):
            raise MapError(path, "an edge is FROM ACTION TO [COST]", number, w[0][0])
        cost = 1.0
        if len(w) == 4:
            cost = _number(w[3], number, path)
        a, b = node(w[0][1], number, w[0][0]), node(w[2][1], number, w[2][0])
        if (w[0][1], w[2][1]) in actions:
            raise MapError(path, f"a second edge from {w[0][1]} to {w[2][1]}", number, w[0][0])
        actions[(w[0][1], w[2][1])] = w[1][1]
        edges.append(Edge(a, b, cost, directed=True, line=number))
    h = None if h_field is None else _table(h_field, names, path)
    graph = Graph.of(list(names), edges, h=h, start=start, goals=goals,
                     name=os.path.basename(path))
    return graph, actions


def _table(field: Field, names: dict[str, int], path: str) -> dict[str, float]:
    """A heuristic block: ``STATE VALUE`` lines (a state left out is 0)."""
    h = dict.fromkeys(names, 0.0)
    for i, line in enumerate(field.text.split("\n")):
        number = field.line + 1 + i
        w = _words(line)
        if not w:
            continue
        if len(w) != 2:
            raise MapError(path, "a heuristic line is STATE VALUE", number, w[0][0])
        if w[0][1] not in names:
            raise MapError(path, f"no state {w[0][1]!r} in the graph", number, w[0][0])
        h[w[0][1]] = _number(w[1], number, path, low=0.0)
    return h


def _words(line: str) -> list[tuple[int, str]]:
    """The words of a line, each with its column."""
    return [(m.start() + 1, m.group()) for m in re.finditer(r"\S+", line)]


def _number(word: tuple[int, str], line: int, path: str, low: float | None = None) -> float:
    col, text = word
    if not _NUMBER.fullmatch(text) or len(text) > 30:
        raise MapError(path, f"{text!r} is not a number", line, col)
    value = float(text)
    if low is None and value <= 0 or not math.isfinite(value):
        raise MapError(path, f"the cost {text} is not above 0", line, col)
    return value
