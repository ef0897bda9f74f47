"""The reference search: one generic loop, written for clarity, for every algorithm and choice.

This is the definition of what a search does here.  The recorded runs use faster loops
(:mod:`tui_search.engine.search.loops`), and a hypothesis test holds each of them equal to this one,
step by step, over random maps and random choices.  The headless command line streams this loop:
it keeps only the frontier, the visited cells and the chains of parents the frontier still
points to, so its memory grows with the map and the frontier, never with the number of steps.

The loop, as in AIMA's ``best_first_search``, takes two parameters: the *frontier*, which
says which entry comes out next (a FIFO :class:`Queue`, a LIFO :class:`Stack`, or a
:class:`PriorityQueue`), and what was *reached*, which says which successors are pushed and
which entries taken off are thrown away (:class:`Visited`, :class:`Cheapest`,
:class:`Shallowest`, or :class:`OnPath` for tree search)::

    push the root
    while frontier:
        node = frontier.take()
        if reached.discards(node): the step is discarded
        if goal test on expand and node.cell is the goal: found
        for each move in the order:
            skip a cell off the map, blocked or refused by the corner rule
            skip it unless reached.admits(it)
            push the child; if goal test on generate and it is the goal: found

BFS takes the oldest entry, DFS the newest.  Uniform-cost, greedy best-first and A* take the
entry of lowest priority (g, h or g + h; ties in the order pushed).  A move costs its length
(1 straight, sqrt(2) diagonally) times the cost of the cell it enters (1 on a plain map), and
the estimates h are scaled by the map's lowest cell cost; a cell is pushed again whenever it is
reached with a lower g than its best so far (lower by more than ``CHEAPER_BY``, 1e-9: the floats'
rounding is no cheaper path) (even after it was expanded: it is *re-opened*), and an entry taken off
with a g above its cell's best is *stale*: a discarded step.  Tree search keeps no best g: a
successor is skipped only when it is on the node's own path.  The goal is tested on expansion unless
told otherwise.

Iterative deepening runs the same loop on a stack with depth limits 0, 1, 2, ...: a node taken
off at the limit is expanded with no successors, and within an iteration a cell is pushed again
only when reached at a smaller depth than before (tree search: when not on the node's own
path).  It stops with no path when an iteration cuts nothing off at its limit.
"""

from __future__ import annotations

import heapq
import itertools
from array import array
from collections import deque
from collections.abc import Callable, Generator, Iterator
from dataclasses import dataclass
from typing import Protocol

from tui_search.engine.maps.grid import DELTAS, Cell, Grid, move_cost
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.heuristics import CHEAPER_BY, heuristic_for, priority_of
from tui_search.engine.search.outcome import Outcome, cost_of
from tui_search.engine.search.registry import Algorithm
from tui_search.engine.search.registry import Frontier as FrontierKind


@dataclass(eq=False, slots=True)
class Node:
    """A frontier entry: a cell, the entry it was generated from, and the move between."""

    event: int  # generation events are numbered from 0 (the start) in the order pushed
    cell: Cell
    parent: Node | None
    move: str | None  # the direction it was reached by (None for a root)
    depth: int
    g: float = 0.0  # the path's cost from the root: each move's length times its cell's cost

    def path(self) -> list[Cell]:
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

    def on_path(self, cell: Cell) -> bool:
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


INF = float("inf")


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


class PriorityQueue:
    """Uniform-cost, greedy and A*: the lowest priority (g, h or g + h) first, ties in the order
    pushed (a heap of ``(priority, event, node)``: the event number breaks ties)."""

    def __init__(self, priority: Callable[[float, int, int], float]) -> None:
        self.priority = priority
        self.heap: list[tuple[float, int, Node]] = []

    def __len__(self) -> int:
        return len(self.heap)

    def add(self, node: Node) -> None:
        heapq.heappush(self.heap, (self.priority(node.g, *node.cell), node.event, node))

    def take(self) -> Node:
        return heapq.heappop(self.heap)[2]


# -- what was reached: which successors are pushed, which entries taken off are discarded -------
class Reached(Protocol):
    def admits(self, parent: Node, cell: Cell, g: float) -> bool:
        """May ``cell``, reached from ``parent`` with cost ``g``, be pushed?"""
        ...

    def pushed(self, node: Node) -> None: ...

    def discards(self, node: Node) -> bool:
        """Is ``node``, just taken off, thrown away (a discarded step)?"""
        ...


class OnPath:
    """Tree search: no visited set; a cell is skipped only when it lies on the path from the
    root to the node being expanded (that node included).  Nothing is discarded."""

    def admits(self, parent: Node, cell: Cell, g: float) -> bool:
        return not parent.on_path(cell)

    def pushed(self, node: Node) -> None:
        pass

    def discards(self, node: Node) -> bool:
        return False


class Visited:
    """BFS's and DFS's visited set.  Visit on generate: a cell is visited when pushed, so it is
    never pushed twice.  Visit on expand: when taken off and expanded, so a cell may sit on the
    frontier several times, and taking off a cell already expanded is a discarded step."""

    def __init__(self, visit: str) -> None:
        self.on_expand = visit == "expand"
        self.cells: set[Cell] = set()

    def admits(self, parent: Node, cell: Cell, g: float) -> bool:
        return cell not in self.cells

    def pushed(self, node: Node) -> None:
        if not self.on_expand:
            self.cells.add(node.cell)

    def discards(self, node: Node) -> bool:
        if not self.on_expand:
            return False
        if node.cell in self.cells:
            return True
        self.cells.add(node.cell)
        return False


class Cheapest:
    """The priority queue's rule: a cell is pushed again whenever it is reached with a lower g
    than its best so far (lower by more than ``CHEAPER_BY``), even after it was expanded (it
    is re-opened); an entry taken off with a g above its cell's best is stale: discarded."""

    def __init__(self) -> None:
        self.best: dict[Cell, float] = {}

    def admits(self, parent: Node, cell: Cell, g: float) -> bool:
        return g + CHEAPER_BY < self.best.get(cell, INF)

    def pushed(self, node: Node) -> None:
        self.best[node.cell] = node.g

    def discards(self, node: Node) -> bool:
        return node.g > self.best[node.cell]


class Shallowest:
    """Iterative deepening, within one iteration: a cell is pushed again when reached at a
    smaller depth than before.  An entry reached shallower since is still expanded."""

    def __init__(self) -> None:
        self.best: dict[Cell, int] = {}

    def admits(self, parent: Node, cell: Cell, g: float) -> bool:
        return parent.depth + 1 < self.best.get(cell, INF)

    def pushed(self, node: Node) -> None:
        self.best[node.cell] = node.depth

    def discards(self, node: Node) -> bool:
        return False


class ReferenceSearch:
    """Iterate over it for the steps; afterwards ``goal`` is the goal's node or None.

    ``generated`` counts pushes (every iteration's root included), ``expanded`` the steps that
    expanded a node, ``discarded`` the others, ``max_frontier`` the largest frontier size.
    ``goal`` is already set, with no step at all, when the start is the goal and the goal is
    tested on generation.
    """

    def __init__(self, grid: Grid, algorithm: Algorithm, semantics: Semantics) -> None:
        if grid.start is None or grid.goal is None:
            raise ValueError("the map needs a start and a goal")
        semantics.check(algorithm)
        self.grid, self.algorithm, self.semantics = grid, algorithm, semantics
        self._start: Cell = grid.start
        self.goal_test = semantics.goal_test_for(algorithm)
        self.goal: Node | None = None
        self.generated = self.expanded = self.discarded = self.max_frontier = 0
        self.iterations = 0
        # Per cell, a bit per move of the order that is legal from it (-1: not worked out
        # yet): the moves never change during a search, and two bytes a cell keep it small.
        self._legal_bits = array("h", [-1]) * (grid.width * grid.height)
        # A move costs its length (1 straight, sqrt(2) diagonally) times the cost of the cell
        # it enters, to the searches ordered by cost; BFS, DFS and iterative deepening count
        # moves, not costs: their g stays 0.
        self._order = [(move, DELTAS[move], move_cost(move) if algorithm.weighted else 0.0)
                       for move in semantics.order]

    def __iter__(self) -> Iterator[Expansion]:
        if self.algorithm.iterative:
            return self._deepening()
        return self._loop(self._frontier(), self._reached())

    def _frontier(self) -> Frontier:
        if self.algorithm.priority is not None:
            goal = self.grid.goal
            assert goal is not None  # checked in __init__
            heuristic = heuristic_for(self.semantics.heuristic, self.grid.lowest_cost())
            return PriorityQueue(priority_of(self.algorithm.priority, heuristic, goal))
        return Queue() if self.algorithm.frontier is FrontierKind.FIFO else Stack()

    def _reached(self) -> Reached:
        if self.semantics.tree_search:
            return OnPath()
        if self.algorithm.iterative:
            return Shallowest()
        if self.algorithm.priority is not None:
            return Cheapest()
        return Visited(self.semantics.visit)

    # -- moves -------------------------------------------------------------------------------
    def _legal(self, cell: Cell) -> list[tuple[str, Cell, float]]:
        """The legal moves from ``cell`` (``Grid.neighbours``), in order, with their cells and
        costs (the move's length times the cost of the cell it enters)."""
        x, y = cell
        i = y * self.grid.width + x
        bits = self._legal_bits[i]
        if bits < 0:
            legal = {move for move, _ in self.grid.neighbours(
                cell, self.semantics.order, self.semantics.corners)}
            bits = sum(1 << j for j, (move, _, _) in enumerate(self._order) if move in legal)
            self._legal_bits[i] = bits
        enter = self.grid.cost
        return [(move, (x + dx, y + dy), length * enter((x + dx, y + dy)))
                for j, (move, (dx, dy), length) in enumerate(self._order) if bits >> j & 1]

    def _push(self, frontier: Frontier, reached: Reached, cell: Cell, parent: Node | None,
              move: str | None, g: float) -> Node:
        node = Node(self.generated, cell, parent, move, parent.depth + 1 if parent else 0, g)
        self.generated += 1
        frontier.add(node)
        reached.pushed(node)
        self.max_frontier = max(self.max_frontier, len(frontier))
        return node

    def _is_goal_pushed(self, node: Node) -> bool:
        if self.goal_test == "generate" and node.cell == self.grid.goal:
            self.goal = node
            return True
        return False

    # -- the loop ----------------------------------------------------------------------------
    def _loop(self, frontier: Frontier, reached: Reached, limit: int | None = None
              ) -> Generator[Expansion, None, bool]:
        """The generic loop.  With a depth ``limit`` (iterative deepening) a node taken off at
        the limit is expanded with no successors; the loop returns whether one was (a deeper
        search may find more), and False when it found the goal."""
        root = self._push(frontier, reached, self._start, None, None, 0.0)
        if self._is_goal_pushed(root):
            return False
        first_step = self.expanded + self.discarded + 1  # steps are numbered across iterations
        cut_off = False
        while frontier:
            node = frontier.take()
            k = self.expanded + self.discarded + 1
            new_root = root if limit and k == first_step else None  # a new iteration began
            if reached.discards(node):
                self.discarded += 1
                yield Expansion(k, node, (), True, False, len(frontier), limit, new_root)
                continue
            self.expanded += 1
            if self.goal_test == "expand" and node.cell == self.grid.goal:
                self.goal = node
                yield Expansion(k, node, (), False, True, len(frontier), limit, new_root)
                return False
            added = []
            found = False
            if limit is not None and node.depth >= limit:
                cut_off = True  # at the depth limit: expanded with no successors
            else:
                for move, cell, cost in self._legal(node.cell):
                    g = node.g + cost
                    if not reached.admits(node, cell, g):
                        continue
                    child = self._push(frontier, reached, cell, node, move, g)
                    added.append(child)
                    if self._is_goal_pushed(child):
                        found = True
                        break
            yield Expansion(k, node, tuple(added), False, found, len(frontier), limit, new_root)
            if found:
                return False
        return cut_off

    # -- iterative deepening: the loop again and again -----------------------------------------
    def _deepening(self) -> Iterator[Expansion]:
        for limit in itertools.count():
            self.iterations += 1
            cut_off = yield from self._loop(self._frontier(), self._reached(), limit)
            if not cut_off:
                return


def stream(
    grid: Grid,
    algorithm: Algorithm,
    semantics: Semantics,
    max_steps: int,
    on_step: Callable[[Expansion], object] | None = None,
) -> Outcome:
    """Run the reference search to its end, or to ``max_steps`` steps, keeping nothing of the
    steps but what ``on_step`` does with each (the headless trace): memory grows with the map
    and the frontier only.  Give-up rules as a recorded run's: a search still going after
    ``max_steps`` steps gave up, and a goal it would find later is not found."""
    search = ReferenceSearch(grid, algorithm, semantics)
    expanded = discarded = 0
    generated = peak = 1
    gave_up = False
    for step in search:
        if expanded + discarded == max_steps:
            gave_up = True
            break
        if step.discarded:
            discarded += 1
        else:
            expanded += 1
        generated += len(step.successors) + (step.new_root is not None)
        peak = max(peak, step.frontier_size)
        if on_step is not None:
            on_step(step)
    goal = None if gave_up else search.goal
    path = goal.path() if goal else None
    return Outcome(
        algorithm=algorithm.key,
        semantics=semantics.for_algorithm(algorithm),
        path=path,
        moves=goal.moves() if goal else None,
        expanded=expanded,
        discarded=discarded,
        generated=generated,
        max_frontier=peak,
        gave_up=gave_up,
        cost=cost_of(grid, path),
    )


__all__ = ["Expansion", "Node", "ReferenceSearch", "stream"]
