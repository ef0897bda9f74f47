"""``.graph`` files: the statements, the built-in Romania, and every error one line naming the
file, the line and the column (a test each)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.helpers import ROOT
from tui_search.engine.maps import graph_file
from tui_search.engine.maps.graph_file import BUILT_IN, built_in_graph, load_graph, parse_graph
from tui_search.engine.maps.read import MapError

GRAPHS = ROOT / "maps" / "graphs"


def test_romania_has_the_book_s_20_cities_23_roads_and_table() -> None:
    g = built_in_graph("romania")
    assert (len(g), len(g.edges), g.start, g.goals) == (20, 23, "Arad", ("Bucharest",))
    assert g.h is not None and g.h["Arad"] == 366 and g.h["Bucharest"] == 0
    assert g.places is not None and g.places[g.index["Arad"]] == (91.0, 492.0)
    # a city's roads in the order the file lists them, both ends of each
    assert [n for n, _, _ in g.successors("Sibiu")] == ["Arad", "Fagaras", "Oradea", "Rimnicu"]
    assert g.cost("Sibiu", "Fagaras") == g.cost("Fagaras", "Sibiu") == 99
    assert load_graph(GRAPHS / "romania.graph") == g  # the shipped copy is the built-in one
    assert BUILT_IN == ("romania",)


def test_every_teaching_graph_reads() -> None:
    names = sorted(p.name for p in GRAPHS.glob("*.graph"))
    assert names == ["dfs-backtracks.graph", "greedy-not-optimal.graph", "romania.graph",
                     "visit-rule.graph"]
    for name in names:
        g = load_graph(GRAPHS / name)
        assert g.start is not None and g.goals


def test_node_lines_are_optional_arcs_go_one_way_and_costs_default_to_1() -> None:
    g = parse_graph("edge A B\narc B C 2.5\nstart A\ngoal C\ngoal B\n")
    assert list(g.names) == ["A", "B", "C"] and g.places is None and g.h is None
    assert [n for n, _, _ in g.successors("B")] == ["A", "C"]
    assert [n for n, _, _ in g.successors("C")] == []  # an arc goes one way
    assert g.cost("A", "B") == 1.0 and g.cost("B", "C") == 2.5 and g.goals == ("C", "B")


def test_by_name_sorts_a_node_s_roads_and_closed_nodes_are_left_out() -> None:
    g = parse_graph("edge S C\nedge S A\nedge S B\nstart S\ngoal C\n")
    assert [n for n, _, _ in g.successors("S", by_name=True)] == ["A", "B", "C"]
    g.closed = frozenset({"A"})
    assert [n for n, _, _ in g.successors("S")] == ["C", "B"]


def test_comments_blank_lines_and_a_bom_are_ignored() -> None:
    g = parse_graph("\ufeff; a comment\n\nnode A 0 0 ; a place\nnode B 1 0\nedge A B 3\n")
    assert g.places == [(0.0, 0.0), (1.0, 0.0)] and g.cost("A", "B") == 3


#: Each error: the file, its line and column, what the message says.
ERRORS = [
    ("node A\nnode A\n", 2, 6, "node 'A' is declared twice (first on line 1)"),
    ("node A\nnode B\nedge A C\n", 3, 8, "unknown node 'C' (no node line declares it)"),
    ("edge A B 0\n", 1, 10, "the cost '0' is not above 0"),
    ("edge A B -2\n", 1, 10, "the cost '-2' is not above 0"),
    ("edge A B far\n", 1, 10, "the cost 'far' is not a number"),
    ("edge A B nan\n", 1, 10, "the cost 'nan' is not a number"),
    ("edge A B\nh A 1\n", 2, None, "the h table misses 1 node: B"),
    ("edge A B\nh A 1\nh A 2\n", 3, 3, "h of 'A' is given twice"),
    ("edge A B\nh A -1\nh B 0\n", 2, 5, "h '-1' is below 0"),
    ("edge A B\nh C 1\n", 2, 3, "h of unknown node 'C'"),
    ("edge A B\nstart X\n", 2, 7, "unknown node 'X'"),
    ("edge A B\ngoal Y\n", 2, 6, "unknown node 'Y'"),
    ("edge A B\nstart A\nstart B\n", 3, 7, "a second start (the first on line 2)"),
    ("node A 0 0\nnode B\n", 2, 6, "a place (x y) for every node or for none"),
    ("node A 0\n", 1, 1, "node: write it node NAME [X Y]"),
    ("edge A\n", 1, 1, "edge: write it edge A B [COST]"),
    ("vertex A\n", 1, 1, "unknown statement 'vertex'"),
    ("edge A A\n", 1, 8, "a road from 'A' to itself"),
    ("edge A B\nedge B A 2\n", 2, 6, "a second road from 'A' to 'B' (the first on line 1)"),
    ("edge A " + "x" * 101 + "\n", 1, 8, "a name of 101 characters: at most 100"),
    ("; nothing\n", None, None, "no nodes"),
]


@pytest.mark.parametrize(("text", "line", "col", "says"), ERRORS)
def test_each_error_names_the_line_and_column(text: str, line: int | None, col: int | None,
                                              says: str) -> None:
    with pytest.raises(MapError) as caught:
        parse_graph(text, "g.graph")
    error = caught.value
    assert (error.line, error.col) == (line, col) and says in error.message, str(error)
    assert "\n" not in str(error) and str(error).startswith("g.graph")


def test_a_missing_file_is_one_line(tmp_path: Path) -> None:
    with pytest.raises(MapError, match="no such file"):
        load_graph(tmp_path / "none.graph")


#: Files read the same whether names are found through a dictionary or the compact table:
#: each error's, Romania, a teaching graph, places and a table with a BOM and comments.
BOTH_WAYS = [text for text, _, _, _ in ERRORS] + [
    (ROOT / "tui_search" / "maps" / "romania.graph").read_text("utf-8"),
    "\ufeffnode A 0 0 ; here\nnode B 1 0\nnode C 2 2\nedge A B 3\narc B C\nedge C A 1.5\n"
    "h A 2\nh B 1\nh C 0\nstart A\ngoal C\n",
    "edge A B\nedge B C\nnode A\nnode B\nnode C\nnode D\nedge C D 2\nstart A\ngoal D\n",
]


@pytest.mark.parametrize("text", BOTH_WAYS)
def test_a_file_dense_in_names_is_read_alike_through_the_compact_table(
        text: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """A file of many short new names for its size numbers them through the compact table
    of ``Names`` (past ``MIN_IN_DICT`` and one name a ``NAMES_IN_DICT`` bytes) instead of a
    dictionary: forced from the first name, the same graph or the same error."""
    def read() -> object:
        try:
            graph = parse_graph(text, "g.graph")
        except MapError as error:
            return str(error)
        return graph, graph.edges, graph.places, graph.h, [graph.index[n] for n in graph.names]

    dictionary = read()
    monkeypatch.setattr(graph_file, "MIN_IN_DICT", 1)
    monkeypatch.setattr(graph_file, "NAMES_IN_DICT", 10**9)
    assert read() == dictionary
