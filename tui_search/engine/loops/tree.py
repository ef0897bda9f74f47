"""Tree search with a queue or a stack: no visited set, only the node's own path is checked.

Tree search is exponential by nature (a run stops at its step limit), so its loop is written
plainly; it exists because the app teaches what graph search saves.  :func:`_on_path` serves
every tree search (iterative deepening's and the priority queue's too).  The specification is
the reference loop (:mod:`tui_search.engine.reference`); a hypothesis test in ``tests/engine``
holds this equal to it, array for array.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator

from tui_search.engine.problem import Problem
from tui_search.engine.record import CHUNK, Record


def _on_path(cell: int, g: int, gen_node: array[int], parent: array[int]) -> bool:
    """Tree search: is ``cell`` on the path from the root to event ``g`` (``g`` included)?"""
    while g >= 0:
        if gen_node[g] == cell:
            return True
        g = parent[g]
    return False


def tree(problem: Problem, rec: Record, chunk: int = CHUNK, lifo: bool = False
         ) -> Iterator[int]:
    """BFS (``lifo`` False) or DFS as tree search: no visited set, a successor on the node's
    own path is skipped; the goal tested on generate or on expand.  Exponential by nature (a
    run stops at its step limit), so written plainly."""
    goal, moves, mask, walls = problem.goal, problem.moves, problem.mask, problem.walls
    test_on_push = problem.goal_test == "generate"
    gen_node = rec.gen_node
    parent = array("i", [-1])  # walked to test "on the node's own path"
    if lifo:
        rec.step_exp = step_exp = array("i", [-1])
    add, add_end, add_parent = gen_node.append, rec.step_end.append, parent.append
    start = problem.start
    add(start)
    if test_on_push and start == goal:
        rec.goal_gen, rec.done = 0, True
        return
    stack = [0]  # LIFO: the stack of events
    head, count = 0, 1  # FIFO: events head .. count-1 are the queue, in generation order
    steps = 0
    while (stack if lifo else head < count):
        if lifo:
            g = stack.pop()
            step_exp.append(g)
        else:
            g = head
            head += 1
        n = gen_node[g]
        steps += 1
        if not test_on_push and n == goal:
            add_end(count)
            rec.goal_gen, rec.done = g, True
            return
        for off in moves[mask[n]]:
            m = n + off
            if walls[m] or _on_path(m, g, gen_node, parent):
                continue
            add_parent(g)
            if lifo:
                stack.append(count)
            add(m)
            count += 1
            if test_on_push and m == goal:
                add_end(count)
                rec.goal_gen, rec.done = count - 1, True
                return
        add_end(count)
        if steps % chunk == 0 and (stack if lifo else head < count):
            yield steps
    rec.done = True
