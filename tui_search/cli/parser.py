"""The command line's parser: every flag, its help, and one-line errors (exit 2).

:func:`tui_search.cli.parse.parse_options` is its one user: it turns what this parses into the
frozen :class:`~tui_search.cli.options.Options` the rest of the program reads.
"""

from __future__ import annotations

import argparse
import shutil
from collections.abc import Sequence
from typing import NoReturn

from tui_search import __version__
from tui_search.cli.class_flags import add_class_arguments
from tui_search.cli.flags import UsageError
from tui_search.cli.serve_flags import add_serve_arguments
from tui_search.engine.course.presets import PRESET_WORDS, PRESETS
from tui_search.engine.maps.grid import DEFAULT_ORDER
from tui_search.engine.maps.recipes import DEFAULT_SEED, DEFAULT_SIZE, KINDS, MAX_SIDE
from tui_search.engine.run.recorded import MAX_STEPS
from tui_search.engine.search.choices import (
    CORNER_RULES,
    GOAL_TESTS,
    RECURSIVE_FORMS,
    STOP_RULES,
    TABLE,
    TIE_RULES,
    TURN_RULES,
    VISIT_RULES,
)
from tui_search.engine.search.heuristics import CHEAPER_BY, DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.loops.compiled import core_name
from tui_search.engine.search.registry import ALGORITHMS, BIDIRECTIONAL
from tui_search.export.kinds import (
    DEFAULT_FPS,
    DEFAULT_HANDOUT_STEPS,
    EXPORT_VIEWS,
    MAX_FPS,
    MIN_FPS,
)
from tui_search.tui.view.themes import THEMES  # plain data: no Textual


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
    # size: asked once here (benchmarks/README.md, "startup").
    width = shutil.get_terminal_size().columns - 2
    p = _Parser(
        prog="tui-search",
        formatter_class=lambda prog: argparse.HelpFormatter(prog, width=width),
        description="Watch a robot plan a path on a grid with breadth-first, depth-first, "
        "iterative-deepening, uniform-cost, greedy best-first and A* search. With no MAP, opens "
        "the tutorial's 6x6 map; 'romania' opens AIMA's road map of Romania, a graph.",
        epilog="Exit codes (headless): 0 path found, 1 no path, 2 bad input, 3 gave up "
        "(--max-steps).",
    )
    p.add_argument("map", nargs="*", default=None, metavar="MAP",
                   help="a text map (.txt), a MovingAI map (.map), a graph (.graph) or "
                   "romania (the built-in graph); several only with --exercise E --headless "
                   "(the class report)")
    p.add_argument("--version", action="version",
                   version=f"tui-search {__version__} ({core_name()})")
    p.add_argument("-a", "--algorithm", choices=[*ALGORITHMS, *BIDIRECTIONAL], default=None,
                   help="; ".join(f"{a.key}: {a.name}" for a in (*ALGORITHMS.values(),
                                                                 *BIDIRECTIONAL.values()))
                   + " (the bidirectional ones: not beside --replay)")
    p.add_argument("--start", metavar="X,Y", help="start cell (overrides the map's S); on a "
                   "graph, a node's name")
    p.add_argument("--goal", metavar="X,Y", help="goal cell (overrides the map's G); on a "
                   "graph, a node's name")
    p.add_argument("--terrain", metavar="FILE",
                   help="a terrain table: lines 'CHAR COST' (a positive number) or 'CHAR "
                   "blocked' naming the map's letters (f 5 in a text map; S, W, T in a .map); "
                   "a text map's digits 1-9 cost themselves")
    p.add_argument("--scen", metavar="FILE",
                   help="a MovingAI .scen file to take start and goal from")
    p.add_argument("--scen-row", metavar="N", type=int, default=None,
                   help="problem N of --scen, counted from 0 after the version line")
    p.add_argument("--preset", choices=PRESETS, default=None,
                   help="a course's choices in one word, each still changed by its own flag "
                   f"after it: cs188 ({PRESET_WORDS['cs188']})")
    p.add_argument("--order", metavar="DIRS", default=",".join(DEFAULT_ORDER),
                   help="the moves tried, in order: any of the 8 directions, e.g. N,W,S,E for "
                   "a 4-connected grid (default %(default)s); on a graph file (its roads as "
                   "listed, the default) or name")
    p.add_argument("--corners", choices=CORNER_RULES, default=None,
                   help="may a diagonal pass blocked corners: always (default); one: not when "
                   "both side cells are blocked; never: not when either is (MovingAI's rule)")
    p.add_argument("--no-corner-cutting", action="store_true",
                   help="the same as --corners never")
    p.add_argument("--visit", choices=VISIT_RULES, default=None,
                   help="when a cell counts as visited: generate (when pushed, default), "
                   "expand (when taken off: a cell may be on the frontier several times, "
                   "taken off again it is discarded) or expand-again (taken off again it is "
                   "expanded again: the node taken off is never checked)")
    p.add_argument("--goal-test", choices=GOAL_TESTS, default=None,
                   help="stop when the goal is pushed (generate: the default of bfs, dfs and "
                   "iddfs) or taken off (expand: the default of ucs, greedy and astar)")
    p.add_argument("--heuristic", choices=[*HEURISTICS, TABLE], default=None,
                   help="greedy's and A*'s estimate of the cost to the goal (default "
                   f"{DEFAULT_HEURISTIC}; manhattan is not admissible with diagonal moves); "
                   "on a graph table (its h lines, the default), euclidean or zero")
    p.add_argument("--tree-search", action="store_true",
                   help="no visited set: skip only cells on the node's own path")
    p.add_argument("--no-path-check", action="store_true",
                   help="with --tree-search: skip nothing, not even the parent (the "
                   "textbook's tree search)")
    p.add_argument("--recursive", action="store_true",
                   help="-a dfs or iddfs written as recursion: each call lists the neighbours "
                   "not yet visited, then calls itself on each (skipping one visited meanwhile)")
    p.add_argument("--recursive-lines", choices=RECURSIVE_FORMS, default=None,
                   help="what a recursion's trace line lists: neighbours (the default) or "
                   "calls (the cells the call recursed into; the goal found as a neighbour); "
                   "implies --recursive")
    p.add_argument("--ties", choices=TIE_RULES, default=None,
                   help="which entry of a priority tie comes out first (-a ucs, greedy, "
                   "astar): fifo the oldest (default), lifo the newest, node the smallest "
                   "cell (heapq on (f, (x, y)) tuples), low-h/high-h the lower/higher h, "
                   "low-g/high-g the lower/higher g")
    p.add_argument("--cost-tolerance", metavar="X", type=_tolerance, default=None,
                   help="how much lower a new g must be to count as cheaper (default "
                   f"{CHEAPER_BY:g}: rounding is no cheaper path; 0 compares exactly, as "
                   "code comparing floats with < does)")
    p.add_argument("--weight", metavar="W", type=_weight, default=None,
                   help="weighted A* (-a astar): f = g + W·h, W 1 or more (default 1: A* "
                   "itself); with an admissible heuristic the path costs at most W times "
                   "the optimum")
    p.add_argument("--stop", choices=STOP_RULES, default=None,
                   help="when -a bibfs, biucs or biastar stops: proven (default) once its "
                   "best meeting is proven the cheapest; first-meeting as soon as the two "
                   "searches reach a cell in common (the trap: not the cheapest path)")
    p.add_argument("--turn", choices=TURN_RULES, default=None,
                   help="whose step -a bibfs, biucs or biastar takes next: alternate "
                   "(default: forward, backward, ...) or smaller (the search whose frontier "
                   "is smaller; forward on a tie)")
    p.add_argument("--reopen", choices=("yes", "no"), default=None,
                   help="may -a ucs, greedy or astar push a cell it has expanded again, "
                   "reached with a lower g (yes, default); no: a closed set")
    p.add_argument("--mark-start", choices=("yes", "no"), default=None,
                   help="is the start marked reached when pushed (yes, default); no: a "
                   "neighbour may push it again, as some library code does")
    p.add_argument("--flip-even", action="store_true",
                   help="reverse the order on every other cell, where x + y is even, as "
                   "some tutorials' grids do (Red Blob Games' A*: --order E,W,N,S "
                   "--flip-even); a grid's only")
    p.add_argument("--compare", metavar="A,B",
                   help="two to four searches side by side in the app (compare mode); with "
                   "--headless, run them on the map and print a table (e.g. bfs,dfs or "
                   "astar:manhattan,ucs: an informed search may name its heuristic; "
                   "astar:w=2 a weight, astar:manhattan:w=2 both)")
    p.add_argument("--exercise", metavar="N|FILE",
                   help="the tutorial's exercise N or an exercise FILE (TOML: "
                   "docs/04-exercises.md) as a live challenge in the app; with --headless, "
                   "grade the maps on it (1: BFS expands fewer nodes than DFS; 2: DFS's path "
                   "has more moves than BFS's): exit 0 all solved, 1 not, 2 bad input, 3 a "
                   "search gave up (one map); several maps print the class report")
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
                   "choices) or a Markdown file (its format: docs/05-lessons.md); pgdn and "
                   "pgup move between its sections. With no name, list the built-in lessons")
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
    p.add_argument("--trace-format", choices=("jsonl", "posthoc"), default="jsonl",
                   help="with --trace: jsonl (one JSON line an expansion, the default) or "
                   "posthoc (Posthoc's search trace, version 1.4.0, as JSON: name the file "
                   "NAME.trace.json to open it in that visualiser)")
    p.add_argument("--check-trace", metavar="FILE",
                   help="with --headless: compare a trace another program wrote (the --trace "
                   "format, or Posthoc's: a .trace.json or .trace.yaml) with -a's search "
                   "under the choice flags, step by step, or without -a find the searches it "
                   "matches longest: exit 0 a match, 1 a difference, 2 a malformed trace")
    p.add_argument("--check-search-py", metavar="FILE",
                   help="run a student's CS188-style search.py (-a bfs runs its "
                   "breadthFirstSearch) in a fenced process on MAP, GRAPH or FILE.test, each "
                   "getSuccessors call an expansion, and check it as an expansions-only trace "
                   "(--preset cs188 unless choice flags are given): with --headless the "
                   "verdict, exit 0 a match, 1 a difference, 2 no answer (its reason, one "
                   "line); without, the app replays it beside the search")
    p.add_argument("--time-limit", metavar="SECONDS", type=_seconds, default=10.0,
                   help="--check-search-py: the student's run may take this long "
                   "(default %(default)g)")
    p.add_argument("--memory-limit", metavar="MB", type=_positive, default=512,
                   help="--check-search-py: the student's process may use this much "
                   "memory (default %(default)s; not enforced on macOS)")
    p.add_argument("--gradescope", metavar="OUT.json",
                   help="with --exercise E --headless MAP... (the class report) or "
                   "--check-search-py: also write Gradescope's results.json there (a test a "
                   "map, or the search and its path); an existing file only with --force")
    p.add_argument("--replay", metavar="FILE",
                   help="open the app on a trace another program wrote (the --trace format), "
                   "beside -a's search under the choice flags (without -a: the search it "
                   "matches best) in lockstep, its first difference marked (d: to it and back)")
    p.add_argument("--export", metavar="FILE",
                   help="with --headless: write the run to FILE, the kind by its ending: .svg "
                   "an animated SVG (no script), .cast an asciicast v2 recording, .gif an "
                   "animated GIF (pip install -e '.[gif]'), .md a handout (its picture FILE's "
                   "name with -final.svg, beside it), .trace.json or .trace.yaml a Posthoc "
                   "search trace (its map beside it as a MovingAI .map); drawn like the app "
                   "at 100x30, in --theme's colours (docs/12-exports-and-plain.md)")
    p.add_argument("--fps", metavar="N", type=_fps, default=None,
                   help=f"with --export: frames (steps) a second (default {DEFAULT_FPS:g})")
    p.add_argument("--export-view", choices=EXPORT_VIEWS, default=None,
                   help="with --export: full (default): the map, the frontier and the tree, "
                   "as the app shows them; map: the map alone (a big map's only view)")
    p.add_argument("--force", action="store_true",
                   help="with --export: replace FILE (and a handout's picture) if it exists")
    p.add_argument("--handout-steps", metavar="N", type=_whole, default=None,
                   help=f"with --export FILE.md: narrate the first N steps (default "
                   f"{DEFAULT_HANDOUT_STEPS})")
    p.add_argument("--plain", action="store_true",
                   help="the line-oriented mode, for screen readers, braille displays and "
                   "SSH: type a command a line (help lists them), read plain sentences")
    add_class_arguments(p)
    add_serve_arguments(p)
    return p


def _whole(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = -1
    if n < 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number")
    return n


def _fps(text: str) -> float:
    try:
        fps = float(text)
    except ValueError:
        fps = 0.0
    if not MIN_FPS <= fps <= MAX_FPS:  # (NaN too)
        raise argparse.ArgumentTypeError(
            f"{text!r}: give frames a second from {MIN_FPS:g} to {MAX_FPS:g}")
    return fps


def _tolerance(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        x = -1.0
    if not 0 <= x < float("inf"):  # NaN fails too
        raise argparse.ArgumentTypeError(f"{text!r} is not a number 0 or more")
    return x


def _weight(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        x = 0.0
    if not 1 <= x < float("inf"):  # NaN fails too
        raise argparse.ArgumentTypeError(f"{text!r} is not a number 1 or more")
    return x


def _seconds(text: str) -> float:
    try:
        seconds = float(text)
    except ValueError:
        seconds = 0.0
    if not 0.1 <= seconds <= 3600:  # (NaN too)
        raise argparse.ArgumentTypeError(f"{text!r}: give seconds from 0.1 to 3600")
    return seconds


def _positive(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive whole number")
    return n


def split_maps(args: argparse.Namespace) -> None:
    """``args.maps``, every MAP given; ``args.map``, the one map (None: none).  Several
    maps are only for the class report (``--exercise E --headless``)."""
    args.maps = list(args.map or [])
    if len(args.maps) > 1 and not (args.exercise and args.headless):
        raise UsageError("one MAP at a time (several only with --exercise E --headless: "
                         "the class report)")
    args.map = args.maps[0] if args.maps else None
