"""The command line: parse arguments, load the map, then either start the app or search headless.

The headless path never imports Textual or Rich, so scripts and graders start in a fraction of
the app's start-up time.  Every bad input ends in one line on stderr and exit code 2.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import IO, NoReturn

from tui_search import __version__
from tui_search.engine.grid import DEFAULT_ORDER, Grid, parse_order
from tui_search.engine.mapfile import (
    MapError,
    check_scenario_matches,
    load_map,
    load_scenario,
    parse_cell,
    parse_map_text,
)
from tui_search.engine.run import MAX_STEPS, Run
from tui_search.engine.search import ALGORITHM_NAMES, ALGORITHMS, SearchOptions

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
        description="Watch a robot plan a path on a grid with breadth-first, depth-first and "
        "iterative-deepening search. With no MAP, opens the tutorial's 6x6 map.",
        epilog="Exit codes (headless): 0 path found, 1 no path, 2 bad input, 3 gave up (--max-steps).",
    )
    p.add_argument("map", nargs="?", help="a text map (.txt) or a MovingAI map (.map)")
    p.add_argument("--version", action="version", version=f"tui-search {__version__}")
    p.add_argument("-a", "--algorithm", choices=ALGORITHMS, default="bfs",
                   help="bfs (FIFO queue), dfs (LIFO stack) or iddfs (iterative deepening)")
    p.add_argument("--start", metavar="X,Y", help="start cell (overrides the map's S)")
    p.add_argument("--goal", metavar="X,Y", help="goal cell (overrides the map's G)")
    p.add_argument("--scen", metavar="FILE", help="a MovingAI .scen file to take start and goal from")
    p.add_argument("--scen-row", metavar="N", type=int, default=None,
                   help="problem N of --scen, counted from 0 after the version line")
    p.add_argument("--order", metavar="DIRS", default=",".join(DEFAULT_ORDER),
                   help="neighbour order, a permutation of the 8 directions "
                   "(default %(default)s)")
    p.add_argument("--no-corner-cutting", action="store_true",
                   help="forbid a diagonal move when a cell beside it is blocked")
    p.add_argument("--max-steps", metavar="N", type=_positive, default=MAX_STEPS,
                   help=f"give up after N expansions (default {MAX_STEPS:,}: iterative "
                   "deepening on a big map can take billions)")
    p.add_argument("--headless", action="store_true",
                   help="search without the app and print the result")
    p.add_argument("--json", action="store_true",
                   help="with --headless: print the result as one JSON object")
    p.add_argument("--trace", metavar="FILE",
                   help="with --headless: write one JSON line per expansion to FILE "
                   "('-' for stdout, without --json)")
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
    if args.scen:
        scen = load_scenario(args.scen, args.scen_row)
        start = start or scen.start
        goal = goal or scen.goal
    grid = load_map(path, start=start, goal=goal)
    if scen is not None:
        check_scenario_matches(scen, grid, args.scen, str(path))
    return grid, path


def _options(args: argparse.Namespace) -> SearchOptions:
    try:
        order = parse_order(args.order)
    except ValueError as exc:
        raise UsageError(f"--order {args.order!r}: {exc}") from None
    return SearchOptions(order=order, corner_cutting=not args.no_corner_cutting)


def write_trace(run: Run, out: IO[str]) -> None:
    """One JSON object per expansion, in order (IDDFS adds the depth limit)."""
    iddfs = run.algorithm == "iddfs"
    for step in run.steps():
        obj: dict = {
            "step": step.index,
            "node": list(step.node),
            "successors": [{"dir": d, "node": list(c)} for d, c in step.successors],
        }
        if iddfs:
            obj["depth_limit"] = step.depth_limit
        out.write(json.dumps(obj, separators=(", ", ": ")) + "\n")


def human_summary(result: dict, where: str) -> str:
    name = ALGORITHM_NAMES[result["algorithm"]]
    outcome = "path found" if result["found"] else "no path"
    if result["gave_up"]:
        outcome = f"gave up at --max-steps {result['expanded']:,} (raise it to search on)"
    lines = [f"{name} on {where}: {outcome}"]
    if result["found"]:
        moves = ", ".join(result["moves"]) or "(start is the goal)"
        lines.append(f"  moves:        {result['steps']} ({moves})")
        lines.append(f"  cost:         {result['cost']:.3f}")
    lines.append(f"  expanded:     {result['expanded']}")
    lines.append(f"  generated:    {result['generated']}")
    lines.append(f"  max frontier: {result['max_frontier']}")
    return "\n".join(lines)


def run_headless(args: argparse.Namespace, grid: Grid, path: Path | None) -> int:
    if args.trace == "-" and args.json:
        raise UsageError("--trace - and --json both want stdout; give --trace a file")
    where = str(path or TUTORIAL_NAME)
    missing = [name for name in ("start", "goal") if getattr(grid, name) is None]
    if missing:
        raise MapError(where, f"the map has no {' or '.join(missing)}: give --start X,Y "
                       "--goal X,Y, or --scen FILE --scen-row N")
    run = Run(grid, args.algorithm, _options(args), args.max_steps)
    if args.trace == "-":
        write_trace(run, sys.stdout)
    elif args.trace:
        try:
            with open(args.trace, "w", encoding="utf-8") as fh:
                write_trace(run, fh)
        except OSError as exc:
            raise MapError(args.trace, f"cannot write the trace: {exc.strerror}") from None
    result = run.summary()
    if args.json:
        print(json.dumps(result))
    elif args.trace != "-":
        print(human_summary(result, where))
    if result["gave_up"]:
        return EXIT_GAVE_UP
    return EXIT_FOUND if result["found"] else EXIT_NO_PATH


def run_app(args: argparse.Namespace, grid: Grid, path: Path | None) -> int:
    from tui_search.tui.app import SearchApp  # Textual only when the app is wanted

    app = SearchApp(grid, path=path, algorithm=args.algorithm, options=_options(args),
                    max_steps=args.max_steps, unsaved_name=BUILT_IN_TITLE)
    app.run()
    return app.return_code or 0


def main(argv: list[str] | None = None) -> int:
    try:
        args = build_parser().parse_args(argv)
        if (args.json or args.trace) and not args.headless:
            raise UsageError("--json and --trace go with --headless")
        grid, path = load_problem(args)
        if args.headless:
            return run_headless(args, grid, path)
        _options(args)  # report a bad --order before the screen changes
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
