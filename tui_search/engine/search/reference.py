"""The reference search: one generic loop, written for clarity, for every algorithm and choice.

This is the definition of what a search does here.  The recorded runs use faster loops
(:mod:`tui_search.engine.search.loops`), and a hypothesis test holds each of them equal to this one,
step by step, over random maps and random choices.  The headless command line streams this loop:
it keeps only the frontier, the visited cells and the chains of parents the frontier still
points to, so its memory grows with the map and the frontier, never with the number of steps.

The loop, as in AIMA's ``best_first_search``, takes two parameters
(:mod:`~tui_search.engine.search.rules`): the *frontier*, which says which entry comes out next
(a FIFO ``Queue``, a LIFO ``Stack``, a ``CallStack`` for recursion, or a ``PriorityQueue``), and
what was *reached*, which says which successors are pushed and which entries taken off are
thrown away (``Visited``, ``Cheapest``, ``Shallowest``, or ``OnPath`` for tree search)::

    push the root
    while frontier:
        node = frontier.take()
        if reached.discards(node): the step is discarded
        node = reached.taken(node): the node expanded (a closed set's: its cell's best g)
        if goal test on expand and node.cell is the goal: found
        for each move in the order:
            skip a cell off the map, blocked or refused by the corner rule
            skip it unless reached.admits(it)
            push the child; if goal test on generate and it is the goal: found

BFS takes the oldest entry, DFS the newest.  Uniform-cost, greedy best-first and A* take the
entry of lowest priority (g, h or g + h); a tie goes by the tie rule (the oldest, the newest, the
smallest cell, the lower or higher h or g), then to the oldest.  A move costs its length
(1 straight, sqrt(2) diagonally) times the cost of the cell it enters (1 on a plain map), and
the estimates h are scaled by the map's lowest cell cost; a cell is pushed again whenever it is
reached with a lower g than its best so far, lower by more than the cost tolerance (by default
``CHEAPER_BY``, 1e-9: the floats' rounding is no cheaper path; 0: compared exactly), even after
it was expanded (it is *re-opened*), and an entry taken off with a g above its cell's best is
*stale*: a discarded step -- unless re-opening is off (a closed set, as published code keeps
one): a cell expanded is never pushed again, an entry of it taken off later is discarded, and
the first entry of a cell taken off is expanded at the cell's best g so far.  Tree search keeps
no best g: a successor is skipped only when it is on the node's own path, or with no path check
never.  With the start
left unmarked (``mark_start`` off) the visited set, the best g or the best depth does not
record the start, so a neighbour may push it again.

Visit on expand takes off a cell already visited as a discarded step; visit on expand, expanded
again, expands it again (the node taken off is never checked).  A recursive DFS (``recursive``)
runs on a ``CallStack``, a cell visited when entered (taken off): its *neighbours* form lists on
each line the neighbours not yet visited, and the recursion skips those visited meanwhile (the
discarded steps); its *calls* form is defined from that one by
:mod:`~tui_search.engine.search.recursion`.

Iterative deepening runs the same loop on a stack (recursive: a call stack) with depth limits 0,
1, 2, ...: a node taken off at the limit is expanded with no successors, and within an
iteration a cell is pushed again only when reached at a smaller depth than before (tree search:
when not on the node's own path).  It stops with no path when an iteration cuts nothing off at
its limit.

IDA* runs it on a stack with limits on f = g + h (weighted: g + W·h) instead, from the start's
f up: a node taken off with f over the limit (by more than the cost tolerance) is *cut off*, a
step with no successors and no goal test, and the smallest f cut off in an iteration is the
next one's limit.  Within an iteration a cell is pushed again only when reached with a lower g
than before (tree search: when not on the node's own path); the goal is tested when taken off
within the limit.  It stops with no path when an iteration cuts nothing off.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Generator, Iterator

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.registry import Algorithm
from tui_search.engine.search.registry import Frontier as FrontierKind
from tui_search.engine.search.rules import (
    INF,
    CallStack,
    Cheaper,
    Cheapest,
    Expansion,
    Frontier,
    Node,
    OnPath,
    PriorityQueue,
    Queue,
    Reached,
    Shallowest,
    Stack,
    Visited,
    tie_key,
)
from tui_search.engine.search.space import space_of
from tui_search.engine.search.state import State


class ReferenceSearch:
    """Iterate over it for the steps; afterwards ``goal`` is the goal's node or None.

    ``generated`` counts pushes (every iteration's root included), ``expanded`` the steps that
    expanded a node, ``discarded`` the others, ``max_frontier`` the largest frontier size.
    ``goal`` is already set, with no step at all, when the start is the goal and the goal is
    tested on generation.
    """

    def __init__(self, board: Grid | Graph, algorithm: Algorithm, semantics: Semantics,
                 max_steps: int | None = None) -> None:
        """Search ``board``, a grid or a graph (:func:`~tui_search.engine.search.space.
        space_of`).  ``max_steps``: where a run of it stops, for a recursion's calls form,
        whose lines list the calls made by then (:func:`~tui_search.engine.search.recursion.
        calls_form`; at most its ``MAX_HELD``, which it holds in memory)."""
        semantics.check(algorithm)
        self.space = space_of(board, semantics, algorithm.weighted)
        self.grid, self.algorithm, self.semantics = board, algorithm, semantics
        self._start: State = self.space.start
        self.goal_test = semantics.goal_test_for(algorithm)
        # The calls form of a recursion: its neighbours form, the goal tested when entered
        # (:mod:`~tui_search.engine.search.recursion`).
        self._calls = semantics.recursive == "calls"
        self._max_steps = max_steps
        if self._calls:
            self.goal_test = "expand"
        self.goal: Node | None = None
        self.generated = self.expanded = self.discarded = self.max_frontier = 0
        self.iterations = 0
        self.next_limit = INF  # IDA*: the last iteration's smallest f cut off

    def __iter__(self) -> Iterator[Expansion]:
        steps: Iterator[Expansion]
        if self.algorithm.contours:
            steps = self._contours()
        elif self.algorithm.iterative:
            steps = self._deepening()
        else:
            steps = self._loop(self._frontier(), self._reached())
        if self._calls:
            from tui_search.engine.search.recursion import MAX_HELD, calls_form

            goal_line = self.semantics.goal_test_for(self.algorithm) == "expand"
            held = min(self._max_steps or MAX_HELD, MAX_HELD)
            return calls_form(self, steps, goal_line, held)
        return steps

    def _frontier(self) -> Frontier:
        sem = self.semantics
        if self.algorithm.priority is not None and self.algorithm.queued:
            return PriorityQueue(self.space.priority(self.algorithm.priority),
                                 tie_key(sem.ties, lambda state: self.space.estimate()(state)))
        if sem.recursive:
            return CallStack()
        return Queue() if self.algorithm.frontier is FrontierKind.FIFO else Stack()

    def _reached(self) -> Reached:
        sem = self.semantics
        if sem.tree_search:
            return OnPath(sem.path_check)
        if self.algorithm.contours:
            return Cheaper(sem.cost_tolerance, sem.mark_start)
        if self.algorithm.iterative:
            return Shallowest(sem.mark_start)
        if self.algorithm.priority is not None:
            return Cheapest(sem.cost_tolerance, sem.reopen, sem.mark_start)
        return Visited("expand" if sem.recursive else sem.visit, sem.mark_start)

    def _push(self, frontier: Frontier, reached: Reached, cell: State, parent: Node | None,
              move: str | None, g: float) -> Node:
        node = Node(self.generated, cell, parent, move, parent.depth + 1 if parent else 0, g)
        self.generated += 1
        frontier.add(node)
        reached.pushed(node)
        self.max_frontier = max(self.max_frontier, len(frontier))
        return node

    def _is_goal_pushed(self, node: Node) -> bool:
        if self.goal_test == "generate" and self.space.is_goal(node.cell):
            self.goal = node
            return True
        return False

    # -- the loop ----------------------------------------------------------------------------
    def _loop(self, frontier: Frontier, reached: Reached, limit: int | None = None,
              f_limit: float | None = None) -> Generator[Expansion, None, bool]:
        """The generic loop.  With a depth ``limit`` (iterative deepening) a node taken off at
        the limit is expanded with no successors; with an ``f_limit`` (IDA*) a node taken off
        with f over it is, before its goal test, and ``next_limit`` keeps the smallest such f.
        The loop returns whether a node was cut off (a deeper search may find more), and False
        when it found the goal."""
        root = self._push(frontier, reached, self._start, None, None, 0.0)
        if self._is_goal_pushed(root):
            return False
        first_step = self.expanded + self.discarded + 1  # steps are numbered across iterations
        cut_off = False
        iterating = limit is not None or f_limit is not None
        over = INF  # IDA*: the smallest f cut off so far
        f = self.space.priority("g+h") if f_limit is not None else None
        while frontier:
            node = frontier.take()
            k = self.expanded + self.discarded + 1
            # a new iteration began (not the first)
            new_root = root if iterating and k == first_step and self.iterations > 1 else None
            if reached.discards(node):
                self.discarded += 1
                yield Expansion(k, node, (), True, False, len(frontier), limit, new_root)
                continue
            self.expanded += 1
            node = reached.taken(node)
            if f is not None and f_limit is not None:
                node_f = f(node.g, node.cell)
                if node_f > f_limit + self.semantics.cost_tolerance:  # over: cut off
                    over = min(over, node_f)
                    yield Expansion(k, node, (), False, False, len(frontier), None, new_root,
                                    f_limit, over)
                    continue
            if self.goal_test == "expand" and self.space.is_goal(node.cell):
                self.goal = node
                yield Expansion(k, node, (), False, True, len(frontier), limit, new_root,
                                f_limit, over)
                return False
            added = []
            found = False
            if limit is not None and node.depth >= limit:
                cut_off = True  # at the depth limit: expanded with no successors
            else:
                for move, cell, cost in self.space.successors(node.cell):
                    g = node.g + cost
                    if not reached.admits(node, cell, g):
                        continue
                    child = self._push(frontier, reached, cell, node, move, g)
                    added.append(child)
                    if self._is_goal_pushed(child):
                        found = True
                        break
            yield Expansion(k, node, tuple(added), False, found, len(frontier), limit, new_root,
                            f_limit, over)
            if found:
                return False
        self.next_limit = over
        return cut_off or over < INF

    # -- iterative deepening: the loop again and again -----------------------------------------
    def _deepening(self) -> Iterator[Expansion]:
        for limit in itertools.count():
            self.iterations += 1
            cut_off = yield from self._loop(self._frontier(), self._reached(), limit)
            if not cut_off:
                return

    # -- IDA*: the loop again and again, on limits of f ------------------------------------------
    def _contours(self) -> Iterator[Expansion]:
        f_limit = self.space.priority("g+h")(0.0, self._start)
        while True:
            self.iterations += 1
            cut_off = yield from self._loop(self._frontier(), self._reached(), None, f_limit)
            if not cut_off:
                return
            f_limit = self.next_limit


def stream(
    grid: Grid | Graph,
    algorithm: Algorithm,
    semantics: Semantics,
    max_steps: int,
    on_step: Callable[[Expansion], object] | None = None,
) -> Outcome:
    """Run the reference search to its end, or to ``max_steps`` steps, keeping nothing of the
    steps but what ``on_step`` does with each (the headless trace): memory grows with the map
    and the frontier only (a bidirectional search: its own loop,
    :mod:`~tui_search.engine.search.bidirectional.loop`).  Give-up rules as a recorded run's: a
    search still going after ``max_steps`` steps gave up, and a goal it would find later is
    not found."""
    if algorithm.bidirectional:
        from tui_search.engine.search.bidirectional.loop import stream_bidirectional

        return stream_bidirectional(grid, algorithm, semantics, max_steps, on_step)
    if semantics.recursive == "calls":
        from tui_search.engine.search.recursion import MAX_HELD

        max_steps = min(max_steps, MAX_HELD)
    search = ReferenceSearch(grid, algorithm, semantics, max_steps)
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
        cost=search.space.path_cost(path),
    )


__all__ = ["Expansion", "Node", "ReferenceSearch", "stream"]
