"""``.graph`` files: a graph as plain text, a statement a line (``;`` starts a comment, as in
text maps)::

    ; Romania, AIMA figure 3.1 (straight-line distances to Bucharest as h)
    node Arad 91 492        ; a name and, optionally, its place: x y (any units; y grows up)
    edge Arad Zerind 75     ; undirected, with a cost (default 1)
    arc  A B 2.5            ; directed
    start Arad
    goal Bucharest          ; one or more goal lines: any goal ends the search
    h Arad 366              ; a table of estimates: every node's, or none

A name has no spaces.  The ``node`` lines may be left out when the edges name every node;
when there are some, every node is declared by one (a name no line declared is an unknown
node).  Places are given for every node or for none.  Every error names the file, the line
and the column of the word that is wrong (:class:`~tui_search.engine.maps.read.MapError`).
A file is untrusted (someone else wrote it): read within :data:`MAX_GRAPH_BYTES`, as UTF-8
without NUL bytes.
"""

from __future__ import annotations

import math
from array import array
from pathlib import Path

from tui_search.engine.maps.graph import NAN, Graph, GraphData
from tui_search.engine.maps.read import MapError, each_line, read_text

#: Bigger graph files are refused before reading (a graph of 100,000 nodes with their places
#: and a few roads each is a few MB).
MAX_GRAPH_BYTES = 64 * 1024 * 1024
KEYWORDS = ("node", "edge", "arc", "start", "goal", "h")
#: The longest name a node may have.
MAX_NAME = 100
#: The graphs shipped inside the package: ``tui-search romania``.
BUILT_IN_DIR = Path(__file__).resolve().parents[2] / "maps"  # tui_search/maps
BUILT_IN = ("romania",)


def is_graph_file(name: str) -> bool:
    return name.endswith(".graph")


def load_graph(path: str | Path) -> Graph:
    """The graph in the file ``path`` (a MapError says why it is not one)."""
    name = str(path)
    return parse_graph(read_text(name, "a graph", MAX_GRAPH_BYTES), name)


def built_in_graph(name: str) -> Graph:
    """A graph shipped with the app, by name (``romania``)."""
    path = BUILT_IN_DIR / f"{name}.graph"
    return parse_graph(path.read_text("utf-8"), path.name)


def _words(line: str) -> list[tuple[int, str]]:
    """A line's words with their columns (from 1), the comment cut off."""
    text = line.split(";", 1)[0]
    words: list[tuple[int, str]] = []
    col = 0
    for word in text.split():
        col = text.index(word, col)
        words.append((col + 1, word))
        col += len(word)
    return words


#: Why a node is in the graph: declared by a node line, named by a road, or named only by a
#: start, goal or h line (then it is an unknown node).
DECLARED, ON_A_ROAD, ONLY_NAMED = 1, 2, 4


class _Reader:
    """Reads a file's statements into a :class:`GraphData`, keeping per node only numbers
    (where it was first named, why it is there): a file of 100,000 nodes takes a few times
    its size."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.line = 0
        self.data = data = GraphData()
        self.names = data.names
        self.kind = bytearray()  # DECLARED | ON_A_ROAD | ONLY_NAMED, by node
        self.first = array("I")  # the line a node was first named on, and the column
        self.first_col = array("I")
        self.declared_on = array("I")  # its node line (0: none)
        self.placed = 0  # node lines with a place
        self.unplaced: tuple[int, int] | None = None  # the first node line without one
        self.road_col = array("I")  # each road's first word's column
        self.start: tuple[str, int, int] | None = None
        self.goals: list[tuple[str, int, int]] = []
        self.h_given = 0
        self.h_last = 0  # the last h line

    def fail(self, message: str, col: int | None = None) -> MapError:
        return MapError(self.path, message, self.line, col)

    def number(self, word: tuple[int, str], what: str) -> float:
        col, text = word
        try:
            value = float(text)
        except ValueError:
            raise self.fail(f"{what} {text!r} is not a number", col) from None
        if not math.isfinite(value):
            raise self.fail(f"{what} {text!r} is not a number", col)
        return value

    def node(self, word: tuple[int, str], why: int) -> int:
        """The number of the node ``word`` names (a new node's if it has none yet)."""
        col, name = word
        if len(name) > MAX_NAME:
            raise self.fail(f"a name of {len(name):,} characters: at most {MAX_NAME}", col)
        i = self.names.add(name)
        if i == len(self.kind):  # new
            data = self.data
            self.kind.append(0)
            self.first.append(self.line)
            self.first_col.append(col)
            self.declared_on.append(0)
            for column in (data.x, data.y, data.h):
                if len(column):  # kept once a line gives one (a place, an estimate)
                    column.append(NAN)
        self.kind[i] |= why
        return i

    def column(self, values: array[float]) -> array[float]:
        """``values`` (places or estimates), a NaN for each node so far if it is empty."""
        if not len(values):
            values.extend(array("d", [NAN]) * len(self.kind))
        return values

    def statement(self, words: list[tuple[int, str]]) -> None:
        (col, key), args = words[0], words[1:]
        if key not in KEYWORDS:
            raise self.fail(f"unknown statement {key!r} (use {', '.join(KEYWORDS)})", col)
        wants = {"node": (1, 3), "edge": (2, 3), "arc": (2, 3), "start": (1, 1),
                 "goal": (1, 1), "h": (2, 2)}[key]
        if not wants[0] <= len(args) <= wants[1] or (key == "node" and len(args) == 2):
            shape = {"node": "node NAME [X Y]", "edge": "edge A B [COST]",
                     "arc": "arc A B [COST]", "start": "start NAME", "goal": "goal NAME",
                     "h": "h NAME VALUE"}[key]
            at = args[wants[1]][0] if len(args) > wants[1] else col
            raise self.fail(f"{key}: write it {shape}", at)
        getattr(self, f"_{key}")(args)

    def _node(self, args: list[tuple[int, str]]) -> None:
        col, name = args[0]
        i = self.node(args[0], 0)
        if self.kind[i] & DECLARED:
            raise self.fail(f"node {name!r} is declared twice (first on line "
                            f"{self.declared_on[i]})", col)
        self.kind[i] |= DECLARED
        self.declared_on[i] = self.line
        if len(args) == 3:
            self.column(self.data.x)[i] = self.number(args[1], "x")
            self.column(self.data.y)[i] = self.number(args[2], "y")
            self.placed += 1
        elif self.unplaced is None:
            self.unplaced = (self.line, col)

    def _edge(self, args: list[tuple[int, str]], directed: bool = False) -> None:
        (ca, a), (cb, b) = args[0], args[1]
        cost = 1.0
        if len(args) == 3:
            cost = self.number(args[2], "the cost")
            if cost <= 0:
                raise self.fail(f"the cost {args[2][1]!r} is not above 0", args[2][0])
        if a == b:
            raise self.fail(f"a road from {a!r} to itself", cb)
        data = self.data
        data.road_a.append(self.node(args[0], ON_A_ROAD))
        data.road_b.append(self.node(args[1], ON_A_ROAD))
        data.road_cost.append(cost)
        data.road_directed.append(directed)
        data.road_line.append(self.line)
        self.road_col.append(ca)

    def _arc(self, args: list[tuple[int, str]]) -> None:
        self._edge(args, directed=True)

    def _start(self, args: list[tuple[int, str]]) -> None:
        if self.start is not None:
            raise self.fail(f"a second start (the first on line {self.start[1]})", args[0][0])
        self.node(args[0], ONLY_NAMED)
        self.start = (args[0][1], self.line, args[0][0])

    def _goal(self, args: list[tuple[int, str]]) -> None:
        self.node(args[0], ONLY_NAMED)
        self.goals.append((args[0][1], self.line, args[0][0]))

    def _h(self, args: list[tuple[int, str]]) -> None:
        (col, name), value = args[0], args[1]
        i = self.node(args[0], ONLY_NAMED)
        if not math.isnan(self.column(self.data.h)[i]):
            raise self.fail(f"h of {name!r} is given twice", col)
        estimate = self.number(value, "h")
        if estimate < 0:
            raise self.fail(f"h {value[1]!r} is below 0", value[0])
        self.data.h[i] = estimate
        self.h_given += 1
        self.h_last = self.line

    def graph(self, text: str) -> Graph:
        data, kind = self.data, self.kind
        any_declared = any(k & DECLARED for k in kind)
        unknown = [i for i, k in enumerate(kind)
                   if not k & (DECLARED | ON_A_ROAD) or (any_declared and not k & DECLARED)]
        if unknown:
            i = min(unknown, key=lambda j: (self.first[j], self.first_col[j]))
            self.line = self.first[i]
            why = " (no node line declares it)" if kind[i] & ON_A_ROAD else ""
            what = "h of unknown node" if kind[i] == ONLY_NAMED and self._only_h(i) else (
                "unknown node")
            raise self.fail(f"{what} {data.names[i]!r}{why}", self.first_col[i])
        if not len(data.names):
            self.line = 0
            raise MapError(self.path, "no nodes: a graph file has node or edge lines")
        self._check_roads()
        if self.placed:
            if self.placed != len(data.names):
                line, col = self.unplaced or (self.first[0], self.first_col[0])
                self.line = line
                raise self.fail("a place (x y) for every node or for none", col)
        else:
            data.x, data.y = array("d"), array("d")
        if self.h_given:
            missing = [n for n, v in zip(data.names, data.h, strict=True) if math.isnan(v)]
            if missing:
                self.line = self.h_last
                raise self.fail(f"the h table misses {len(missing)} node"
                                f"{'s' if len(missing) > 1 else ''}: "
                                f"{', '.join(missing[:5])}{' ...' if len(missing) > 5 else ''}")
        else:
            data.h = array("d")
        goals = tuple(dict.fromkeys(name for name, _, _ in self.goals))
        return Graph(data, start=self.start[0] if self.start else None, goals=goals,
                     source=text, name=Path(self.path).name)

    def _only_h(self, i: int) -> bool:
        """Was node ``i`` named by an h line (not only by the start or a goal)?"""
        named = {name for name, _, _ in [*([self.start] if self.start else []), *self.goals]}
        return self.data.names[i] not in named

    def _check_roads(self) -> None:
        """One road a pair of nodes and direction: a second is refused at its line."""
        data = self.data
        starts, roads = data.outgoing()
        for i in range(len(data.names)):
            seen: dict[int, int] = {}
            for r in roads[starts[i]:starts[i + 1]]:
                e = r >> 1
                b = data.road_a[e] if r & 1 else data.road_b[e]
                first = seen.setdefault(b, e)
                if first != e:
                    later = max(first, e)
                    self.line = data.road_line[later]
                    raise self.fail(f"a second road from {data.names[i]!r} to "
                                    f"{data.names[b]!r} (the first on line "
                                    f"{data.road_line[min(first, e)]})", self.road_col[later])


def parse_graph(text: str, path: str = "<graph>") -> Graph:
    """The graph the text of a ``.graph`` file says (``path`` names it in errors)."""
    reader = _Reader(path)
    for number, line in enumerate(each_line(text.removeprefix("\ufeff")), 1):
        reader.line = number
        words = _words(line)
        if words:
            reader.statement(words)
    return reader.graph(text)


__all__ = ["BUILT_IN", "MAX_GRAPH_BYTES", "built_in_graph", "is_graph_file", "load_graph",
           "parse_graph"]
