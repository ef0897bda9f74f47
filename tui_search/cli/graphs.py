"""A graph on the command line: ``tui-search romania`` (the built-in Romania, as ``tui-search``
alone opens the tutorial's grid) or ``tui-search FILE.graph``, its start and goal by name
(``--start Arad --goal Bucharest``).  The flags that are a grid's alone (terrain, corners,
scenarios, generated maps) are refused by name; the choices that apply to a graph
(``--order file|name``, ``--heuristic table|euclidean|zero``) are
:func:`~tui_search.cli.flags.semantics_from`'s."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.cli.flags import UsageError
from tui_search.engine.maps.graph_file import BUILT_IN, built_in_graph, is_graph_file, load_graph

if TYPE_CHECKING:
    from tui_search.cli.options import Options
    from tui_search.engine.maps.graph import Graph

def names_a_graph(name: str | None) -> bool:
    """Does the MAP argument name a graph: a built-in one (``romania``) or a ``.graph``
    file?  (``./romania`` names a file called ``romania``.)"""
    return name is not None and (name in BUILT_IN or is_graph_file(name))


def load_graph_problem(options: Options) -> Graph:
    """The graph MAP names, with ``--start`` and ``--goal`` (a node's name each) in place of
    the file's; the grid's own flags refused."""
    _refuse_grid_flags(options)
    name = options.map
    assert name is not None and names_a_graph(name), "a graph's MAP"
    graph = built_in_graph(name) if name in BUILT_IN else load_graph(name)
    for flag, given in (("--start", options.start), ("--goal", options.goal)):
        if given is not None and given not in graph:
            raise UsageError(f"{flag} {given!r}: {graph.name} has no node of that name")
    if options.start is not None:
        graph.start = options.start
    if options.goal is not None:
        graph.goals = (options.goal,)
    missing = [what for what, there in (("start", graph.start), ("goal", graph.goals))
               if not there]
    if missing:
        raise UsageError(f"{graph.name} has no {' or '.join(missing)}: give --start NAME "
                         "--goal NAME, or a start or goal line in the file")
    return graph


def _refuse_grid_flags(options: Options) -> None:
    for flag, given in (("--terrain", options.terrain), ("--scen", options.scen),
                        ("--corners", options.corners),
                        ("--no-corner-cutting", options.no_corner_cutting),
                        ("--generate", options.generate)):
        if given:
            raise UsageError(f"{flag} is a grid's: a graph has no cells")
