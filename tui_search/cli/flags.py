"""What the command line's flags ask for: the map (:func:`load_problem`), the search choices
(:func:`semantics_from`) and the searches to compare (:func:`contenders_from`), with
:class:`UsageError` for flags that make no sense.

Shared by the dispatch (:mod:`tui_search.cli.main`), the headless runs (:mod:`tui_search.cli.headless`)
and the server (:mod:`tui_search.serve.web`), so that none of them imports another.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import DEFAULT_ORDER, Cell, Grid, parse_order
from tui_search.engine.maps.load import load_map, parse_cell, parse_map_text
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.recipes import DEFAULT_SEED, DEFAULT_SIZE
from tui_search.engine.maps.terrain import load_terrain
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.compare import Contender, parse_compare
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC
from tui_search.engine.search.registry import ALGORITHMS, DEFAULT_ALGORITHM, get_algorithm
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.engine.course.exercise_file import Exercise

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


def load_problem(args: argparse.Namespace) -> tuple[Grid, Path | None]:
    """The grid to search (start and goal resolved) and the file it came from."""
    start = _cell_arg("--start", args.start)
    goal = _cell_arg("--goal", args.goal)
    if (args.scen is None) != (args.scen_row is None):
        raise UsageError("--scen and --scen-row go together")
    terrain = load_terrain(args.terrain) if args.terrain is not None else None
    recipe = getattr(args, "recipe", None)
    if recipe is not None:
        if args.scen:
            raise UsageError("--scen needs a MAP, not --generate")
        from tui_search.engine.maps.generate import generated_text  # only for a generated map

        text = generated_text(recipe)
        return parse_map_text(text, recipe.title, start=start, goal=goal, terrain=terrain), None
    own = _teachers_exercise(args)
    if args.map is None and own is not None:  # a teacher's exercise starts on its own map
        if args.scen:
            raise UsageError("--scen needs a MAP")
        grid = own.grid.copy()
        grid.start, grid.goal = start or grid.start, goal or grid.goal
        return grid, None
    if args.map is None:
        if args.scen:
            raise UsageError("--scen needs a MAP")
        # The map ships inside the package (a plain file: importlib.resources would cost
        # ~10 ms of start-up to import).
        text = (Path(__file__).parents[1] / "maps" / TUTORIAL_NAME).read_text("utf-8")
        return parse_map_text(text, TUTORIAL_NAME, start=start, goal=goal,
                              terrain=terrain), None
    path = Path(args.map)
    scen = None
    args.scenario = None
    if args.scen:
        from tui_search.engine.maps.scenarios import (  # only with --scen: not the tutorial's start
            check_scenario_map,
            check_scenario_matches,
            load_scenario,
        )

        scen = load_scenario(args.scen, args.scen_row)
        # A row for another map is refused by name, before its start and goal are tried on
        # this map's cells (they would fail there for the wrong reason).
        check_scenario_map(scen, args.scen, path)
        start = start or scen.start
        goal = goal or scen.goal
    grid = load_map(path, start=start, goal=goal, terrain=terrain)
    if scen is not None:
        check_scenario_matches(scen, grid, args.scen, str(path))
        # Its optimal length is for its own start and goal, every cell costing 1: not when a
        # flag moved one, nor on terrain.
        if (grid.start, grid.goal) == (scen.start, scen.goal) and grid.costs is None:
            args.scenario = scen
    return grid, path


def _teachers_exercise(args: argparse.Namespace) -> Exercise | None:
    """``--exercise FILE``'s exercise (read by the command line), None for none or the
    tutorial's 1 and 2 (whose map is the tutorial's)."""
    exercise = getattr(args, "exercise_read", None)
    return exercise if exercise is not None and exercise.number is None else None


def map_name(args: argparse.Namespace, path: Path | None) -> str:
    """What a headless run calls the map: its file, a generated map's recipe, a teacher's
    exercise's own map, or the tutorial's file name."""
    recipe = getattr(args, "recipe", None)
    own = _teachers_exercise(args)
    if path is not None:
        return str(path)
    if recipe is not None:
        return str(recipe.title)
    return f"{Path(own.path).name}'s map" if own is not None else TUTORIAL_NAME


def check_generate(args: argparse.Namespace) -> None:
    """``--generate``'s recipe in ``args.recipe`` (None without it); its companions without
    it, or a MAP with it, are a UsageError."""
    args.recipe = None
    if args.generate is None:
        for flag in ("size", "seed", "output"):
            if getattr(args, flag) is not None:
                raise UsageError(f"--{flag} goes with --generate")
        return
    if args.map is not None:
        raise UsageError("--generate makes the map: leave out MAP")
    if args.output is not None:
        for flag in ("headless", "pseudocode", "serve", "exercise", "compare"):
            if getattr(args, flag, None) not in (None, False):
                raise UsageError(f"--output writes the map and exits: leave out --{flag}")
    for flag, what in (("size", "WxH, as 40x20"), ("seed", "a number or a word")):
        if getattr(args, flag) is not None and not getattr(args, flag).strip():
            raise UsageError(f"--{flag} is empty: give {what}")
    try:
        from tui_search.engine.maps.generate import make_recipe  # only with --generate

        args.recipe = make_recipe(args.generate,
                                  DEFAULT_SIZE if args.size is None else args.size,
                                  DEFAULT_SEED if args.seed is None else args.seed)
    except ValueError as exc:
        raise UsageError(f"--generate: {exc}") from None


def write_generated(args: argparse.Namespace) -> int:
    """--generate with --output: write the map to a new file (never over one), or with
    ``--output -`` to standard output (``./-`` names a file called ``-``), exit 0."""
    from tui_search.engine.maps.generate import generate, generated_text
    from tui_search.engine.maps.write import save_new

    if args.output == "-":
        sys.stdout.write(generated_text(args.recipe))  # the bytes a file would get
        return 0
    try:
        save_new(generate(args.recipe, args.output), args.output)
    except MapError as exc:
        raise UsageError(f"--output {describe_name(args.output)}: {exc.message}") from None
    return 0


#: The choice flags whose default is None (not given).
_CHOICE_FLAGS = ("corners", "visit", "goal_test", "heuristic")


def changed_choice_flags(args: argparse.Namespace) -> list[str]:
    """The choice flags given a value other than their default (``--visit``, ``--order``)."""
    changed = [f"--{f.replace('_', '-')}" for f in _CHOICE_FLAGS if getattr(args, f) is not None]
    changed += [flag for flag, on in (("--order", args.order != ",".join(DEFAULT_ORDER)),
                                      ("--no-corner-cutting", args.no_corner_cutting),
                                      ("--tree-search", args.tree_search)) if on]
    return changed


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


def contenders_from(args: argparse.Namespace) -> list[Contender]:
    """``--compare``'s searches, each under the flags' choices (``--heuristic`` for the
    informed ones that name none)."""
    base = semantics_from(args, checked=False)
    try:
        return parse_compare(args.compare, base)
    except ValueError as exc:
        raise UsageError(f"--compare {args.compare!r}: {exc}") from None
