"""The command line: parse arguments, load the map, then either start the app or search headless
(:mod:`tui_search.cli.headless`).

The headless path never imports Textual or Rich, so scripts and graders start in a fraction of
the app's start-up time.  Every bad input ends in one line on stderr and exit code 2.
"""

from __future__ import annotations

import argparse
import gc
import shutil
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

from tui_search import __version__
from tui_search.cli.flags import (
    EXIT_BAD_INPUT,
    TUTORIAL_NAME,
    UsageError,
    changed_choice_flags,
    check_generate,
    contenders_from,
    load_problem,
    map_name,
    semantics_from,
    write_generated,
)
from tui_search.engine.maps.grid import DEFAULT_ORDER, Grid
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.recipes import DEFAULT_SEED, DEFAULT_SIZE, KINDS, MAX_SIDE
from tui_search.engine.run.recorded import MAX_STEPS
from tui_search.engine.search.choices import CORNER_RULES, GOAL_TESTS, VISIT_RULES
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.loops.compiled import CoreUnavailable, core_name
from tui_search.engine.search.registry import ALGORITHMS, DEFAULT_ALGORITHM
from tui_search.engine.util.collector import collector_held
from tui_search.tui.view.themes import THEMES  # plain data: no Textual

if TYPE_CHECKING:
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.tui.app import SearchApp

BUILT_IN_TITLE = "tutorial (built-in)"  # the app's title for the map with no file


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:  # one line, not argparse's usage + message
        raise UsageError(f"{message} (see tui-search --help)")

    def parse_known_args(  # type: ignore[override]
        self, args: Sequence[str] | None = None, namespace: argparse.Namespace | None = None,
    ) -> tuple[argparse.Namespace, list[str]]:
        """The arguments, ``map`` the one MAP (:func:`split_maps`)."""
        parsed, extra = super().parse_known_args(args, namespace)
        split_maps(parsed)
        return parsed, extra


def build_parser() -> argparse.ArgumentParser:
    # argparse makes a help formatter for every argument it adds, and each asks the terminal's
    # size: asked once here (build_parser 0.85 -> 0.46 ms).
    width = shutil.get_terminal_size().columns - 2
    p = _Parser(
        prog="tui-search",
        formatter_class=lambda prog: argparse.HelpFormatter(prog, width=width),
        description="Watch a robot plan a path on a grid with breadth-first, depth-first, "
        "iterative-deepening, uniform-cost, greedy best-first and A* search. With no MAP, opens "
        "the tutorial's 6x6 map.",
        epilog="Exit codes (headless): 0 path found, 1 no path, 2 bad input, 3 gave up (--max-steps).",
    )
    p.add_argument("map", nargs="*", default=None, metavar="MAP",
                   help="a text map (.txt) or a MovingAI map (.map); several only with "
                   "--exercise E --headless (the class report)")
    p.add_argument("--version", action="version", version=f"tui-search {__version__} ({core_name()})")
    p.add_argument("-a", "--algorithm", choices=list(ALGORITHMS), default=None,
                   help="; ".join(f"{a.key}: {a.name}" for a in ALGORITHMS.values()))
    p.add_argument("--start", metavar="X,Y", help="start cell (overrides the map's S)")
    p.add_argument("--goal", metavar="X,Y", help="goal cell (overrides the map's G)")
    p.add_argument("--terrain", metavar="FILE",
                   help="a terrain table: lines 'CHAR COST' (a positive number) or 'CHAR "
                   "blocked' naming the map's letters (f 5 in a text map; S, W, T in a .map); "
                   "a text map's digits 1-9 cost themselves")
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
    p.add_argument("--exercise", metavar="N|FILE",
                   help="the tutorial's exercise N or an exercise FILE (TOML: see the README) "
                   "as a live challenge in the app; with --headless, grade the maps on it (1: "
                   "BFS expands fewer nodes than DFS; 2: DFS's path has more moves than "
                   "BFS's): exit 0 all solved, 1 not, 2 bad input, 3 a search gave up (one "
                   "map); several maps print the class report")
    p.add_argument("--generate", metavar="KIND",
                   help="make a map instead of reading one: " + "; ".join(
                       f"{k.name}: {k.help}".replace("%", "%%") for k in KINDS.values())
                   + " (with --output FILE, write it and exit; else open it in the app)")
    p.add_argument("--size", metavar="WxH",
                   help=f"with --generate: the map's size (default {DEFAULT_SIZE}, at most "
                   f"{MAX_SIDE}x{MAX_SIDE})")
    p.add_argument("--seed", metavar="SEED",
                   help=f"with --generate: a whole number or any text (default {DEFAULT_SEED}); "
                   "the same kind, size and seed make the same map everywhere")
    p.add_argument("--output", metavar="FILE",
                   help="with --generate: write the map to FILE (never over an existing file; "
                   "- for standard output)")
    p.add_argument("--max-steps", metavar="N", type=_positive, default=MAX_STEPS,
                   help=f"give up after N expansions (default {MAX_STEPS:,}: iterative "
                   "deepening on a big map can take billions)")
    p.add_argument("--theme", choices=list(THEMES), default=None,
                   help="the app's colours for this run (the app remembers a theme chosen in "
                   "it with t or ctrl+p): " + "; ".join(f"{t.name}: {t.description}"
                                                         for t in THEMES.values()))
    p.add_argument("--pseudocode", action="store_true",
                   help="print the pseudocode of -a's search under the choice flags, one "
                   "numbered line per line (for handouts), and exit")
    p.add_argument("--lesson", metavar="NAME|FILE.md", nargs="?", const="",
                   help="open a lesson beside the panes: a built-in one by name (tutorial, "
                   "choices) or a Markdown file (its format: the README); pgdn and pgup move "
                   "between its sections. With no name, list the built-in lessons")
    p.add_argument("--headless", action="store_true",
                   help="search without the app and print the result")
    p.add_argument("--json", action="store_true",
                   help="with --headless: print the result as one JSON object")
    p.add_argument("--csv", action="store_true",
                   help="with --exercise E --headless: print the grades as CSV (file, verdict, "
                   "then a column per field the exercise's condition names)")
    p.add_argument("--trace", metavar="FILE",
                   help="with --headless: write one JSON line per expansion to FILE "
                   "('-' for stdout, without --json)")
    p.add_argument("--check-trace", metavar="FILE",
                   help="with --headless: compare a trace another program wrote (the --trace "
                   "format) with -a's search under the choice flags, step by step, or without "
                   "-a find the searches it matches longest: exit 0 a match, 1 a difference, "
                   "2 a malformed trace")
    p.add_argument("--replay", metavar="FILE",
                   help="open the app on a trace another program wrote (the --trace format), "
                   "beside -a's search under the choice flags (without -a: the search it "
                   "matches best) in lockstep, its first difference marked (d: to it and back)")
    from tui_search.serve import (
        web as serve,  # the flags of --serve (textual-serve only when serving)
    )

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


def build_app(args: argparse.Namespace, grid: Grid, path: Path | None) -> SearchApp:
    """The app the command line asks for (Textual imported here: only when it is wanted)."""
    from tui_search.serve.web import file_access
    from tui_search.tui.app import SearchApp
    from tui_search.tui.config import Config

    scenario = getattr(args, "scenario", None)
    lesson = getattr(args, "lesson_read", None)
    replay = getattr(args, "replay_read", None)  # its search and choices are the panes'
    return SearchApp(grid, path=path, algorithm=replay.algorithm if replay else args.algorithm,
                     semantics=replay.semantics if replay else semantics_from(args),
                     max_steps=args.max_steps, replay=replay,
                     unsaved_name=app_title(args),
                     theme=args.theme,
                     optimal_cost=scenario.optimal_length if scenario is not None else None,
                     exercise=getattr(args, "exercise_read", None), compare=args.compare,
                     file_access=file_access(args),
                     config=Config.in_memory() if args.served else None, lesson=lesson)


def app_title(args: argparse.Namespace) -> str:
    """The app's title for a map with no file: a generated map's recipe, a teacher's
    exercise's own map, or the tutorial."""
    name = map_name(args, None)
    return BUILT_IN_TITLE if name == TUTORIAL_NAME else name


def run_app(args: argparse.Namespace, grid: Grid, path: Path | None) -> int:
    # The collector off for Textual's import, the app's build and its first frame, on again
    # once that frame is drawn (tui_search/engine/util/collector.py).
    with collector_held() as resume:
        app = build_app(args, grid, path)
        # What is imported and built by now lives as long as the app.  Without this, the
        # cyclic collector's first full pass (over Textual's ~60,000 objects) fell in the
        # first frame's rendering: 30-60 ms of a ~400 ms start (benchmarks/README.md,
        # "startup").  Objects still go when their last reference does; only cycles among
        # them are left to the end.
        gc.freeze()
        app.call_after_refresh(resume)
        if args.served:
            from tui_search.serve.web import exit_with_server, greet_visitor

            exit_with_server(app)
            greet_visitor(app, args)
        app.run()
    return app.return_code or 0


def check_modes(args: argparse.Namespace) -> None:
    """Refuse the combinations of --compare, --exercise and the rest that make no sense; then
    resolve ``-a``'s default."""
    if args.compare and args.exercise is not None:
        searches = " and ".join(c.label for _, c in read_exercise(args.exercise).searches)
        raise UsageError(f"--compare and --exercise: choose one (the exercise compares "
                         f"{searches} itself)")
    for mode in ("compare", "exercise"):
        if getattr(args, mode) is None:
            continue
        flag = f"--{mode}"
        if args.algorithm is not None:
            raise UsageError(f"{flag} chooses the searches: leave out -a")
        if args.trace:
            raise UsageError(f"--trace is for one search, not {flag}")
    args.exercise_read = None
    if args.exercise is not None:
        args.exercise_read = read_exercise(args.exercise)
        changed = changed_choice_flags(args)
        if changed:
            raise UsageError(f"--exercise grades with the tutorial's rules: leave out "
                             f"{', '.join(changed)}")
    args.algorithm = args.algorithm or DEFAULT_ALGORITHM


def refuse_with_traces(args: argparse.Namespace) -> None:
    """``--check-trace`` and ``--replay`` take one trace and one search: no ``--exercise`` or
    ``--compare``; ``--replay`` is the app's, and not a lesson's either."""
    if args.check_trace is not None and (args.exercise or args.compare):
        raise UsageError("--check-trace checks one trace against one search: leave out "
                         f"--{'exercise' if args.exercise else 'compare'}")
    if args.replay is None:
        return
    for flag in ("exercise", "compare", "lesson", "check_trace", "trace", "headless", "serve"):
        if getattr(args, flag, None) not in (None, False):
            raise UsageError("--replay shows one trace beside one search in the app: leave "
                             f"out --{flag.replace('_', '-')}")


def read_exercise(name: str) -> Exercise:
    """``--exercise``'s exercise: 1, 2 or a file (a bad file: MapError, exit 2)."""
    from tui_search.engine.course.exercise_file import find_exercise

    if not name.strip():
        raise UsageError("--exercise: the name is empty (give 1, 2 or an exercise file)")
    try:
        return find_exercise(name)
    except ValueError as exc:
        raise UsageError(f"--exercise {name}: {exc} (or give an exercise file)") from None


def split_maps(args: argparse.Namespace) -> None:
    """``args.maps``, every MAP given; ``args.map``, the one map (None: none).  Several
    maps are only for the class report (``--exercise E --headless``)."""
    args.maps = list(args.map or [])
    if len(args.maps) > 1 and not (args.exercise and args.headless):
        raise UsageError("one MAP at a time (several only with --exercise E --headless: "
                         "the class report)")
    args.map = args.maps[0] if args.maps else None


def open_lesson(args: argparse.Namespace) -> bool:
    """``--lesson``: read the lesson (a bad one is a MapError: exit 2), or with no name print
    the built-in lessons (True: done)."""
    from tui_search.engine.course.lesson import built_in, find_lesson, read_lesson

    if args.headless or args.serve:
        raise UsageError("--lesson is for the app, not --headless or --serve")
    for flag in ("compare", "exercise"):  # a section sets the searches and the exercise
        if getattr(args, flag) is not None:
            raise UsageError(f"--lesson sets the searches itself, section by section: leave "
                             f"out --{flag}")
    if not args.lesson:
        for name, title in built_in().items():
            print(f"{name:10} {title}")
        return True
    args.lesson_read = read_lesson(find_lesson(args.lesson),
                                   None if args.lesson.endswith(".md") else args.lesson)
    return False


def main(argv: list[str] | None = None) -> int:
    try:
        parser = build_parser()
        args = parser.parse_args(argv)
        typed = argparse.Namespace(**vars(args))  # as typed: the checks below fill in defaults
        from tui_search.serve import web as serve

        serve.check_args(args)
        refuse_with_traces(args)
        if (args.json or args.trace or args.csv or args.check_trace) and not args.headless:
            raise UsageError("--json, --csv, --trace and --check-trace go with --headless")
        if args.csv and (args.json or not args.exercise):
            raise UsageError("--csv is for --exercise E --headless, without --json")
        if args.theme and args.headless:
            raise UsageError("--theme is for the app, not --headless")
        algorithm_given = args.algorithm is not None
        check_modes(args)
        check_generate(args)
        if args.output is not None:
            return write_generated(args)
        if args.pseudocode:
            from tui_search.cli.headless import print_pseudocode  # the app's start does without

            return print_pseudocode(args)
        if args.lesson is not None and open_lesson(args):
            return 0
        if args.headless and args.exercise:
            from tui_search.cli.report import run_exercise  # not the app's: its start does without

            return run_exercise(args)
        grid, path = load_problem(args)
        if args.headless or args.check_trace is not None or args.replay is not None:
            # the headless output and the traces: modules the app's start does without
            from tui_search.cli.headless import run_compare, run_headless
            from tui_search.cli.traces import read_replay, run_check_trace
        if args.headless and args.compare:
            return run_compare(args, grid, path)
        if args.check_trace is not None:
            return run_check_trace(args, grid, path, algorithm_given)
        if args.headless:
            return run_headless(args, grid, path)
        semantics_from(args)  # report bad choices before the screen changes
        if args.compare:
            contenders_from(args)
        if args.serve:
            # The visitors' apps get the flags as typed: not -a's default, which --exercise and
            # --compare refuse.
            return serve.serve(parser, typed, title=path.name if path else app_title(args))
        if args.replay is not None:
            args.replay_read = read_replay(args, grid, path, algorithm_given)
        return run_app(args, grid, path)
    except (UsageError, CoreUnavailable) as exc:
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
