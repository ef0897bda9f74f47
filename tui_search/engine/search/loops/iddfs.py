"""Iterative deepening: depth-limited DFS with limits 0, 1, 2, ..., one loop for every choice.

Its record has an iteration per limit, each from a new root event, and each event's depth
(:class:`~tui_search.engine.search.record.Record`'s ``gen_depth`` and ``iter_*``).  The
specification is the reference loop (:mod:`tui_search.engine.search.reference`); a hypothesis test
in ``tests/engine`` holds this equal to it, array for array.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator

from tui_search.engine.search.loops.tree import Path
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import CHUNK, Record


def _new_iteration(rec: Record, gen_depth: array[int], path: Path, tree: bool, start: int,
                   limit: int) -> int:
    """Begin iteration ``limit`` (its first step, its root, its limit) with a new root event
    at the start, at depth 0 (``gen_depth``: the record's); the root's event number."""
    root = len(rec.gen_node)
    if limit:
        rec.iter_first_step.append(len(rec.step_end))
        rec.iter_root.append(root)
        rec.iter_limit.append(limit)
    else:
        rec.iter_limit[0] = 0
    rec.gen_node.append(start)
    gen_depth.append(0)
    if tree:
        path.add(-1)
    return root


def iddfs(problem: Problem, rec: Record, chunk: int = CHUNK) -> Iterator[int]:
    """Iterative deepening: depth-limited DFS with limits 0, 1, 2, ...

    Within an iteration a cell is generated again only when it is reached at a smaller depth
    than before (it is *re-opened*); a node popped at the depth limit is expanded with no
    successors.  So iteration L reaches every cell within L moves, the goal is first found in
    iteration L = its distance, and the path has the fewest moves -- the same length as BFS.
    The search stops with no path when an iteration cuts nothing off at its limit.  With tree
    search a successor is skipped only when it is on the node's own path (depth-limited search
    with path checking); the goal may be tested when taken off instead of when pushed.
    """
    sem = problem.semantics
    tree, test_on_push = sem.tree_search, problem.goal_test == "generate"
    walls, goal, moves, mask = problem.walls, problem.goal, problem.moves, problem.mask
    gen_node = rec.gen_node
    rec.gen_depth = gen_depth = array("i")
    rec.step_exp = array("i", [-1])
    path = Path(len(walls), gen_node)  # tree search: the node's own path, for "on the path"
    add, add_depth = gen_node.append, gen_depth.append
    add_exp, add_end = rec.step_exp.append, rec.step_end.append
    start = problem.start
    steps, pause, limit = 0, chunk, 0
    while True:
        root = _new_iteration(rec, gen_depth, path, tree, start, limit)
        if test_on_push and start == goal:
            rec.goal_gen, rec.done = root, True
            return
        best = {start: 0}
        stack = [root]
        cut_off = False
        while stack:
            g = stack.pop()
            n = gen_node[g]
            depth = gen_depth[g]
            if not test_on_push and n == goal:
                add_exp(g)
                add_end(len(gen_node))
                rec.goal_gen, rec.done = g, True
                return
            if depth >= limit:
                cut_off = True
            else:
                child_depth = depth + 1
                on_path = path.move_to(g) if tree else None
                for off in moves[mask[n]]:
                    m = n + off
                    if walls[m]:
                        continue
                    if on_path is not None:
                        if on_path[m]:
                            continue
                        path.add(g)
                    elif best.get(m, limit + 1) <= child_depth:
                        continue
                    else:
                        best[m] = child_depth
                    stack.append(len(gen_node))
                    add(m)
                    add_depth(child_depth)
                    if test_on_push and m == goal:
                        add_exp(g)
                        add_end(len(gen_node))
                        rec.goal_gen, rec.done = len(gen_node) - 1, True
                        return
            add_exp(g)
            add_end(len(gen_node))
            steps += 1
            if steps == pause:
                pause += chunk
                if stack or cut_off:  # not when this step ended the search
                    yield steps
        if not cut_off:
            rec.done = True
            return
        limit += 1
