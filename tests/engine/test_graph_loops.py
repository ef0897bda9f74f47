"""The fast loop of the priority queue's searches on a graph
(:mod:`tui_search.engine.search.loops.graph_best_first`) records exactly what the reference
loop does (:mod:`tui_search.engine.search.loops.published` records the reference itself): the
same events, expansions, g of each step, discarded steps and goal, array for array, on random
graphs for every algorithm and choice it serves, in chunks of any size."""

from __future__ import annotations

from functools import partial
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from tests.engine.test_graph_search import app_graph, graphs
from tui_search.engine.maps.graph import Graph
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.graph_problem import GraphProblem
from tui_search.engine.search.loops.dispatch import loop_for
from tui_search.engine.search.loops.graph_best_first import graph_best_first
from tui_search.engine.search.loops.published import published
from tui_search.engine.search.record import Record
from tui_search.engine.search.reference import stream
from tui_search.engine.search.registry import get_algorithm


def placed(g: dict[str, Any], places: list[tuple[int, int]]) -> Graph:
    """The random graph with places (for ``euclidean``)."""
    return Graph.of(g["names"], g["edges"], h=g["h"], places=[
        (float(x), float(y)) for x, y in places[:len(g["names"])]],
        start=g["start"], goals=(g["goal"],), closed=g["closed"])


def record(graph: Graph, key: str, sem: Semantics, chunk: int, fast: bool) -> tuple:
    algorithm = get_algorithm(key)
    problem = GraphProblem(graph, sem, sem.goal_test_for(algorithm), algorithm.weighted)
    rec = Record()
    loop = (partial(graph_best_first, priority=algorithm.priority) if fast
            else partial(published, algorithm=algorithm))
    pauses = []
    for steps in loop(problem, rec, chunk):
        # a pause every `chunk` steps, the record whole up to there
        assert len(rec.gen_node) == rec.step_end[-1] and len(rec.step_exp) == steps + 1
        pauses.append(steps)
    assert rec.step_g is not None
    return (list(rec.gen_node), list(rec.step_end), list(rec.step_exp),
            [g.hex() for g in rec.step_g], list(rec.discarded), rec.goal_gen, rec.done, pauses)


@settings(max_examples=300, deadline=None)
@given(graphs(), st.sampled_from(["ucs", "greedy", "astar"]), st.sampled_from(["file", "name"]),
       st.sampled_from([None, "generate", "expand"]),
       st.sampled_from(["table", "zero", "euclidean"]),
       st.lists(st.tuples(st.integers(-9, 9), st.integers(-9, 9)), min_size=8, max_size=8),
       st.integers(1, 5))
def test_the_graph_loop_records_what_the_reference_does(
        g: dict[str, Any], key: str, order: str, goal_test: str | None, heuristic: str,
        places: list[tuple[int, int]], chunk: int) -> None:
    graph = placed(g, places)
    sem = Semantics(order=(order,), goal_test=goal_test, heuristic=heuristic)
    assert record(graph, key, sem, chunk, True) == record(graph, key, sem, chunk, False)


@settings(max_examples=100, deadline=None)
@given(graphs(), st.sampled_from(["ucs", "greedy", "astar"]), st.sampled_from(["file", "name"]))
def test_a_run_on_a_graph_takes_the_graph_loop_and_ends_as_the_reference(
        g: dict[str, Any], key: str, order: str) -> None:
    """A run under the plain choices of a priority queue records through the graph loop (a
    tie rule other than fifo is not plain: the reference's loop), and its outcome is the
    streamed reference's (path, counts, cost)."""
    graph = app_graph(g)
    algorithm = get_algorithm(key)
    sem = Semantics(order=(order,), heuristic="table")
    assert loop_for(algorithm, sem, graph=True).func is graph_best_first
    ties = Semantics(order=(order,), heuristic="table", ties="lifo")
    assert loop_for(algorithm, ties, graph=True).func is published
    assert Run(graph, key, sem).outcome() == stream(graph, algorithm, sem, 10**6)
