"""A student's ``search.py`` as a trace: the problem the app gives it, in the course's
conventions, and each ``getSuccessors`` call it made as an expansion.

The problem (:func:`student_problem`): on a map, Pacman's (x, y) with y from the bottom row,
successors North, South, East, West, each move costing 1 (or a course test's cost function);
on a graph, its roads in the file's order, each named by the test's action (``A->B`` for a
``.graph`` file's).  :func:`as_trace` turns the states the student's code asked the successors
of into an expansions-only trace (:mod:`~tui_search.engine.traces.read`), checked as any other;
a state that is not the problem's is refused by the parent, whatever the child said.
"""

from __future__ import annotations

import json
from typing import cast

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.traces.read import Trace, read_trace

#: A graph's actions by (from, to): a course test's names for its edges.
Actions = dict[tuple[str, str], str]

__all__ = ["FUNCTIONS", "MAX_EXPANSIONS", "NO_PATH", "as_trace", "has_path", "path_found",
           "path_words", "student_problem"]

#: The course's search functions by the app's keys.
FUNCTIONS = {"dfs": "depthFirstSearch", "bfs": "breadthFirstSearch",
             "ucs": "uniformCostSearch", "astar": "aStarSearch"}
#: At most this many getSuccessors calls are recorded (then the student's run is stopped).
MAX_EXPANSIONS = 1_000_000
_MOVES = {"North": (0, -1), "South": (0, 1), "East": (1, 0), "West": (-1, 0)}
#: What an empty answer (``[]``, or ``None`` as the course allows) comes to where no path is.
NO_PATH = "none, and no path to the goal exists: right"


def student_problem(board: Grid | Graph, algorithm: str, heuristic: str,
                    actions: Actions | None = None, cost_fn: str = "1") -> dict[str, object]:
    """What the child builds its problem from (JSON): the start, the goals, the walls or the
    roads (``actions``: a course test's names of them), the function to run, A*'s heuristic
    (the app's name; a graph's table) and the course's cost function (``0.5 ** x``)."""
    spec: dict[str, object] = {"function": FUNCTIONS[algorithm], "max_expansions": MAX_EXPANSIONS}
    if isinstance(board, Grid):
        assert board.start is not None and board.goal is not None
        h = board.height
        spec.update(kind="grid", start=[board.start[0], h - 1 - board.start[1]],
                    goals=[[board.goal[0], h - 1 - board.goal[1]]],
                    walls=["".join("%" if board.is_blocked((x, y)) else " "
                                   for x in range(board.width)) for y in range(h)],
                    heuristic=heuristic,
                    column_cost={"0.5 ** x": 0.5, "2 ** x": 2.0}.get(cost_fn, 1.0),
                    path_exists=has_path(board))
        return spec
    actions = actions or {}
    roads: dict[str, list[list[object]]] = {}
    for name in board.names:
        roads[name] = [[actions.get((name, b), f"{name}->{b}"), b, cost]
                       for b, cost, _ in board.successors(name)]
    table = board.h if heuristic == "table" else None
    spec.update(path_exists=has_path(board))
    spec.update(kind="graph", start=board.start, goals=list(board.goals), roads=roads,
                heuristic=table)
    return spec


def as_trace(board: Grid | Graph, expanded: list[object], name: str) -> Trace:
    """The states asked of, as an expansions-only trace of ``board`` (``name``: the student's
    file, for the messages); a state not on the board is a MapError."""
    lines = []
    for state in expanded:
        if isinstance(board, Grid):
            ok = (isinstance(state, list) and len(state) == 2
                  and all(isinstance(v, int) for v in state))
            node: object = [state[0], board.height - 1 - state[1]] if ok else None  # type: ignore[index]
        else:
            node = state if isinstance(state, str) else None
        lines.append(json.dumps({"node": node}))
    return read_trace("\n".join(lines) + "\n", board, name)


def has_path(board: Grid | Graph) -> bool:
    """Whether the problem has a path from its start to a goal (the course's moves: N, S, E,
    W on a map; a graph's roads as directed)."""
    seen: set[object] = set()
    if isinstance(board, Grid):
        todo: list[object] = [board.start]
        goals: set[object] = {board.goal}
    else:
        todo, goals = [board.start], set(board.goals)
    while todo:
        state = todo.pop()
        if state in goals:
            return True
        if state in seen:
            continue
        seen.add(state)
        if isinstance(board, Grid):
            x, y = cast("tuple[int, int]", state)
            for dx, dy in _MOVES.values():
                cell = (x + dx, y + dy)
                if board.in_bounds(cell) and not board.is_blocked(cell):
                    todo.append(cell)
        else:
            todo.extend(b for b, _, _ in board.successors(str(state)))
    return False


def path_found(words: str) -> bool:
    """Whether :func:`path_words` says the answer is right."""
    return words.endswith("a path to the goal") or words == NO_PATH


def path_words(board: Grid | Graph, actions: list[str], names: Actions | None = None) -> str:
    """What the returned actions come to: a path to the goal and its cost, or where they go
    wrong (none, :data:`NO_PATH`, is right where there is no path)."""
    if not actions and not has_path(board):
        return NO_PATH
    if isinstance(board, Grid):
        assert board.start is not None
        x, y = board.start
        for k, action in enumerate(actions, 1):
            if action not in _MOVES:
                return f"action {k}, {action[:30]!r}, is not North, South, East or West"
            dx, dy = _MOVES[action]
            x, y = x + dx, y + dy
            if not board.in_bounds((x, y)) or board.is_blocked((x, y)):
                return f"action {k}, {action}, walks into a wall"
        if (x, y) != board.goal:
            return f"the {len(actions)} actions end at ({x}, {board.height - 1 - y}), not the goal"
        return f"{len(actions)} actions, a path to the goal"
    by_action = {}
    for name in board.names:
        for b, _, _ in board.successors(name):
            action = (names or {}).get((name, b)) or f"{name}->{b}"
            by_action[(name, action)] = b
    state = board.start
    for k, action in enumerate(actions, 1):
        nxt = by_action.get((str(state), action))
        if nxt is None:
            return f"action {k}, {action[:30]!r}, is not one of {state}'s"
        state = nxt
    if state not in board.goals:
        return f"the {len(actions)} actions end at {state}, not a goal"
    return f"{len(actions)} actions, a path to the goal"
