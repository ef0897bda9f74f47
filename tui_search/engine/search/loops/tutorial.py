"""The tutorial's hot paths: BFS and DFS, graph search, under the tutorial's rules.

Under the rules the tutorial teaches -- a cell is visited when generated, the goal tested when
generated -- and no corner rule in force, every step does the least work: no visit rule or goal
test to choose, every cell the same moves.  They are what the app runs by default, so they are
written for speed alone; :mod:`tui_search.engine.search.loops.general` serves every other choice.
The specification is the reference loop (:mod:`tui_search.engine.search.reference`); a hypothesis
test in ``tests/engine`` holds these equal to it, array for array.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator
from itertools import repeat

from tui_search.engine.search.loops.buffers import _Buffers
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import CHUNK, Record


def bfs(problem: Problem, rec: Record, chunk: int = CHUNK) -> Iterator[int]:
    """Breadth-first search with the tutorial's rules and no corner rule in force (the
    others go to :func:`general`).  The queue is implicit: BFS expands events in the order
    they were generated, so the queue at step k is events ``k .. step_end[k]-1``."""
    goal, offsets = problem.goal, problem.plain_moves
    closed = bytearray(problem.walls)
    gen_node = rec.gen_node
    gen_node.append(problem.start)
    closed[problem.start] = 1
    if problem.start == goal:
        rec.goal_gen, rec.done = 0, True
        return
    buf = _Buffers(rec)  # the new events and ends, written to the record before each slice
    nodes, ends = buf.nodes, buf.ends
    head, count, pause = 0, 1, chunk
    while head < count:
        buf.flush()  # the slice below must see every event generated so far
        # A chunk of the queue at a time: iterating a slice is cheaper than a counter per step.
        end = min(count, pause)  # never past the pause: chunks of exactly `chunk` steps
        for n in gen_node[head:end]:
            for off in offsets:
                m = n + off
                if closed[m]:
                    continue
                closed[m] = 1
                nodes.append(m)
                count += 1
                if m == goal:
                    ends.append(count)
                    buf.flush()
                    rec.goal_gen, rec.done = count - 1, True
                    return
            ends.append(count)
        head = end
        if head >= pause and head < count:
            buf.flush()
            pause = head + chunk
            yield head
    buf.flush()
    rec.done = True


def dfs(problem: Problem, rec: Record, chunk: int = CHUNK) -> Iterator[int]:
    """Depth-first search: the same loop with a LIFO stack (the same rules as :func:`bfs`).
    The stack holds each entry's cell beside its event, so a step reads no array; the chunk's
    new events, ends and expansions go to lists first (:func:`_flush`).

    Written for CPython's specialising interpreter: the lists' ``append`` and ``pop`` are
    called as methods (``cells.append(m)``, which 3.11 runs inline) rather than as bound
    methods kept in locals, and every cell tries the same moves (no corner mask to look up):
    fewer instructions a step, counted on a full traversal (benchmarks/README.md,
    "choices")."""
    goal, offsets = problem.goal, problem.plain_moves
    closed = bytearray(problem.walls)
    rec.step_exp = array("i", [-1])
    rec.gen_node.append(problem.start)
    closed[problem.start] = 1
    if problem.start == goal:
        rec.goal_gen, rec.done = 0, True
        return
    cells, events = [problem.start], [0]
    buf = _Buffers(rec)
    nodes, ends, exps = buf.nodes, buf.ends, buf.exps
    count = 1
    while cells:
        for _ in repeat(None, chunk):  # a chunk of steps, with no counter per step
            try:
                n = cells.pop()
            except IndexError:  # the stack is empty: the search is over
                break
            exps.append(events.pop())
            for off in offsets:
                m = n + off
                if closed[m]:
                    continue
                closed[m] = 1
                cells.append(m)
                events.append(count)
                nodes.append(m)
                count += 1
                if m == goal:
                    ends.append(count)
                    buf.flush()
                    rec.goal_gen, rec.done = count - 1, True
                    return
            ends.append(count)
        buf.flush()
        if cells:
            yield rec.steps
    rec.done = True
