"""A recorded run: a search's steps, and the state of the search at any step k.

The app and the headless command stand on :class:`Run`, which *has* three parts, each with
one job: a :class:`~tui_search.engine.run.recording.Recording` (the search computed lazily, in
chunks, into a compact record), an :class:`~tui_search.engine.run.queries.EventTree` over it
(parents, moves, depths, costs, the path) and a :class:`~tui_search.engine.run.position.Position`
(after ``k`` steps: what each cell is, the frontier, the tree shown).  The run answers a small
set of named queries about itself, and the rest through three facets
(:mod:`~tui_search.engine.run.facets`): ``run.nodes`` (one event), ``run.steps`` (one step) and
``run.now`` (the state at the position).  The recording stays inside: the engine's own checks
and the benchmarks reach it through :func:`recording_of`, the app never does
(``tests/test_architecture.py``).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.facets import Nodes, Now, Steps
from tui_search.engine.run.position import Position
from tui_search.engine.run.queries import EventTree
from tui_search.engine.run.recording import MAX_STEPS, Recording, Source, Step
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.record import CHUNK
from tui_search.engine.search.registry import DEFAULT_ALGORITHM
from tui_search.engine.search.state import State

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.search.state import State

class OnBoard:
    """What a run searches, by name: its ``board`` (a grid or a graph), the graph, the start
    and the goal -- a run's and a bidirectional search's
    (:class:`~tui_search.engine.run.bidirectional.BiRun`) alike."""

    board: Grid | Graph

    @property
    def graph(self) -> Graph | None:
        """The run's own copy of the graph, when it searches one."""
        board = self.board
        return None if isinstance(board, Grid) else board

    @property
    def start(self) -> State | None:
        """Where the search starts: a cell, or a node's name."""
        return self.board.start

    @property
    def goal(self) -> State | None:
        """The goal (a graph's first, where it has several)."""
        board = self.board
        if isinstance(board, Grid):
            return board.goal
        return board.goals[0] if board.goals else None


class Run(OnBoard):
    """A search on a snapshot of a grid, recorded lazily, with a movable position.

    The grid is copied: editing the original afterwards never changes this run.  Its names
    (``tests/engine/test_run.py`` pins them):

    - what it is: ``grid``, ``algorithm``, ``algo``, ``semantics``, ``max_steps``,
      ``known_lowest``;
    - how much is recorded: ``advance``, ``advance_some``, ``done``, ``found``, ``gave_up``,
      ``recorded``, ``total``, ``goal_test``;
    - where it stands: ``k``, ``goto``, ``forward``, ``backward``, ``reset``, ``at_end``,
      ``rebuild_pieces`` (tuned by ``REBUILD_AFTER``, ``REBUILD_PIECE``, ``REBUILD_CELLS``);
    - the answer: ``outcome``, ``outcome_so_far``, ``path``, ``moves``, ``admissible``;
    - the facets: ``nodes`` (:class:`~tui_search.engine.run.facets.Nodes`), ``steps``
      (:class:`~tui_search.engine.run.facets.Steps`), ``now``
      (:class:`~tui_search.engine.run.facets.Now`).
    """

    #: A jump longer than this rebuilds the state in bulk instead of stepping.
    REBUILD_AFTER = 512

    #: Events one piece of :meth:`rebuild_pieces` handles: a few milliseconds of work.
    REBUILD_PIECE = 1 << 14

    #: Counters one piece of :meth:`rebuild_pieces` allocates (2 MB; a 4096x4096 map's counters
    #: are 67 MB each, too long to zero in one go: benchmarks/README.md, "jump").
    REBUILD_CELLS = 1 << 19

    def __init__(
        self,
        grid: Grid | Graph,
        algorithm: str = DEFAULT_ALGORITHM,
        semantics: Semantics = DEFAULT_SEMANTICS,
        max_steps: int = MAX_STEPS,
        source: Source | None = None,
        first_chunk: int = CHUNK,
    ) -> None:
        """Search ``grid`` (copied) with ``algorithm`` (a key of the algorithm table) under
        ``semantics``, giving up after ``max_steps`` expansions.  ``source``: take the steps
        from its loop instead (a replayed trace, :func:`~tui_search.engine.traces.as_run.
        trace_run`), a run like any other to every query.  ``first_chunk``: the steps
        recorded at first (:class:`~tui_search.engine.run.recording.Recording`'s)."""
        # The loop and the raw record: the engine's own checks reach it by recording_of(run).
        self._recording = recording = Recording(grid, algorithm, semantics, max_steps, source,
                                                   first_chunk)
        self._rec = recording.rec  # the same record as long as the recording lives
        self._tree = tree = EventTree(recording)
        self._position = position = Position(recording, tree)
        self.nodes = Nodes(recording, tree)  #: the generation events, by number
        self.steps = Steps(recording, tree, position)  #: the recorded steps, by number
        self.now = Now(position)  #: the state of the search at the position
        self.board = recording.board  #: the run's own copy of the grid or the graph
        self.algorithm = recording.algo.key  #: the algorithm's key
        self.algo = recording.algo  #: the algorithm's description
        self.semantics = recording.semantics  #: the rules in force for this algorithm
        self.max_steps = max_steps  #: the step limit
        #: The cheapest path's cost when known from elsewhere (a benchmark's optimum for this
        #: map, start, goal and rules), for the app to show beside the path's.
        self.known_lowest: float | None = None

    @property
    def grid(self) -> Grid:
        """The run's own copy of the grid (a run on a graph has none: :attr:`board`)."""
        return self._recording.grid

    def path_cost(self) -> float:
        """The path's cost (0.0 until the goal is found)."""
        path = self.path()
        return (self._recording.problem.path_cost(path) or 0.0) if path else 0.0

    # -- the recording: how much is known -----------------------------------------------
    def advance(self, until_step: int | None = None) -> bool:
        """Record at least up to ``until_step`` (all of it when None); True once done."""
        return self._recording.advance(until_step)

    def advance_some(self) -> bool:
        """Record one more chunk (for callers that compute in slices); True when done."""
        return self._recording.advance_some()

    @property
    def done(self) -> bool:
        """True when the whole search has been recorded."""
        return self._rec.done

    @property
    def found(self) -> bool:
        """True once the goal has been found (and recorded)."""
        return self._rec.found

    @property
    def gave_up(self) -> bool:
        """True when the search was stopped at ``max_steps`` expansions, unfinished."""
        return self._rec.gave_up

    @property
    def recorded(self) -> int:
        """Steps recorded so far."""
        return self._rec.steps

    @property
    def total(self) -> int | None:
        """Number of steps of the whole run, once known (None until then)."""
        return self._rec.steps if self._rec.done else None

    @property
    def goal_test(self) -> str:
        """When the goal is tested, ``"generate"`` or ``"expand"`` (the one in force)."""
        return self._recording.problem.goal_test

    @property
    def replayed(self) -> bool:
        """Do the run's steps come from a source (a replayed trace), not from its rules?  Its
        rules are then the matched search's, which the trace never declared."""
        return self._recording.source is not None

    def differences(self) -> list[str]:
        """What the status line says of the run's rules, a few words each: how they differ
        from the defaults ("moves N,W,S,E", "visit on expand"), or for a run from a source
        (a replayed trace) the source's own words."""
        source = self._recording.source
        if source is not None:
            return list(source.notes)
        return self.semantics.differences(self.algo)

    # -- the answer -----------------------------------------------------------------------
    @property
    def admissible(self) -> bool:
        """Can the run's heuristic be trusted to find the cheapest path (True when none)?"""
        return self._tree.admissible

    def estimate_warning(self) -> str:
        """Why the heuristic may miss the cheapest path, in a sentence ("" when it cannot)."""
        return self._tree.estimate_warning()

    def path(self) -> list[State] | None:
        """Cells from the start to the goal (None until found)."""
        return self._tree.path()

    def moves(self) -> list[str] | None:
        """The path's moves (None until found)."""
        return self._tree.moves()

    def outcome(self) -> Outcome:
        """The result of the whole search (records it all first)."""
        return self._tree.outcome()

    def outcome_so_far(self, k: int) -> Outcome:
        """The figures after recorded step ``k`` (the path only at the last step)."""
        return self._tree.outcome_so_far(k)

    # -- the position ---------------------------------------------------------------------
    @property
    def k(self) -> int:
        """The position: steps taken (0: only the start is on the frontier)."""
        return self._position.k

    def goto(self, k: int) -> None:
        """Move the position to step ``k`` (clamped to the run), recording as needed."""
        k = max(0, k)
        rec = self._rec
        if k > rec.steps:
            self._recording.advance(k)
        k = min(k, rec.steps)
        position = self._position
        if abs(k - position.k) > self.REBUILD_AFTER:
            for _ in position.rebuild_pieces(k, self.REBUILD_PIECE, self.REBUILD_CELLS):
                pass
        position.step_to(k)

    def rebuild_pieces(self, k: int) -> Iterator[float]:
        """Move to recorded step ``k`` in bulk, a bounded piece of work per ``next()``
        (:attr:`REBUILD_PIECE` events, :attr:`REBUILD_CELLS` counters), yielding the fraction
        done; the run stays whole at its old position until the last piece."""
        return self._position.rebuild_pieces(k, self.REBUILD_PIECE, self.REBUILD_CELLS)

    def forward(self) -> bool:
        """One step forwards, recording as needed; False when already at the end."""
        return self._position.forward()

    def backward(self) -> bool:
        """One step backwards; False at step 0."""
        return self._position.backward()

    def reset(self) -> None:
        """Back to step 0 (all counters cleared)."""
        self._position.reset()

    @property
    def at_end(self) -> bool:
        """True at the last step of a wholly recorded search."""
        return self._position.at_end


def recording_of(run: Run) -> Recording:
    """The run's recording: its loop and its raw record, for the engine's own checks and the
    benchmarks (a record's contents, its memory).  The app never calls it
    (``tests/test_architecture.py``): it asks the run and its facets."""
    return run._recording


__all__ = ["MAX_STEPS", "OnBoard", "Run", "Source", "Step", "recording_of"]
