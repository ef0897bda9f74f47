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

import itertools
import math
from array import array
from collections.abc import Iterator
from pathlib import Path

from tui_search.engine.maps.graph import NAN, Graph, GraphData, Names
from tui_search.engine.maps.read import MapError, each_line, read_text

#: Bigger graph files are refused before reading (a graph of 100,000 nodes with their places
#: and a few roads each is a few MB).
MAX_GRAPH_BYTES = 64 * 1024 * 1024
KEYWORDS = ("node", "edge", "arc", "start", "goal", "closed", "h")
#: The longest name a node may have.
MAX_NAME = 100
#: Names are numbered through a dictionary (fast, a hundred bytes and more a name) while
#: there is at most one a this many bytes of the file (the test of untrusted files holds a
#: reader within ten times its file); past that, through the compact table of :class:`Names`.
NAMES_IN_DICT = 40
#: ... and at least this many names are (a small file is read through a dictionary).
MIN_IN_DICT = 1024
INF = math.inf
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
    its size.

    Names are numbered through a dictionary while it stays within :data:`NAMES_IN_DICT` of
    the file's size, then through the compact table of :class:`Names` (a file of little but
    short new names: ``edge a1 b1``, ...).  :func:`parse_graph` reads well-formed ``node``,
    ``edge`` and ``arc`` lines itself, on the fast path; every other line, and any of these
    it finds something wrong with, goes through :meth:`statement`, which says what."""

    def __init__(self, path: str, size: int = 0) -> None:
        self.path = path
        self.line = 0
        self.data = GraphData()
        #: Each name's number, while the names are few for the file's size (None: after,
        #: when ``data.names`` finds them).
        self.ids: dict[str, int] | None = {}
        self.max_ids = max(size // NAMES_IN_DICT, MIN_IN_DICT)
        self.kind = bytearray()  # DECLARED | ON_A_ROAD | ONLY_NAMED, by node
        self.first = array("I")  # the line a node was first named on, and which word named it
        self.first_word = bytearray()
        self.declared_on = array("I")  # its node line (0: none)
        self.placed = 0  # node lines with a place
        self.unplaced: tuple[int, int] | None = None  # the first node line without one
        self.start: tuple[str, int, int] | None = None
        self.goals: list[tuple[str, int, int]] = []
        self.closed: list[tuple[str, int, int]] = []  # ``closed`` lines: nodes no search enters
        self.h_given = 0
        self.h_last = 0  # the last h line
        self.text = ""  # the file's text, for the column of an error found after its line

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

    def node(self, word: tuple[int, str], why: int, at: int) -> int:
        """The number of the node ``word`` names, the line's word ``at`` (a new node's if it
        has none yet)."""
        col, name = word
        if len(name) > MAX_NAME:
            raise self.fail(f"a name of {len(name):,} characters: at most {MAX_NAME}", col)
        i = self.lookup(name)
        if i < 0:
            i = self.new(name, at)
        self.kind[i] |= why
        return i

    def lookup(self, name: str) -> int:
        """The number of the node called ``name``, or -1."""
        return self.data.names.number(name) if self.ids is None else self.ids.get(name, -1)

    def new(self, name: str, at: int) -> int:
        """A new node's number: ``name``, the line's word ``at``."""
        data = self.data
        i = len(self.kind)
        if self.ids is None:
            data.names.add(name)
        else:
            self.ids[name] = i
            if i >= self.max_ids:  # the names take too much room in a dictionary
                data.names = Names.indexed(self.ids)
                data.names.compact()
                self.ids = None
        self.kind.append(0)
        self.first.append(self.line)
        self.first_word.append(at)
        self.declared_on.append(0)
        for column in (data.x, data.y, data.h):
            if len(column):  # kept once a line gives one (a place, an estimate)
                column.append(NAN)
        return i

    def col(self, i: int) -> int:
        """The column of the word that first named node ``i``."""
        line = next(itertools.islice(each_line(self.text), self.first[i] - 1, None))
        return _words(line)[self.first_word[i]][0]

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
                 "goal": (1, 1), "closed": (1, 1), "h": (2, 2)}[key]
        if not wants[0] <= len(args) <= wants[1] or (key == "node" and len(args) == 2):
            shape = {"node": "node NAME [X Y]", "edge": "edge A B [COST]",
                     "arc": "arc A B [COST]", "start": "start NAME", "goal": "goal NAME",
                     "closed": "closed NAME",
                     "h": "h NAME VALUE"}[key]
            at = args[wants[1]][0] if len(args) > wants[1] else col
            raise self.fail(f"{key}: write it {shape}", at)
        getattr(self, f"_{key}")(args)

    def _node(self, args: list[tuple[int, str]]) -> None:
        col, name = args[0]
        i = self.node(args[0], 0, 1)
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
        (_, a), (cb, b) = args[0], args[1]
        cost = 1.0
        if len(args) == 3:
            cost = self.number(args[2], "the cost")
            if cost <= 0:
                raise self.fail(f"the cost {args[2][1]!r} is not above 0", args[2][0])
        if a == b:
            raise self.fail(f"a road from {a!r} to itself", cb)
        data = self.data
        data.road_a.append(self.node(args[0], ON_A_ROAD, 1))
        data.road_b.append(self.node(args[1], ON_A_ROAD, 2))
        data.road_cost.append(cost)
        data.road_directed.append(directed)
        data.road_line.append(self.line)

    def _arc(self, args: list[tuple[int, str]]) -> None:
        self._edge(args, directed=True)

    def _start(self, args: list[tuple[int, str]]) -> None:
        if self.start is not None:
            raise self.fail(f"a second start (the first on line {self.start[1]})", args[0][0])
        self.node(args[0], ONLY_NAMED, 1)
        self.start = (args[0][1], self.line, args[0][0])

    def _goal(self, args: list[tuple[int, str]]) -> None:
        self.node(args[0], ONLY_NAMED, 1)
        self.goals.append((args[0][1], self.line, args[0][0]))

    def _closed(self, args: list[tuple[int, str]]) -> None:
        self.node(args[0], ONLY_NAMED, 1)
        self.closed.append((args[0][1], self.line, args[0][0]))

    def _h(self, args: list[tuple[int, str]]) -> None:
        (col, name), value = args[0], args[1]
        i = self.node(args[0], ONLY_NAMED, 1)
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
        if self.ids is not None:
            data.names = Names.indexed(self.ids)
            self.ids = None
        any_declared = DECLARED in kind.translate(_DECLARED)
        if 1 in kind.translate(_UNKNOWN_IF_ANY_DECLARED if any_declared else _UNKNOWN):
            unknown = [i for i, k in enumerate(kind)
                       if not k & (DECLARED | ON_A_ROAD) or (any_declared and not k & DECLARED)]
            i = min(unknown, key=lambda j: (self.first[j], self.first_word[j]))
            self.line = self.first[i]
            why = " (no node line declares it)" if kind[i] & ON_A_ROAD else ""
            what = "h of unknown node" if kind[i] == ONLY_NAMED and self._only_h(i) else (
                "unknown node")
            raise self.fail(f"{what} {data.names[i]!r}{why}", self.col(i))
        if not len(data.names):
            self.line = 0
            raise MapError(self.path, "no nodes: a graph file has node or edge lines")
        self._check_roads()
        if self.placed:
            if self.placed != len(data.names):
                line, col = self.unplaced or (self.first[0], self.col(0))
                self.line = line
                raise self.fail("a place (x y) for every node or for none", col)
        else:
            data.x, data.y = array("d"), array("d")
        if self.h_given:
            missing = [data.names[i] for i, v in enumerate(data.h) if math.isnan(v)]
            if missing:
                self.line = self.h_last
                raise self.fail(f"the h table misses {len(missing)} node"
                                f"{'s' if len(missing) > 1 else ''}: "
                                f"{', '.join(missing[:5])}{' ...' if len(missing) > 5 else ''}")
        else:
            data.h = array("d")
        goals = tuple(dict.fromkeys(name for name, _, _ in self.goals))
        closed = frozenset(name for name, _, _ in self.closed)
        return Graph(data, start=self.start[0] if self.start else None, goals=goals,
                     closed=closed, source=text, name=Path(self.path).name)

    def _only_h(self, i: int) -> bool:
        """Was node ``i`` named by an h line (not only by the start or a goal)?"""
        named = {name for name, _, _ in [*([self.start] if self.start else []), *self.goals,
                                         *self.closed]}
        return self.data.names[i] not in named

    def _check_roads(self) -> None:
        """One road a pair of nodes and direction: a second is refused at its line."""
        data = self.data
        starts, roads, nodes = data.rows()
        for i in range(len(data.names)):
            s, e = starts[i], starts[i + 1]
            if e - s > 1 and len(set(nodes[s:e])) < e - s:
                self._second_road(i, roads[s:e])

    def _second_road(self, i: int, roads: array[int]) -> None:
        """Refuse the second of two roads from node ``i`` (``roads``: its own) to a node."""
        data = self.data
        seen: dict[int, int] = {}
        for r in roads:
            e = r >> 1
            b = data.road_a[e] if r & 1 else data.road_b[e]
            first = seen.setdefault(b, e)
            if first != e:
                later = max(first, e)
                self.line = data.road_line[later]
                line = next(itertools.islice(each_line(self.text), self.line - 1, None))
                raise self.fail(f"a second road from {data.names[i]!r} to "
                                f"{data.names[b]!r} (the first on line "
                                f"{data.road_line[min(first, e)]})", _words(line)[1][0])


#: ``kind.translate`` tables: DECLARED where a node is declared; 1 where it is unknown (named
#: by no road and declared by no line; or, when some node line declares nodes, by none).
_DECLARED = bytes(k & DECLARED for k in range(256))
_UNKNOWN = bytes(int(not k & (DECLARED | ON_A_ROAD)) for k in range(256))
_UNKNOWN_IF_ANY_DECLARED = bytes(int(not k & DECLARED) for k in range(256))


def _lines(text: str, block: int = 1 << 16) -> Iterator[str]:
    """:func:`each_line`'s lines, split a block of about ``block`` characters at a time (a
    list of a block's lines is fast to walk, and small)."""
    start = 0
    while start < len(text):
        end = text.find("\n", start + block)
        if end < 0:
            yield from text[start:].split("\n")
            return
        yield from text[start:end].split("\n")
        start = end + 1


def parse_graph(text: str, path: str = "<graph>") -> Graph:
    """The graph the text of a ``.graph`` file says (``path`` names it in errors).

    Well-formed ``node NAME X Y``, ``edge A B [COST]`` and ``arc A B [COST]`` lines, all but
    a few lines of a big file, are read here, as the reader's statements would read them;
    a line of any other kind, or one with anything to say about (a cost that is no number, a
    name too long or declared twice, ...), is read again by :meth:`_Reader.statement`, which
    says what is wrong where."""
    source, text = text, text.removeprefix("\ufeff")
    reader = _Reader(path, len(text))
    reader.text = text
    data, kind, declared_on = reader.data, reader.kind, reader.declared_on
    road_a, road_b, road_cost = data.road_a, data.road_b, data.road_cost
    road_directed, road_line = data.road_directed, data.road_line
    xs, ys = data.x, data.y
    for number, line in enumerate(_lines(text), 1):
        words = (line.split(";", 1)[0] if ";" in line else line).split()
        if not words:
            continue
        key, n = words[0], len(words)
        ids = reader.ids
        if ids is not None and (key == "edge" or key == "arc") and (n == 3 or n == 4):
            a, b = words[1], words[2]
            if n == 4:
                try:
                    cost = float(words[3])
                except ValueError:
                    cost = NAN  # read again: "is not a number"
            else:
                cost = 1.0
            if 0 < cost < INF and a != b and len(a) <= MAX_NAME and len(b) <= MAX_NAME:
                i, j = ids.get(a, -1), ids.get(b, -1)
                if i < 0 or j < 0:
                    reader.line = number
                    if i < 0:
                        i = reader.new(a, 1)
                    if j < 0:
                        j = reader.new(b, 2)
                kind[i] |= ON_A_ROAD
                kind[j] |= ON_A_ROAD
                road_a.append(i)
                road_b.append(j)
                road_cost.append(cost)
                road_directed.append(key == "arc")
                road_line.append(number)
                continue
        elif ids is not None and key == "node" and n == 4:
            name = words[1]
            try:
                x, y = float(words[2]), float(words[3])
            except ValueError:
                x = NAN  # read again: "is not a number"
            i = ids.get(name, -1)
            if (i < 0 and len(xs) == len(kind) and -INF < x < INF and -INF < y < INF
                    and len(name) <= MAX_NAME and not len(data.h)):
                reader.line = number
                i = reader.new(name, 1)  # (a NaN place for it unless it is the first)
                kind[i] = DECLARED
                declared_on[i] = number
                if i:
                    xs[i], ys[i] = x, y
                else:
                    xs.append(x)
                    ys.append(y)
                reader.placed += 1
                continue
        reader.line = number
        reader.statement(_words(line))
    return reader.graph(source)


__all__ = ["BUILT_IN", "MAX_GRAPH_BYTES", "built_in_graph", "is_graph_file", "load_graph",
           "parse_graph"]
