"""The three named query facets of a recorded run: its generation events (``run.nodes``), its
steps (``run.steps``) and the state at its position (``run.now``).

A :class:`~tui_search.engine.run.recorded.Run` answers about itself (progress, position, outcome);
what it knows of one event, one step or one cell at step ``k`` it answers through these, so its own
surface stays small.  Each facet only *names* queries of the run's parts (the recording, the event
tree, the position): its names are the parts' methods bound once, so asking through a facet costs no
forwarding call.  A hot loop still fetches the facet (or the method) once, outside the loop.
"""

from __future__ import annotations

from tui_search.engine.run.position import Position
from tui_search.engine.run.queries import EventTree
from tui_search.engine.run.recording import Recording


class Nodes:
    """The run's generation events ("nodes" of the search tree), each by its number ``g``
    (0 is the start; numbered in the order generated, over the whole record):

    - ``cell(g)``: the event's cell.
    - ``move(g)``: the move that reached it from its parent (``START`` for a root).
    - ``parent(g)``: the event expanded to generate it (-1 for a root).
    - ``depth(g)``: its depth, moves from its root.
    - ``cheap_depth(g)``: its depth when that costs little to know, else None.
    - ``cost(g)``: its cost so far (a cost-ordered search only).
    - ``costs(g)``: its (g, h, priority); None for a queue or a stack.
    - ``generated_at(g)``: the step whose successors include it (0 for the start).
    - ``expanded_at(g)``: the step that expanded it, if one did (in the whole record).
    - ``ancestors(g)``: the events from its root down to it.
    - ``goal``: the event that reached the goal, once found; -1 until then.
    - ``path()``: the events from the start to the goal (empty until found).
    """

    __slots__ = ("_recording", "ancestors", "cell", "cheap_depth", "cost", "costs", "depth",
                 "expanded_at", "generated_at", "move", "parent", "path")

    def __init__(self, recording: Recording, tree: EventTree) -> None:
        self._recording = recording
        self.cell = tree.gen_cell
        self.move = tree.gen_dir
        self.parent = tree.gen_parent
        self.depth = tree.gen_depth
        self.cheap_depth = tree.cheap_depth
        self.cost = tree.gen_g
        self.costs = tree.gen_costs
        self.generated_at = recording.generated_at
        self.expanded_at = tree.expanded_at
        self.ancestors = tree.ancestors
        self.path = tree.path_gens

    @property
    def goal(self) -> int:
        """The event that reached the goal, once found; -1 until then."""
        return self._recording.goal_event


class Steps:
    """The run's recorded steps, each by its number ``k`` (1-based; a step takes one event off
    the frontier and adds its successors):

    - ``at(k)``: step ``k`` as a :class:`~tui_search.engine.run.recording.Step` value, recording
      as far as needed.
    - ``all()``: every step in order, recording the search as it goes.
    - ``expanded_event(k)``: the event step ``k`` took off the frontier.
    - ``succ_range(k)``: the events step ``k`` added, in the order added.
    - ``expansions(first, last)``: steps ``first .. last`` of one iteration, each as (event
      taken off, events added).
    - ``is_discarded(k)``: did step ``k`` take off a cell already expanded, and do nothing?
    - ``iteration_of(k)``: the iteration step ``k`` belongs to (0 but for iterative
      deepening).
    - ``first_of_iteration(it)``: the first step of iteration ``it``.
    - ``depth_limit(k=None)``: iterative deepening's depth limit at step ``k`` (default: the
      run's position; None for other searches).
    - ``is_cut_off(k=None)``: IDA*: was step ``k``'s node over the limit, cut off?
    - ``f_limits(k=None)``: IDA*'s limit on f at step ``k`` and the smallest f over it met
      by then in its iteration (inf: none yet); None for other searches.
    - ``peak_frontier(k=None)``: the largest frontier size over steps 0..k (default: the
      run's position).
    """

    __slots__ = ("_costs", "_position", "_recording", "all", "at", "expanded_event",
                 "expansions", "first_of_iteration", "is_discarded", "iteration_of",
                 "succ_range")

    def __init__(self, recording: Recording, tree: EventTree, position: Position) -> None:
        self._recording, self._position = recording, position
        self._costs = tree.gen_costs
        self.at = tree.step
        self.all = tree.steps
        self.expanded_event = recording.expanded_event
        self.succ_range = recording.succ_range
        self.expansions = recording.expansions
        self.is_discarded = recording.is_discarded
        self.iteration_of = recording.iteration_of
        self.first_of_iteration = recording.first_step_of_iteration

    def depth_limit(self, k: int | None = None) -> int | None:
        """Iterative deepening's depth limit at step ``k`` (default: the position)."""
        return self._recording.depth_limit(self._position.k if k is None else k)

    def f_limits(self, k: int | None = None) -> tuple[float, float] | None:
        """IDA*'s limit on f at step ``k`` and the next so far (default: the position)."""
        return self._recording.f_limits(self._position.k if k is None else k)

    def is_cut_off(self, k: int | None = None) -> bool:
        """IDA*: did step ``k`` (default: the position) take off a node whose f is over the
        limit (by more than the cost tolerance), cut off with no successors?"""
        k = self._position.k if k is None else k
        limits = self._recording.f_limits(k)
        if limits is None or k == 0:
            return False
        costs = self._costs(self._recording.expanded_event(k))
        tolerance = self._recording.problem.semantics.cost_tolerance
        return costs is not None and costs[2] > limits[0] + tolerance

    def peak_frontier(self, k: int | None = None) -> int:
        """The largest frontier size over steps 0..k (default: the position)."""
        return self._recording.peak_frontier(self._position.k if k is None else k)


class Now:
    """The state of the search at the run's position (after ``run.k`` steps):

    - ``cell_state(cell)``: what the cell is (a
      :class:`~tui_search.engine.run.position.CellState`).
    - ``row_states(y, x0=0, x1=None)``: the states of cells ``x0 .. x1-1`` of row ``y`` (the
      fast path for drawing a line).
    - ``current_node()``: the cell expanded by the step just taken (None at step 0).
    - ``changed_cells(k)``: the cells whose state step ``k`` changes.
    - ``times_reached(cell)``: how often the cell was generated and expanded so far.
    - ``last_event(cell)``: the cell's latest event (None: not reached).
    - ``is_stale(g)``: is event ``g`` superseded (its cell pushed again, cheaper)?
    - ``frontier_len()``: the entries on the frontier.
    - ``frontier(start=0, stop=None)``: the events on the frontier, the next to come out
      first (a slice of them).
    - ``added_now()``: the events added by the step just taken (empty at step 0).
    - ``children(g)``: the events generated by expanding ``g``, if it has been expanded.
    - ``tree_root()``: the root event of the tree shown (the current iteration's).
    - ``tree_size()``: the events in that tree.
    - ``expanded``, ``discarded``, ``generated``: the counts so far (steps that expanded a
      node, steps that took off a cell already expanded, events generated).
    """

    __slots__ = ("_position", "added_now", "cell_state", "changed_cells", "children",
                 "current_node", "frontier", "frontier_len", "is_stale", "last_event",
                 "row_states", "times_reached", "tree_root", "tree_size")

    def __init__(self, position: Position) -> None:
        self._position = position
        self.cell_state = position.cell_state
        self.row_states = position.row_states
        self.current_node = position.current_node
        self.changed_cells = position.changed_cells
        self.times_reached = position.times_reached
        self.last_event = position.last_event
        self.is_stale = position.is_stale
        self.frontier_len = position.frontier_len
        self.frontier = position.frontier
        self.added_now = position.added_now
        self.children = position.children
        self.tree_root = position.tree_root
        self.tree_size = position.tree_size

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


__all__ = ["Nodes", "Now", "Steps"]
