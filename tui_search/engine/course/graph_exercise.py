"""An exercise on a graph (``graph = "FILE"`` in its file, docs/04-exercises.md): the graph
read beside the file, the rules a graph's searches take (``order = "file"`` or ``"name"``;
``heuristic = "table"``, ``"euclidean"`` or ``"zero"``, by default the graph's own table, else
the straight line, else zero), the edits a graph allows (``start``, ``goal``, ``closed``), and
what a student's graph changed of the exercise's.  Plain Python, no UI."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Protocol

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.read import MapError
from tui_search.engine.search.choices import GOAL_TESTS, GRAPH_ORDERS, Semantics


class KeyReader(Protocol):
    """What is asked of the exercise file's reader
    (:class:`~tui_search.engine.course.exercise_file.KeyReader`: named here, not imported,
    so the two modules make no circle)."""

    path: str
    data: dict[str, Any]

    def error(self, key: str, message: str) -> MapError: ...
    def string(self, key: str, default: str | None = None) -> str: ...

#: What a student may change of a graph.
GRAPH_EDITS = ("start", "goal", "closed")
#: The rules' keys that are a grid's alone.
GRID_RULES = ("corners",)


def read_graph(reader: KeyReader) -> Graph:
    """``graph = "FILE"`` (relative to the exercise's file; ``romania``: the built-in one)."""
    from tui_search.engine.maps.graph_file import BUILT_IN, built_in_graph, load_graph

    name = reader.string("graph")
    try:
        if name in BUILT_IN:
            graph = built_in_graph(name)
        else:
            graph = load_graph(Path(reader.path).parent / name)
    except MapError as exc:
        raise reader.error("graph", str(exc)) from None
    if graph.start is None or not graph.goals:
        raise reader.error("graph", "the exercise's graph needs a start and a goal line")
    return graph


def graph_semantics(reader: KeyReader, graph: Graph) -> Semantics:
    """The rules the file's keys set for a graph's searches."""
    from tui_search.engine.search.choices import graph_heuristics

    data = reader.data
    for key in GRID_RULES:
        if key in data:
            raise reader.error(key, "is a grid's rule: a graph has no cells")
    choices: dict[str, Any] = {"order": (GRAPH_ORDERS[0],),
                               "heuristic": graph_heuristics(graph)[0]}
    for key, allowed in (("order", GRAPH_ORDERS), ("heuristic", tuple(graph_heuristics(graph))),
                         ("goal_test", GOAL_TESTS), ("visit", ("generate", "expand"))):
        if key in data:
            value = reader.string(key)
            if value not in allowed:
                raise reader.error(key, f"{value!r}: on this graph use {', '.join(allowed)}")
            choices[key] = (value,) if key == "order" else value
    if "tree_search" in data:
        if not isinstance(data["tree_search"], bool):
            raise reader.error("tree_search", "expected true or false")
        choices["tree_search"] = data["tree_search"]
    return Semantics(**choices)


def check_graph_edits(reader: KeyReader, edits: list[str]) -> None:
    for edit in edits:
        if edit not in GRAPH_EDITS:
            raise reader.error("edits", f"unknown edit {edit!r} on a graph (use "
                               f"{', '.join(GRAPH_EDITS)})")


def graph_changes(graph: Graph, base: Graph) -> list[str]:
    """What ``graph`` changed of the exercise's ``base``: "roads" (its nodes, roads, places
    or table), or any of start, goal, closed."""
    if (graph.names != base.names or graph.edges != base.edges or graph.places != base.places
            or graph.h != base.h):
        return ["roads"]
    return [name for name, differs in (("start", graph.start != base.start),
                                       ("goal", set(graph.goals) != set(base.goals)),
                                       ("closed", graph.closed != base.closed)) if differs]
