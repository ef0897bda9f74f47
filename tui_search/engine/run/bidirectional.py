"""A bidirectional search as a run (:class:`BiRun`): the reference loop
(:mod:`~tui_search.engine.search.bidirectional.loop`) recorded step by step into two runs of
its own, one a direction, and one position over both.

Each half is a :class:`~tui_search.engine.run.recorded.Run` like any other -- its frontier,
its tree, what each cell is -- whose record is filled from the reference's steps in its
direction (a :class:`~tui_search.engine.run.recording.Source`) under the one-directional
search it runs (BFS for ``bibfs``, UCS for ``biucs``, A* for ``biastar``): so every query the
app asks of a run answers for either half.  The backward half searches a copy of the board
with its start and goal swapped (a graph's roads reversed; on a grid a move's cost is that
of the cell it *leaves*, :attr:`Source.reverse`), from the goal to the start.

The position is the number of steps taken by both, in the order taken: step ``k`` is the
``forward_steps(k)``-th of the forward half or the rest of the backward half's.  After each
step the best meeting so far (its cell and its cost μ) is kept, for the map's mark and the
narration; the answer is the reference's (its path through the best meeting, and why it
stopped).
"""

from __future__ import annotations

from array import array
from collections import deque
from collections.abc import Iterator
from typing import TYPE_CHECKING

from tui_search.engine.maps.graph import Edge, Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import MAX_STEPS, OnBoard, Run, Source
from tui_search.engine.search.bidirectional.loop import FORWARD, BidirectionalSearch
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.record import CHUNK, Record
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.rules import INF, Expansion
from tui_search.engine.search.state import State

if TYPE_CHECKING:
    from tui_search.engine.search.graph_problem import GraphProblem
    from tui_search.engine.search.problem import Problem


def one_way(key: str) -> str:
    """The one-directional search each half of bidirectional ``key`` runs: ``biastar``'s A*."""
    return key[2:]


def app_refusal(board: Grid | Graph) -> str:
    """Why the app cannot show a bidirectional search of ``board`` ("" when it can): its
    backward half has one root, the goal (headless runs search from several)."""
    if isinstance(board, Graph) and len(board.goals) > 1:
        return (f"{board.name} has {len(board.goals)} goals: the app shows a bidirectional "
                "search from one (run it with --headless, or keep one goal)")
    return ""


def _reversed(board: Grid | Graph) -> Grid | Graph:
    """``board`` to be searched from its goal: start and goal swapped (a graph's roads
    reversed)."""
    if isinstance(board, Grid):
        back = board.copy()
        back.start, back.goal = board.goal, board.start
        return back
    edges = [Edge(e.b, e.a, e.cost, e.directed, e.line) if e.directed else e
             for e in board.edges]
    return Graph.of(list(board.names), edges, places=board.places,
                    start=board.goals[0] if board.goals else None,
                    goals=(board.start,) if board.start is not None else (),
                    closed=board.closed, name=board.name)


class _Driver:
    """The reference run step by step on demand, each step handed to its half's queue."""

    def __init__(self, board: Grid | Graph, key: str, semantics: Semantics,
                 max_steps: int) -> None:
        self.search = BidirectionalSearch(board, get_algorithm(key), semantics)
        self._steps: Iterator[Expansion] = iter(self.search)
        self.max_steps = max_steps
        self.backward = bytearray()  # step k's direction at k - 1: 1 backward
        self.forward_upto = array("i", [0])  # forward steps among steps 1 .. k
        self.pending: tuple[deque[Expansion], deque[Expansion]] = (deque(), deque())
        #: After each step (index 0: the roots pushed), the best meeting: cost and cell.
        self.mu: list[float] = [INF]
        self.meeting: list[State | None] = [None]
        #: The largest frontiers (the two together) by the end of each step.
        self.peak = array("i", [1 + len(self.search.roots)])
        self.over = self.gave_up = False

    @property
    def steps(self) -> int:
        return len(self.backward)

    def pull(self) -> bool:
        """Take the reference's next step; False once it has stopped (or given up)."""
        if self.over:
            return False
        if self.steps == self.max_steps:
            self.over = self.gave_up = True
            return False
        step = next(self._steps, None)
        if step is None:
            self.over = True
            if self.steps == 0:  # the roots alone: met at once, or nothing to search
                self._note_meeting(0)
            return False
        back = step.direction != FORWARD
        self.backward.append(back)
        self.forward_upto.append(self.forward_upto[-1] + (not back))
        self.pending[back].append(step)
        self.peak.append(max(self.peak[-1], step.frontier_size))
        self.mu.append(0.0)
        self.meeting.append(None)
        self._note_meeting(self.steps)  # the best meeting after this step
        return True

    def _note_meeting(self, k: int) -> None:
        meeting = self.search.meeting
        self.mu[k] = self.search.mu
        self.meeting[k] = None if meeting is None else meeting[0].cell

    def upto(self, k: int) -> None:
        """Pull until ``k`` steps are taken or the search stops."""
        while self.steps < k and self.pull():
            pass


class _Half:
    """What a half's loop writes: the reference's nodes' events in its record."""

    def __init__(self, driver: _Driver, back: bool) -> None:
        self.driver, self.back = driver, back
        self.event: dict[int, int] = {}  # a reference node's number -> this half's event

    def loop(self, problem: Problem | GraphProblem, rec: Record, chunk: int = CHUNK
             ) -> Iterator[int]:
        driver, event = self.driver, self.event
        pad, gen_node, step_end = problem.pad, rec.gen_node, rec.step_end
        rec.step_exp = step_exp = array("i", [-1])
        costed = driver.search.algorithm.weighted
        step_g = rec.step_g = array("d", [0.0]) if costed else None
        half = driver.search.backward if self.back else driver.search.forward
        root = half.space.start
        event[0 if not self.back else 1] = 0
        gen_node.append(pad(root))
        queue = driver.pending[self.back]
        k = 0
        while True:
            while not queue and driver.pull():
                pass
            if not queue:
                break
            step = queue.popleft()
            k += 1
            step_exp.append(event[step.node.event])
            if step_g is not None:
                step_g.append(step.node.g)
            if step.discarded:
                rec.discarded.append(k)
            for node in step.successors:
                event[node.event] = len(gen_node)
                gen_node.append(pad(node.cell))
            step_end.append(len(gen_node))
            if k % chunk == 0:
                yield k
        rec.gave_up = driver.gave_up
        rec.done = True


class BiRun(OnBoard):
    """A bidirectional search recorded as its two halves (:attr:`halves`: forward, backward),
    with a position over both.  Its names, as a run's where they mean the same: ``board``,
    ``grid``, ``graph``, ``algorithm``, ``algo``, ``semantics``, ``max_steps``,
    ``known_lowest``; ``advance``, ``advance_some``, ``done``, ``found``, ``gave_up``,
    ``recorded``, ``total``; ``k``, ``goto``, ``forward``, ``backward``, ``reset``,
    ``at_end``; ``path``, ``moves``, ``path_cost``, ``outcome``.  Its own: ``direction``
    (of a step), ``half_steps``, ``meeting``, ``mu``, ``why``."""

    def __init__(self, board: Grid | Graph, algorithm: str,
                 semantics: Semantics = DEFAULT_SEMANTICS, max_steps: int = MAX_STEPS) -> None:
        self.algo = algo = get_algorithm(algorithm)
        if not algo.bidirectional:
            raise ValueError(f"{algo.short} is not a bidirectional search")
        refusal = app_refusal(board)
        if refusal:
            raise ValueError(refusal)
        semantics = semantics.fitted(algo)
        semantics.check(algo)
        self.board = board.copy()
        self.algorithm, self.semantics, self.max_steps = algo.key, semantics, max_steps
        self.known_lowest: float | None = None
        self._driver = driver = _Driver(self.board, algo.key, semantics, max_steps)
        half_algo = get_algorithm(one_way(algo.key))
        half_sem = semantics.fitted(half_algo)
        halves = []
        for back, half_board in ((False, self.board), (True, _reversed(self.board))):
            source = Source(half_algo, _Half(driver, back).loop, reverse=back)
            halves.append(Run(half_board, half_algo.key, half_sem, max_steps, source))
        #: The forward half and the backward half, each a run of its own.
        self.halves: tuple[Run, Run] = (halves[0], halves[1])
        self._k = 0
        self._path: list[State] | None = None  # once found: the answer never changes

    # -- what it searches ------------------------------------------------------------------
    @property
    def grid(self) -> Grid:
        assert isinstance(self.board, Grid), "a run on a graph has no grid"
        return self.board

    # -- how much is recorded --------------------------------------------------------------
    def advance(self, until_step: int | None = None) -> bool:
        """Record at least up to ``until_step`` (all of it when None); True once done."""
        self._driver.upto(self.max_steps if until_step is None else until_step)
        return self.done

    def advance_some(self) -> bool:
        """Record one more chunk; True when done."""
        self._driver.upto(self._driver.steps + CHUNK)
        return self.done

    @property
    def done(self) -> bool:
        return self._driver.over

    @property
    def gave_up(self) -> bool:
        return self._driver.gave_up

    @property
    def found(self) -> bool:
        """Did the searches meet (known once it is recorded whole)?"""
        return self.done and not self.gave_up and self._driver.search.meeting is not None

    @property
    def recorded(self) -> int:
        return self._driver.steps

    @property
    def total(self) -> int | None:
        return self._driver.steps if self.done else None

    # -- the position ----------------------------------------------------------------------
    @property
    def k(self) -> int:
        return self._k

    def half_steps(self, k: int) -> tuple[int, int]:
        """The forward and backward halves' steps among steps 1 .. ``k`` (recorded)."""
        ahead = self._driver.forward_upto[k]
        return ahead, k - ahead

    def direction(self, k: int) -> str:
        """``"forward"`` or ``"backward"``: which half took step ``k`` (k >= 1, recorded)."""
        return "backward" if self._driver.backward[k - 1] else FORWARD

    def goto(self, k: int) -> None:
        """Move both halves to step ``k`` (clamped to the run), recording as needed."""
        self._driver.upto(max(0, k))
        self._k = k = max(0, min(k, self._driver.steps))
        ahead, behind = self.half_steps(k)
        self.halves[0].goto(ahead)
        self.halves[1].goto(behind)

    def forward(self) -> bool:
        """One step forwards (the half whose turn it is); False at the end."""
        self._driver.upto(self._k + 1)
        if self._k >= self._driver.steps:
            return False
        self._k += 1
        self.halves[self._driver.backward[self._k - 1]].forward()
        return True

    def backward(self) -> bool:
        """One step backwards; False at step 0."""
        if not self._k:
            return False
        self.halves[self._driver.backward[self._k - 1]].backward()
        self._k -= 1
        return True

    def reset(self) -> None:
        self.goto(0)

    #: A jump longer than this is a seek's (the halves rebuild in bulk as a run's do).
    REBUILD_AFTER = Run.REBUILD_AFTER

    def rebuild_pieces(self, k: int) -> Iterator[float]:
        """Move to step ``k`` (each half rebuilds in bulk as a run does), in one piece: the
        halves never stand at two positions."""
        self.goto(k)
        return iter(())

    def current_node(self) -> State | None:
        """The node expanded by the step just taken (None at step 0)."""
        if not self._k:
            return None
        return self.halves[self._driver.backward[self._k - 1]].now.current_node()

    def next_direction(self) -> str | None:
        """Whose turn is the next step (None: the search is over)."""
        self._driver.upto(self._k + 1)
        return self.direction(self._k + 1) if self._k < self._driver.steps else None

    @property
    def at_end(self) -> bool:
        return self.done and self._k == self._driver.steps

    # -- the meeting and the answer ----------------------------------------------------------
    def meeting(self, k: int | None = None) -> State | None:
        """The best meeting's cell after step ``k`` (the position's by default; None: the
        searches have not met)."""
        return self._driver.meeting[self._k if k is None else k]

    def mu(self, k: int | None = None) -> float:
        """The best meeting's cost μ after step ``k`` (inf: not met): moves for BiBFS."""
        return self._driver.mu[self._k if k is None else k]

    def why(self) -> str:
        """Why it stopped, in a sentence (once recorded whole; "" before, or given up)."""
        if not self.done or self.gave_up:
            return ""
        return self._driver.search.why()

    def path(self) -> list[State] | None:
        """Start to goal through the meeting (None until recorded whole, or not met):
        walked once, the search being over (the map asks it for every line it draws)."""
        if not self.found:
            return None
        if self._path is None:
            self._path = self._driver.search.path
        return self._path

    def moves(self) -> list[str] | None:
        return self._driver.search.moves if self.found else None

    def path_cost(self) -> float:
        """The path's cost (0.0 until found)."""
        path = self.path()
        return (self._driver.search.space.path_cost(path) or 0.0) if path else 0.0

    def outcome_so_far(self, k: int) -> Outcome:
        """The figures after recorded step ``k`` (the path only at the end), as a run's."""
        halves = [half.outcome_so_far(steps)
                  for half, steps in zip(self.halves, self.half_steps(k), strict=True)]
        counts = [sum(getattr(o, name) for o in halves)
                  for name in ("expanded", "discarded", "generated")]
        end = self.done and k == self._driver.steps
        path = self.path() if end else None
        return Outcome(
            algorithm=self.algorithm, semantics=self.semantics.for_algorithm(self.algo),
            path=path, moves=self.moves() if end else None, expanded=counts[0],
            discarded=counts[1], generated=counts[2], max_frontier=self._driver.peak[k],
            gave_up=end and self.gave_up,
            cost=self._driver.search.space.path_cost(path) if path else None,
            stopped=self.why() if end else "", meeting=self.meeting(k) if end else None)

    def outcome(self) -> Outcome:
        """The whole search's figures (records it all first), as the headless run's."""
        self.advance()
        search, driver = self._driver.search, self._driver
        gave_up = driver.gave_up
        path = self.path()
        return Outcome(
            algorithm=self.algorithm, semantics=self.semantics.for_algorithm(self.algo),
            path=path, moves=self.moves(),
            expanded=search.expanded, discarded=search.discarded,
            generated=search.generated, max_frontier=search.max_frontier, gave_up=gave_up,
            cost=search.space.path_cost(path), stopped=self.why(),
            meeting=None if gave_up or search.meeting is None else search.meeting[0].cell)


__all__ = ["BiRun", "app_refusal", "one_way"]
