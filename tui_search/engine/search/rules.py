"""The reference loop's entries and steps (:class:`Node`, :class:`Expansion`) and its two
parameters (:mod:`tui_search.engine.search.reference`): the
*frontier*, which says which entry comes out next, and what was *reached*, which says which
successors are pushed and which entries taken off are thrown away.

Frontiers: a FIFO :class:`Queue` (BFS), a LIFO :class:`Stack` (DFS, iterative deepening), a
:class:`CallStack` (recursion: the first successor of a step comes out first, as the call for
it is made first) and a :class:`PriorityQueue` (uniform-cost, greedy, A*: the lowest priority
first, a tie by the tie rule, then the oldest).

What was reached: :class:`Visited` (BFS's and DFS's visited set, under each visit rule),
:class:`Cheapest` (the best g: re-pushed when reached cheaper, stale entries discarded, a
closed set when re-opening is off), :class:`Shallowest` (iterative deepening: re-pushed when
reached shallower), :class:`Cheaper` (IDA*: re-pushed when reached cheaper) and
:class:`OnPath` (tree search: the node's own path, or nothing at all).
"""

from __future__ import annotations

import heapq
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from tui_search.engine.search.state import State

INF = float("inf")

@dataclass(eq=False, slots=True)
class Node:
    """A frontier entry: a state (a cell, a node), the entry it was generated from, and the
    move between."""

    event: int  # generation events are numbered from 0 (the start) in the order pushed
    cell: State
    parent: Node | None
    move: str | None  # the direction it was reached by (None for a root)
    depth: int
    g: float = 0.0  # the path's cost from the root: each move's length times its cell's cost

    def path(self) -> list[State]:
        """Cells from the root down to this node."""
        chain = []
        node: Node | None = self
        while node is not None:
            chain.append(node.cell)
            node = node.parent
        chain.reverse()
        return chain

    def moves(self) -> list[str]:
        out = []
        node: Node | None = self
        while node is not None and node.move is not None:
            out.append(node.move)
            node = node.parent
        out.reverse()
        return out

    def on_path(self, cell: State) -> bool:
        """Is ``cell`` on the path from the root to this node (this node included)?"""
        node: Node | None = self
        while node is not None:
            if node.cell == cell:
                return True
            node = node.parent
        return False


@dataclass(frozen=True, slots=True)
class Expansion:
    """One step: the node taken off the frontier and what it added, in order."""

    index: int  # steps are numbered from 1
    node: Node
    successors: tuple[Node, ...]
    discarded: bool  # visit on expand: the cell was expanded before; nothing is done
    found: bool  # this step found the goal
    frontier_size: int  # entries on the frontier after the step
    depth_limit: int | None = None  # iterative deepening's limit in force
    new_root: Node | None = None  # iterative deepening: this step began a new iteration
    f_limit: float | None = None  # IDA*'s limit on f in force
    #: IDA*: the smallest f over the limit met so far in this iteration (the next limit if
    #: the iteration ends with no goal; inf while there is none)
    next_limit: float = INF
    #: A bidirectional search's: "forward" (from the start) or "backward" (from the goal);
    #: "" for a search one way.
    direction: str = ""


# -- the frontier: which entry comes out next ---------------------------------------------------
class Frontier(Protocol):
    def __len__(self) -> int: ...
    def add(self, node: Node) -> None: ...
    def take(self) -> Node: ...


class Queue:
    """FIFO (BFS): the oldest entry comes out first."""

    def __init__(self) -> None:
        self.entries: deque[Node] = deque()

    def __len__(self) -> int:
        return len(self.entries)

    def add(self, node: Node) -> None:
        self.entries.append(node)

    def take(self) -> Node:
        return self.entries.popleft()


class Stack(Queue):
    """LIFO (DFS, iterative deepening): the same line of entries, the newest coming out first."""

    def take(self) -> Node:
        return self.entries.pop()


class CallStack:
    """Recursion (``--recursive``): a stack whose step's successors come out in the order
    pushed -- the first successor is the first call made -- each before anything pushed
    earlier.  Each push goes in below the step's earlier pushes (at ``mark``, the top as the
    step began)."""

    def __init__(self) -> None:
        self.entries: list[Node] = []
        self.mark = 0

    def __len__(self) -> int:
        return len(self.entries)

    def add(self, node: Node) -> None:
        self.entries.insert(self.mark, node)

    def take(self) -> Node:
        node = self.entries.pop()
        self.mark = len(self.entries)
        return node


def tie_key(ties: str, h: Callable[[State], float]) -> Callable[[Node], object]:
    """What orders a priority queue's entries of equal priority, before their age (the
    oldest first): nothing (``fifo``), the newest first, the smallest cell (x, then y), the
    lower or higher h, the lower or higher g."""
    keys: dict[str, Callable[[Node], object]] = {
        "fifo": lambda node: 0,
        "lifo": lambda node: -node.event,
        "node": lambda node: node.cell,
        "low-h": lambda node: h(node.cell),
        "high-h": lambda node: -h(node.cell),
        "low-g": lambda node: node.g,
        "high-g": lambda node: -node.g,
    }
    return keys[ties]


class PriorityQueue:
    """Uniform-cost, greedy and A*: the lowest priority (g, h or g + h) first, ties by the tie
    rule (:func:`tie_key`), then in the order pushed (a heap of ``(priority, tie, event,
    node)``: the event number breaks what is left)."""

    def __init__(self, priority: Callable[[float, State], float],
                 tie: Callable[[Node], object] = lambda node: 0) -> None:
        self.priority, self.tie = priority, tie
        self.heap: list[tuple[float, object, int, Node]] = []

    def __len__(self) -> int:
        return len(self.heap)

    def add(self, node: Node) -> None:
        heapq.heappush(self.heap, (self.priority(node.g, node.cell), self.tie(node),
                                   node.event, node))

    def take(self) -> Node:
        return heapq.heappop(self.heap)[3]


# -- what was reached: which successors are pushed, which entries taken off are discarded -------
class Reached(Protocol):
    def admits(self, parent: Node, cell: State, g: float) -> bool:
        """May ``cell``, reached from ``parent`` with cost ``g``, be pushed?"""
        ...

    def pushed(self, node: Node) -> None: ...

    def discards(self, node: Node) -> bool:
        """Is ``node``, just taken off, thrown away (a discarded step)?"""
        ...

    def taken(self, node: Node) -> Node:
        """The node expanded for ``node``, taken off and not discarded (itself but for a
        closed set's, expanded at its cell's best g)."""
        ...


class OnPath:
    """Tree search: no visited set; a cell is skipped only when it lies on the path from the
    root to the node being expanded (that node included) -- or, with no ``check``, never (the
    textbook's tree search skips nothing, not even the parent).  Nothing is discarded."""

    def __init__(self, check: bool = True) -> None:
        self.check = check

    def admits(self, parent: Node, cell: State, g: float) -> bool:
        return not (self.check and parent.on_path(cell))

    def pushed(self, node: Node) -> None:
        pass

    def discards(self, node: Node) -> bool:
        return False

    def taken(self, node: Node) -> Node:
        return node


class Visited:
    """BFS's and DFS's visited set.  Visit on generate: a cell is visited when pushed, so it is
    never pushed twice (but for the start, with ``mark_start`` off: it is not marked, so a
    neighbour pushes it again).  Visit on expand: when taken off and expanded, so a cell may
    sit on the frontier several times, and taking off a cell already expanded is a discarded
    step.  Visit on expand, expanded again: marked when taken off, but the node taken off is
    never checked, so a cell taken off again is expanded again."""

    def __init__(self, visit: str, mark_start: bool = True) -> None:
        self.on_push = visit == "generate"
        self.checked = visit == "expand"
        self.mark_start = mark_start
        self.cells: set[State] = set()

    def admits(self, parent: Node, cell: State, g: float) -> bool:
        return cell not in self.cells

    def pushed(self, node: Node) -> None:
        if self.on_push and (self.mark_start or node.parent is not None):
            self.cells.add(node.cell)

    def discards(self, node: Node) -> bool:
        if self.on_push:
            return False
        if self.checked and node.cell in self.cells:
            return True
        self.cells.add(node.cell)
        return False

    def taken(self, node: Node) -> Node:
        return node


class Cheapest:
    """The priority queue's rule: a cell is pushed again whenever it is reached with a lower g
    than its best so far (lower by more than ``tolerance``), even after it was expanded (it
    is re-opened), and an entry taken off with a g above its cell's best is stale: discarded
    -- unless ``reopen`` is off: then a cell expanded is closed, never pushed again, an entry
    of it taken off later is discarded, and its first entry taken off is expanded at the
    cell's best g (as code with a closed set and a table of g does).  With ``mark_start`` off
    the start's g is not kept, so a neighbour pushes it again."""

    def __init__(self, tolerance: float, reopen: bool = True, mark_start: bool = True) -> None:
        self.tolerance, self.reopen, self.mark_start = tolerance, reopen, mark_start
        self.best: dict[State, float] = {}
        self.closed: set[State] = set()

    def admits(self, parent: Node, cell: State, g: float) -> bool:
        if not self.reopen and cell in self.closed:
            return False
        return g + self.tolerance < self.best.get(cell, INF)

    def pushed(self, node: Node) -> None:
        if self.mark_start or node.parent is not None:
            self.best[node.cell] = node.g

    def discards(self, node: Node) -> bool:
        if not self.reopen:
            if node.cell in self.closed:
                return True
            self.closed.add(node.cell)
            return False
        return node.g > self.best.get(node.cell, INF)

    def taken(self, node: Node) -> Node:
        best = self.best.get(node.cell, node.g)
        if self.reopen or best == node.g:
            return node
        return Node(node.event, node.cell, node.parent, node.move, node.depth, best)


class Shallowest:
    """Iterative deepening, within one iteration: a cell is pushed again when reached at a
    smaller depth than before.  An entry reached shallower since is still expanded.  With
    ``mark_start`` off the start's depth is not kept."""

    def __init__(self, mark_start: bool = True) -> None:
        self.mark_start = mark_start
        self.best: dict[State, int] = {}

    def admits(self, parent: Node, cell: State, g: float) -> bool:
        return parent.depth + 1 < self.best.get(cell, INF)

    def pushed(self, node: Node) -> None:
        if self.mark_start or node.parent is not None:
            self.best[node.cell] = node.depth

    def discards(self, node: Node) -> bool:
        return False

    def taken(self, node: Node) -> Node:
        return node


class Cheaper(Shallowest):
    """IDA*, within one iteration: a cell is pushed again when reached with a lower g than
    before (lower by more than ``tolerance``).  An entry reached cheaper since is still
    expanded.  With ``mark_start`` off the start's g is not kept."""

    def __init__(self, tolerance: float, mark_start: bool = True) -> None:
        super().__init__(mark_start)
        self.tolerance = tolerance
        self.cheapest: dict[State, float] = {}

    def admits(self, parent: Node, cell: State, g: float) -> bool:
        return g + self.tolerance < self.cheapest.get(cell, INF)

    def pushed(self, node: Node) -> None:
        if self.mark_start or node.parent is not None:
            self.cheapest[node.cell] = node.g


__all__ = ["CallStack", "Cheaper", "Cheapest", "Expansion", "Frontier", "Node", "OnPath",
           "PriorityQueue", "Queue", "Reached", "Shallowest", "Stack", "Visited", "tie_key"]
