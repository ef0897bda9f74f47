"""A trace another program wrote (:mod:`~tui_search.engine.traces.read`) as a
:class:`~tui_search.engine.run.recorded.Run` like any other: its record is filled from the trace
instead of by a search, so every query the app asks of a run -- what each cell is, the
frontier, the tree, the narration -- answers for the student's search as for the app's own.

The trace says which cell each step expanded, not which entry of the frontier: where a cell
was added more than once (visit on expand, tree search, a cheaper path found) the replay takes
the entry that the matched search's discipline would (:func:`trace_loop`).  Its frontier is
kept in the order added (:class:`~tui_search.engine.run.frontier.AddedFrontier`): the trace does
not say its discipline.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable, Iterator

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import DELTAS, SQRT2, Grid
from tui_search.engine.run.recorded import MAX_STEPS, Run, Source
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.graph_problem import GraphProblem
from tui_search.engine.search.loops.dispatch import Loop
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import CHUNK, Record
from tui_search.engine.search.registry import Algorithm, Frontier, get_algorithm
from tui_search.engine.traces.read import Trace

#: What a replayed trace is to the app: not in the registry (no key, menu, setting or
#: ``--compare`` offers it), its frontier kept in the order added.
TRACE_ALGORITHM = Algorithm(
    "trace", "Your trace", "your trace", Frontier.ADDED, "",
    "a trace another program wrote, replayed: its frontier in the order added", "you")


def trace_loop(trace: Trace, pick: str = "oldest", infer_discards: bool = True) -> Loop:
    """The loop that fills a record from ``trace``: each step takes off an entry added
    earlier and not yet taken off whose cell is the one the trace expanded, and adds its
    successors in the trace's order.  Which entry, when the cell has several (``pick``):
    ``"oldest"`` (a queue's rule, and greedy best-first's, whose entries of one cell tie on
    h), ``"newest"`` (a stack's) or ``"cheapest"``, the lowest path cost so far, the oldest
    of a tie (uniform-cost's and A*'s: entries of one cell share their h).

    A step that says ``"discarded": true`` is a discarded step, and so, with
    ``infer_discards`` (not for tree search, iterative deepening or a priority queue, which
    may expand a cell again), is one that takes off a cell already expanded and adds nothing.  A
    step that expands the start when no entry of it is left begins a new iteration from it
    (iterative deepening's restart); a cell expanded again with no entry left takes its latest entry
    again.  The goal is found where the trace expanded it, else (goal test on generate) where it
    first added it."""

    def loop(problem: Problem | GraphProblem, rec: Record, chunk: int = CHUNK) -> Iterator[int]:
        pad = problem.pad
        rec.step_exp = step_exp = array("i", [-1])
        gen_node, step_end = rec.gen_node, rec.step_end
        gen_node.append(problem.start)
        # cell -> its open events, oldest first
        open_of: dict[int, list[int]] = {problem.start: [0]}
        latest: dict[int, int] = {problem.start: 0}
        costs = _costs(problem) if pick == "cheapest" else None
        gs = [0.0]  # each event's path cost (the cheapest pick only)
        expanded: set[int] = set()
        goal_added = -1
        for k, t in enumerate(trace.steps, 1):
            n = pad(t.node)
            entries = open_of.get(n)
            if not entries and n == problem.start:  # a new iteration from the start
                root = len(gen_node)
                gen_node.append(n)
                rec.iter_first_step.append(k)
                rec.iter_root.append(root)
                rec.iter_limit.append(None)
                open_of, latest, expanded = {n: [root]}, {n: root}, set()
                entries = open_of[n]
            discard = t.discarded or (infer_discards and n in expanded and not t.successors)
            if entries:
                at = {"oldest": 0, "newest": -1}.get(pick)
                if at is None:
                    at = min(range(len(entries)), key=lambda i: (gs[entries[i]], i))
                e = entries.pop(at)
            else:
                e = latest[n]
            step_exp.append(e)
            if discard:
                rec.discarded.append(k)
            else:
                expanded.add(n)
            for cell in t.successors:
                m = pad(cell)
                g = len(gen_node)
                gen_node.append(m)
                open_of.setdefault(m, []).append(g)
                latest[m] = g
                if costs is not None:
                    gs.append(gs[e] + costs(n, m))
                if goal_added < 0 and problem.is_goal(m):
                    goal_added = g
            step_end.append(len(gen_node))
            if not discard and problem.is_goal(n):
                rec.goal_gen = e
            if k % chunk == 0:
                yield k
        if rec.goal_gen < 0 and problem.goal_test == "generate":
            rec.goal_gen = goal_added
        rec.done = True

    return loop


def _costs(problem: Problem | GraphProblem) -> Callable[[int, int], float]:
    """The cost of a move between two padded cells: the loops' floats (1 straight, sqrt(2)
    diagonally, times the cell's terrain cost), for any move a trace makes; on a graph the
    road's cost (1 where a trace takes a road the graph does not have)."""
    if isinstance(problem, GraphProblem):
        graph_problem = problem

        def road(n: int, m: int) -> float:
            try:
                return graph_problem.step_cost(n, m)
            except KeyError:
                return 1.0

        return road
    lengths = {dy * problem.stride + dx: SQRT2 if dx and dy else 1.0
               for dx, dy in DELTAS.values()}
    terrain = problem.terrain

    def cost(n: int, m: int) -> float:
        length = lengths.get(m - n, 1.0)
        return length if terrain is None else length * terrain[m]

    return cost


def trace_run(trace: Trace, grid: Grid | Graph, algorithm: str, semantics: Semantics,
              max_steps: int = MAX_STEPS, notes: tuple[str, ...] = ()) -> Run:
    """``trace`` on ``grid`` as a run, beside the search it is matched with (``algorithm``
    under ``semantics``): that search's discipline picks the entries (:func:`trace_loop`),
    its choices are the run's (the narration's words), its goal test the run's.  ``notes``:
    what its status line says of its rules (the trace declares none: not the search's)."""
    algo = get_algorithm(algorithm)
    pick = ("newest" if algo.frontier is Frontier.LIFO
            else "cheapest" if algo.priority in ("g", "g+h") else "oldest")
    # A priority queue's search may expand a cell again, adding nothing (greedy reopens a
    # cell reached by a cheaper path): only a trace's own "discarded" says it discarded one.
    infer = not (semantics.tree_search or algo.iterative or algo.frontier is Frontier.PRIORITY)
    loop = trace_loop(trace, pick, infer_discards=infer)
    # the choices the trace's own run can take (a priority queue's and recursion are the
    # search's: the trace's frontier is as added)
    sem = semantics.replace(goal_test=semantics.goal_test_for(algo)).fitted(TRACE_ALGORITHM)
    return Run(grid, TRACE_ALGORITHM.key, sem, max_steps, Source(TRACE_ALGORITHM, loop, notes))


__all__ = ["TRACE_ALGORITHM", "trace_loop", "trace_run"]
