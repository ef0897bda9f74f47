"""A graph's estimate checked against the graph (engine/search/estimate_check.py): Romania's
table, straight lines and zero are admissible and consistent; a table that says too much
somewhere is named at the node, one that drops too fast along a road at the road."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from tui_search.engine.maps.graph import Edge, Graph
from tui_search.engine.maps.graph_file import built_in_graph, parse_graph
from tui_search.engine.search.estimate_check import estimate_faults, true_costs


def test_romania_s_estimates_are_admissible_and_consistent() -> None:
    romania = built_in_graph("romania")
    for name in ("table", "euclidean", "zero"):
        assert estimate_faults(romania, name) == []
    costs = true_costs(romania)
    assert costs[romania.index["Arad"]] == 418
    assert costs[romania.index["Bucharest"]] == 0


def test_an_overestimate_is_named_at_its_node() -> None:
    graph = parse_graph("edge A B 2\nedge B C 3\nstart A\ngoal C\n"
                        "h A 5\nh B 9\nh C 0\n", "over.graph")
    faults = estimate_faults(graph, "table")
    assert faults[0] == ("the table estimate is not admissible: h(B) = 9 but the cheapest way "
                         "to a goal costs 3 (A* may miss the cheapest path)")
    assert faults[1] == ("the table estimate is not consistent: h(B) = 9 is more than the "
                         "road to C (3) plus h(C) = 0 (A* may expand a node again)")


def test_an_admissible_table_may_still_be_inconsistent() -> None:
    graph = parse_graph("edge A B 1\nedge B C 10\nstart A\ngoal C\n"
                        "h A 11\nh B 2\nh C 0\n", "drop.graph")
    assert estimate_faults(graph, "table") == [
        "the table estimate is not consistent: h(A) = 11 is more than the road to B (1) "
        "plus h(B) = 2 (A* may expand a node again)"]


@given(st.lists(st.tuples(st.integers(0, 5), st.integers(0, 5), st.integers(1, 9)),
                min_size=1, max_size=15))
def test_the_true_costs_are_what_every_path_costs_at_least(roads: list[tuple[int, int, int]]
                                                           ) -> None:
    """Zero is always fine; the true costs as a table are admissible and consistent."""
    names = [f"n{i}" for i in range(6)]
    seen = set()
    edges = []
    for a, b, cost in roads:
        if a != b and (a, b) not in seen and (b, a) not in seen:
            seen.add((a, b))
            edges.append(Edge(a, b, float(cost)))
    graph = Graph.of(names, edges, start="n0", goals=("n5",))
    assert estimate_faults(graph, "zero") == []
    costs = true_costs(graph)
    table = {n: (c if c < float("inf") else 0.0) for n, c in zip(names, costs, strict=True)}
    exact = Graph.of(names, edges, h=table, start="n0", goals=("n5",))
    assert estimate_faults(exact, "table") == []
