"""A recorded run: a search's steps, and the state of the search at any step k.

The app and the headless command stand on :class:`Run`, which *has* three parts, each with
one job: a :class:`~tui_search.engine.recording.Recording` (the search computed lazily, in
chunks, into a compact record), an :class:`~tui_search.engine.queries.EventTree` over it
(parents, moves, depths, costs, the path) and a :class:`~tui_search.engine.position.Position`
(after ``k`` steps: what each cell is, the frontier, the tree shown).  The run answers through
the named queries below; the record's arrays stay inside the parts (the app never reads them:
``tests/test_architecture.py``).
"""

from __future__ import annotations

from collections.abc import Iterator

from tui_search.engine.algorithms import DEFAULT_ALGORITHM
from tui_search.engine.grid import Cell, Grid
from tui_search.engine.outcome import Outcome
from tui_search.engine.position import CellState, Position
from tui_search.engine.queries import EventTree
from tui_search.engine.recording import MAX_STEPS, Recording, Step
from tui_search.engine.semantics import DEFAULT_SEMANTICS, Semantics


class Run:
    """A search on a snapshot of a grid, recorded lazily, with a movable position.

    The grid is copied: editing the original afterwards never changes this run.
    """

    #: A jump longer than this rebuilds the state in bulk instead of stepping.
    REBUILD_AFTER = 512

    #: Events one piece of :meth:`rebuild_pieces` handles: a few milliseconds of work.
    REBUILD_PIECE = 1 << 14

    #: Counters one piece of :meth:`rebuild_pieces` allocates (zeroing 2 MB: a millisecond or
    #: two; a 4096x4096 map's counters are 67 MB each, which took a tenth of a second in one go).
    REBUILD_CELLS = 1 << 19

    def __init__(
        self,
        grid: Grid,
        algorithm: str = DEFAULT_ALGORITHM,
        semantics: Semantics = DEFAULT_SEMANTICS,
        max_steps: int = MAX_STEPS,
    ) -> None:
        """Search ``grid`` (copied) with ``algorithm`` (a key of the algorithm table) under
        ``semantics``, giving up after ``max_steps`` expansions."""
        #: The loop and the raw record: for the engine's own checks and the benchmarks.
        self.recording = recording = Recording(grid, algorithm, semantics, max_steps)
        self._rec = recording.rec  # the same record as long as the recording lives
        self._tree = tree = EventTree(recording)
        self._position = Position(recording, tree)
        self.grid = recording.grid  #: the run's own copy of the grid
        self.algorithm = algorithm  #: the algorithm's key
        self.algo = recording.algo  #: the algorithm's description
        self.semantics = recording.semantics  #: the rules in force for this algorithm
        self.max_steps = max_steps  #: the step limit
        #: The cheapest path's cost when known from elsewhere (a benchmark's optimum for this
        #: map, start, goal and rules), for the app to show beside the path's.
        self.known_lowest: float | None = None

    # -- the recording: how much is known -----------------------------------------------
    def advance(self, until_step: int | None = None) -> bool:
        """Record at least up to ``until_step`` (all of it when None); True once done."""
        return self.recording.advance(until_step)

    def advance_some(self) -> bool:
        """Record one more chunk (for callers that compute in slices); True when done."""
        return self.recording.advance_some()

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
    def recorded_events(self) -> int:
        """Generation events recorded so far (numbered from 0, the start)."""
        return len(self._rec.gen_node)

    @property
    def total(self) -> int | None:
        """Number of steps of the whole run, once known (None until then)."""
        return self._rec.steps if self._rec.done else None

    @property
    def goal_test(self) -> str:
        """When the goal is tested, ``"generate"`` or ``"expand"`` (the one in force)."""
        return self.recording.problem.goal_test

    # -- steps ----------------------------------------------------------------------------
    def step(self, k: int) -> Step:
        """Step ``k`` (1-based) as a value, recording as far as needed."""
        return self._tree.step(k)

    def steps(self) -> Iterator[Step]:
        """Every step, in order, recording the search as it goes."""
        return self._tree.steps()

    def expanded_event(self, k: int) -> int:
        """The event step ``k`` took off the frontier (k >= 1)."""
        return self.recording.expanded_event(k)

    def succ_range(self, k: int) -> range:
        """Events added by step ``k`` (k >= 1), in the order added."""
        return self.recording.succ_range(k)

    def expansions(self, first: int, last: int) -> Iterator[tuple[int, range]]:
        """Steps ``first .. last`` of one iteration: (event taken off, events it added)."""
        return self.recording.expansions(first, last)

    def is_discarded(self, k: int) -> bool:
        """Did step ``k`` take off a cell already expanded, and so do nothing?"""
        return self.recording.is_discarded(k)

    def discarded_steps(self) -> list[int]:
        """The discarded steps recorded so far, in order."""
        return self.recording.discarded_steps()

    def iteration_of(self, k: int) -> int:
        """The iteration step ``k`` belongs to (always 0 but for iterative deepening)."""
        return self.recording.iteration_of(k)

    def first_step_of_iteration(self, it: int) -> int:
        """The first step of iteration ``it``."""
        return self.recording.first_step_of_iteration(it)

    def depth_limit(self, k: int | None = None) -> int | None:
        """Iterative deepening's depth limit at step ``k`` (default: the position)."""
        return self.recording.depth_limit(self.k if k is None else k)

    def peak_frontier(self, k: int | None = None) -> int:
        """The largest frontier size over steps 0..k (default: the position)."""
        return self.recording.peak_frontier(self.k if k is None else k)

    # -- events: the tree of the whole record ---------------------------------------------
    def gen_cell(self, g: int) -> Cell:
        """Event ``g``'s cell."""
        return self._tree.gen_cell(g)

    def gen_dir(self, g: int) -> str:
        """The move that reached event ``g`` (``START`` for a root)."""
        return self._tree.gen_dir(g)

    def gen_parent(self, g: int) -> int:
        """The event expanded to generate ``g`` (-1 for a root)."""
        return self._tree.gen_parent(g)

    def gen_depth(self, g: int) -> int:
        """Event ``g``'s depth (moves from its root)."""
        return self._tree.gen_depth(g)

    def cheap_depth(self, g: int) -> int | None:
        """Event ``g``'s depth when it costs little to know, else None."""
        return self._tree.cheap_depth(g)

    def gen_g(self, g: int) -> float:
        """Event ``g``'s cost so far (a cost-ordered search only)."""
        return self._tree.gen_g(g)

    def gen_costs(self, g: int) -> tuple[float, float, float] | None:
        """Event ``g``'s (g, h, priority); None for a queue or a stack."""
        return self._tree.gen_costs(g)

    def priority_key(self, g: int) -> float:
        """The priority event ``g`` was pushed with."""
        return self._tree.priority_key(g)

    def generated_at(self, g: int) -> int:
        """The step whose successors include event ``g`` (0 for the start)."""
        return self.recording.generated_at(g)

    def expanded_at(self, g: int) -> int | None:
        """The step at which event ``g`` was expanded, if it was (in the whole record)."""
        return self._tree.expanded_at(g)

    def ancestors(self, g: int) -> list[int]:
        """Events from the root down to ``g``."""
        return self._tree.ancestors(g)

    @property
    def admissible(self) -> bool:
        """Can the run's heuristic be trusted to find the cheapest path (True when none)?"""
        return self._tree.admissible

    # -- the answer -----------------------------------------------------------------------
    @property
    def goal_event(self) -> int:
        """The event that reached the goal, once found; -1 until then."""
        return self.recording.goal_event

    def path_gens(self) -> list[int]:
        """Events from the start to the goal (empty until found)."""
        return self._tree.path_gens()

    def path(self) -> list[Cell] | None:
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
            self.recording.advance(k)
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

    def cell_state(self, cell: Cell) -> CellState:
        """What ``cell`` is at the position."""
        return self._position.cell_state(cell)

    def row_states(self, y: int, x0: int = 0, x1: int | None = None) -> list[int]:
        """States of cells ``x0 .. x1-1`` of row ``y`` (the fast path for drawing a line)."""
        return self._position.row_states(y, x0, x1)

    def current_node(self) -> Cell | None:
        """The node expanded by the step just taken (None at step 0)."""
        return self._position.current_node()

    def changed_cells(self, k: int) -> list[Cell]:
        """Cells whose state step ``k`` changes (its node and its successors)."""
        return self._position.changed_cells(k)

    def times_reached(self, cell: Cell) -> tuple[int, int]:
        """How often ``cell`` was generated and expanded up to the position."""
        return self._position.times_reached(cell)

    def last_event(self, cell: Cell) -> int | None:
        """The latest event of ``cell`` at the position (None: not reached)."""
        return self._position.last_event(cell)

    def is_stale(self, g: int) -> bool:
        """Is event ``g`` superseded at the position (its cell pushed again, cheaper)?"""
        return self._position.is_stale(g)

    def frontier_len(self) -> int:
        """Entries on the frontier at the position."""
        return self._position.frontier_len()

    def frontier(self, start: int = 0, stop: int | None = None) -> list[int]:
        """Events on the frontier, the next to come out first (a slice of them)."""
        return self._position.frontier(start, stop)

    def added_now(self) -> range:
        """Events added by the step just taken (empty at step 0)."""
        return self._position.added_now()

    def children(self, g: int) -> range:
        """Events generated by expanding ``g``, if it has been expanded by the position."""
        return self._position.children(g)

    def tree_root(self) -> int:
        """The root event of the tree shown at the position (the current iteration's)."""
        return self._position.tree_root()

    def tree_size(self) -> int:
        """Events in the tree at the position."""
        return self._position.tree_size()

    @property
    def expanded(self) -> int:
        """Steps up to the position that expanded a node (discarded ones do not)."""
        return self._position.expanded

    @property
    def discarded(self) -> int:
        """Steps up to the position that took off a cell already expanded."""
        return self._position.discarded

    @property
    def generated(self) -> int:
        """Events generated up to the position (all iterations counted)."""
        return self._position.generated


__all__ = ["MAX_STEPS", "Run", "Step"]
