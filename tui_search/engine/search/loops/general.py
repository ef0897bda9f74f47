"""BFS and DFS, graph search, under any choice the tutorial's loops do not serve.

Visit on expand (a cell closed when taken off; taking off a closed cell is a discarded step),
the goal tested on expand, or a corner rule (each cell's own moves): :func:`general` picks one
of four loops, a FIFO queue or a LIFO stack under each visit rule, so that no step tests a
choice.  The specification is the reference loop (:mod:`tui_search.engine.search.reference`); a
hypothesis test in ``tests/engine`` holds these equal to it, array for array.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator
from itertools import repeat

from tui_search.engine.search.loops.buffers import _Buffers, _flush
from tui_search.engine.search.problem import Problem, corner_free
from tui_search.engine.search.record import CHUNK, Record


def general(
    problem: Problem, rec: Record, chunk: int = CHUNK, lifo: bool = False
) -> Iterator[int]:
    """BFS (``lifo`` False) or DFS, graph search, under any visit rule, goal test and corner
    rule: visit on expand (a cell is closed when taken off, and taking off a closed cell is a
    discarded step), the goal tested on expand, or a corner rule (each cell's moves).  The goal
    tests compare with -1 (no cell) where they do not apply, so a step tests no choice."""
    sem = problem.semantics
    closed = bytearray(problem.walls)
    goal_on_push = problem.goal if problem.goal_test == "generate" else -1
    goal_on_pop = -1 if problem.goal_test == "generate" else problem.goal
    start = problem.start
    rec.gen_node.append(start)
    if start == goal_on_push:
        rec.goal_gen, rec.done = 0, True
        return
    if sem.visit == "generate":
        closed[start] = 1
        loop = _general_lifo if lifo else _general_fifo
    else:
        loop = _expand_lifo if lifo else _expand_fifo
    yield from loop(problem, rec, chunk, closed, goal_on_push, goal_on_pop)


# The loops of `general` are four, not one with a branch a step: FIFO takes the events in the
# order generated, so it walks the record like `bfs` (no queue, no counter); LIFO keeps a stack
# like `dfs`; and each is written once for each visit rule, so that no step tests the rule.
# Their successor loops are alike, but the split pays, against one deque serving both
# frontiers and against one loop testing the visit rule a step (benchmarks/README.md,
# "choices").  What is left over the bare floors: the record (an append or two a step, the
# events stack of LIFO); the run's peak-frontier table outside the loop
# (:meth:`~tui_search.engine.run.peak.PeakTable._max_size`).


def _plain_moves(problem: Problem) -> tuple[int, ...]:
    """For the loops of `general`: the moves every cell tries when no corner rule is in force,
    else ``()``; a loop tries ``plain or moves[mask[n]]``, so a corner-free search skips the
    two lookups a cell (the ``bytes`` subscript is no specialised one), which brings DFS
    visit on expand close to its recorded floor (benchmarks/README.md, "choices")."""
    return problem.plain_moves if corner_free(problem.semantics) else ()


def _general_fifo(problem: Problem, rec: Record, chunk: int, closed: bytearray,
                  goal_on_push: int, goal_on_pop: int) -> Iterator[int]:
    """`general` with a FIFO queue, visit on generate: events ``head .. count-1`` of the
    record, as in `bfs`."""
    moves, mask, gen_node = problem.moves, problem.mask, rec.gen_node
    plain = _plain_moves(problem)
    buf = _Buffers(rec)
    nodes, ends = buf.nodes, buf.ends
    head, count, pause = 0, 1, chunk
    while head < count:
        buf.flush()  # the slice below must see every event generated so far
        end = min(count, pause)  # never past the pause: chunks of exactly `chunk` steps
        for step, n in enumerate(gen_node[head:end], head + 1):  # step k expands event k-1
            if n == goal_on_pop:
                ends.append(count)
                buf.flush()
                rec.goal_gen, rec.done = step - 1, True
                return
            for off in plain or moves[mask[n]]:
                m = n + off
                if closed[m]:
                    continue
                closed[m] = 1
                nodes.append(m)
                count += 1
                if m == goal_on_push:
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


def _expand_fifo(problem: Problem, rec: Record, chunk: int, closed: bytearray,
                 goal_on_push: int, goal_on_pop: int) -> Iterator[int]:
    """`general` with a FIFO queue, visit on expand: a cell is closed when taken off; taking
    off a closed cell is a discarded step."""
    moves, mask, gen_node = problem.moves, problem.mask, rec.gen_node
    plain = _plain_moves(problem)
    buf = _Buffers(rec)
    nodes, ends, discarded = buf.nodes, buf.ends, buf.discarded
    head, count, pause = 0, 1, chunk
    while head < count:
        buf.flush()  # the slice below must see every event generated so far
        end = min(count, pause)  # never past the pause: chunks of exactly `chunk` steps
        for step, n in enumerate(gen_node[head:end], head + 1):  # step k expands event k-1
            if closed[n]:
                discarded.append(step)
                ends.append(count)
                continue
            closed[n] = 1
            if n == goal_on_pop:
                ends.append(count)
                buf.flush()
                rec.goal_gen, rec.done = step - 1, True
                return
            for off in plain or moves[mask[n]]:
                m = n + off
                if closed[m]:
                    continue
                nodes.append(m)
                count += 1
                if m == goal_on_push:
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


def _general_lifo(problem: Problem, rec: Record, chunk: int, closed: bytearray,
                  goal_on_push: int, goal_on_pop: int) -> Iterator[int]:
    """`general` with a LIFO stack of cells beside their events, as in `dfs`, visit on
    generate."""
    moves, mask = problem.moves, problem.mask
    plain = _plain_moves(problem)
    rec.step_exp = array("i", [-1])
    cells, events = [problem.start], [0]
    buf = _Buffers(rec)
    nodes, ends, exps = buf.nodes, buf.ends, buf.exps
    count = 1
    while cells:
        for _ in repeat(None, chunk):
            try:
                n = cells.pop()
            except IndexError:
                break
            g = events.pop()
            exps.append(g)
            if n == goal_on_pop:
                ends.append(count)
                buf.flush()
                rec.goal_gen, rec.done = g, True
                return
            for off in plain or moves[mask[n]]:
                m = n + off
                if closed[m]:
                    continue
                closed[m] = 1
                cells.append(m)
                events.append(count)
                nodes.append(m)
                count += 1
                if m == goal_on_push:
                    ends.append(count)
                    buf.flush()
                    rec.goal_gen, rec.done = count - 1, True
                    return
            ends.append(count)
        buf.flush()
        if cells:
            yield rec.steps
    rec.done = True


def _expand_lifo(problem: Problem, rec: Record, chunk: int, closed: bytearray,
                 goal_on_push: int, goal_on_pop: int) -> Iterator[int]:
    """`general` with a LIFO stack, visit on expand.  The stack holds events only, and the
    cell of every event of the run stays in a list (``cell_of``, the record's ``gen_node``
    as Python ints, written to it at each pause): a step reads its cell with a subscript
    rather than a second pop, and a push is one append fewer.  On a full traversal (four
    steps a cell, three of them discarded) this and the step numbers from the chunk's
    ``range`` cut the loop's instructions (benchmarks/README.md, "choices"); the price is
    memory while recording: every event's cell, as a Python int, where the stack held the
    cells of its entries only."""
    moves, mask = problem.moves, problem.mask
    plain = _plain_moves(problem)
    rec.step_exp = array("i", [-1])
    events = [0]
    gen_node = rec.gen_node
    cell_of = list(gen_node)  # the start
    buf = _Buffers(rec)
    ends, exps, discarded = buf.ends, buf.exps, buf.discarded

    def flush() -> None:
        buf.flush()
        _flush(gen_node, cell_of[len(gen_node):])

    count = 1
    while events:
        first = rec.steps + 1
        for step in range(first, first + chunk):  # the step's number, with no counter
            try:
                g = events.pop()
            except IndexError:
                break
            exps.append(g)
            n = cell_of[g]
            if closed[n]:
                discarded.append(step)
                ends.append(count)
                continue
            closed[n] = 1
            if n == goal_on_pop:
                ends.append(count)
                flush()
                rec.goal_gen, rec.done = g, True
                return
            for off in plain or moves[mask[n]]:
                m = n + off
                if closed[m]:
                    continue
                events.append(count)
                cell_of.append(m)
                count += 1
                if m == goal_on_push:
                    ends.append(count)
                    flush()
                    rec.goal_gen, rec.done = count - 1, True
                    return
            ends.append(count)
        flush()
        if events:
            yield rec.steps
    rec.done = True
