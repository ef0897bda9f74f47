"""The bare searches the engine is measured against: the fastest plain-Python BFS (and DFS) we
could write, with the engine's semantics, so they find paths of the same length."""

from __future__ import annotations

from array import array
from collections import deque
from itertools import repeat
from struct import pack
from typing import NamedTuple

from tui_search.engine.maps.grid import DEFAULT_ORDER, DELTAS, Grid


def pad(grid: Grid) -> tuple[bytearray, int, int, int, tuple[int, ...]]:
    """The engine's technique, written out: walls with a one-cell wall border, flat indices,
    the eight neighbour offsets in the default order."""
    w, h = grid.width, grid.height
    stride = w + 2
    walls = bytearray(b"\x01") * (stride * (h + 2))
    for y in range(h):
        row = (y + 1) * stride + 1
        walls[row : row + w] = grid.blocked[y * w : (y + 1) * w]
    start = (grid.start[1] + 1) * stride + grid.start[0] + 1
    goal = (grid.goal[1] + 1) * stride + grid.goal[0] + 1
    offs = tuple(DELTAS[d][1] * stride + DELTAS[d][0] for d in DEFAULT_ORDER)
    return walls, stride, start, goal, offs


def bare_search(grid: Grid, lifo: bool = False) -> list[int]:
    """The fastest plain-Python BFS we could write: a deque, a closed bytearray (the padded
    walls themselves), a parent list; no recording.  Same semantics as the engine (mark and
    goal-test on generation, neighbours in the default order), so the same path.  With
    ``lifo`` the deque is a stack: the engine's DFS, same path again."""
    closed, _, start, goal, offs = pad(grid)
    parent = [-1] * len(closed)
    if start == goal:
        return parent
    q = deque([start])
    closed[start] = 1
    pop, push = (q.pop if lifo else q.popleft), q.append
    while q:
        n = pop()
        for off in offs:
            m = n + off
            if closed[m]:
                continue
            closed[m] = 1
            parent[m] = n
            if m == goal:
                return parent
            push(m)
    return parent


def bare_search_visit_on_expand(grid: Grid, lifo: bool = False) -> list[int]:
    """The floor of "visit on expand": the same bare loop, but a cell is closed when popped,
    so it is pushed once per neighbour that reaches it first (several times the work of
    :func:`bare_search`); popping a closed cell is skipped.  The parent is the entry popped
    first: for FIFO the first push of the cell (kept), for LIFO its last (overwritten).  The
    goal is tested when pushed, as in the engine's loop for this choice."""
    closed, _, start, goal, offs = pad(grid)
    parent = [-1] * len(closed)
    if start == goal:
        return parent
    q = deque([start])
    pop, push = (q.pop if lifo else q.popleft), q.append
    while q:
        n = pop()
        if closed[n]:
            continue
        closed[n] = 1
        for off in offs:
            m = n + off
            if closed[m]:
                continue
            if lifo or parent[m] < 0:
                parent[m] = n
            if m == goal:
                return parent
            push(m)
    return parent


class BareRecord(NamedTuple):
    """What a recorded run keeps of a DFS, the arrays of the engine's ``Record``: each
    event's cell, each step's end and expanded event, the discarded steps (visit on expand),
    and the event that generated the goal (-1: not found)."""

    gen_node: array
    step_end: array
    step_exp: array
    discarded: array
    goal_gen: int


#: Steps between two packings of the floors' lists into their arrays (the engine's chunk).
PACK_EVERY = 4096


def _pack(out: tuple[array, ...], bufs: tuple[list[int], ...]) -> None:
    """Append each list to its array as one ``struct.pack`` (``array.append`` converts
    each int through ``PyArg_Parse``) and empty it."""
    for arr, buf in zip(out, bufs, strict=True):
        arr.frombytes(pack(f"{len(buf)}i", *buf))
        buf.clear()


def bare_dfs_recorded(grid: Grid) -> BareRecord:
    """The floor of a *recorded* DFS: :func:`bare_dfs` plus the least record that lets an
    app move to any step -- each event's cell, each step's end and the event it expanded,
    the same arrays as the engine's ``Record`` -- with no generator, chunk buffers or
    ``Run``.  A stack of cells beside a stack of their events, one list append per value
    recorded, and the lists packed into the arrays every :data:`PACK_EVERY` steps.  The
    fastest of the forms we tried (callgrind, full traversal of open 256², × a bare BFS):
    this 1.23; the events-only stack reading the cell from a list of every event's cell
    1.20 in instructions but no faster in CPU time on open 1024²; lists kept for the whole
    run and made arrays at the end 1.28; preallocated lists written by index 1.31."""
    closed, _, start, goal, offs = pad(grid)
    out = (array("i", [start]), array("i", [1]), array("i", [-1]))
    nodes: list[int] = []
    ends: list[int] = []
    exps: list[int] = []
    bufs = (nodes, ends, exps)
    closed[start] = 1
    cells, events = [start], [0]
    count = 1
    if start == goal:
        return BareRecord(*out, array("i"), 0)
    while cells:
        for _ in repeat(None, PACK_EVERY):
            try:
                n = cells.pop()
            except IndexError:
                break
            exps.append(events.pop())
            for off in offs:
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
                    _pack(out, bufs)
                    return BareRecord(*out, array("i"), count - 1)
            ends.append(count)
        _pack(out, bufs)
    return BareRecord(*out, array("i"), -1)


def bare_dfs_visit_on_expand_recorded(grid: Grid) -> BareRecord:
    """The floor of a recorded DFS with visit on expand: :func:`bare_search_visit_on_expand`
    (LIFO) plus the same record as :func:`bare_dfs_recorded` and the discarded steps.  A
    stack of events only, every event's cell in a list (a step reads its cell by subscript),
    the step numbers from a ``range``, the lists packed every :data:`PACK_EVERY` steps: on
    open 1024² the fastest in CPU time of the three forms tried (a stack of cells beside the
    events, or the lists made arrays only at the end, were 0.3-0.6x a bare BFS slower)."""
    closed, _, start, goal, offs = pad(grid)
    out = (array("i"), array("i", [1]), array("i", [-1]), array("i"))
    cell_of = [start]
    ends: list[int] = []
    exps: list[int] = []
    disc: list[int] = []

    def packed(goal_gen: int) -> BareRecord:
        _pack(out, (cell_of[len(out[0]):], ends, exps, disc))
        return BareRecord(*out, goal_gen)

    if start == goal:
        return packed(0)
    events = [0]
    count, steps = 1, 0
    while events:
        for step in range(steps + 1, steps + 1 + PACK_EVERY):  # the step numbers, no counter
            try:
                g = events.pop()
            except IndexError:
                break
            exps.append(g)
            n = cell_of[g]
            if closed[n]:
                disc.append(step)
                ends.append(count)
                continue
            closed[n] = 1
            for off in offs:
                m = n + off
                if closed[m]:
                    continue
                events.append(count)
                cell_of.append(m)
                count += 1
                if m == goal:
                    ends.append(count)
                    return packed(count - 1)
            ends.append(count)
        steps += PACK_EVERY
        packed(-1)
    return packed(-1)


def walled_in(grid: Grid) -> Grid:
    """A copy with every free neighbour of the goal blocked: no search finds the goal, so a
    BFS or DFS traverses everything it can reach (the "full traversal" rows)."""
    out = grid.copy()
    gx, gy = out.goal
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            cell = (gx + dx, gy + dy)
            if (dx or dy) and out.is_free(cell) and cell != out.start:
                out.set_blocked(cell, True)
    return out


def bare_bfs(grid: Grid) -> list[int]:
    return bare_search(grid)


def bare_dfs(grid: Grid) -> list[int]:
    return bare_search(grid, lifo=True)


def bare_path_len(grid: Grid, parent: list[int]) -> int:
    _, _, start, goal, _ = pad(grid)
    n, moves = goal, 0
    while n != start:
        n = parent[n]
        if n < 0:
            return -1
        moves += 1
    return moves
