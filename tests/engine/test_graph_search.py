"""The app's searches on graphs (the reference loop over a graph's space, recorded as a run)
equal, step by step, the searches written again with no tui_search in
tests/engine/graph_searches.py, on random graphs, for every algorithm and the choices that
apply to it (order, visit, goal test, tree search, the table, zero or the straight line, every
tie rule, re-opening or a closed set, the start marked or not); and the book's figures on
Romania."""

from __future__ import annotations

from math import hypot
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.engine.graph_searches import (
    Roads,
    iterative_deepening,
    priority_search,
    queue_search,
)
from tui_search.engine.maps.graph import Edge, Graph
from tui_search.engine.maps.graph_file import built_in_graph
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import TIE_RULES, Semantics

NAMES = ["Mo", "Al", "Zed", "Cy", "Bo", "Xi", "Di", "Ed"]
LIMIT = 120  # steps compared (tree search may take many more on a graph with cycles)


@st.composite
def graphs(draw: st.DrawFn) -> dict[str, Any]:
    """A graph of 2 to 8 nodes, named out of alphabetical order, with roads both ways and one
    way in any order, costs 1 to 9, a table of estimates, some closed nodes; start and goal
    apart."""
    n = draw(st.integers(2, 8))
    names = draw(st.permutations(NAMES))[:n]
    road = st.tuples(st.integers(0, n - 1), st.integers(0, n - 1), st.integers(1, 9),
                     st.booleans())
    # a chain through every node first (most graphs connected), then roads anywhere
    chain = draw(st.permutations(range(n)))
    costs = draw(st.lists(st.integers(1, 9), min_size=n - 1, max_size=n - 1))
    pairs = [(chain[i], chain[i + 1], costs[i], False) for i in range(n - 1)]
    pairs += draw(st.lists(road, max_size=16))
    pairs = draw(st.permutations(pairs))  # the file's order
    seen: set[tuple[int, int]] = set()
    edges = []
    for a, b, cost, directed in pairs:
        if a == b or (a, b) in seen or (not directed and (b, a) in seen):
            continue
        seen.add((a, b))
        if not directed:
            seen.add((b, a))
        edges.append(Edge(a, b, float(cost), directed))
    start, goal = draw(st.lists(st.sampled_from(names), min_size=2, max_size=2, unique=True))
    closed = draw(st.sets(st.sampled_from([m for m in names if m != start]), max_size=2))
    h = {m: float(draw(st.integers(0, 20))) for m in names}
    places = [(float(draw(st.integers(0, 9))), float(draw(st.integers(0, 9)))) for _ in names]
    return {"names": names, "edges": edges, "start": start, "goal": goal,
            "closed": frozenset(closed), "h": h, "places": places}


def app_graph(g: dict[str, Any]) -> Graph:
    return Graph.of(g["names"], g["edges"], h=g["h"], places=g.get("places"),
                    start=g["start"], goals=(g["goal"],), closed=g["closed"])


def straight_line(g: dict[str, Any]) -> Any:
    """The euclidean estimate written again: the straight line to the goal times the least
    cost a unit of road length (so that it never says more than a road costs)."""
    names, places = g["names"], g["places"]
    ratios = [e.cost / length for e in g["edges"]
              if (length := hypot(places[e.a][0] - places[e.b][0],
                                  places[e.a][1] - places[e.b][1])) > 0]
    scale = min(ratios, default=1.0)
    gx, gy = places[names.index(g["goal"])]

    def h(node: str) -> float:
        x, y = places[names.index(node)]
        return scale * min([hypot(x - gx, y - gy)])

    return h


def roads_of(g: dict[str, Any], by_name: bool) -> Roads:
    """Each node's roads in the file's order (a road both ways listed at both ends), without
    the closed nodes; sorted by name for ``--order name``."""
    names, closed = g["names"], g["closed"]
    roads: Roads = {m: [] for m in names}
    for e in g["edges"]:
        a, b = names[e.a], names[e.b]
        if b not in closed:
            roads[a].append((b, e.cost))
        if not e.directed and a not in closed:
            roads[b].append((a, e.cost))
    if by_name:
        for m in roads:
            roads[m].sort(key=lambda road: road[0])
    return roads


def app_steps(graph: Graph, key: str, sem: Semantics) -> tuple[list[Any], list[Any] | None]:
    run = Run(graph, key, sem, LIMIT)
    steps = [(s.node, tuple(state for _, state in s.successors), s.discarded)
             for s in run.steps.all()]
    return steps, run.outcome().path


def both(g: dict[str, Any], key: str, order: str, **choices: Any) -> None:
    sem = Semantics(order=(order,), **choices)
    roads = roads_of(g, order == "name")
    start, goals = g["start"], {g["goal"]}
    goal_test = choices.get("goal_test") or ("expand" if key in ("ucs", "greedy", "astar")
                                             else "generate")
    tree = choices.get("tree_search", False)
    if key in ("bfs", "dfs"):
        want = queue_search(roads, start, goals, key == "dfs", choices.get("visit", "generate"),
                            goal_test, tree, LIMIT)
    elif key == "iddfs":
        want = iterative_deepening(roads, start, goals, LIMIT)
    else:
        priority = {"ucs": "g", "greedy": "h", "astar": "g+h"}[key]
        h = {"table": lambda node: g["h"][node], "zero": lambda node: 0.0,
             "euclidean": straight_line(g) if "places" in g else None}[
            choices.get("heuristic", "table")]
        want = priority_search(roads, start, goals, priority, h, goal_test, tree, LIMIT,
                               choices.get("ties", "fifo"), choices.get("reopen", True),
                               choices.get("mark_start", True))
    got = app_steps(app_graph(g), key, sem)
    assert got[0] == want[0]
    if len(want[0]) < LIMIT:  # the search ended within the steps compared
        assert got[1] == want[1]


ORDERS = st.sampled_from(["file", "name"])
GOAL_TESTS = st.sampled_from(["generate", "expand"])


@settings(max_examples=150)
@given(graphs(), st.sampled_from(["bfs", "dfs"]), ORDERS, st.sampled_from(["generate", "expand"]),
       GOAL_TESTS, st.booleans())
def test_bfs_and_dfs_equal_the_plain_searches(g: dict[str, Any], key: str, order: str,
                                              visit: str, goal_test: str, tree: bool) -> None:
    choices: dict[str, Any] = {"goal_test": goal_test, "tree_search": tree}
    if not tree:
        choices["visit"] = visit
    both(g, key, order, **choices)


@settings(max_examples=200)
@given(graphs(), st.sampled_from(["ucs", "greedy", "astar"]), ORDERS, GOAL_TESTS,
       st.booleans(), st.sampled_from(["table", "zero", "euclidean"]),
       st.sampled_from(TIE_RULES),
       st.booleans(), st.booleans())
def test_the_priority_searches_equal_the_plain_ones(g: dict[str, Any], key: str, order: str,
                                                    goal_test: str, tree: bool, heuristic: str,
                                                    ties: str, reopen: bool,
                                                    mark_start: bool) -> None:
    """Tree or graph search, every tie rule, re-opening or a closed set, the start marked
    reached or not."""
    if key == "ucs" and ties not in ("fifo", "lifo", "node"):
        ties = "fifo"  # (refused: uniform-cost's priority is g, and it uses no h)
    choices: dict[str, Any] = {"goal_test": goal_test, "tree_search": tree,
                               "heuristic": heuristic, "ties": ties}
    if not tree:
        choices["reopen"] = reopen
        choices["mark_start"] = mark_start
    both(g, key, order, **choices)


@settings(max_examples=100)
@given(graphs(), ORDERS)
def test_iterative_deepening_equals_the_plain_one(g: dict[str, Any], order: str) -> None:
    """On graphs where the goal is reached (a road added from the start to it when none is)."""
    names = g["names"]
    roads = roads_of(g, False)
    seen, todo = {g["start"]}, [g["start"]]
    while todo:
        for succ, _ in roads[todo.pop()]:
            if succ not in seen:
                seen.add(succ)
                todo.append(succ)
    if g["goal"] not in seen:
        edges = g["edges"]
        if any({names[e.a], names[e.b]} == {g["start"], g["goal"]} for e in edges):
            return  # a road the other way (one way) or through a closed node: left out
        if g["goal"] in g["closed"]:
            return
        g = {**g, "edges": [*edges, Edge(names.index(g["start"]), names.index(g["goal"]), 1.0)]}
    both(g, "iddfs", order)


@pytest.mark.parametrize(("key", "path", "cost"), [
    ("astar", ["Arad", "Sibiu", "Rimnicu", "Pitesti", "Bucharest"], 418),
    ("ucs", ["Arad", "Sibiu", "Rimnicu", "Pitesti", "Bucharest"], 418),
    ("greedy", ["Arad", "Sibiu", "Fagaras", "Bucharest"], 450),
])
def test_romania_s_book_answers(key: str, path: list[str], cost: float) -> None:
    """AIMA: A* from Arad with the straight-line table goes through Rimnicu and Pitesti at 418,
    uniform-cost finds the same cost, greedy the road through Fagaras at 450."""
    run = Run(built_in_graph("romania"), key, Semantics(order=("file",), heuristic="table"))
    run.advance()
    assert run.path() == path
    assert run.path_cost() == cost
    assert run.outcome().cost == cost


def test_a_stale_entry_is_discarded_as_the_plain_search_discards_it() -> None:
    """B is pushed at 9 from A, then at 2 through C: its entry at 9 is stale when it comes
    off (random graphs rarely get that far before the goal)."""
    g = {"names": ["A", "B", "C", "D"], "start": "A", "goal": "D", "closed": frozenset(),
         "h": {"A": 0.0, "B": 0.0, "C": 0.0, "D": 0.0},
         "edges": [Edge(0, 1, 9.0), Edge(0, 2, 1.0), Edge(2, 1, 1.0), Edge(1, 3, 20.0)]}
    for key in ("ucs", "astar", "greedy"):
        both(g, key, "file", heuristic="table")
    steps, _ = app_steps(app_graph(g), "ucs", Semantics(order=("file",)))
    assert ("B", (), True) in steps
