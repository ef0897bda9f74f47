"""``--check-trace FILE``: compare a trace another program wrote with one of the app's searches
(:mod:`tui_search.engine.traces.check`) and print the verdict as text or JSON.

No Textual or Rich here (the headless path).
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from tui_search.cli.flags import UsageError, changed_choice_flags, map_name, semantics_from
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import MapError
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.engine.traces.replay import Replay

EXIT_MATCH, EXIT_DIFFERENCE = 0, 1


def _needs_ends(args: argparse.Namespace, grid: Grid, path: Path | None) -> str:
    """The map's name as the messages say it; a map with no start or goal is an error."""
    where = describe_name(map_name(args, path))
    missing = [name for name in ("start", "goal") if getattr(grid, name) is None]
    if missing:
        raise MapError(where, f"the map has no {' or '.join(missing)}: give --start X,Y "
                       "--goal X,Y")
    return where


def _no_choices_without_a(flag: str, what: str, verb: str, args: argparse.Namespace) -> None:
    """Without ``-a`` the choices are found, not given: a choice flag is a usage error."""
    given = changed_choice_flags(args)
    if given:
        raise UsageError(f"without -a, {flag} {what}: give -a to {verb} {', '.join(given)}")


def read_replay(args: argparse.Namespace, grid: Grid, path: Path | None,
                algorithm_given: bool) -> Replay:
    """``--replay FILE``: the trace beside ``-a``'s search under the choice flags, else the
    search the diagnosis finds it nearest (a malformed trace is a MapError: exit 2)."""
    from tui_search.engine.traces.read import load_trace
    from tui_search.engine.traces.replay import replay_of

    _needs_ends(args, grid, path)
    if not algorithm_given:
        _no_choices_without_a("--replay", "replays beside the search it matches best",
                              "replay beside", args)
    trace = load_trace(args.replay, grid)
    return replay_of(trace, grid, args.algorithm if algorithm_given else None,
                     semantics_from(args), args.max_steps)


def run_check_trace(args: argparse.Namespace, grid: Grid, path: Path | None,
                    algorithm_given: bool) -> int:
    """Read the trace, check it against ``-a``'s search, print the verdict; exit 0 on a
    match, 1 on a difference (a malformed trace is a MapError: exit 2)."""
    from tui_search.cli.headless import to_json
    from tui_search.engine.traces.check import check_trace
    from tui_search.engine.traces.read import load_trace

    for flag in ("trace", "compare", "exercise"):
        if getattr(args, flag):
            raise UsageError(f"--check-trace checks one search: leave out --{flag}")
    where = _needs_ends(args, grid, path)
    if not algorithm_given:
        return _diagnose(args, grid, where)
    semantics = semantics_from(args)
    trace = load_trace(args.check_trace, grid)
    verdict = check_trace(trace, grid, args.algorithm, semantics, max_steps=args.max_steps)
    if args.json:
        print(to_json({"trace": describe_name(args.check_trace), "map": where,
                       **verdict.as_json()}))
    else:
        print(verdict.text())
    return EXIT_MATCH if verdict.matches else EXIT_DIFFERENCE


def _diagnose(args: argparse.Namespace, grid: Grid, where: str) -> int:
    """Without ``-a``: the searches and choices that match the trace longest."""
    from tui_search.cli.headless import to_json
    from tui_search.engine.traces.diagnose import diagnose
    from tui_search.engine.traces.read import load_trace

    _no_choices_without_a("--check-trace", "tries every search and choice", "check", args)
    diagnosis = diagnose(load_trace(args.check_trace, grid), grid, args.max_steps)
    if args.json:
        print(to_json({"trace": describe_name(args.check_trace), "map": where,
                       **diagnosis.as_json()}))
    else:
        print(diagnosis.text())
    return EXIT_MATCH if diagnosis.matches else EXIT_DIFFERENCE
