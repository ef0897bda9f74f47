"""The graph model: named nodes (with places, or none), roads between them with their costs,
the start, the goals, the closed nodes and a table of estimates -- the second kind of space
the searches run on, beside the grid (:mod:`tui_search.engine.maps.grid`).

A node's successors are the roads that leave it, in the order they were given (an undirected
edge counts for both its ends; :meth:`Graph.successors` with ``by_name`` sorts them by name
instead).  A *closed* node is a graph's obstacle: no search enters it (``o`` in the app).
Nodes are numbered in the order they were first named; a search's record keeps them by those
numbers, and the names are what a person reads.

A graph someone else wrote is untrusted, and a big one has 100,000 nodes: it is kept in flat
arrays (:class:`GraphData`, a few tens of bytes a node and a road), never an object a node
or a road, so that it takes a few times its file's size, not tens of times.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator, Mapping, Sequence
from itertools import accumulate
from math import hypot
from typing import overload

from tui_search.engine.util.frozen import Frozen

#: A place on the page: x to the right, y *up* (as a map is drawn), in any unit.
Point = tuple[float, float]
NAN = float("nan")


class Edge(Frozen):
    """A road as the file gives it: from ``a`` to ``b`` (numbers), its cost, whether it goes
    one way only (an ``arc``), and the file's line (0: made in code).  A :class:`Frozen`
    value, not a NamedTuple: the first frame imports this module (CONTRIBUTING.md,
    "Start-up")."""

    __slots__ = _FIELDS = ("a", "b", "cost", "directed", "line")

    a: int
    b: int
    cost: float
    directed: bool
    line: int

    def __init__(self, a: int, b: int, cost: float, directed: bool = False,
                 line: int = 0) -> None:
        self._assign(a=a, b=b, cost=cost, directed=directed, line=line)


class Names(Sequence[str]):
    """Node names by number, kept as one UTF-8 buffer and where each name ends, and a way to
    find a name's number: a dictionary (:meth:`indexed`: fast, a hundred bytes and more a
    name), or a hash table of numbers over the buffer (open addressing: a few bytes a node
    beyond its name), for a file so dense in names that a dictionary would take many times its size
    (:meth:`compact`)."""

    __slots__ = ("_buf", "_ends", "_index", "_table")

    def __init__(self, names: Sequence[str] = ()) -> None:
        self._buf = bytearray()
        self._ends = array("I", [0])
        self._index: dict[str, int] | None = None
        self._table = array("i", [0]) * 8  # a node's number + 1 (0: empty)
        for name in names:
            self.add(name)

    @classmethod
    def indexed(cls, index: dict[str, int]) -> Names:
        """The names of ``index`` (each name's number, numbered 0, 1, ... in its order),
        found through it from now on (it is kept, not copied)."""
        names = cls()
        names._table = array("i")
        names._index = index
        text = "".join(index)
        names._buf = bytearray(text.encode())
        lengths = map(len, index) if len(names._buf) == len(text) else (
            len(name.encode()) for name in index)  # not all ASCII: the bytes of each
        names._ends.extend(accumulate(lengths))
        return names

    def compact(self) -> None:
        """Find names through the hash table over the buffer from now on, not a dictionary."""
        index, self._index = self._index, None
        if index is not None:
            size = 8
            while size < 2 * len(index):
                size *= 2
            self._table = array("i", [0]) * size
            for i, name in enumerate(index):
                self._place(name, i)

    def __len__(self) -> int:
        return len(self._ends) - 1

    @overload
    def __getitem__(self, i: int) -> str: ...
    @overload
    def __getitem__(self, i: slice) -> list[str]: ...
    def __getitem__(self, i: int | slice) -> str | list[str]:
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(len(self)))]
        if i < 0:
            i += len(self)
        if not 0 <= i < len(self):
            raise IndexError("no node of that number")
        return self._buf[self._ends[i]:self._ends[i + 1]].decode()

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Sequence):
            return NotImplemented
        return len(self) == len(other) and all(a == b for a, b in zip(self, other, strict=True))

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"Names({list(self)!r})"

    def number(self, name: str) -> int:
        """The number of the node called ``name``, or -1."""
        if self._index is not None:
            return self._index.get(name, -1)
        table, mask = self._table, len(self._table) - 1
        data, ends = name.encode(), self._ends
        slot = hash(name) & mask
        while True:
            entry = table[slot]
            if not entry:
                return -1
            i = entry - 1
            if self._buf[ends[i]:ends[i + 1]] == data:
                return i
            slot = (slot + 1) & mask

    def add(self, name: str) -> int:
        """The number of ``name``, a new node's if it has none yet."""
        i = self.number(name)
        if i >= 0:
            return i
        i = len(self)
        self._buf += name.encode()
        self._ends.append(len(self._buf))
        if self._index is not None:
            self._index[name] = i
        elif 2 * (i + 1) > len(self._table):  # at most half full: short probes
            self._rehash(2 * len(self._table))
        else:
            self._place(name, i)
        return i

    def _place(self, name: str, i: int) -> None:
        table, mask = self._table, len(self._table) - 1
        slot = hash(name) & mask
        while table[slot]:
            slot = (slot + 1) & mask
        table[slot] = i + 1

    def _rehash(self, size: int) -> None:
        self._table = array("i", [0]) * size
        for i, name in enumerate(self):
            self._place(name, i)


class NameIndex(Mapping[str, int]):
    """A name's node number (``graph.index[name]``), over :class:`Names`."""

    __slots__ = ("_names",)

    def __init__(self, names: Names) -> None:
        self._names = names

    def __getitem__(self, name: str) -> int:
        i = self._names.number(name)
        if i < 0:
            raise KeyError(name)
        return i

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and self._names.number(name) >= 0

    def __iter__(self) -> Iterator[str]:
        return iter(self._names)

    def __len__(self) -> int:
        return len(self._names)


class GraphData:
    """What a graph file says, in flat arrays: the names, each node's place (two floats, or
    none), each road's ends, cost, direction and line, and each node's estimate (NaN: none).
    Built by :mod:`tui_search.engine.maps.graph_file` (or :meth:`Graph.of` in code); never
    changed once a graph has it (a copy of the graph shares it)."""

    def __init__(self) -> None:
        self.names = Names()
        self.x = array("d")  # places, by node number (empty: none)
        self.y = array("d")
        self.road_a = array("i")
        self.road_b = array("i")
        self.road_cost = array("d")
        self.road_directed = bytearray()
        self.road_line = array("I")
        self.h = array("d")  # estimates by node number (empty: no table)
        self._rows: tuple[array[int], array[int], array[int]] | None = None
        self._row_costs: array[float] | None = None

    def outgoing(self) -> tuple[array[int], array[int]]:
        """Each node's roads out in the file's order, as compressed rows: node ``i``'s are
        ``roads[starts[i]:starts[i + 1]]``, each a road's number times 2, plus 1 when it is
        taken backwards (an undirected road from its ``b`` end)."""
        starts, roads, _ = self.rows()
        return starts, roads

    def rows(self) -> tuple[array[int], array[int], array[int]]:
        """:meth:`outgoing`'s ``starts`` and ``roads``, and beside each road the node it
        reaches (``nodes[j]`` for ``roads[j]``)."""
        if self._rows is None:
            n = len(self.names)
            road_a, road_b, directed = self.road_a, self.road_b, self.road_directed
            counts = array("I", [0]) * (n + 1)
            for a in road_a:
                counts[a + 1] += 1
            if 1 in directed:  # some roads go one way: only the others count at their b
                for b, one_way in zip(road_b, directed, strict=True):
                    if not one_way:
                        counts[b + 1] += 1
            else:
                for b in road_b:
                    counts[b + 1] += 1
            starts = array("I", accumulate(counts))
            fill = array("I", starts)
            roads = array("i", [0]) * starts[n]
            nodes = array("i", [0]) * starts[n]
            for e, a, b, one_way in zip(range(len(road_a)), road_a, road_b, directed,
                                        strict=True):
                j = fill[a]
                fill[a] = j + 1
                roads[j], nodes[j] = 2 * e, b
                if not one_way:
                    j = fill[b]
                    fill[b] = j + 1
                    roads[j], nodes[j] = 2 * e + 1, a
            self._rows = (starts, roads, nodes)
        return self._rows

    def row_costs(self) -> array[float]:
        """The cost of each road of :meth:`rows`, beside it (worked out once: a graph's data
        never changes)."""
        if self._row_costs is None:
            cost = self.road_cost
            self._row_costs = array("d", [cost[r >> 1] for r in self.rows()[1]])
        return self._row_costs


class Graph:
    """A graph: its :class:`GraphData` (``names``, ``places``, ``edges``, ``h``), and what the
    app edits -- ``start`` and ``goals`` (names) and the ``closed`` nodes.  Mutable as a grid
    is (:meth:`copy` for a search's own snapshot; a copy shares the data)."""

    #: What two graphs are compared by (``==``); the file they came from is not part of it.
    COMPARED = ("names", "places", "edges", "start", "goals", "closed", "h")

    def __init__(self, data: GraphData, *, start: str | None = None,
                 goals: tuple[str, ...] = (), closed: frozenset[str] = frozenset(),
                 source: str | None = None, name: str = "graph") -> None:
        if not len(data.names):
            raise ValueError("a graph needs at least one node")
        self.data = data
        self.names: Names = data.names
        self.index = NameIndex(data.names)
        self.start = start
        self.goals = goals
        self.closed = closed
        #: The file text the graph was read from (None: built in code); saving writes it
        #: back with only the edited lines changed.  Not part of the graph's value.
        self.source = source
        #: What the messages call it (its file's name).
        self.name = name

    @classmethod
    def of(cls, names: list[str], edges: list[Edge], *, places: list[Point] | None = None,
           h: dict[str, float] | None = None, **kwargs: object) -> Graph:
        """A graph made in code (tests, generators): its names, roads, places and table."""
        data = GraphData()
        for name in names:
            data.names.add(name)
        if places is not None:
            data.x.extend(x for x, _ in places)
            data.y.extend(y for _, y in places)
        for edge in edges:
            data.road_a.append(edge.a)
            data.road_b.append(edge.b)
            data.road_cost.append(edge.cost)
            data.road_directed.append(edge.directed)
            data.road_line.append(edge.line)
        if h is not None:
            data.h.extend(h[name] for name in names)
        return cls(data, **kwargs)  # type: ignore[arg-type]

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        return all(getattr(self, n) == getattr(other, n) for n in self.COMPARED)

    __hash__ = None  # type: ignore[assignment]  # mutable: unhashable

    def __repr__(self) -> str:
        return (f"Graph({len(self)} nodes, {len(self.data.road_a)} roads, "
                f"start={self.start!r}, goals={self.goals!r})")

    # -- the data, as values -----------------------------------------------------------------
    @property
    def places(self) -> list[Point] | None:
        """Every node's place, by number (None: the nodes have none)."""
        d = self.data
        return list(zip(d.x, d.y, strict=True)) if len(d.x) else None

    def place(self, i: int) -> Point:
        return self.data.x[i], self.data.y[i]

    @property
    def has_places(self) -> bool:
        return len(self.data.x) > 0

    @property
    def edges(self) -> list[Edge]:
        d = self.data
        return [Edge(d.road_a[e], d.road_b[e], d.road_cost[e], bool(d.road_directed[e]),
                     d.road_line[e]) for e in range(len(d.road_a))]

    @property
    def h(self) -> dict[str, float] | None:
        """The table of estimates by name (None: the file gives none)."""
        d = self.data
        return dict(zip(self.names, d.h, strict=True)) if len(d.h) else None

    def estimate(self, i: int) -> float:
        """Node ``i``'s estimate in the table."""
        return self.data.h[i]

    @property
    def has_table(self) -> bool:
        return len(self.data.h) > 0

    # -- queries ---------------------------------------------------------------------------
    def __len__(self) -> int:
        return len(self.names)

    def __contains__(self, name: object) -> bool:
        return name in self.index

    def is_goal(self, name: str) -> bool:
        return name in self.goals

    def is_closed(self, name: str) -> bool:
        return name in self.closed

    def roads_out(self, i: int) -> Iterator[tuple[int, float, int]]:
        """Node ``i``'s roads out in the file's order: the node each reaches, its cost and
        the road's number (closed nodes included)."""
        starts, roads, nodes = self.data.rows()
        cost = self.data.road_cost
        for j in range(starts[i], starts[i + 1]):
            e = roads[j] >> 1
            yield nodes[j], cost[e], e

    def successors(self, name: str, by_name: bool = False) -> Iterator[tuple[str, float, int]]:
        """The open nodes a road from ``name`` reaches, in the file's order (or by name),
        with the road's cost and its number."""
        names, closed = self.names, self.closed
        roads = [(names[b], cost, e) for b, cost, e in self.roads_out(self.index[name])]
        if by_name:
            roads.sort(key=lambda road: (road[0], road[2]))
        return (road for road in roads if road[0] not in closed)

    def cost(self, a: str, b: str) -> float:
        """The road's cost from ``a`` to ``b`` (one road a pair and direction)."""
        j = self.index[b]
        return next(cost for k, cost, _ in self.roads_out(self.index[a]) if k == j)

    def path_cost(self, path: list[str]) -> float:
        return sum((self.cost(a, b) for a, b in zip(path, path[1:], strict=False)), 0.0)

    def lowest_cost(self) -> float:
        """The cheapest road's cost."""
        return min(self.data.road_cost, default=1.0)

    def distance(self, a: str, b: str) -> float:
        """The straight-line distance between two nodes' places."""
        (x1, y1), (x2, y2) = self.place(self.index[a]), self.place(self.index[b])
        return hypot(x1 - x2, y1 - y2)

    # -- edits ---------------------------------------------------------------------------
    def copy(self) -> Graph:
        """Another graph of the same data (shared: it never changes) and the same start,
        goals and closed nodes, which the copy may change on its own."""
        return Graph(self.data, start=self.start, goals=self.goals, closed=self.closed,
                     source=self.source, name=self.name)


__all__ = ["NAN", "Edge", "Graph", "GraphData", "NameIndex", "Names", "Point"]
