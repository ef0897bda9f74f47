"""The command line: parse arguments, load the map, then either start the app or search headless.

The headless path never imports Textual or Rich, so scripts and graders start in a fraction of
the app's start-up time.  Every bad input ends in one line on stderr and exit code 2.
"""

from __future__ import annotations

import argparse
import gc
import sys
from pathlib import Path
from typing import IO, TYPE_CHECKING, NoReturn

from tui_search import __version__
from tui_search.engine.algorithms import ALGORITHMS, DEFAULT_ALGORITHM, get_algorithm
from tui_search.engine.exercises import (
    MARKS_KEY,
    QUOTES,
    Contender,
    Verdict,
    check,
    comparison,
    parse_compare,
    summary_sentence,
    table_cells,
    table_lines,
    tutorial_grid,
)
from tui_search.engine.grid import DEFAULT_ORDER, Grid, parse_order
from tui_search.engine.heuristics import DEFAULT_HEURISTIC, HEURISTICS, INADMISSIBLE, admissible
from tui_search.engine.mapfile import load_map, parse_cell, parse_map_text
from tui_search.engine.mapread import MapError
from tui_search.engine.outcome import Outcome
from tui_search.engine.run import MAX_STEPS, Run, Step
from tui_search.engine.scenarios import (
    Scenario,
    check_scenario_map,
    check_scenario_matches,
    load_scenario,
)
from tui_search.engine.semantics import CORNER_RULES, GOAL_TESTS, VISIT_RULES, Semantics
from tui_search.launch import collector_paused

if TYPE_CHECKING:
    from tui_search.engine.reference import Expansion
from tui_search.tui.themes import THEMES  # plain data: no Textual

EXIT_FOUND, EXIT_NO_PATH, EXIT_BAD_INPUT, EXIT_GAVE_UP = 0, 1, 2, 3
TUTORIAL_NAME = "tutorial.txt"
BUILT_IN_TITLE = "tutorial (built-in)"  # the app's title for the map with no file


class UsageError(Exception):
    """A bad command line: reported as one line, exit code 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:  # one line, not argparse's usage + message
        raise UsageError(f"{message} (see tui-search --help)")


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(
        prog="tui-search",
        description="Watch a robot plan a path on a grid with breadth-first, depth-first, "
        "iterative-deepening, uniform-cost, greedy best-first and A* search. With no MAP, opens "
        "the tutorial's 6x6 map.",
        epilog="Exit codes (headless): 0 path found, 1 no path, 2 bad input, 3 gave up (--max-steps).",
    )
    p.add_argument("map", nargs="?", help="a text map (.txt) or a MovingAI map (.map)")
    p.add_argument("--version", action="version", version=f"tui-search {__version__}")
    p.add_argument("-a", "--algorithm", choices=list(ALGORITHMS), default=None,
                   help="; ".join(f"{a.key}: {a.name}" for a in ALGORITHMS.values()))
    p.add_argument("--start", metavar="X,Y", help="start cell (overrides the map's S)")
    p.add_argument("--goal", metavar="X,Y", help="goal cell (overrides the map's G)")
    p.add_argument("--scen", metavar="FILE", help="a MovingAI .scen file to take start and goal from")
    p.add_argument("--scen-row", metavar="N", type=int, default=None,
                   help="problem N of --scen, counted from 0 after the version line")
    p.add_argument("--order", metavar="DIRS", default=",".join(DEFAULT_ORDER),
                   help="the moves tried, in order: any of the 8 directions, e.g. N,W,S,E for "
                   "a 4-connected grid (default %(default)s)")
    p.add_argument("--corners", choices=CORNER_RULES, default=None,
                   help="may a diagonal pass blocked corners: always (default); one: not when "
                   "both side cells are blocked; never: not when either is (MovingAI's rule)")
    p.add_argument("--no-corner-cutting", action="store_true",
                   help="the same as --corners never")
    p.add_argument("--visit", choices=VISIT_RULES, default=None,
                   help="when a cell counts as visited: generate (when pushed, default) or "
                   "expand (when taken off: a cell may be on the frontier several times)")
    p.add_argument("--goal-test", choices=GOAL_TESTS, default=None,
                   help="stop when the goal is pushed (generate: the default of bfs, dfs and "
                   "iddfs) or taken off (expand: the default of ucs, greedy and astar)")
    p.add_argument("--heuristic", choices=list(HEURISTICS), default=None,
                   help="greedy's and A*'s estimate of the cost to the goal (default "
                   f"{DEFAULT_HEURISTIC}; manhattan is not admissible with diagonal moves)")
    p.add_argument("--tree-search", action="store_true",
                   help="no visited set: skip only cells on the node's own path")
    p.add_argument("--compare", metavar="A,B",
                   help="two to four searches side by side in the app (compare mode); with "
                   "--headless, run them on the map and print a table (e.g. bfs,dfs or "
                   "astar:manhattan,ucs: an informed search may name its heuristic)")
    p.add_argument("--exercise", metavar="N", type=int, choices=sorted(QUOTES),
                   help="the tutorial's exercise N as a live challenge in the app; with "
                   "--headless, grade the map on it (1: BFS "
                   "expands fewer nodes than DFS; 2: DFS's path has more moves than BFS's): "
                   "exit 0 solved, 1 not solved, 2 a bad map")
    p.add_argument("--max-steps", metavar="N", type=_positive, default=MAX_STEPS,
                   help=f"give up after N expansions (default {MAX_STEPS:,}: iterative "
                   "deepening on a big map can take billions)")
    p.add_argument("--theme", choices=list(THEMES), default=None,
                   help="the app's colours for this run (the app remembers a theme chosen in "
                   "it with t or ctrl+p): " + "; ".join(f"{t.name}: {t.description}"
                                                         for t in THEMES.values()))
    p.add_argument("--headless", action="store_true",
                   help="search without the app and print the result")
    p.add_argument("--json", action="store_true",
                   help="with --headless: print the result as one JSON object")
    p.add_argument("--trace", metavar="FILE",
                   help="with --headless: write one JSON line per expansion to FILE "
                   "('-' for stdout, without --json)")
    from tui_search import serve  # the flags of --serve (textual-serve only when serving)

    serve.add_arguments(p)
    return p


def _positive(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive whole number")
    return n


def _cell_arg(flag: str, text: str | None):
    if text is None:
        return None
    try:
        return parse_cell(text)
    except ValueError as exc:
        raise UsageError(f"{flag} {text!r}: {exc}") from None


def load_problem(args: argparse.Namespace) -> tuple[Grid, Path | None]:
    """The grid to search (start and goal resolved) and the file it came from."""
    start = _cell_arg("--start", args.start)
    goal = _cell_arg("--goal", args.goal)
    if (args.scen is None) != (args.scen_row is None):
        raise UsageError("--scen and --scen-row go together")
    if args.map is None:
        if args.scen:
            raise UsageError("--scen needs a MAP")
        # The map ships inside the package (a plain file: importlib.resources would cost
        # ~10 ms of start-up to import).
        text = (Path(__file__).parent / "maps" / TUTORIAL_NAME).read_text("utf-8")
        return parse_map_text(text, TUTORIAL_NAME, start=start, goal=goal), None
    path = Path(args.map)
    scen = None
    args.scenario = None
    if args.scen:
        scen = load_scenario(args.scen, args.scen_row)
        # A row for another map is refused by name, before its start and goal are tried on
        # this map's cells (they would fail there for the wrong reason).
        check_scenario_map(scen, args.scen, path)
        start = start or scen.start
        goal = goal or scen.goal
    grid = load_map(path, start=start, goal=goal)
    if scen is not None:
        check_scenario_matches(scen, grid, args.scen, str(path))
        # Its optimal length is for its own start and goal: not when a flag moved one.
        if (grid.start, grid.goal) == (scen.start, scen.goal):
            args.scenario = scen
    return grid, path


def semantics_from(args: argparse.Namespace, checked: bool = True) -> Semantics:
    """The search choices the flags ask for; a combination that makes no sense is a
    UsageError.  ``checked`` False leaves out the checks against ``-a`` (a comparison checks
    each of its searches)."""
    try:
        order = parse_order(args.order)
    except ValueError as exc:
        raise UsageError(f"--order {args.order!r}: {exc}") from None
    corners = args.corners or ("never" if args.no_corner_cutting else "always")
    if args.no_corner_cutting and corners != "never":
        raise UsageError(f"--no-corner-cutting means --corners never, not {corners}")
    if args.tree_search and args.visit is not None:
        raise UsageError("--visit does not apply to --tree-search (it has no visited set)")
    if not checked:
        try:
            return Semantics(order=order, corners=corners, visit=args.visit or "generate",
                             goal_test=args.goal_test, tree_search=args.tree_search,
                             heuristic=args.heuristic or DEFAULT_HEURISTIC)
        except ValueError as exc:
            raise UsageError(str(exc)) from None
    args.algorithm = args.algorithm or DEFAULT_ALGORITHM  # -a's default (None: not given)
    algorithm = get_algorithm(args.algorithm)
    if algorithm.iterative and args.visit is not None:
        raise UsageError(f"--visit does not apply to -a {args.algorithm} "
                         "(it re-opens a cell reached at a smaller depth)")
    if algorithm.weighted and args.visit is not None:
        raise UsageError(f"--visit does not apply to -a {args.algorithm} "
                         "(it re-opens a cell reached with a lower g)")
    if args.heuristic is not None and not algorithm.informed:
        informed = ", ".join(a.key for a in ALGORITHMS.values() if a.informed)
        raise UsageError(f"--heuristic applies to -a {informed} only, not {args.algorithm}")
    try:
        sem = Semantics(order=order, corners=corners, visit=args.visit or "generate",
                        goal_test=args.goal_test, tree_search=args.tree_search,
                        heuristic=args.heuristic or DEFAULT_HEURISTIC)
        sem.check(algorithm)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return sem


def trace_line(step: Step) -> str:
    """One JSON object per step: the node taken off and exactly the successors it added, in
    order; iterative deepening adds the depth limit, a discarded step says so."""
    obj: dict = {
        "step": step.index,
        "node": list(step.node),
        "successors": [{"dir": d, "node": list(c)} for d, c in step.successors],
    }
    if step.depth_limit is not None:
        obj["depth_limit"] = step.depth_limit
    if step.discarded:
        obj["discarded"] = True
    return to_json(obj, separators=(", ", ": ")) + "\n"


def _as_step(step: Expansion) -> Step:
    return Step(step.index, step.node.cell, tuple((s.move or "", s.cell) for s in step.successors),
                step.depth_limit, step.found, step.discarded)


def search_headless(grid: Grid, key: str, semantics: Semantics, max_steps: int,
                    out: IO[str] | None) -> Outcome:
    """The whole search, its steps written to ``out`` as they happen.  Graph BFS and DFS take
    at most a few steps per cell, so they run on the fast recorded loops (the record is
    bounded by the map); iterative deepening and tree search can take billions of steps on a
    small map, so they stream the reference loop, which keeps only the frontier and the
    parents it points to.  The two are held equal by a property test."""
    algorithm = get_algorithm(key)
    if algorithm.iterative or semantics.tree_search:
        from tui_search.engine.reference import stream  # not imported at start-up

        write = None if out is None else (lambda step: out.write(trace_line(_as_step(step))))
        return stream(grid, algorithm, semantics, max_steps, write)
    run = Run(grid, key, semantics, max_steps)
    if out is not None:
        for step in run.steps():
            out.write(trace_line(step))
    return run.outcome()


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


def json_summary(outcome: Outcome, scenario: Scenario | None = None) -> dict:
    """The headless JSON object (README: "Headless output")."""
    path, moves = outcome.path, outcome.moves
    extra = {} if scenario is None else {
        "optimal_length": round(scenario.optimal_length, 6),
        "optimal": optimal(outcome, scenario),
    }
    return {
        "algorithm": outcome.algorithm,
        "found": outcome.found,
        "path": [list(c) for c in path] if path is not None else None,
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
    scenario: Scenario | None = None,
) -> str:
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
    if algorithm.informed and not admissible(outcome.semantics.heuristic,
                                             outcome.semantics.order):
        lines.append(f"  warning:      {INADMISSIBLE}")
    if outcome.moves is not None:
        lines.append(f"  moves:        {outcome.length:,} ({moves_text(outcome.moves)})")
        lines.append(f"  cost:         {outcome.cost:.3f}")
    if scenario is not None:
        lines.append(f"  benchmark:    {benchmark_text(outcome, scenario)}")
    lines.append(f"  expanded:     {outcome.expanded:,}")
    if outcome.discarded:
        lines.append(f"  discarded:    {outcome.discarded:,}")
    lines.append(f"  generated:    {outcome.generated:,}")
    lines.append(f"  max frontier: {outcome.max_frontier:,}")
    return "\n".join(lines)


def run_headless(args: argparse.Namespace, grid: Grid, path: Path | None) -> int:
    if args.trace == "-" and args.json:
        raise UsageError("--trace - and --json both want stdout; give --trace a file")
    where = str(path or TUTORIAL_NAME)
    _need_endpoints(grid, where)
    semantics = semantics_from(args)

    def search(out: IO[str] | None) -> Outcome:
        return search_headless(grid, args.algorithm, semantics, args.max_steps, out)

    if args.trace == "-":
        outcome = search(sys.stdout)
    elif args.trace:
        try:
            with open(args.trace, "w", encoding="utf-8") as fh:
                outcome = search(fh)
        except OSError as exc:
            raise MapError(args.trace, f"cannot write the trace: {exc.strerror}") from None
    else:
        outcome = search(None)
    scenario = getattr(args, "scenario", None)
    if args.json:
        print(to_json(json_summary(outcome, scenario)))
    elif args.trace != "-":
        blocked_by = None
        if not outcome.found and not outcome.gave_up and not semantics.is_default:
            from tui_search.engine.diagnose import blocking_rule

            blocked_by = blocking_rule(grid, semantics)
        print(human_summary(outcome, where, args.max_steps, blocked_by, scenario))
    if outcome.gave_up:
        return EXIT_GAVE_UP
    return EXIT_FOUND if outcome.found else EXIT_NO_PATH


def contenders_from(args: argparse.Namespace) -> list[Contender]:
    """``--compare``'s searches, each under the flags' choices (``--heuristic`` for the
    informed ones that name none)."""
    base = semantics_from(args, checked=False)
    try:
        return parse_compare(args.compare, base)
    except ValueError as exc:
        raise UsageError(f"--compare {args.compare!r}: {exc}") from None


def compare_table(labels: list[str], outcomes: list[Outcome]) -> str:
    """The comparison as text: a row a search, marks on the fewest expanded and the
    cheapest path, and the tutorial's sentence."""
    rows = comparison(labels, outcomes)
    lines = table_lines(table_cells(rows)) + [MARKS_KEY, summary_sentence(rows)]
    return "\n".join("  " + line for line in lines)


def run_compare(args: argparse.Namespace, grid: Grid, path: Path | None) -> int:
    where = str(path or TUTORIAL_NAME)
    _need_endpoints(grid, where)
    contenders = contenders_from(args)
    outcomes = [search_headless(grid, c.algorithm, c.semantics, args.max_steps, None)
                for c in contenders]
    if args.json:
        print(to_json({"runs": [json_summary(o, getattr(args, "scenario", None))
                                   for o in outcomes]}))
    else:
        print(f"Comparison on {where}:")
        print(compare_table([c.label for c in contenders], outcomes))
    if any(o.gave_up for o in outcomes):
        return EXIT_GAVE_UP
    return EXIT_FOUND if all(o.found for o in outcomes) else EXIT_NO_PATH


def run_exercise(args: argparse.Namespace, grid: Grid, path: Path | None) -> int:
    """Grade the map on an exercise: ``solved`` or ``not solved`` with the figures."""
    where = str(path or TUTORIAL_NAME)
    _need_endpoints(grid, where)
    verdict: Verdict = check(args.exercise, grid, tutorial_grid(), args.max_steps)
    if args.json:
        print(to_json({"map": where, **verdict.as_json()}))
    else:
        print(f"{where}: exercise {verdict.exercise} "
              f"{'solved' if verdict.solved else 'not solved'} — {verdict.reason}")
        if verdict.hint:
            print(f"  hint: {verdict.hint}")
    return EXIT_FOUND if verdict.solved else EXIT_NO_PATH


def _need_endpoints(grid: Grid, where: str) -> None:
    missing = [name for name in ("start", "goal") if getattr(grid, name) is None]
    if missing:
        raise MapError(where, f"the map has no {' or '.join(missing)}: give --start X,Y "
                       "--goal X,Y, or --scen FILE --scen-row N")


def run_app(args: argparse.Namespace, grid: Grid, path: Path | None) -> int:
    with collector_paused():  # Textual's import and the app's build (tui_search/launch.py)
        from tui_search.serve import exit_with_server, file_access
        from tui_search.tui.app import SearchApp  # Textual only when the app is wanted
        from tui_search.tui.config import Config

        scenario = getattr(args, "scenario", None)
        app = SearchApp(grid, path=path, algorithm=args.algorithm,
                        semantics=semantics_from(args), max_steps=args.max_steps,
                        unsaved_name=BUILT_IN_TITLE, theme=args.theme,
                        optimal_cost=scenario.optimal_length if scenario is not None else None,
                        exercise=args.exercise, compare=args.compare,
                        file_access=file_access(args),
                        config=Config.in_memory() if args.served else None)
        # What is imported and built by now lives as long as the app.  Without this, the
        # cyclic collector's first full pass (over Textual's ~60,000 objects) fell in the
        # first frame's rendering: 30-60 ms of a ~400 ms start (benchmarks/README.md,
        # "startup").  Objects still go when their last reference does; only cycles among
        # them are left to the end.
        gc.freeze()
    if args.served:
        exit_with_server(app)
    app.run()
    return app.return_code or 0


#: The search flags an exercise leaves at the tutorial's defaults (it grades BFS and DFS as
#: the tutorial runs them).
_SEARCH_FLAGS = ("corners", "visit", "goal_test", "heuristic")


def check_modes(args: argparse.Namespace) -> None:
    """Refuse the combinations of --compare, --exercise and the rest that make no sense; then
    resolve ``-a``'s default."""
    if args.compare and args.exercise:
        raise UsageError("--compare and --exercise: choose one (an exercise compares BFS "
                         "and DFS itself)")
    for mode in ("compare", "exercise"):
        if getattr(args, mode) is None:
            continue
        flag = f"--{mode}"
        if args.algorithm is not None:
            raise UsageError(f"{flag} chooses the searches: leave out -a")
        if args.trace:
            raise UsageError(f"--trace is for one search, not {flag}")
    if args.exercise is not None:
        changed = [f"--{f.replace('_', '-')}" for f in _SEARCH_FLAGS
                   if getattr(args, f) is not None]
        changed += [flag for flag, on in (("--order", args.order != ",".join(DEFAULT_ORDER)),
                                          ("--no-corner-cutting", args.no_corner_cutting),
                                          ("--tree-search", args.tree_search)) if on]
        if changed:
            raise UsageError(f"--exercise grades with the tutorial's rules: leave out "
                             f"{', '.join(changed)}")
    args.algorithm = args.algorithm or DEFAULT_ALGORITHM


def main(argv: list[str] | None = None) -> int:
    try:
        parser = build_parser()
        args = parser.parse_args(argv)
        from tui_search import serve

        serve.check_args(args)
        if (args.json or args.trace) and not args.headless:
            raise UsageError("--json and --trace go with --headless")
        if args.theme and args.headless:
            raise UsageError("--theme is for the app, not --headless")
        check_modes(args)
        grid, path = load_problem(args)
        if args.headless and args.compare:
            return run_compare(args, grid, path)
        if args.headless and args.exercise:
            return run_exercise(args, grid, path)
        if args.headless:
            return run_headless(args, grid, path)
        semantics_from(args)  # report bad choices before the screen changes
        if args.compare:
            contenders_from(args)
        if args.serve:
            return serve.serve(parser, args, title=path.name if path else BUILT_IN_TITLE)
        return run_app(args, grid, path)
    except UsageError as exc:
        print(f"tui-search: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except MapError as exc:
        print(f"tui-search: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:  # e.g. `tui-search ... --trace - | head`
        sys.stderr.close()
        return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
