"""What the command line's options ask for: the map (:func:`load_problem`), the search choices
(:func:`semantics_from`) and the searches to compare (:func:`contenders_from`), with
:class:`UsageError` for flags that make no sense.

Shared by the parsing (:mod:`tui_search.cli.parse`), the dispatch (:mod:`tui_search.cli.main`)
and the headless runs (:mod:`tui_search.cli.headless`), so that none of them imports another.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import DEFAULT_ORDER, Cell, Grid, parse_order
from tui_search.engine.maps.load import load_map, parse_cell, parse_map_text
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.terrain import load_terrain
from tui_search.engine.search.choices import GRAPH_HEURISTICS, GRAPH_ORDERS, TABLE, Semantics
from tui_search.engine.search.compare import Contender, parse_compare
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC
from tui_search.engine.search.registry import ALGORITHMS, get_algorithm
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.cli.options import Options
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.maps.scenarios import Scenario

TUTORIAL_NAME = "tutorial.txt"


EXIT_FOUND, EXIT_NO_PATH, EXIT_BAD_INPUT, EXIT_GAVE_UP = 0, 1, 2, 3


class UsageError(Exception):
    """A bad command line: reported as one line, exit code 2."""


def _cell_arg(flag: str, text: str | None) -> Cell | None:
    if text is None:
        return None
    try:
        return parse_cell(text)
    except ValueError as exc:
        raise UsageError(f"{flag} {text!r}: {exc}") from None


def load_problem(options: Options) -> tuple[Grid, Path | None, Scenario | None]:
    """The grid to search (start and goal resolved), the file it came from, and ``--scen``'s
    scenario while its optimal length holds for the grid as read."""
    start = _cell_arg("--start", options.start)
    goal = _cell_arg("--goal", options.goal)
    if (options.scen is None) != (options.scen_row is None):
        raise UsageError("--scen and --scen-row go together")
    terrain = load_terrain(options.terrain) if options.terrain is not None else None
    recipe = options.recipe
    if recipe is not None:
        if options.scen:
            raise UsageError("--scen needs a MAP, not --generate")
        from tui_search.engine.maps.generate import generated_text  # only for a generated map

        text = generated_text(recipe)
        grid = parse_map_text(text, recipe.title, start=start, goal=goal, terrain=terrain)
        return grid, None, None
    own = _teachers_exercise(options)
    if options.map is None and own is not None:  # a teacher's exercise starts on its own map
        if options.scen:
            raise UsageError("--scen needs a MAP")
        grid = own.grid.copy()
        grid.start, grid.goal = start or grid.start, goal or grid.goal
        return grid, None, None
    if options.map is None:
        if options.scen:
            raise UsageError("--scen needs a MAP")
        # The map ships inside the package (a plain file: importlib.resources would cost
        # start-up time to import).
        text = (Path(__file__).parents[1] / "maps" / TUTORIAL_NAME).read_text("utf-8")
        return parse_map_text(text, TUTORIAL_NAME, start=start, goal=goal,
                              terrain=terrain), None, None
    path = Path(options.map)
    scen = None
    scen_file, scen_row = options.scen, options.scen_row
    if scen_file and scen_row is not None:
        from tui_search.engine.maps.scenarios import (  # only with --scen: not the tutorial's start
            check_scenario_map,
            check_scenario_matches,
            load_scenario,
        )

        scen = load_scenario(scen_file, scen_row)
        # A row for another map is refused by name, before its start and goal are tried on
        # this map's cells (they would fail there for the wrong reason).
        check_scenario_map(scen, scen_file, path)
        start = start or scen.start
        goal = goal or scen.goal
    grid = load_map(path, start=start, goal=goal, terrain=terrain)
    if scen is not None and scen_file:
        check_scenario_matches(scen, grid, scen_file, str(path))
        # Its optimal length is for its own start and goal, every cell costing 1: not when a
        # flag moved one, nor on terrain.
        if (grid.start, grid.goal) != (scen.start, scen.goal) or grid.costs is not None:
            scen = None
    return grid, path, scen


def _teachers_exercise(options: Options) -> Exercise | None:
    """``--exercise FILE``'s exercise (read by the command line), None for none or the
    tutorial's 1 and 2 (whose map is the tutorial's)."""
    exercise = options.exercise_read
    return exercise if exercise is not None and exercise.number is None else None


def map_name(options: Options, path: Path | None) -> str:
    """What a headless run calls the map: its file, a generated map's recipe, a teacher's
    exercise's own map, or the tutorial's file name."""
    recipe = options.recipe
    own = _teachers_exercise(options)
    if path is not None:
        return str(path)
    if recipe is not None:
        return str(recipe.title)
    return f"{Path(own.path).name}'s map" if own is not None else TUTORIAL_NAME


def write_generated(options: Options) -> int:
    """--generate with --output: write the map to a new file (never over one), or with
    ``--output -`` to standard output (``./-`` names a file called ``-``), exit 0."""
    from tui_search.engine.maps.generate import generate, generated_text
    from tui_search.engine.maps.write import save_new

    recipe, output = options.recipe, options.output
    assert recipe is not None and output is not None, "--output goes with --generate"
    if output == "-":
        sys.stdout.write(generated_text(recipe))  # the bytes a file would get
        return 0
    try:
        save_new(generate(recipe, output), output)
    except MapError as exc:
        raise UsageError(f"--output {describe_name(output)}: {exc.message}") from None
    return 0


#: The choice flags whose default is None (not given).
_CHOICE_FLAGS = ("corners", "visit", "goal_test", "heuristic", "recursive_lines", "ties",
                 "cost_tolerance", "weight", "reopen", "mark_start", "preset", "stop", "turn")


def changed_choice_flags(options: Options) -> list[str]:
    """The choice flags given a value other than their default (``--visit``, ``--order``)."""
    changed = [f"--{f.replace('_', '-')}" for f in _CHOICE_FLAGS if getattr(options, f) is not None]
    changed += [flag for flag, on in (("--order", options.order != ",".join(DEFAULT_ORDER)),
                                      ("--no-corner-cutting", options.no_corner_cutting),
                                      ("--tree-search", options.tree_search),
                                      ("--no-path-check", options.no_path_check),
                                      ("--recursive", options.recursive),
                                      ("--flip-even", options.flip_even)) if on]
    return changed


def _choices_of(options: Options) -> dict[str, object]:
    """The :class:`~tui_search.engine.search.choices.Semantics` fields the flags give (the
    defaults where they give none); a flag that goes with another missing is a UsageError."""
    graph = options.graph
    if graph is not None:  # a graph's orders and heuristics
        order = graph_order(options.order, options.order != ",".join(DEFAULT_ORDER))
        heuristic = graph_heuristic(options.heuristic, graph,
                                    get_algorithm(options.algorithm).bidirectional)
    else:
        try:
            order = parse_order(options.order)
        except ValueError as exc:
            raise UsageError(f"--order {options.order!r}: {exc}") from None
        heuristic = options.heuristic or DEFAULT_HEURISTIC
    corners = options.corners or ("never" if options.no_corner_cutting else "always")
    if options.no_corner_cutting and corners != "never":
        raise UsageError(f"--no-corner-cutting means --corners never, not {corners}")
    if options.tree_search and options.visit is not None:
        raise UsageError("--visit does not apply to --tree-search (it has no visited set)")
    if options.no_path_check and not options.tree_search:
        raise UsageError("--no-path-check goes with --tree-search (graph search has a "
                         "visited set)")
    recursive = options.recursive_lines or ("neighbours" if options.recursive else "")
    if recursive and options.visit is not None:
        raise UsageError("--visit does not apply to --recursive (a recursion visits a cell "
                         "when it enters it)")
    choices: dict[str, object] = dict(
        order=order, corners=corners, visit=options.visit or "generate",
        goal_test=options.goal_test, tree_search=options.tree_search,
        heuristic=heuristic, recursive=recursive,
        path_check=not options.no_path_check)
    if options.flip_even:
        if graph is not None:
            raise UsageError("--flip-even reverses a grid's moves on every other cell: a "
                             "graph has no cells")
        choices["flip_even"] = True
    for name, value in (("ties", options.ties), ("cost_tolerance", options.cost_tolerance),
                        ("weight", options.weight), ("stop", options.stop),
                        ("turn", options.turn)):
        if value is not None:
            choices[name] = value
    for name, value in (("reopen", options.reopen), ("mark_start", options.mark_start)):
        if value is not None:
            choices[name] = value == "yes"
    return choices


#: How ``--order`` is given for a graph, spelt out in the errors.
ORDERS_TEXT = " or ".join(GRAPH_ORDERS)


def graph_order(text: str, given: bool) -> tuple[str, ...]:
    """``--order`` on a graph: ``file`` (the default) or ``name``."""
    if not given:
        return (GRAPH_ORDERS[0],)
    if text not in GRAPH_ORDERS:
        raise UsageError(f"--order {text!r}: a graph's order is {ORDERS_TEXT} "
                         "(a grid's is directions)")
    return (text,)


def graph_heuristic(given: str | None, graph: Graph, both_ways: bool = False) -> str:
    """``--heuristic`` on a graph, checked against what the graph has (``both_ways``: for a
    bidirectional search, whose backward half needs an estimate to the start: not the
    table, which estimates the cost to the goal)."""
    if given is None:  # the file's table, else the straight line between places, else 0
        from tui_search.engine.search.choices import graph_heuristics

        return next(h for h in graph_heuristics(graph) if not (both_ways and h == TABLE))
    if both_ways and given == TABLE:
        raise UsageError("--heuristic table estimates the cost to the goal; a bidirectional "
                         "search's backward half needs one to the start: use euclidean or "
                         "zero")
    if given not in GRAPH_HEURISTICS:
        raise UsageError(f"--heuristic {given}: a graph's heuristics are "
                         f"{', '.join(GRAPH_HEURISTICS)}")
    if given == TABLE and not graph.has_table:
        raise UsageError(f"--heuristic table: {graph.name} has no h lines")
    if given == "euclidean" and not graph.has_places:
        raise UsageError(f"--heuristic euclidean: {graph.name}'s nodes have no places "
                         "(x y on their node lines)")
    return given


def _refused_flag(options: Options) -> str:
    """Why a choice flag does not apply to ``-a``'s search, naming the flag ("" when all
    apply)."""
    algorithm = get_algorithm(options.algorithm)
    key = options.algorithm
    if algorithm.iterative and options.visit is not None:
        return f"--visit does not apply to -a {key} (it re-opens a cell reached at a smaller depth)"
    if algorithm.weighted and options.visit is not None:
        return f"--visit does not apply to -a {key} (it re-opens a cell reached with a lower g)"
    if options.heuristic is not None and not algorithm.informed:
        informed = ", ".join(a.key for a in ALGORITHMS.values() if a.informed)
        return f"--heuristic applies to -a {informed} only, not {key}"
    weighted = ", ".join(a.key for a in ALGORITHMS.values() if a.queued)
    for flag in ("ties", "cost_tolerance", "reopen"):
        if getattr(options, flag) is not None and not algorithm.queued:
            return f"--{flag.replace('_', '-')} applies to -a {weighted} only, not {key}"
    for flag in ("stop", "turn"):
        if getattr(options, flag) is not None and not algorithm.bidirectional:
            return f"--{flag} applies to -a bibfs, biucs, biastar only, not {key}"
    if options.weight is not None and (algorithm.priority != "g+h" or algorithm.bidirectional):
        return f"--weight applies to -a astar, idastar only (f = g + W·h), not {key}"
    if (options.recursive or options.recursive_lines) and algorithm.key not in ("dfs", "iddfs"):
        return f"--recursive applies to -a dfs, iddfs only, not {key}"
    return ""


def _with_preset(options: Options, choices: dict[str, object], checked: bool
                 ) -> dict[str, object]:
    """``choices`` with ``--preset``'s where no flag gave one (a flag changes a preset's
    choice); fitted to ``-a``'s search when ``checked``, else left for compare mode to fit."""
    if options.preset is None:
        return choices
    from tui_search.engine.course.presets import preset_semantics

    preset = preset_semantics(options.preset,
                              get_algorithm(options.algorithm) if checked else None)
    given = {
        "order": options.order != ",".join(DEFAULT_ORDER) or options.graph is not None,
        "corners": options.corners is not None or options.no_corner_cutting,
        "heuristic": options.heuristic is not None or options.graph is not None,
        "tree_search": options.tree_search, "path_check": options.no_path_check,
        "recursive": options.recursive or options.recursive_lines is not None,
        **{name: getattr(options, name) is not None
           for name in ("visit", "goal_test", "ties", "cost_tolerance", "weight", "reopen",
                        "mark_start")},
    }
    out = dict(choices)
    for name, was_given in given.items():
        if not was_given:
            out[name] = getattr(preset, name)
    if out["tree_search"] or out["recursive"]:  # no visited set to mark on expansion
        out["visit"] = "generate" if options.visit is None else out["visit"]
    return out


def semantics_from(options: Options, checked: bool = True) -> Semantics:
    """The search choices the flags ask for (``--preset``'s where they give none); a
    combination that makes no sense is a UsageError.  ``checked`` False leaves out the
    checks against ``-a`` (a comparison checks each of its searches)."""
    choices = _with_preset(options, _choices_of(options), checked)
    if checked:
        refused = _refused_flag(options)
        if refused:
            raise UsageError(refused)
    try:
        sem = Semantics(**choices)  # type: ignore[arg-type]
        if checked:
            sem.check(get_algorithm(options.algorithm))
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return sem


def contenders_from(options: Options) -> list[Contender]:
    """``--compare``'s searches, each under the flags' choices (``--heuristic`` for the
    informed ones that name none)."""
    base = semantics_from(options, checked=False)
    assert options.compare is not None, "the searches --compare names"
    try:
        return parse_compare(options.compare, base, fit=options.preset is not None)
    except ValueError as exc:
        raise UsageError(f"--compare {options.compare!r}: {exc}") from None
