"""Maps graded on an exercise, headless (``--exercise E --headless MAP...``): one map as a line
or the **class report** of many -- a line a map and a summary.  ``--json`` is always a list (an
object a map) and ``--csv`` always a table, whatever the folder holds.  One bad map never
stops the report: it is a line saying why it is unreadable.

No Textual or Rich here.
"""

from __future__ import annotations

import csv
import sys
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from tui_search.cli.flags import (
    EXIT_FOUND,
    EXIT_GAVE_UP,
    EXIT_NO_PATH,
    UsageError,
    load_problem,
    map_name,
)
from tui_search.cli.graphs import names_a_graph
from tui_search.cli.headless import need_endpoints, to_json
from tui_search.engine.course.exercise_file import Exercise
from tui_search.engine.course.grading import Verdict, grade
from tui_search.engine.maps.read import MapError
from tui_search.engine.util.filenames import describe_name
from tui_search.engine.util.numbers import group_digits

if TYPE_CHECKING:
    from tui_search.cli.options import Options
    from tui_search.engine.maps.graph import Graph


class Graded(NamedTuple):
    """One map of the report: its name, and its verdict or why it could not be read."""

    where: str
    verdict: Verdict | None
    error: str = ""

    @property
    def status(self) -> str:
        return "unreadable" if self.verdict is None else self.verdict.status

    @property
    def reason(self) -> str:
        """Why: the figures (and what else changed), or why the map is unreadable -- the
        words of its line, after the dash, as the CSV's ``reason`` column has them."""
        v = self.verdict
        if v is None:
            return self.error
        return v.said + (f" (hint: {v.hint})" if v.hint else "")

    def line(self) -> str:
        return f"{self.where}: {self.status}{_dash(self.reason)}"

    def as_json(self) -> dict[str, object]:
        if self.verdict is None:
            return {"map": self.where, "verdict": "unreadable", "solved": False,
                    "error": self.error}
        return {"map": self.where, **self.verdict.as_json()}


def _dash(said: str) -> str:
    """`` — `` and the verdict's reason with its figures; nothing when it has none (a
    condition that names no field)."""
    return f" — {said}" if said else ""


def _error_text(exc: MapError) -> str:
    where = ", ".join(f"{word} {n}" for word, n in (("line", exc.line), ("column", exc.col))
                      if n is not None)
    return f"{where}: {exc.message}" if where else exc.message


def grade_one(options: Options, exercise: Exercise) -> Graded:
    """``options.map`` (with the command line's --start, --goal and --terrain) graded."""
    where = describe_name(options.map) if options.map else map_name(options, None)
    try:
        if exercise.graph is not None or names_a_graph(options.map):
            return Graded(where, grade(exercise, _graph_of(options, exercise),
                                       options.max_steps))
        grid, path, _ = load_problem(options)
        where = describe_name(map_name(options, path))  # escape sequences shown, not run
        need_endpoints(grid, where)
    except MapError as exc:
        return Graded(where, None, _error_text(exc))
    except UsageError as exc:
        return Graded(where, None, str(exc))
    return Graded(where, grade(exercise, grid, options.max_steps))


def _graph_of(options: Options, exercise: Exercise) -> Graph:
    """A student's graph file (an exercise on a graph grades graphs), or the exercise's own
    when no file is named."""
    from tui_search.cli.graphs import load_graph_problem

    if options.map is None:
        assert exercise.graph is not None
        return exercise.graph.copy()
    if not names_a_graph(options.map):
        raise UsageError("the exercise is on a graph: a student's file is a .graph")
    return load_graph_problem(options)


def summary(rows: list[Graded]) -> str:
    """"14 of 17 solved, 2 not solved, 1 unreadable"."""
    counts = {s: sum(r.status == s for r in rows)
              for s in ("solved", "not solved", "not graded", "unreadable")}
    return ", ".join([f"{group_digits(counts['solved'])} of {group_digits(len(rows))} solved"]
                     + [f"{group_digits(n)} {s}" for s, n in counts.items()
                        if n and s != "solved"])


def heading(exercise: Exercise) -> list[str]:
    """The report's first lines: the exercise's title and words, and its rules where they
    are not the tutorial's."""
    return [f"{exercise.title}: {exercise.text}"] + (
        [f"Rules: {exercise.rules}"] if exercise.rules else [])


def write_csv(rows: list[Graded], exercise: Exercise) -> None:
    """``file,verdict,reason,`` then a column per field the condition names."""
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["file", "verdict", "reason", *exercise.fields])
    for row in rows:
        figures = row.verdict.figures if row.verdict is not None else {}
        out.writerow([row.where, row.status, row.reason,
                      *(_cell(figures.get(f)) for f in exercise.fields)])


def _cell(value: object) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def run_exercise(options: Options) -> int:
    """Grade ``options.maps`` (none: the tutorial's map, or --generate's) on ``--exercise``."""
    exercise = options.exercise_read
    assert exercise is not None, "the exercise --exercise names, read"
    # A report (a line, a CSV row or a JSON object a map, a bad map one of them) for several
    # maps, and for one under --csv or --json, so that a spreadsheet gets its table and a
    # gradebook script its list whatever the folder holds.
    if (len(options.maps) <= 1 and not ((options.csv or options.json) and options.maps)
            and (exercise.graph is not None or names_a_graph(options.map))):
        where = describe_name(options.map) if options.map else Path(exercise.path).name
        rows = [Graded(where, grade(exercise, _graph_of(options, exercise),
                                    options.max_steps))]  # a bad graph: exit 2
    elif len(options.maps) <= 1 and not ((options.csv or options.json) and options.maps):
        grid, path, _ = load_problem(options)  # a bad map is bad input: exit 2
        where = describe_name(map_name(options, path))
        need_endpoints(grid, where)
        rows = [Graded(where, grade(exercise, grid, options.max_steps))]
    else:
        if options.scen:
            raise UsageError("--scen is for one map, not the class report")
        rows = [grade_one(options.replace(map=name), exercise) for name in options.maps]
    if options.gradescope is not None:
        write_gradescope(options, report_results(rows, exercise))
    if options.csv:
        write_csv(rows, exercise)
    elif options.json:
        print(to_json([row.as_json() for row in rows]))
    elif len(rows) == 1:
        _print_one(rows[0])
    else:  # the class report: the exercise, a line a map, the summary, the exercise's hint
        for line in heading(exercise):
            print(line)
        for row in rows:
            print(row.line())
        print(summary(rows))
        if exercise.hint:
            print(f"Hint (shown while not solved): {exercise.hint}")
    if len(rows) == 1 and rows[0].verdict is not None and not rows[0].verdict.graded:
        return EXIT_GAVE_UP
    return EXIT_FOUND if all(row.status == "solved" for row in rows) else EXIT_NO_PATH


def write_gradescope(options: Options, data: dict[str, object]) -> None:
    """``--gradescope OUT.json``: ``data`` written there, into a new file, or atomically over
    an old one with ``--force`` (a UsageError, one line, when it exists without it or
    cannot be written)."""
    from tui_search.engine.util.atomic import os_reason, write_atomically

    target = options.gradescope
    assert target is not None
    body = (to_json(data) + "\n").encode("utf-8")
    try:
        if options.force:
            write_atomically(target, body)
        else:
            with open(target, "xb") as out:
                out.write(body)
    except FileExistsError:
        raise UsageError(f"{describe_name(target)} exists: --force replaces it") from None
    except OSError as err:
        raise UsageError(f"{describe_name(target)}: cannot write: {os_reason(err)}") from None


def report_results(rows: list[Graded], exercise: Exercise) -> dict[str, object]:
    """The class report as Gradescope's results: a test a map, a point when it is solved."""
    from tui_search.engine.course.gradescope import graded_test, results

    tests = [graded_test(row.where, row.status == "solved",
                         f"{row.status}{_dash(row.reason)}") for row in rows]
    return results("\n".join([*heading(exercise), summary(rows)]), tests)


def _print_one(row: Graded) -> None:
    """One map, as before the report: the exercise named, and the hint on its own line."""
    verdict = row.verdict
    assert verdict is not None
    print(f"{row.where}: {verdict.exercise.name} {verdict.status}{_dash(verdict.said)}")
    if verdict.hints:
        print(f"  hint: {verdict.hints}")


__all__ = ["Graded", "run_exercise", "summary"]
