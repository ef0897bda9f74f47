"""Tree search with a queue or a stack: no visited set, only the node's own path is checked.

Tree search is exponential by nature (a run stops at its step limit), so its loop is written
plainly; it exists because the app teaches what graph search saves.  :class:`Path` serves
every tree search (iterative deepening's and the priority queue's too).  The specification is
the reference loop (:mod:`tui_search.engine.search.reference`); a hypothesis test in
``tests/engine`` holds this equal to it, array for array.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator

from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import CHUNK, Record


class Path:
    """Tree search: the cells on the path from the root to one event (the node being
    expanded), kept as a flag per cell while the walk moves from event to event -- up to
    their common ancestor and down again -- so "is this cell on the node's own path" costs
    one look-up, not a walk to the root per successor (which made a deep DFS quadratic).
    Moving costs the tree distance between two expansions: one or two steps for a stack,
    amortized little for a queue, which takes a level's nodes in tree order.  A path's cells
    are distinct (tree search never adds a cell on its own path), so a flag is enough."""

    __slots__ = ("cur", "depth", "gen_node", "on", "parent")

    def __init__(self, cells: int, gen_node: array[int]) -> None:
        self.on = bytearray(cells)
        self.gen_node = gen_node
        self.parent = array("i")  # event -> the event it was generated from (-1: a root)
        self.depth = array("i")
        self.cur = -1  # the event whose path is flagged (-1: none)

    def add(self, g: int) -> None:
        """The next event was generated from event ``g`` (-1: it is a root)."""
        self.parent.append(g)
        self.depth.append(self.depth[g] + 1 if g >= 0 else 0)

    def move_to(self, g: int) -> bytearray:
        """Flag the path from the root to event ``g`` (``g`` included); the flags, by cell."""
        on, parent, depth, cell = self.on, self.parent, self.depth, self.gen_node
        a, b = self.cur, g
        da, db = (depth[a] if a >= 0 else -1), depth[b]
        down = []
        while da > db:
            on[cell[a]] = 0
            a = parent[a]
            da -= 1
        while db > da:
            down.append(b)
            b = parent[b]
            db -= 1
        while a != b:
            on[cell[a]] = 0
            a = parent[a]
            down.append(b)
            b = parent[b]
        for x in down:
            on[cell[x]] = 1
        self.cur = g
        return on


def tree(problem: Problem, rec: Record, chunk: int = CHUNK, lifo: bool = False
         ) -> Iterator[int]:
    """BFS (``lifo`` False) or DFS as tree search: no visited set, a successor on the node's
    own path is skipped; the goal tested on generate or on expand.  Exponential by nature (a
    run stops at its step limit), so written plainly."""
    goal, moves, mask, walls = problem.goal, problem.moves, problem.mask, problem.walls
    test_on_push = problem.goal_test == "generate"
    gen_node = rec.gen_node
    path = Path(len(walls), gen_node)  # the node's own path, for "on the path"
    path.add(-1)
    if lifo:
        rec.step_exp = step_exp = array("i", [-1])
    add, add_end, add_parent = gen_node.append, rec.step_end.append, path.add
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
        on_path = path.move_to(g)
        if not test_on_push and n == goal:
            add_end(count)
            rec.goal_gen, rec.done = g, True
            return
        for off in moves[mask[n]]:
            m = n + off
            if walls[m] or on_path[m]:
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
