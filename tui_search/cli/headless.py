"""The headless runs: one search (:func:`run_headless`), a comparison (:func:`run_compare`) or
an exercise graded (:func:`run_exercise`), printed as text or JSON, and the per-step trace.

No Textual or Rich here, so scripts and graders start in a fraction of the app's start-up time.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import IO, TYPE_CHECKING

from tui_search.cli.flags import (
    EXIT_FOUND,
    EXIT_GAVE_UP,
    EXIT_NO_PATH,
    UsageError,
    contenders_from,
    load_problem,
    map_name,
    semantics_from,
)
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import LAY
from tui_search.engine.run.each_step import search_each_step
from tui_search.engine.run.recorded import Step
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.compare import (
    MARKS_KEY,
    comparison,
    summary_sentence,
    table_cells,
    table_lines,
)
from tui_search.engine.search.heuristics import INADMISSIBLE, admissible
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.state import state_json
from tui_search.engine.traces.read import trace_line
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.cli.options import Options
    from tui_search.engine.maps.scenarios import Scenario



def print_pseudocode(options: Options) -> int:
    """``--pseudocode``: the code of ``-a``'s search under the flags' choices, numbered, on
    stdout (:mod:`tui_search.engine.search.pseudocode`); exit 0."""
    from tui_search.engine.search.pseudocode import MOVE_COST, TERRAIN_MOVE_COST, pseudocode

    for flag in ("compare", "exercise", "trace", "lesson"):
        if getattr(options, flag, None) not in (None, False):  # --lesson alone is ""
            raise UsageError(f"--pseudocode prints one search's code: leave out "
                             f"--{flag.replace('_', '-')}")
    if options.headless or options.json:
        raise UsageError("--pseudocode prints the code without a search: leave out "
                         "--headless and --json")
    costed = False
    if options.map is not None or options.terrain is not None:  # the code of a search on this map
        costed = load_problem(options)[0].costs is not None
    code = pseudocode(get_algorithm(options.algorithm), semantics_from(options),
                      move_cost=TERRAIN_MOVE_COST if costed else MOVE_COST)
    print(code.title)
    print("\n".join(code.numbered()))
    return EXIT_FOUND




def search_headless(grid: Grid | Graph, key: str, semantics: Semantics, max_steps: int,
                    out: IO[str] | None, on_step: Callable[[Step], object] | None = None
                    ) -> Outcome:
    """The whole search (:func:`~tui_search.engine.run.each_step.search_each_step`), its
    steps written to ``out`` as they happen.  ``on_step``: what to do with each step instead
    of writing its line (a Posthoc trace collects them)."""
    emit = on_step or (None if out is None else (lambda step: out.write(trace_line(step))))
    return search_each_step(grid, key, semantics, max_steps, emit)


def benchmark_rules(outcome: Outcome) -> bool:
    """Do the benchmark's optima apply: all eight moves, no corner cutting?"""
    sem = outcome.semantics
    return sem.corners == "never" and len(sem.order) == 8


def optimal(outcome: Outcome, scenario: Scenario | None) -> bool | None:
    """Does the path meet the benchmark's optimal length (to 1e-4, relative)?  None when no
    scenario is given, no path was found, or the rules are not the benchmark's (all eight
    moves, ``--corners never``)."""
    if scenario is None or outcome.cost is None or not benchmark_rules(outcome):
        return None
    return outcome.cost <= scenario.optimal_length * (1 + 1e-4)


def benchmark_text(outcome: Outcome, scenario: Scenario) -> str:
    """The benchmark's lowest cost beside the path's: "lowest cost 2.000: met"."""
    text = f"lowest cost {scenario.optimal_length:.3f}"
    if not benchmark_rules(outcome):
        return text + " (with all eight moves and --corners never: not these rules)"
    verdict = optimal(outcome, scenario)
    if verdict is None:
        return text
    return text + (": this path is optimal" if verdict else ": this path costs more")


def to_json(obj: object, separators: tuple[str, str] | None = None) -> str:
    """``json.dumps`` (json is imported for the headless output, not at the app's start-up)."""
    import json

    return json.dumps(obj, separators=separators)


def json_summary(outcome: Outcome, scenario: Scenario | None = None) -> dict[str, object]:
    """The headless JSON object (docs/02-command-line.md, "The JSON")."""
    path, moves = outcome.path, outcome.moves
    extra = {} if scenario is None else {
        "optimal_length": round(scenario.optimal_length, 6),
        "optimal": optimal(outcome, scenario),
    }
    return {
        "algorithm": outcome.algorithm,
        "found": outcome.found,
        "path": [state_json(c) for c in path] if path is not None else None,
        "moves": moves,
        "length": outcome.length,
        "cost": round(outcome.cost, 6) if outcome.cost is not None else None,
        "expanded": outcome.expanded,
        "discarded": outcome.discarded,
        "generated": outcome.generated,
        "max_frontier": outcome.max_frontier,
        "gave_up": outcome.gave_up,
        "semantics": outcome.semantics.as_json(get_algorithm(outcome.algorithm)),
        **extra,
        **({"meeting": None if outcome.meeting is None else state_json(outcome.meeting),
            "stopped": outcome.stopped} if get_algorithm(outcome.algorithm).bidirectional
           else {}),
    }


#: Paths with more moves than this print their first and last few moves and a count.
SHORT_PATH = 24
PATH_ENDS = 8


def moves_text(moves: list[str]) -> str:
    if not moves:
        return "none: the start is the goal"
    if len(moves) <= SHORT_PATH:
        return ", ".join(moves)
    hidden = len(moves) - 2 * PATH_ENDS
    return (", ".join(moves[:PATH_ENDS]) + f", … {hidden:,} more …, "
            + ", ".join(moves[-PATH_ENDS:]))


def human_summary(
    outcome: Outcome, where: str, max_steps: int, blocked_by: str | None = None,
    scenario: Scenario | None = None, warnings: list[str] | None = None,
    layout: str | None = None,
) -> str:
    """The text a headless run prints; ``warnings``: :func:`warnings_of`'s; ``layout``: on
    a Pacman layout, its reader's note ("" none): then the course's count is said too."""
    algorithm = get_algorithm(outcome.algorithm)
    name = algorithm.name
    result = "path found" if outcome.found else "no path"
    if not outcome.found and not outcome.gave_up and blocked_by:
        result += f" — {blocked_by}"
    if outcome.gave_up:
        result = f"gave up at --max-steps {max_steps:,} (raise it to search on)"
    lines = [f"{name} on {where}: {result}"]
    differences = outcome.semantics.differences(algorithm)
    if differences:
        lines.append(f"  semantics:    {' · '.join(differences)}")
    for warning in warnings or ():
        lines.append(f"  warning:      {warning}")
    if layout:
        lines.append(f"  note:         {layout}")
    if outcome.path is not None and outcome.path and isinstance(outcome.path[0], str):
        roads = len(outcome.path) - 1
        lines.append(f"  path:         {roads:,} road{'s' * (roads != 1)} "
                     f"({moves_text(outcome.path)})")
        lines.append(f"  cost:         {outcome.cost:g}")
    elif outcome.moves is not None:
        lines.append(f"  moves:        {outcome.length:,} ({moves_text(outcome.moves)})")
        lines.append(f"  cost:         {outcome.cost:.3f}")
    if scenario is not None:
        lines.append(f"  benchmark:    {benchmark_text(outcome, scenario)}")
    lines.append(f"  expanded:     {outcome.expanded:,}")
    if layout is not None:  # the course counts getSuccessors calls: the goal gets none
        goal_step = outcome.found and outcome.semantics.goal_test_for(algorithm) == "expand"
        course = outcome.expanded - goal_step
        lines.append(f"  course count: {course:,} expanded (getSuccessors calls"
                     + ("; the goal's step makes none)" if goal_step else ")"))
    if outcome.discarded:
        lines.append(f"  discarded:    {outcome.discarded:,}")
    lines.append(f"  generated:    {outcome.generated:,}")
    lines.append(f"  max frontier: {outcome.max_frontier:,}")
    if outcome.stopped:
        lines.append(f"  stopped:      {outcome.stopped}")
    return "\n".join(lines)


def warnings_of(board: Grid | Graph, outcome: Outcome) -> list[str]:
    """What the output warns of: an informed search's estimate that may mislead it (on a
    graph, checked against the graph's roads)."""
    algorithm, sem = get_algorithm(outcome.algorithm), outcome.semantics
    if not algorithm.informed:
        return []
    if isinstance(board, Graph):
        from tui_search.engine.search.estimate_check import estimate_faults

        return estimate_faults(board, sem.heuristic)
    return [] if admissible(sem.heuristic, sem.order) else [INADMISSIBLE]


def board_of(options: Options) -> tuple[Grid | Graph, str]:
    """The map or graph the command line read, and its name as the output says it (escape
    sequences shown, not run); a map with no start or goal is an error."""
    if options.graph is not None:
        name = map_name(options, options.path) if options.path else "romania (built-in)"
        return options.graph, describe_name(name) if options.path else name
    grid = options.grid
    assert grid is not None, "a headless search runs on the map the command line read"
    where = describe_name(map_name(options, options.path))
    need_endpoints(grid, where)
    return grid, where


def run_headless(options: Options) -> int:
    if options.trace == "-" and options.json:
        raise UsageError("--trace - and --json both want stdout; give --trace a file")
    grid, where = board_of(options)
    semantics = semantics_from(options)
    if isinstance(grid, Graph) and options.trace_format == "posthoc":
        raise UsageError("--trace-format posthoc writes a grid's search: on a graph, leave it "
                         "out (the trace names the nodes)")

    def search(out: IO[str] | None) -> Outcome:
        if out is None or options.trace_format != "posthoc":
            return search_headless(grid, options.algorithm, semantics, options.max_steps, out)
        from tui_search.engine.traces.posthoc import posthoc_trace  # only for its format

        assert isinstance(grid, Grid), "refused above"
        text, found = posthoc_trace(grid, options.algorithm, semantics, options.max_steps)
        out.write(text)
        return found

    if options.trace == "-":
        outcome = search(sys.stdout)
    elif options.trace:
        try:
            with open(options.trace, "w", encoding="utf-8") as fh:
                outcome = search(fh)
        except OSError as exc:
            raise MapError(options.trace, f"cannot write the trace: {exc.strerror}") from None
    else:
        outcome = search(None)
    scenario = options.scenario
    if options.json:
        print(to_json(json_summary(outcome, scenario)))
    elif options.trace != "-":
        blocked_by = None
        if (not outcome.found and not outcome.gave_up and not semantics.is_default
                and isinstance(grid, Grid)):
            from tui_search.engine.run.blocked import blocking_rule

            blocked_by = blocking_rule(grid, semantics)
        source = grid.source if isinstance(grid, Grid) else None
        layout = source.note if source is not None and source.kind == LAY else None
        print(human_summary(outcome, where, options.max_steps, blocked_by, scenario,
                            warnings_of(grid, outcome), layout))
    if outcome.gave_up:
        return EXIT_GAVE_UP
    return EXIT_FOUND if outcome.found else EXIT_NO_PATH


def compare_table(labels: list[str], outcomes: list[Outcome], terrain: bool = False) -> str:
    """The comparison as text: a row a search, marks on the fewest expanded and the
    cheapest path, and the tutorial's sentence (with the paths' costs on ``terrain``)."""
    rows = comparison(labels, outcomes)
    lines = table_lines(table_cells(rows)) + [MARKS_KEY, summary_sentence(rows, terrain)]
    return "\n".join("  " + line for line in lines)


def run_compare(options: Options) -> int:
    grid, where = board_of(options)
    contenders = contenders_from(options)
    outcomes = [search_headless(grid, c.algorithm, c.semantics, options.max_steps, None)
                for c in contenders]
    if options.json:
        print(to_json({"runs": [json_summary(o, options.scenario)
                                   for o in outcomes]}))
    else:
        print(f"Comparison on {where}:")
        costed = isinstance(grid, Graph) or grid.costs is not None
        print(compare_table([c.label for c in contenders], outcomes, costed))
    if any(o.gave_up for o in outcomes):
        return EXIT_GAVE_UP
    return EXIT_FOUND if all(o.found for o in outcomes) else EXIT_NO_PATH


def need_endpoints(grid: Grid, where: str) -> None:
    missing = [name for name in ("start", "goal") if getattr(grid, name) is None]
    if missing:
        raise MapError(where, f"the map has no {' or '.join(missing)}: give --start X,Y "
                       "--goal X,Y, or --scen FILE --scen-row N")
