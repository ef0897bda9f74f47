"""Bidirectional search, the reference: a forward search from the start and a backward one
from the goal (:mod:`~tui_search.engine.search.bidirectional.backward`: the moves reversed),
one step each in turn, the forward first (or, ``--turn smaller``, the step of the search whose
frontier is smaller, the forward's on a tie), until they meet.  Part of the specification, as
:mod:`~tui_search.engine.search.reference` is, and streamed as it is by the headless runs.

Each half is the one-directional search's own loop on its own frontier and reached set: BFS's
FIFO queue and visited set (visit on generate) for ``bibfs``; the priority queue of g
(``biucs``) or of f = g + h (``biastar``, h the estimate to the goal forward and to the start
backward) with its best g per cell, re-opened when reached cheaper and a stale entry
discarded, for the cost-ordered ones.  A discarded step takes its turn too.  A path's cost is
its g; BFS's counts moves (each node's depth).

**Meeting is tested on generation.**  Whenever a half pushes a cell (a new one, or one reached
cheaper) that the other half has reached, the two chains through it make a path: its cost is
the cell's g forward plus its g backward, and the best so far is μ (its cell, the *meeting
cell*).  The roots count: the forward search pushing the goal meets the backward root.

**The stopping rule** (``--stop``, :attr:`~tui_search.engine.search.choices.Semantics.stop`):

* ``first-meeting``: stop at the first meeting, after the push that made it (that step
  *found*), and answer its path.  This is the trap: it is not the cheapest path for costs
  (PathFinding.js's bidirectional A*, remade in ``maps/pathfinding-js-28.txt``), nor always
  the fewest moves (bidirectional BFS).
* ``proven``: keep the best meeting μ and stop, before taking an entry off, once no path
  cheaper than μ is left: for ``bibfs`` and ``biucs`` when the two frontiers' smallest g (BFS:
  the depths at the front of the two queues) sum to μ or more; for ``biastar`` by the
  *front-to-end* bound, when the smaller f of either frontier is μ or more
  (max(fmin forward, fmin backward) ≥ μ: with an admissible h, no path through that frontier
  costs less than its fmin).  The answer is μ's path, the cheapest.

Either way the search stops when a frontier is empty: with no meeting, there is no path.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.bidirectional.backward import both_ways
from tui_search.engine.search.choices import STOP_RULES, TURN_RULES, Semantics
from tui_search.engine.search.heuristics import admissible
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.registry import Algorithm
from tui_search.engine.search.rules import (
    INF,
    Cheapest,
    Expansion,
    Node,
    PriorityQueue,
    Queue,
    Visited,
)
from tui_search.engine.search.space import Space
from tui_search.engine.search.state import State, state_text

FORWARD, BACKWARD = "forward", "backward"


class _Half:
    """One direction: its space, frontier, reached set and each cell's best node."""

    def __init__(self, name: str, space: Space, algorithm: Algorithm,
                 semantics: Semantics) -> None:
        self.name, self.space = name, space
        self.queue: Queue | PriorityQueue
        self.reached: Visited | Cheapest
        if algorithm.priority is None:
            self.queue, self.reached = Queue(), Visited("generate")
        else:
            self.queue = PriorityQueue(space.priority(algorithm.priority))
            self.reached = Cheapest(semantics.cost_tolerance)
        self.best: dict[State, Node] = {}

    def smallest(self) -> float:
        """The least priority on the frontier (BFS: the depth at its front)."""
        if isinstance(self.queue, Queue):
            return float(self.queue.entries[0].depth)
        return self.queue.heap[0][0]


class BidirectionalSearch:
    """Iterate over it for the steps (each :class:`Expansion` says its ``direction``);
    afterwards ``meeting`` is the best meeting's two nodes (forward, backward) or None,
    ``mu`` its cost, and ``path``/``moves`` its path.  ``generated``, ``expanded``,
    ``discarded`` and ``max_frontier`` (the two frontiers together) as the reference's."""

    def __init__(self, board: Grid | Graph, algorithm: Algorithm, semantics: Semantics,
                 meet_on_expand: bool = False) -> None:
        """``meet_on_expand``: the classroom slip a trace check looks for, not a rule of the
        app's -- no stop at a push; the search stops when it takes off a cell the other has
        reached (that step adds nothing)."""
        semantics.check(algorithm)
        self.board, self.algorithm, self.semantics = board, algorithm, semantics
        self.meet_on_expand = meet_on_expand
        self.proven = semantics.stop == STOP_RULES[0] and not meet_on_expand
        forward, backward, self.roots = both_ways(board, semantics, algorithm.weighted)
        self.space = forward
        self.forward = _Half(FORWARD, forward, algorithm, semantics)
        self.backward = _Half(BACKWARD, backward, algorithm, semantics)
        self._cost: Callable[[Node], float] = (
            (lambda node: node.g) if algorithm.weighted else (lambda node: float(node.depth)))
        self._tolerance = semantics.cost_tolerance if algorithm.weighted else 0.0
        self.mu = INF
        self.meeting: tuple[Node, Node] | None = None
        self.generated = self.expanded = self.discarded = self.max_frontier = 0
        self.stopped_by = ""  # why it stopped: "meeting", "proven" or "empty"
        self.bound = INF  # the bound that proved μ (proven)

    def _push(self, half: _Half, cell: State, parent: Node | None, move: str | None,
              g: float) -> bool:
        """Push ``cell`` on ``half``; did it meet the other half with a new best μ?"""
        node = Node(self.generated, cell, parent, move, parent.depth + 1 if parent else 0, g)
        self.generated += 1
        half.queue.add(node)
        half.reached.pushed(node)
        half.best[cell] = node
        self.max_frontier = max(self.max_frontier,
                                len(self.forward.queue) + len(self.backward.queue))
        other = self.backward if half is self.forward else self.forward
        met = other.best.get(cell)
        if met is None:
            return False
        total = self._cost(node) + self._cost(met)
        if total + self._tolerance >= self.mu:
            return False
        self.mu = total
        self.meeting = (node, met) if half is self.forward else (met, node)
        return True

    def _done(self) -> bool:
        """Is the search over before its next step (a frontier empty, or μ proven)?"""
        fwd, bwd = self.forward, self.backward
        if not fwd.queue or not bwd.queue:
            self.stopped_by = "empty"
            return True
        if not self.proven or self.meeting is None:
            return False
        if self.algorithm.informed:  # front-to-end: either frontier's fmin
            bound = max(fwd.smallest(), bwd.smallest())
        else:
            bound = fwd.smallest() + bwd.smallest()
        if bound >= self.mu:
            self.stopped_by = "proven"
            self.bound = bound
            return True
        return False

    def _admissible(self) -> bool:
        """Can the heuristic be trusted never to overestimate (the front-to-end bound's
        proof needs it)?  A graph's estimates are the app's checked ones."""
        if not isinstance(self.board, Grid):
            return True
        return admissible(self.semantics.heuristic, self.semantics.order)

    def why(self) -> str:
        """Why it stopped, in a sentence: "both searches reached (7,3): with first-meeting
        this is the path, cost 14.24; nothing proves it the cheapest"."""
        measure = "cost" if self.algorithm.weighted else "moves"
        if self.meeting is None:
            return "a frontier emptied before the two searches met: there is no path"
        cell = state_text(self.meeting[0].cell)
        mu = f"{self.mu:.2f}" if self.algorithm.weighted else f"{self.mu:g}"
        if self.meeting[0].parent is None and self.meeting[1].parent is None:
            return "the start is the goal"
        if self.stopped_by == "meeting":
            return (f"both searches reached {cell}: with first-meeting this is the path, "
                    f"{measure} {mu}; nothing proves it the cheapest")
        if self.stopped_by == "taken":
            return (f"it took off {cell}, which the other search had reached (meeting tested "
                    f"on expansion): this path, {measure} {mu}; nothing proves it the cheapest")
        if self.stopped_by == "empty":
            side = "forward" if not self.forward.queue else "backward"
            return (f"the {side} frontier emptied: the best meeting, {cell}, {measure} {mu}, "
                    "is the cheapest")
        if self.algorithm.informed and not self._admissible():
            return (f"the best meeting, {cell}, {measure} μ = {mu}: a frontier's smallest f is "
                    f"{self.bound:.2f}, μ or more (front-to-end), no proof with "
                    f"{self.semantics.heuristic}, which overestimates here: it may not be the "
                    "cheapest")
        if self.algorithm.informed:
            rule = f"a frontier's smallest f is {self.bound:.2f}, μ or more (front-to-end)"
        else:
            word, bound = (("g", f"{self.bound:.2f}") if self.algorithm.weighted
                           else ("depths", f"{self.bound:g}"))
            rule = f"the two frontiers' smallest {word} sum to {bound}, μ or more"
        return (f"the best meeting, {cell}, {measure} μ = {mu}, is proven the cheapest: "
                f"{rule}")

    def __iter__(self) -> Iterator[Expansion]:
        met = self._push(self.forward, self.space.start, None, None, 0.0)
        for root in self.roots:
            met = self._push(self.backward, root, None, None, 0.0) or met
        if met and not self.proven and not self.meet_on_expand:
            self.stopped_by = "meeting"
            return
        turn = (self.forward, self.backward)
        smaller = self.semantics.turn == TURN_RULES[1]
        k = 0
        while not self._done():
            if smaller:  # the smaller frontier's step; forward on a tie
                half = turn[len(self.forward.queue) > len(self.backward.queue)]
            else:
                half = turn[k % 2]
            k += 1
            node = half.queue.take()
            size = len(self.forward.queue) + len(self.backward.queue)
            if half.reached.discards(node):
                self.discarded += 1
                yield Expansion(k, node, (), True, False, size, direction=half.name)
                continue
            self.expanded += 1
            node = half.reached.taken(node)
            other = self.backward if half is self.forward else self.forward
            if self.meet_on_expand and node.cell in other.best:  # the slip: met on taking off
                met_node = other.best[node.cell]
                self.mu = self._cost(node) + self._cost(met_node)
                self.meeting = (node, met_node) if half is self.forward else (met_node, node)
                self.stopped_by = "taken"
                yield Expansion(k, node, (), False, True, size, direction=half.name)
                return
            added, found = [], False
            for move, cell, cost in half.space.successors(node.cell):
                g = node.g + cost
                if not half.reached.admits(node, cell, g):
                    continue
                met = self._push(half, cell, node, move, g)
                added.append(half.best[cell])
                if met and not self.proven and not self.meet_on_expand:
                    found = True
                    break
            size = len(self.forward.queue) + len(self.backward.queue)
            yield Expansion(k, node, tuple(added), False, found, size, direction=half.name)
            if found:
                self.stopped_by = "meeting"
                return

    @property
    def path(self) -> list[State] | None:
        """Start to goal through the meeting cell (None: they never met)."""
        if self.meeting is None:
            return None
        ahead, behind = self.meeting
        return ahead.path() + behind.path()[::-1][1:]

    @property
    def moves(self) -> list[str] | None:
        if self.meeting is None:
            return None
        ahead, behind = self.meeting
        return ahead.moves() + behind.moves()[::-1]


def stream_bidirectional(board: Grid | Graph, algorithm: Algorithm, semantics: Semantics,
                         max_steps: int, on_step: Callable[[Expansion], object] | None = None
                         ) -> Outcome:
    """:func:`~tui_search.engine.search.reference.stream` of a bidirectional search: run to
    its end or to ``max_steps`` steps (then it gave up, and a meeting is no answer)."""
    search = BidirectionalSearch(board, algorithm, semantics)
    expanded = discarded = 0
    generated = peak = 1 + len(search.roots)
    gave_up = False
    for step in search:
        if expanded + discarded == max_steps:
            gave_up = True
            break
        if step.discarded:
            discarded += 1
        else:
            expanded += 1
        generated += len(step.successors)
        peak = max(peak, step.frontier_size)
        if on_step is not None:
            on_step(step)
    if not gave_up:  # the counts of a whole search: every push, the largest frontiers
        generated, peak = search.generated, search.max_frontier
    path = None if gave_up else search.path
    moves = None if gave_up else search.moves
    return Outcome(
        algorithm=algorithm.key,
        semantics=semantics.for_algorithm(algorithm),
        path=path,
        moves=moves,
        expanded=expanded,
        discarded=discarded,
        generated=generated,
        max_frontier=peak,
        gave_up=gave_up,
        cost=search.space.path_cost(path),
        stopped="" if gave_up else search.why(),
        meeting=None if gave_up or search.meeting is None else search.meeting[0].cell,
    )


__all__ = ["BACKWARD", "FORWARD", "BidirectionalSearch", "stream_bidirectional"]
