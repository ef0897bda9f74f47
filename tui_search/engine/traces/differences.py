"""Where a trace parts from a search, and why: one cause a difference, in a sentence a student
can act on, with the choices of the search that would explain it (what the diagnosis tries
next, :mod:`~tui_search.engine.traces.diagnose`).

The check (:mod:`~tui_search.engine.traces.check`) finds the first step where they part; this
module says why, from the run's state just before that step (its frontier, what it reached
and at what cost) and from the trace's own earlier steps: a cell expanded twice (a search that
marks cells visited when it takes them off), a tie of the priority taken another way (and by
which rule), the start pushed again, a cell re-opened or not, a cost cheaper by rounding only,
a cell on the node's own path, the corner rule -- never two causes at once.  Each cause has
a code (:data:`~tui_search.engine.traces.causes.CAUSES`), and the sentences speak of a trace's
author or of a student stepping the search by hand (a
:class:`~tui_search.engine.traces.causes.Voice`): one vocabulary for both.
"""

from __future__ import annotations

from tui_search.engine.maps.grid import DELTAS, Grid, move_cost
from tui_search.engine.run.recorded import Run, Step
from tui_search.engine.search.choices import corner_allowed
from tui_search.engine.search.registry import Frontier
from tui_search.engine.search.state import State, as_cell
from tui_search.engine.traces.causes import TRACE_VOICE, Difference, Said, Suggestion, Voice
from tui_search.engine.traces.orders import call_first, flipped_order
from tui_search.engine.traces.read import Trace, TraceStep, show
from tui_search.engine.traces.ties import TIE_ORDER, tie


def swapped(cell: State) -> State:
    """The cell with x and y swapped (a node is itself)."""
    return cell if isinstance(cell, str) else (cell[1], cell[0])


class Causes:
    """Why a trace parts from ``run`` (a search's run) at a step: the sentence and what would
    explain it.  ``name`` is what the sentences call the search ("BFS"); ``voice`` whom they
    speak of (a trace's author, or a student stepping the search by hand)."""

    def __init__(self, trace: Trace, run: Run, name: str, voice: Voice = TRACE_VOICE) -> None:
        self.trace, self.run, self.name, self.voice = trace, run, name, voice
        self.algo, self.sem = run.algo, run.semantics
        self.says, self.flag = voice.says, voice.flag
        self.by_trace = voice is TRACE_VOICE
        #: The order in which a tie's difference names the rules that explain it (where
        #: several do, :func:`~tui_search.engine.traces.check.check_trace` puts first the one
        #: the trace follows longest).
        self.tie_order: tuple[str, ...] = TIE_ORDER

    # -- the trace's own earlier steps ----------------------------------------------------------
    def first_added(self, cell: State, before: int) -> int | None:
        """The trace's step (from 1) that first added ``cell``, among its first ``before``
        steps; 0 for the start; None: none did."""
        if cell == self.run.start:
            return 0
        for i, t in enumerate(self.trace.steps[:before], 1):
            if cell in t.successors:
                return i
        return None

    def expanded_at(self, cell: State, before: int) -> int | None:
        """The trace's step that first expanded ``cell`` among its first ``before``."""
        for i, t in enumerate(self.trace.steps[:before], 1):
            if t.node == cell and not t.discarded:
                return i
        return None

    # -- an expansion out of turn -----------------------------------------------------------
    def expansion(self, n: int, t: TraceStep, e: Step, k: int, where: str) -> Difference:
        """The trace expands ``t.node`` at its step ``n`` where the search expands ``e.node``
        (its step ``k``); ``where``: what the search would do with the trace's cell."""
        name, cell = self.name, t.node
        before = self.expanded_at(cell, n - 1)
        # (a tie first: code that takes an out-of-date heap entry off takes it at a tie)
        tie = self._tie(k, e.node, cell) if self.algo.priority is not None else None
        if before is not None and tie is None:
            return Difference(n, t.line, "expand", f"step {n}: {self._twice(cell, before)}",
                              e.node, cell, suggest=self._twice_suggests(), cause="twice")
        if tie is not None:
            words, kind, rules = tie
            return Difference(n, t.line, "expand", f"step {n}: {words}", e.node, cell, kind,
                              tuple(((("ties", r),)) for r in rules), "tie")
        discipline = self._discipline(n, cell, e.node) or self._by_frontier(k, cell, e.node)
        if discipline is not None:
            words, suggest, cause = discipline
            return Difference(n, t.line, "expand", f"step {n}: {words}", e.node, cell,
                              suggest=suggest, cause=cause)
        return Difference(n, t.line, "expand",
                          f"step {n}: {name} expands {show(e.node)} next "
                          f"({self._next_words()}); {self.says('expands')} {show(cell)}, "
                          f"{where}", e.node, cell, cause="out-of-turn")

    def not_dropped(self, n: int, e: Step, cell: State) -> Difference:
        """Step ``n`` takes ``cell`` where the search takes ``e.node`` off first and drops it,
        a cell it has expanded already (visit on expand: a student stepping by hand takes it
        off too)."""
        before = self.expanded_at(e.node, n - 1)
        at = f" (at step {before})" if before is not None else ""
        return Difference(n, None, "expand",
                          f"step {n}: {self.name} takes {show(e.node)} off first "
                          f"({self._next_words()}): it was expanded already{at}, so "
                          f"{self.name} drops it; {self.says('takes')} {show(cell)}",
                          e.node, cell, cause="not-dropped")

    def _discipline(self, n: int, cell: State, theirs: State) -> Said | None:
        """When both cells were added by the trace's previous step: a stack takes the last
        of them, a recursion the first, a queue the oldest.  The trace that takes the first
        where a stack takes the last is a recursion; the one that takes the newest where a
        queue takes the oldest, a stack."""
        if n < 2:
            return None
        listed = list(self.trace.steps[n - 2].successors)
        if cell not in listed or theirs not in listed:
            return None
        first = listed.index(cell) < listed.index(theirs)
        name, algo = self.name, self.algo
        if algo.frontier is Frontier.LIFO and not self.sem.recursive and first:
            # the first listed: a queue's (its next is a sibling) or a recursion's (a child)
            later = self.trace.steps[n].node if n < len(self.trace.steps) else None
            own = self.trace.steps[n - 1].successors
            which = "the first it listed" if self.by_trace else f"the first step {n - 1} added"
            head = (f"{name} takes {show(theirs)}, the last cell step {n - 1} pushed; "
                    f"{self.says('takes')} {show(cell)}, {which}")
            recursion = ((("recursive", "neighbours"),), (("recursive", "calls"),))
            if algo.iterative or (later is not None and later in own):
                return (f"{head}, and then a cell it added, as a recursion calling itself on "
                        f"each neighbour in turn does{self.flag('--recursive')}", recursion,
                        "recursion")
            if own and later in listed:
                bfs = ": -a bfs" if self.by_trace else ""
                return (f"{head}, and then {show(later)}, the next: a queue (a BFS{bfs})", (),
                        "first-listed")
            return (f"{head}, as a queue or a recursion does, not a stack"
                    f"{self.flag('-a bfs, or --recursive')}", recursion, "first-listed")
        if algo.frontier is Frontier.FIFO and not first and cell == listed[-1]:
            return self._newest(theirs, cell)
        return None

    def _newest(self, theirs: State, cell: State) -> Said:
        dfs = ": -a dfs" if self.by_trace else ""
        return (f"{self.name} takes {show(theirs)}, the oldest cell on its queue; "
                f"{self.says('takes')} {show(cell)}, the newest, as a stack does (a DFS{dfs})",
                (), "newest")

    def _by_frontier(self, k: int, cell: State, theirs: State) -> Said | None:
        """The search's frontier before its step ``k`` (the trace's too: every step before
        matched): the newest entry taken from a queue, the oldest from a stack."""
        algo = self.algo
        if algo.frontier not in (Frontier.FIFO, Frontier.LIFO) or self.sem.recursive:
            return None
        run = self.run
        run.goto(k - 1)
        cell_of = run.nodes.cell
        cells = [cell_of(g) for g in run.now.frontier()]  # the next out first
        if len(cells) < 2 or cells[-1] != cell or cell == theirs:
            return None
        if algo.frontier is Frontier.FIFO:
            return self._newest(theirs, cell)
        bfs = ": -a bfs" if self.by_trace else ""
        return (f"{self.name} takes {show(theirs)}, the top of its stack, the newest; "
                f"{self.says('takes')} {show(cell)}, the oldest, at its bottom, as a queue "
                f"does (a BFS{bfs})", (), "oldest")

    def _twice(self, cell: State, before: int) -> str:
        what = (f"{show(cell)} was expanded already at step {before}: "
                f"{self.says('expanded', search=True)} it twice")
        if self.algo.weighted:
            return (f"{what}; {self.name} expands a cell again only when it is reached cheaper "
                    "after" + ("" if self.sem.reopen else " (and never, with no re-opening)"))
        if self.sem.visit == "expand":
            return (f"{what}, as a search that marks cells visited when it takes them off, but "
                    "does not check the node it takes off, does")
        return f"{what}, as a search that marks cells visited when it takes them off does"

    def _twice_suggests(self) -> tuple[Suggestion, ...]:
        sem, algo = self.sem, self.algo
        if algo.weighted:
            out: list[Suggestion] = []
            if not sem.reopen:
                out.append((("reopen", True),))
            if sem.cost_tolerance:
                out.append((("cost_tolerance", 0.0),))
            return tuple(out)
        if algo.iterative or sem.tree_search or sem.recursive:
            return ()
        return ((("visit", "expand-again"), ("mark_start", True)),)

    def _next_words(self) -> str:
        """Where the search takes its next node from: "the queue's front"."""
        algo = self.algo
        if algo.frontier is Frontier.PRIORITY:
            return f"the lowest {algo.priority_name} in the priority queue"
        if self.sem.recursive:
            return "the next call of the recursion"
        return f"the {algo.frontier.noun}'s {algo.frontier.next_end}"

    def _tie(self, k: int, mine: State, theirs: State) -> tuple[str, str, list[str]] | None:
        """When the trace's cell ties with the search's on the priority
        (:func:`~tui_search.engine.traces.ties.tie`)."""
        return tie(self.run, k, mine, theirs, self.name, self.voice, self.tie_order)

    # -- a successor list ---------------------------------------------------------------------
    def successors(self, n: int, t: TraceStep, e: Step, whole: bool = True
                   ) -> Difference | None:
        """The first difference between the successors the trace's step ``n`` added and the
        search's step's (None: the same, in the same order).  ``whole=False``: the trace's
        list is the start of one (a student's marks so far): a cell it has not listed yet is
        no difference, one listed before its turn is."""
        got, want = list(t.successors), [c for _, c in e.successors]
        if got == want or (not whole and want[:len(got)] == got):
            return None
        seen: set[State] = set()
        for c in got:
            if c in seen:
                return self._diff(n, t, f"{self.says('added')} {show(c)} twice", None, c,
                                  cause="added-twice")
            seen.add(c)
        for c in got:
            if c not in want:
                words, suggest, cause = self._added(n, t, e, c, want)
                return self._diff(n, t, words, None, c, suggest, cause)
        for c in want if whole else ():
            if c not in seen:
                words, suggest, cause = self._left_out(n, t, e, c, got, want)
                return self._diff(n, t, words, c, None, suggest, cause)
        first = next(i for i, (a, b) in enumerate(zip(got, want, strict=False)) if a != b)
        order = ",".join(self.sem.order)
        if whole:
            words = (f"{self.says('added')} {', '.join(map(show, got))}; {self.name} adds "
                     f"{', '.join(map(show, want))} (order {order}): {show(want[first])} "
                     f"before {show(got[first])}")
            flip = self._flipped()
            if flip and got == want[::-1]:
                flipped = flip[0][1][1]
                assert isinstance(flipped, tuple)
                flag = ("--flip-even" if flipped == self.sem.order
                        else f"--order {','.join(flipped)} --flip-even")
                words += (f", the reverse of its order, as a grid reversing its moves on every "
                          f"other cell does{self.flag(flag)}")
                return self._diff(n, t, words, want[first], got[first], flip, "flip-even")
            return self._diff(n, t, words, want[first], got[first], flip, "order")
        else:  # not the whole list: that would give the rest away
            words = (f"{self.says('added')} {', '.join(map(show, got))}; {self.name} adds "
                     f"{show(want[first])} before {show(got[first])} (order {order})")
        return self._diff(n, t, words, want[first], got[first], cause="order")

    def _call_first(self, t: TraceStep, c: State, want: list[State]) -> tuple[Suggestion, ...]:
        """A recursion's calls: the order with the move to ``c`` just before the search's call
        in its place (:func:`~tui_search.engine.traces.orders.call_first`)."""
        i = t.successors.index(c) if c in t.successors else -1
        order = (call_first(self.sem.order, t.node, c, want[i])
                 if self.sem.recursive == "calls" and 0 <= i < len(want) else None)
        return () if order is None else ((("order", order),),)

    def _flipped(self) -> tuple[Suggestion, ...]:
        """That choice, where the trace reads so (:func:`~tui_search.engine.traces.orders.
        flipped_order`), with the order the trace gives it."""
        if self.sem.flip_even or not isinstance(self.run.board, Grid):
            return ()
        order = flipped_order(self.trace, self.run.goal)
        if order is not None and [m for m in self.sem.order if m in order] == list(order):
            order = self.sem.order  # (the moves the trace never took where they were)
        return () if order is None else ((("flip_even", True), ("order", order)),)

    @staticmethod
    def _diff(n: int, t: TraceStep, words: str, expected: State | None, got: State | None,
              suggest: tuple[Suggestion, ...] = (), cause: str = "") -> Difference:
        return Difference(n, t.line, "successors", f"step {n}: {words}", expected, got,
                          suggest=suggest, cause=cause)

    def _added(self, n: int, t: TraceStep, e: Step, c: State, want: list[State]) -> Said:
        """The trace adds ``c``, which the search does not: why, in one cause."""
        name, node, sem = self.name, t.node, self.sem
        goal = self.run.goal
        board = self.run.board
        if isinstance(board, Grid) and isinstance(c, tuple):  # a grid's cell
            if not board.in_bounds(c):
                return f"{self.says('added')} {show(c)}, which is off the map", (), "off-map"
            if board.is_blocked(c):
                return (f"{self.says('added')} {show(c)}, an obstacle: no search adds it", (),
                        "obstacle")
        if want and want[-1] == goal and e.found_goal:
            return (f"{self.says('added')} {show(c)} after the goal {show(goal)}; {name} stops "
                    "when it adds the goal (the goal tested on generate), yours goes on",
                    ((("goal_test", "expand"),), *self._call_first(t, c, want)), "after-goal")
        head = f"{self.says('added')} {show(c)}, which {name} does not add from {show(node)}"
        cut = self._cut_off(e)
        if cut:
            return f"{head}: {cut}", (), "cut-off"
        if isinstance(c, str) or isinstance(node, str):  # a graph's: no move names the cause
            return f"{head}: no road of it leads there", (), "no-road"
        hint = "; x is the column, y the row: swapped?" if swapped(c) in want else ""
        delta = (c[0] - node[0], c[1] - node[1])
        move = next((d for d, v in DELTAS.items() if v == delta), None)
        if move is None:
            return f"{head}: it is not one move away{hint}", (), "not-a-move"
        if move not in sem.order:
            return (f"{head}: move {move} is not in order {','.join(sem.order)}{hint}", (),
                    "move-not-allowed")
        dx, dy = delta
        grid = self.run.grid
        if dx and dy and not corner_allowed(sem.corners, grid.is_free((node[0] + dx, node[1])),
                                            grid.is_free((node[0], node[1] + dy))):
            others = tuple((("corners", r),) for r in ("always", "one", "never")
                           if r != sem.corners and corner_allowed(
                               r, grid.is_free((node[0] + dx, node[1])),
                               grid.is_free((node[0], node[1] + dy))))
            return (f"{head}: the move {move} passes a blocked corner, and the corner rule "
                    f"{sem.corners} refuses it", others, "corner")
        return self._reached(n, t, e, c, head)

    def _cut_off(self, e: Step) -> str:
        """IDA*'s step ``e`` cut its node off, f over the limit: those words ("" else)."""
        limits = self.run.steps.f_limits(e.index)
        if limits is None or e.successors:
            return ""
        costs = self.run.nodes.costs(self.run.steps.expanded_event(e.index))
        if costs is None or costs[2] <= limits[0] + self.sem.cost_tolerance:
            return ""
        return (f"its f = {costs[2]:.2f} is over the limit {limits[0]:.2f}, so {self.name} "
                "cuts it off, adding nothing (the smallest such f is the next limit)")

    def _reached(self, n: int, t: TraceStep, e: Step, c: State, head: str) -> Said:
        """The trace adds ``c``, a legal move the search refuses as reached: which rule."""
        name, sem, algo = self.name, self.sem, self.algo
        if sem.tree_search:
            return (f"{head}: it is on the path to {show(t.node)}, which tree search with a "
                    f"path check skips; yours skips nothing{self.flag('--no-path-check')}",
                    ((("path_check", False),),), "on-path")
        if c == self.run.start and sem.mark_start:
            return (f"{self.says('pushes')} the start {show(c)} again: {name} marks the start "
                    "reached when it begins; a search that does not (as some library code) "
                    f"pushes it again{self.flag('--mark-start no')}",
                    ((("mark_start", False),),), "start-again")
        added = self.first_added(c, n - 1)
        expanded = self.expanded_at(c, n - 1)
        if algo.weighted and not algo.contours:
            return self._cheaper(n, t, e, c, head, expanded)
        if algo.contours:
            return (f"{head}: it was reached already in this iteration, no more cheaply than "
                    f"from {show(t.node)}, and {name} pushes a cell again only when reached "
                    "cheaper", (), "not-cheaper")
        if algo.iterative:
            return (f"{head}: it was reached already in this iteration, no deeper than from "
                    f"{show(t.node)}, and {name} pushes a cell again only when reached "
                    "shallower", (), "reached-shallower")
        if sem.visit == "generate" and not sem.recursive and expanded is None:
            at = {0: "the start", None: "an earlier step"}.get(added, f"step {added}")
            one = "one" if self.by_trace else "a search"
            return (f"{head}: it was added already, at {at}; {name} marks a cell visited when "
                    f"it adds it, so it adds it once, and {self.says('adds', search=True)} it "
                    f"again, as {one} that marks cells visited when it takes them off does"
                    f"{self.flag('--visit expand')}",
                    ((("visit", "expand"),), (("visit", "expand-again"),)), "reached")
        if expanded is None:  # a recursion's calls: visited deeper down before the call
            return (f"{head}: {name} visits it deeper down, from an earlier call, before this "
                    "call comes to it", self._call_first(t, c, [s for _, s in e.successors]),
                    "visited")
        return (f"{head}: it was expanded already, at step {expanded}, and {name} adds a cell "
                "it has visited no more", (), "expanded")

    def _cheaper(self, n: int, t: TraceStep, e: Step, c: State, head: str,
                 expanded: int | None) -> Said:
        """A cost-ordered search refuses ``c``: closed, reached as cheaply, or cheaper by less
        than its cost tolerance."""
        run, sem, name = self.run, self.sem, self.name
        k = e.index
        run.goto(k - 1)
        if not sem.reopen and expanded is not None:
            return (f"{head}: it is closed (expanded at step {expanded}), and {name} never "
                    f"re-opens a cell; yours does{self.flag('--reopen yes')}",
                    ((("reopen", True),),), "reopened")
        node_event = run.steps.expanded_event(k)
        g = run.nodes.cost(node_event) + _step_cost(run, t.node, c)
        last = run.now.last_event(c)
        best = run.nodes.cost(last) if last is not None else float("inf")
        if g < best:
            return (f"{head}: it costs {g:.6f} from here, cheaper than its best so far "
                    f"({best:.6f}) by only {best - g:.1e}, which {name} calls no cheaper (cost "
                    f"tolerance {sem.cost_tolerance:g}); yours compares costs exactly"
                    f"{self.flag('--cost-tolerance 0')}", ((("cost_tolerance", 0.0),),),
                    "rounding")
        return (f"{head}: it was reached already at g {best:.2f}, and this path costs "
                f"{g:.2f}, no cheaper ({name} pushes a cell again only when reached cheaper)",
                (), "not-cheaper")

    def _left_out(self, n: int, t: TraceStep, e: Step, c: State, got: list[State],
                  want: list[State]) -> Said:
        """The search adds ``c``, which the trace does not: why, in one cause."""
        name, sem, algo = self.name, self.sem, self.algo
        head = f"{name} adds {show(c)} from {show(t.node)}; {self.says('does not')}"
        expanded = self.expanded_at(c, n - 1)
        if algo.weighted and sem.reopen and expanded is not None:
            return (f"{name} re-opens {show(c)} from {show(t.node)} (reached cheaper than when "
                    f"it was expanded, at step {expanded}); {self.says('does not')}: it never "
                    f"re-opens a cell (a closed set{': --reopen no' if self.by_trace else ''})",
                    ((("reopen", False),),), "not-reopened")
        if algo.weighted and sem.cost_tolerance == 0:
            return (f"{head}: {show(c)} is cheaper from here by rounding only, which "
                    f"{'your search calls' if self.by_trace else 'you called'} no cheaper"
                    f"{self.flag('--cost-tolerance 1e-09')}",
                    ((("cost_tolerance", 1e-9),),), "rounding-missed")
        goal = self.run.goal
        if got and got[-1] == goal and want[:len(got)] == got:
            return (f"{head}: {self.says('stops')} when it adds the goal {show(goal)}, as a "
                    "search that tests the goal on generate does",
                    ((("goal_test", "generate"),),), "stopped-at-goal")
        if sem.recursive == "neighbours" and _subsequence(got, want):
            return (f"{head}: your line lists the cells the call recursed into, not all the "
                    f"neighbours it would try{self.flag('--recursive-lines calls')}",
                    ((("recursive", "calls"),),), "calls")
        return head, (), "left-out"


def _step_cost(run: Run, a: State, b: State) -> float:
    """What the move from ``a`` to ``b`` adds to g: a road's cost on a graph; on a grid the
    move's length times the cost of the cell it enters."""
    graph = run.graph
    if graph is not None:
        return graph.cost(str(a), str(b))
    (ax, ay), (bx, by) = as_cell(a), as_cell(b)
    move = next(d for d, v in DELTAS.items() if v == (bx - ax, by - ay))
    return move_cost(move) * run.grid.cost((bx, by))


def _subsequence(short: list[State], long: list[State]) -> bool:
    it = iter(long)
    return all(c in it for c in short)


__all__ = ["Causes", "Difference", "Suggestion", "swapped"]
