"""Where a trace parts from a search, and why: one cause a difference, in a sentence a student
can act on, with the choices of the search that would explain it (what the diagnosis tries
next, :mod:`~tui_search.engine.traces.diagnose`).

The check (:mod:`~tui_search.engine.traces.check`) finds the first step where they part; this
module says why, from the run's state just before that step (its frontier, what it reached
and at what cost) and from the trace's own earlier steps: a cell expanded twice (a search that
marks cells visited when it takes them off), a tie of the priority taken another way (and by
which rule), the start pushed again, a cell re-opened or not, a cost cheaper by rounding only,
a cell on the node's own path, the corner rule -- never two causes at once.
"""

from __future__ import annotations

from dataclasses import dataclass

from tui_search.engine.maps.grid import DELTAS, move_cost
from tui_search.engine.run.recorded import Run, Step
from tui_search.engine.search.choices import TIE_RULES, corner_allowed
from tui_search.engine.search.registry import Frontier
from tui_search.engine.search.state import State, as_cell
from tui_search.engine.traces.read import Trace, TraceStep, show

#: Two priorities closer than this tie (the floats of one cost summed in another order).
TIE = 1e-9

#: The choices a difference suggests, as ``(field, value)`` pairs of
#: :class:`~tui_search.engine.search.choices.Semantics`.
Suggestion = tuple[tuple[str, object], ...]


@dataclass(frozen=True)
class Difference:
    """The first place the trace parts from the search: its step (the trace's numbering), the
    trace line, what kind (``expand``, ``successors``, ``ends``, ``goes_on``), the sentence, and
    the cells the search expected and the trace had (None where it has none)."""

    step: int
    line: int | None
    kind: str
    message: str
    expected: State | None = None
    got: State | None = None
    #: The search parts from the trace at a tie of its priority: "h" where the trace took
    #: the lower or higher h of an f tie, "entry" where it took another entry; "" no tie.
    tie: str = ""
    #: The choices that would explain it, each a change the diagnosis tries.
    suggest: tuple[Suggestion, ...] = ()

    def as_json(self) -> dict[str, object]:
        return {"step": self.step, "line": self.line, "kind": self.kind,
                "message": self.message,
                "expected": state_json(self.expected), "got": state_json(self.got),
                "tie": self.tie or None}


def state_json(state: State | None) -> object:
    """A cell as JSON writes it (``[x, y]``), a node as its name, None as null."""
    return list(state) if isinstance(state, tuple) else state


def swapped(cell: State) -> State:
    """The cell with x and y swapped (a node is itself)."""
    return cell if isinstance(cell, str) else (cell[1], cell[0])


class Causes:
    """Why a trace parts from ``run`` (a search's run) at a step: the sentence and what would
    explain it.  ``name`` is what the sentences call the search ("BFS")."""

    def __init__(self, trace: Trace, run: Run, name: str) -> None:
        self.trace, self.run, self.name = trace, run, name
        self.algo, self.sem = run.algo, run.semantics

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
        if before is not None:
            return Difference(n, t.line, "expand", f"step {n}: {self._twice(cell, before)}",
                              e.node, cell, suggest=self._twice_suggests())
        tie = self._tie(k, e.node, cell) if self.algo.priority is not None else None
        if tie is not None:
            words, kind, rules = tie
            return Difference(n, t.line, "expand", f"step {n}: {words}", e.node, cell, kind,
                              tuple(((("ties", r),)) for r in rules))
        discipline = self._discipline(n, cell, e.node)
        if discipline is not None:
            words, suggest = discipline
            return Difference(n, t.line, "expand", f"step {n}: {words}", e.node, cell,
                              suggest=suggest)
        return Difference(n, t.line, "expand",
                          f"step {n}: {name} expands {show(e.node)} next "
                          f"({self._next_words()}); your trace expands {show(cell)}, {where}",
                          e.node, cell)

    def _discipline(self, n: int, cell: State, theirs: State
                    ) -> tuple[str, tuple[Suggestion, ...]] | None:
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
            head = (f"{name} takes {show(theirs)}, the last cell step {n - 1} pushed; your "
                    f"trace takes {show(cell)}, the first it listed")
            recursion = ((("recursive", "neighbours"),), (("recursive", "calls"),))
            if algo.iterative or (later is not None and later in own):
                return (f"{head}, and then a cell it added, as a recursion calling itself on "
                        "each neighbour in turn does (--recursive)", recursion)
            if own and later in listed:
                return f"{head}, and then {show(later)}, the next: a queue (a BFS: -a bfs)", ()
            return (f"{head}, as a queue or a recursion does, not a stack (-a bfs, or "
                    "--recursive)", recursion)
        if algo.frontier is Frontier.FIFO and not first and cell == listed[-1]:
            return (f"{name} takes {show(theirs)}, the oldest cell on its queue; your trace "
                    f"takes {show(cell)}, the newest, as a stack does (a DFS: -a dfs)", ())
        return None

    def _twice(self, cell: State, before: int) -> str:
        what = f"{show(cell)} was expanded already at step {before}: your search expanded it twice"
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
        """When the trace's cell ties with the search's on the priority: the sentence, the
        tie's kind ("h" where the trace took the lower or higher h of an f tie, else "entry")
        and the tie rules that would take the trace's cell."""
        run = self.run
        run.goto(k - 1)
        now, cell_of, costs = run.now, run.nodes.cell, run.nodes.costs
        entries: list[tuple[int, State, tuple[float, float, float]]] = []
        for g in now.frontier():
            c = costs(g)
            if c is not None and not now.is_stale(g):
                entries.append((g, cell_of(g), c))
        top = next((c for _, cell, c in entries if cell == mine), None)
        got = next((c for _, cell, c in entries if cell == theirs), None)
        if top is None or got is None or abs(top[2] - got[2]) > TIE:
            return None
        tied = [(g, cell, c) for g, cell, c in entries if abs(c[2] - top[2]) <= TIE]
        rules = [r for r in _PREFERRED if r != self.sem.ties and _picks(r, tied) == theirs
                 and not self.sem.replace(ties=r).refusal(self.algo)]
        p = self.algo.priority_name
        mine_words = _RULE_WORDS[self.sem.ties]
        start = f"{self.name} expands {show(mine)} next; your trace expands {show(theirs)}: "
        if rules:
            rule = rules[0]
            how = f"{_RULE_WORDS[rule]} of the tie"
            if rule in ("low-h", "high-h"):
                how += f" ({got[1]:.2f}, not {top[1]:.2f})"
            elif rule in ("low-g", "high-g"):
                how += f" ({got[0]:.2f}, not {top[0]:.2f})"
            words = (f"{start}{p} ties at {top[2]:.2f}, and your search takes {how}"
                     f"{_RULE_WHY.get(rule, '')}; this search takes {mine_words} "
                     f"(--ties {rule})")
            kind = "h" if rule in ("low-h", "high-h") and p == "f" else "entry"
            return words, kind, rules
        words = (f"{start}{p} ties at {top[2]:.2f}, and your search takes another entry of the "
                 f"tie, one no tie rule here takes; this search takes {mine_words}")
        return words, "entry", []

    # -- a successor list ---------------------------------------------------------------------
    def successors(self, n: int, t: TraceStep, e: Step) -> Difference | None:
        """The first difference between the successors the trace's step ``n`` added and the
        search's step's (None: the same, in the same order)."""
        got: list[State] = list(t.successors)
        want: list[State] = [c for _, c in e.successors]
        if got == want:
            return None
        seen: set[State] = set()
        for c in got:
            if c in seen:
                return self._diff(n, t, f"your trace added {show(c)} twice", None, c)
            seen.add(c)
        for c in got:
            if c not in want:
                words, suggest = self._added(n, t, e, c, want)
                return self._diff(n, t, words, None, c, suggest)
        for c in want:
            if c not in seen:
                words, suggest = self._left_out(n, t, e, c, got, want)
                return self._diff(n, t, words, c, None, suggest)
        first = next(i for i, (a, b) in enumerate(zip(got, want, strict=True)) if a != b)
        order = ",".join(self.sem.order)
        words = (f"your trace added {', '.join(map(show, got))}; {self.name} adds "
                 f"{', '.join(map(show, want))} (order {order}): {show(want[first])} before "
                 f"{show(got[first])}")
        return self._diff(n, t, words, want[first], got[first])

    @staticmethod
    def _diff(n: int, t: TraceStep, words: str, expected: State | None, got: State | None,
              suggest: tuple[Suggestion, ...] = ()) -> Difference:
        return Difference(n, t.line, "successors", f"step {n}: {words}", expected, got,
                          suggest=suggest)

    def _added(self, n: int, t: TraceStep, e: Step, c: State, want: list[State]
               ) -> tuple[str, tuple[Suggestion, ...]]:
        """The trace adds ``c``, which the search does not: why, in one cause."""
        name, node, sem = self.name, t.node, self.sem
        goal = self.run.goal
        if want and want[-1] == goal and e.found_goal:
            return (f"your trace added {show(c)} after the goal {show(goal)}; {name} stops when "
                    "it adds the goal (the goal tested on generate), yours goes on",
                    ((("goal_test", "expand"),),))
        head = f"your trace added {show(c)}, which {name} does not add from {show(node)}"
        if isinstance(c, str) or isinstance(node, str):  # a graph's: no move names the cause
            return f"{head}: no road of it leads there", ()
        hint = "; x is the column, y the row: swapped?" if swapped(c) in want else ""
        delta = (c[0] - node[0], c[1] - node[1])
        move = next((d for d, v in DELTAS.items() if v == delta), None)
        if move is None:
            return f"{head}: it is not one move away{hint}", ()
        if move not in sem.order:
            return f"{head}: move {move} is not in order {','.join(sem.order)}{hint}", ()
        grid = self.run.grid
        dx, dy = delta
        if dx and dy and not corner_allowed(sem.corners, grid.is_free((node[0] + dx, node[1])),
                                            grid.is_free((node[0], node[1] + dy))):
            others = tuple((("corners", r),) for r in ("always", "one", "never")
                           if r != sem.corners and corner_allowed(
                               r, grid.is_free((node[0] + dx, node[1])),
                               grid.is_free((node[0], node[1] + dy))))
            return (f"{head}: the move {move} passes a blocked corner, and the corner rule "
                    f"{sem.corners} refuses it", others)
        return self._reached(n, t, e, c, head)

    def _reached(self, n: int, t: TraceStep, e: Step, c: State, head: str
                 ) -> tuple[str, tuple[Suggestion, ...]]:
        """The trace adds ``c``, a legal move the search refuses as reached: which rule."""
        name, sem, algo = self.name, self.sem, self.algo
        if sem.tree_search:
            return (f"{head}: it is on the path to {show(t.node)}, which tree search with a "
                    "path check skips; yours skips nothing (--no-path-check)",
                    ((("path_check", False),),))
        if c == self.run.start and sem.mark_start:
            return (f"your trace pushes the start {show(c)} again: {name} marks the start "
                    "reached when it begins; a search that does not (as some library code) "
                    "pushes it again (--mark-start no)", ((("mark_start", False),),))
        added = self.first_added(c, n - 1)
        expanded = self.expanded_at(c, n - 1)
        if algo.weighted:
            return self._cheaper(n, t, e, c, head, expanded)
        if algo.iterative:
            return (f"{head}: it was reached already in this iteration, no deeper than from "
                    f"{show(t.node)}, and {name} pushes a cell again only when reached "
                    "shallower", ())
        if sem.visit == "generate" and not sem.recursive and expanded is None:
            at = {0: "the start", None: "an earlier step"}.get(added, f"step {added}")
            return (f"{head}: it was added already, at {at}; {name} marks a cell visited when "
                    "it adds it, so it adds it once, and your search adds it again, as one "
                    "that marks cells visited when it takes them off does (--visit expand)",
                    ((("visit", "expand"),), (("visit", "expand-again"),)))
        if expanded is None:  # a recursion's calls: visited deeper down before the call
            return (f"{head}: {name} visits it deeper down, from an earlier call, before this "
                    "call comes to it", ())
        return (f"{head}: it was expanded already, at step {expanded}, and {name} adds a cell "
                "it has visited no more", ())

    def _cheaper(self, n: int, t: TraceStep, e: Step, c: State, head: str,
                 expanded: int | None) -> tuple[str, tuple[Suggestion, ...]]:
        """A cost-ordered search refuses ``c``: closed, reached as cheaply, or cheaper by less
        than its cost tolerance."""
        run, sem, name = self.run, self.sem, self.name
        k = e.index
        run.goto(k - 1)
        if not sem.reopen and expanded is not None:
            return (f"{head}: it is closed (expanded at step {expanded}), and {name} never "
                    "re-opens a cell; yours does (--reopen yes)", ((("reopen", True),),))
        node_event = run.steps.expanded_event(k)
        g = run.nodes.cost(node_event) + _step_cost(run, t.node, c)
        last = run.now.last_event(c)
        best = run.nodes.cost(last) if last is not None else float("inf")
        if g < best:
            return (f"{head}: it costs {g:.6f} from here, cheaper than its best so far "
                    f"({best:.6f}) by only {best - g:.1e}, which {name} calls no cheaper (cost "
                    f"tolerance {sem.cost_tolerance:g}); yours compares costs exactly "
                    "(--cost-tolerance 0)", ((("cost_tolerance", 0.0),),))
        return (f"{head}: it was reached already at g {best:.2f}, and this path costs "
                f"{g:.2f}, no cheaper ({name} pushes a cell again only when reached cheaper)", ())

    def _left_out(self, n: int, t: TraceStep, e: Step, c: State, got: list[State],
                  want: list[State]) -> tuple[str, tuple[Suggestion, ...]]:
        """The search adds ``c``, which the trace does not: why, in one cause."""
        name, sem, algo = self.name, self.sem, self.algo
        head = f"{name} adds {show(c)} from {show(t.node)}; your trace does not"
        expanded = self.expanded_at(c, n - 1)
        if algo.weighted and sem.reopen and expanded is not None:
            return (f"{name} re-opens {show(c)} from {show(t.node)} (reached cheaper than when "
                    f"it was expanded, at step {expanded}); your trace does not: it never "
                    "re-opens a cell (a closed set: --reopen no)", ((("reopen", False),),))
        if algo.weighted and sem.cost_tolerance == 0:
            return (f"{head}: {show(c)} is cheaper from here by rounding only, which your "
                    "search calls no cheaper (--cost-tolerance 1e-09)",
                    ((("cost_tolerance", 1e-9),),))
        goal = self.run.goal
        if got and got[-1] == goal and want[:len(got)] == got:
            return (f"{head}: your trace stops when it adds the goal {show(goal)}, as a search "
                    "that tests the goal on generate does", ((("goal_test", "generate"),),))
        if sem.recursive == "neighbours" and _subsequence(got, want):
            return (f"{head}: your line lists the cells the call recursed into, not all the "
                    "neighbours it would try (--recursive-lines calls)",
                    ((("recursive", "calls"),),))
        return head, ()


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


#: How a tie rule takes an entry of a tie, and why a student's code does so.
_RULE_WORDS = {"fifo": "the oldest entry", "lifo": "the newest entry",
               "node": "the smallest cell", "low-h": "the lower h", "high-h": "the higher h",
               "low-g": "the lower g", "high-g": "the higher g"}
_RULE_WHY = {"node": ", as a heap of (f, (x, y)) tuples does"}
#: The tie rules in the order a difference names them (a student's tuple first).
_PREFERRED = ("node", "low-h", "high-h", "lifo", "low-g", "high-g", "fifo")
assert set(_PREFERRED) == set(TIE_RULES)


def _picks(rule: str, tied: list[tuple[int, State, tuple[float, float, float]]]) -> State:
    """The cell the tie ``rule`` takes of ``tied`` entries (event, cell, (g, h, f)); then the
    oldest, as :func:`~tui_search.engine.search.rules.tie_key` orders them."""
    def key(entry: tuple[int, State, tuple[float, float, float]]) -> tuple[object, int]:
        g, cell, (cost, h, _) = entry
        by: dict[str, object] = {"fifo": 0, "lifo": -g, "node": cell, "low-h": h,
                                 "high-h": -h, "low-g": cost, "high-g": -cost}
        return by[rule], g

    return min(tied, key=key)[1]


__all__ = ["Causes", "Difference", "Suggestion", "swapped"]
