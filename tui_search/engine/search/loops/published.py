"""The recorded loop of the choices published code and students' code make that the tutorial's
loops and the compiled core do not: a priority queue's tie rules, a cost tolerance, a closed
set, recursion, tree search with no path check, an unmarked start, a node expanded again
(:meth:`~tui_search.engine.search.choices.Semantics.plain` is False) -- and IDA* under every
choice.

It records the reference loop itself (:class:`~tui_search.engine.search.reference.ReferenceSearch`,
the definition) into a :class:`~tui_search.engine.search.record.Record`, a chunk at a time: these
choices are the diagnosis's and a student's, on small maps mostly, so one loop serving them all
is worth more than a fast one each.  It records the searches on a graph too, but for the
priority queue's under the plain choices
(:mod:`~tui_search.engine.search.loops.graph_best_first`): the graphs a course draws are
small, and this loop is the definition itself.  A hypothesis test in
``tests/engine`` holds the record equal to the reference's steps, array for array, as it holds
the fast loops.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator

from tui_search.engine.search.graph_problem import GraphProblem
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import CHUNK, Record
from tui_search.engine.search.registry import Algorithm


def published(problem: Problem | GraphProblem, rec: Record, chunk: int = CHUNK, *,
              algorithm: Algorithm) -> Iterator[int]:
    """Record ``algorithm`` under ``problem``'s choices, as the reference loop runs it (on a
    grid or a graph: ``problem.board``)."""
    from tui_search.engine.search.reference import ReferenceSearch  # only for these choices

    search = ReferenceSearch(problem.board, algorithm, problem.semantics, problem.max_steps)
    pad = problem.pad
    gen_node, step_end = rec.gen_node, rec.step_end
    rec.step_exp = step_exp = array("i", [-1])
    step_g = gen_depth = None
    if algorithm.weighted:
        rec.step_g = step_g = array("d", [0.0])
    step_next = f_limits = None
    if algorithm.contours:  # IDA*: its limits on f, and the next one as it goes
        rec.iter_f_limit = f_limits = [search.space.priority("g+h")(0.0, search.space.start)]
        rec.step_next = step_next = array("d", [float("inf")])
    elif algorithm.iterative:
        rec.gen_depth = gen_depth = array("i", [0])
        rec.iter_limit[0] = 0
    gen_node.append(pad(search.space.start))
    pause = False  # a chunk ended: pause before the next step (none when the search ended)
    for step in search:
        if pause:
            yield rec.steps
            pause = False
        root = step.new_root
        if root is not None:
            rec.iter_first_step.append(step.index)
            rec.iter_root.append(len(gen_node))
            rec.iter_limit.append(step.depth_limit)
            if f_limits is not None and step.f_limit is not None:
                f_limits.append(step.f_limit)
            gen_node.append(pad(root.cell))
            if gen_depth is not None:
                gen_depth.append(0)
        step_exp.append(step.node.event)
        if step_g is not None:
            step_g.append(step.node.g)
        if step_next is not None:
            step_next.append(step.next_limit)
        for s in step.successors:
            gen_node.append(pad(s.cell))
            if gen_depth is not None:
                gen_depth.append(s.depth)
        step_end.append(len(gen_node))
        if step.discarded:
            rec.discarded.append(step.index)
        pause = step.index % chunk == 0
    if search.goal is not None:
        rec.goal_gen = search.goal.event
    rec.done = True


__all__ = ["published"]
