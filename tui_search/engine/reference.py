"""The reference search: one generic loop, written for clarity, for every algorithm and choice.

This is the definition of what a search does here.  The recorded runs use faster loops
(:mod:`tui_search.engine.search`), and a hypothesis test holds each of them equal to this one,
step by step, over random maps and random choices.  The headless command line streams this loop:
it keeps only the frontier, the visited cells and the chains of parents the frontier still
points to, so its memory grows with the map and the frontier, never with the number of steps.

The loop, as in AIMA's ``best_first_search`` with the frontier as a parameter::

    frontier = [root]
    while frontier:
        node = take(frontier)          # the oldest (FIFO queue) or the newest (LIFO stack)
        if visit on expand and node.cell was expanded: the step is discarded
        if goal test on expand and node.cell is the goal: found
        for each move in the order:
            skip a cell off the map, blocked, refused by the corner rule, or visited
            (tree search: on the path from the root to this node)
            push the child; if goal test on generate and it is the goal: found

Uniform-cost, greedy best-first and A* take the entry of lowest priority (g, h or g + h; ties
in the order pushed) from a priority queue.  A move costs 1 straight and sqrt(2) diagonally; a
cell is pushed again whenever it is reached with a lower g than its best so far (lower by
more than ``CHEAPER_BY``, 1e-9: the floats' rounding is no cheaper path) (even after it
was expanded: it is *re-opened*), and an entry taken off with a g above its cell's best is
*stale*: a discarded step.  Tree search keeps no best g: a successor is skipped only when it is
on the node's own path.  The goal is tested on expansion unless told otherwise.

Iterative deepening runs a depth-limited DFS with limits 0, 1, 2, ...: a node taken off at the
limit is expanded with no successors, and within an iteration a cell is pushed again only when
reached at a smaller depth than before (tree search: when not on the node's own path).  It stops
with no path when an iteration cuts nothing off at its limit.
"""

from __future__ import annotations

import heapq
from array import array
from collections import deque
from collections.abc import Callable, Iterator
from dataclasses import dataclass

from tui_search.engine.algorithms import Algorithm, Frontier
from tui_search.engine.grid import DELTAS, Cell, Grid, move_cost
from tui_search.engine.heuristics import CHEAPER_BY, HEURISTICS, priority_of
from tui_search.engine.outcome import Outcome
from tui_search.engine.semantics import Semantics


@dataclass(eq=False, slots=True)
class Node:
    """A frontier entry: a cell, the entry it was generated from, and the move between."""

    event: int  # generation events are numbered from 0 (the start) in the order pushed
    cell: Cell
    parent: Node | None
    move: str | None  # the direction it was reached by (None for a root)
    depth: int
    g: float = 0.0  # the path's cost from the root: 1 a straight move, sqrt(2) a diagonal

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
        self.goal_test = semantics.goal_test_for(algorithm)
        self.goal: Node | None = None
        self.generated = self.expanded = self.discarded = self.max_frontier = 0
        self.iterations = 0
        # Per cell, a bit per move of the order that is legal from it (-1: not worked out
        # yet): the moves never change during a search, and two bytes a cell keep it small.
        self._legal_bits = array("h", [-1]) * (grid.width * grid.height)
        self._order = [(move, DELTAS[move]) for move in semantics.order]

    def __iter__(self) -> Iterator[Expansion]:
        if self.algorithm.iterative:
            return self._deepening()
        if self.algorithm.priority is not None:
            return self._best_first(self.algorithm.priority)
        return self._search()

    # -- moves -------------------------------------------------------------------------------
    def _legal(self, cell: Cell) -> list[tuple[str, Cell]]:
        """The legal moves from ``cell`` (``Grid.neighbours``), in order, with their cells."""
        x, y = cell
        i = y * self.grid.width + x
        bits = self._legal_bits[i]
        if bits < 0:
            legal = {move for move, _ in self.grid.neighbours(
                cell, self.semantics.order, self.semantics.corners)}
            bits = sum(1 << j for j, (move, _) in enumerate(self._order) if move in legal)
            self._legal_bits[i] = bits
        return [(move, (x + dx, y + dy)) for j, (move, (dx, dy)) in enumerate(self._order)
                if bits >> j & 1]

    def _push(self, frontier: list[Node] | deque[Node], cell: Cell, parent: Node | None,
              move: str | None) -> Node:
        node = Node(self.generated, cell, parent, move, parent.depth + 1 if parent else 0)
        self.generated += 1
        frontier.append(node)
        self.max_frontier = max(self.max_frontier, len(frontier))
        return node

    def _is_goal_pushed(self, node: Node) -> bool:
        if self.goal_test == "generate" and node.cell == self.grid.goal:
            self.goal = node
            return True
        return False

    # -- BFS and DFS ---------------------------------------------------------------------------
    def _search(self) -> Iterator[Expansion]:
        sem = self.semantics
        fifo = self.algorithm.frontier is Frontier.FIFO
        frontier: deque[Node] | list[Node] = deque() if fifo else []
        take = frontier.popleft if isinstance(frontier, deque) else frontier.pop
        graph = not sem.tree_search
        visited: set[Cell] = set()  # pushed (visit on generate) or expanded (visit on expand)
        root = self._push(frontier, self.grid.start, None, None)  # type: ignore[arg-type]
        if graph and sem.visit == "generate":
            visited.add(root.cell)
        if self._is_goal_pushed(root):
            return
        k = 0
        while frontier:
            node = take()
            k += 1
            if graph and sem.visit == "expand":
                if node.cell in visited:
                    self.discarded += 1
                    yield Expansion(k, node, (), True, False, len(frontier))
                    continue
                visited.add(node.cell)
            self.expanded += 1
            if self.goal_test == "expand" and node.cell == self.grid.goal:
                self.goal = node
                yield Expansion(k, node, (), False, True, len(frontier))
                return
            added = []
            found = False
            for move, cell in self._legal(node.cell):
                if not graph:
                    if node.on_path(cell):
                        continue
                elif cell in visited:
                    continue
                elif sem.visit == "generate":
                    visited.add(cell)
                child = self._push(frontier, cell, node, move)
                added.append(child)
                if self._is_goal_pushed(child):
                    found = True
                    break
            yield Expansion(k, node, tuple(added), False, found, len(frontier))
            if found:
                return

    # -- uniform-cost, greedy best-first and A* ----------------------------------------------
    def _best_first(self, order: str) -> Iterator[Expansion]:
        graph = not self.semantics.tree_search
        goal = self.grid.goal
        assert goal is not None  # checked in __init__
        priority = priority_of(order, HEURISTICS[self.semantics.heuristic], goal)
        queue: list[tuple[float, int, Node]] = []  # (priority, event, node): ties oldest first
        best: dict[Cell, float] = {}  # graph search: the lowest g each cell was reached with

        def push(cell: Cell, parent: Node | None, move: str | None, g: float) -> Node:
            node = Node(self.generated, cell, parent, move, parent.depth + 1 if parent else 0, g)
            self.generated += 1
            heapq.heappush(queue, (priority(g, *cell), node.event, node))
            self.max_frontier = max(self.max_frontier, len(queue))
            best[cell] = g
            return node

        root = push(self.grid.start, None, None, 0.0)  # type: ignore[arg-type]
        if self._is_goal_pushed(root):
            return
        k = 0
        while queue:
            node = heapq.heappop(queue)[2]
            k += 1
            if graph and node.g > best[node.cell]:  # stale: its cell was reached cheaper since
                self.discarded += 1
                yield Expansion(k, node, (), True, False, len(queue))
                continue
            self.expanded += 1
            if self.goal_test == "expand" and node.cell == self.grid.goal:
                self.goal = node
                yield Expansion(k, node, (), False, True, len(queue))
                return
            added = []
            found = False
            for move, cell in self._legal(node.cell):
                g = node.g + move_cost(move)
                if graph:
                    if g + CHEAPER_BY >= best.get(cell, INF):
                        continue
                elif node.on_path(cell):
                    continue
                child = push(cell, node, move, g)
                added.append(child)
                if self._is_goal_pushed(child):
                    found = True
                    break
            yield Expansion(k, node, tuple(added), False, found, len(queue))
            if found:
                return

    # -- iterative deepening -------------------------------------------------------------------
    def _deepening(self) -> Iterator[Expansion]:
        sem = self.semantics
        k, limit = 0, 0
        while True:
            self.iterations += 1
            stack: list[Node] = []
            root = self._push(stack, self.grid.start, None, None)  # type: ignore[arg-type]
            if self._is_goal_pushed(root):
                return
            best = {root.cell: 0}  # the smallest depth each cell was reached at, this iteration
            cut_off = False
            new_root: Node | None = root if limit else None
            while stack:
                node = stack.pop()
                k += 1
                self.expanded += 1
                if self.goal_test == "expand" and node.cell == self.grid.goal:
                    self.goal = node
                    yield Expansion(k, node, (), False, True, len(stack), limit, new_root)
                    return
                added = []
                found = False
                if node.depth >= limit:
                    cut_off = True
                else:
                    depth = node.depth + 1
                    for move, cell in self._legal(node.cell):
                        if sem.tree_search:
                            if node.on_path(cell):
                                continue
                        elif best.get(cell, limit + 1) <= depth:
                            continue
                        best[cell] = depth
                        child = self._push(stack, cell, node, move)
                        added.append(child)
                        if self._is_goal_pushed(child):
                            found = True
                            break
                yield Expansion(k, node, tuple(added), False, found, len(stack), limit, new_root)
                new_root = None
                if found:
                    return
            if not cut_off:
                return
            limit += 1




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
    return Outcome(
        algorithm=algorithm.key,
        semantics=semantics.for_algorithm(algorithm),
        path=goal.path() if goal else None,
        moves=goal.moves() if goal else None,
        expanded=expanded,
        discarded=discarded,
        generated=generated,
        max_frontier=peak,
        gave_up=gave_up,
    )


__all__ = ["Expansion", "Node", "ReferenceSearch", "stream"]
