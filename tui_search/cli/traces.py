"""``--check-trace FILE``: compare a trace another program wrote with one of the app's searches
(:mod:`tui_search.engine.traces.check`) and print the verdict as text or JSON.

No Textual or Rich here (the headless path).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.cli.flags import UsageError, changed_choice_flags, map_name, semantics_from
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import MapError
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.cli.options import Options
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.search.choices import Semantics
    from tui_search.engine.traces.replay import Replay

EXIT_MATCH, EXIT_DIFFERENCE = 0, 1


def _needs_ends(options: Options) -> tuple[Grid | Graph, str]:
    """The map or graph, and its name as the messages say it; a map with no start or goal is
    an error (a graph's were checked as it was read)."""
    if options.graph is not None:
        from tui_search.cli.headless import board_of

        return board_of(options)
    grid = options.grid
    assert grid is not None, "a trace is read for the map the command line read"
    where = describe_name(map_name(options, options.path))
    missing = [name for name in ("start", "goal") if getattr(grid, name) is None]
    if missing:
        raise MapError(where, f"the map has no {' or '.join(missing)}: give --start X,Y "
                       "--goal X,Y")
    return grid, where


def _no_choices_without_a(flag: str, what: str, verb: str, options: Options) -> None:
    """Without ``-a`` the choices are found, not given: a choice flag is a usage error."""
    given = changed_choice_flags(options)
    if given:
        raise UsageError(f"without -a, {flag} {what}: give -a to {verb} {', '.join(given)}")


def read_replay(options: Options) -> Replay:
    """``--replay FILE``: the trace beside ``-a``'s search under the choice flags, else the
    search the diagnosis finds it nearest (a malformed trace is a MapError: exit 2)."""
    from tui_search.engine.traces.posthoc import load_any_trace as load_trace
    from tui_search.engine.traces.replay import replay_of

    grid, _ = _needs_ends(options)
    if not options.algorithm_given:
        _no_choices_without_a("--replay", "replays beside the search it matches best",
                              "replay beside", options)
    assert options.replay is not None, "the trace --replay names"
    trace = load_trace(options.replay, grid)
    return replay_of(trace, grid, options.algorithm if options.algorithm_given else None,
                     semantics_from(options), options.max_steps)


def _record(options: Options, where: str, **fields: object) -> None:
    """``--records DIR --student NAME``: the check's verdict and diagnosis, a line of the
    student's records (a problem writing it is a warning: the check's answer stands)."""
    if options.records is None:
        return
    import sys

    from tui_search.engine.course.records import Writer

    assert options.check_trace is not None
    writer = Writer(options.records, options.student or "student")
    problem = writer.write("trace_check", trace=describe_name(options.check_trace), map=where,
                           **fields)
    if problem:
        print(f"tui-search: warning: {problem}", file=sys.stderr)


def run_check_trace(options: Options) -> int:
    """Read the trace, check it against ``-a``'s search, print the verdict; exit 0 on a
    match, 1 on a difference (a malformed trace is a MapError: exit 2)."""
    from tui_search.cli.headless import to_json
    from tui_search.engine.traces.check import check_trace
    from tui_search.engine.traces.posthoc import load_any_trace as load_trace

    for flag in ("trace", "compare", "exercise"):
        if getattr(options, flag):
            raise UsageError(f"--check-trace checks one search: leave out --{flag}")
    grid, where = _needs_ends(options)
    assert options.check_trace is not None, "the trace --check-trace names"
    if not options.algorithm_given:
        return _diagnose(options, grid, options.check_trace, where)
    semantics = semantics_from(options)
    if get_algorithm(options.algorithm).bidirectional:
        return _check_bidirectional(options, grid, semantics, where)
    trace = load_trace(options.check_trace, grid)
    verdict = check_trace(trace, grid, options.algorithm, semantics, max_steps=options.max_steps)
    difference = verdict.difference
    _record(options, where, algorithm=verdict.algorithm, search=verdict.choices,
            verdict="match" if verdict.matches else "difference", steps=verdict.steps,
            matched_steps=verdict.matched, cause=difference.cause if difference else None,
            diagnosis=verdict.text())
    if options.json:
        print(to_json({"trace": describe_name(options.check_trace), "map": where,
                       **verdict.as_json()}))
    else:
        print(verdict.text())
    return EXIT_MATCH if verdict.matches else EXIT_DIFFERENCE


def _check_bidirectional(options: Options, grid: Grid | Graph, semantics: Semantics,
                         where: str) -> int:
    """``--check-trace`` with ``-a bibfs``, ``biucs`` or ``biastar``: the trace (the app's
    JSON lines) against the bidirectional search, its stopping rule included."""
    from tui_search.cli.headless import to_json
    from tui_search.engine.traces.meeting import check_bidirectional
    from tui_search.engine.traces.read import load_trace

    assert options.check_trace is not None
    trace = load_trace(options.check_trace, grid, both_ways=True)
    verdict = check_bidirectional(trace, grid, options.algorithm, semantics, options.max_steps)
    _record(options, where, algorithm=verdict.algorithm, search=verdict.search,
            verdict="match" if verdict.matches else "difference", steps=verdict.steps,
            matched_steps=verdict.matched, cause=verdict.cause or None,
            diagnosis=verdict.text())
    if options.json:
        print(to_json({"trace": describe_name(options.check_trace), "map": where,
                       **verdict.as_json()}))
    else:
        print(verdict.text())
    return EXIT_MATCH if verdict.matches else EXIT_DIFFERENCE


def _diagnose(options: Options, grid: Grid | Graph, trace: str, where: str) -> int:
    """Without ``-a``: the searches and choices that match the trace longest (the
    bidirectional ones too for a trace that looks bidirectional)."""
    from tui_search.cli.headless import to_json
    from tui_search.engine.traces.meeting import diagnose_trace, summary
    from tui_search.engine.traces.posthoc import load_any_trace as load_trace

    _no_choices_without_a("--check-trace", "tries every search and choice", "check", options)
    diagnosis = diagnose_trace(load_trace(trace, grid, both_ways=None), grid,
                               options.max_steps)
    _record(options, where, **summary(diagnosis),
            verdict="match" if diagnosis.matches else "closest", diagnosis=diagnosis.text())
    if options.json:
        print(to_json({"trace": describe_name(trace), "map": where,
                       **diagnosis.as_json()}))
    else:
        print(diagnosis.text())
    return EXIT_MATCH if diagnosis.matches else EXIT_DIFFERENCE
