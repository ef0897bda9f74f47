"""``tui-search --class-report DIR``: a records folder (``--records DIR``, written by the app in
a terminal or served) read back as the class's table -- a student a row: the exercises
solved, the quiz's score, the runs by hand and their mistakes by kind, the traces checked --
then the misconceptions, each with how many students showed it.  ``--csv`` and ``--json``
give the same for a gradebook.

A line the reading skips (torn by a kill, or edited) is a warning on stderr naming the file
and the line; the report goes on.  No Textual or Rich here.
"""

from __future__ import annotations

import csv
import sys
from typing import TYPE_CHECKING

from tui_search.cli.flags import UsageError
from tui_search.engine.course.class_table import ClassTable, Row, class_table
from tui_search.engine.course.records import RecordsError, read_records
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.cli.options import Options


def mistakes_text(row: Row) -> str:
    """"newest 2, reached 1" (most first), "none" for a student with runs and no mistake,
    "" for one with no run by hand."""
    if not row.runs:
        return ""
    if not row.mistakes:
        return "none"
    items = sorted(row.mistakes.items(), key=lambda item: (-item[1], item[0]))
    return ", ".join(f"{cause} {n}" for cause, n in items)


def table_lines(table: ClassTable) -> list[str]:
    """The report as text: the table, then the misconceptions."""
    head = ("student", "exercises solved", "quiz", "by hand", "mistakes by kind",
            "traces matched")
    rows = [head] + [
        (r.student, ", ".join(r.solved) if r.solved else ("none" if r.tried else ""),
         f"{r.quiz_right} of {r.quiz_asked}" if r.quiz_asked else "",
         f"{r.runs_finished} of {r.runs} finished" if r.runs else "", mistakes_text(r),
         f"{r.checks_matched} of {r.checks}" if r.checks else "")
        for r in table.rows]
    widths = [max(len(row[i]) for row in rows) for i in range(len(head))]
    lines = ["  ".join(cell.ljust(w) for cell, w in zip(row, widths, strict=True)).rstrip()
             for row in rows]
    of = len(table.rows)
    if table.misconceptions:
        lines.append("Misconceptions:")
        lines += [f"  {m.sentence(of)}" for m in table.misconceptions]
    else:
        lines.append("Misconceptions: none recorded")
    return lines


def write_csv(table: ClassTable) -> None:
    """A row a student: the figures, then a column for each kind of mistake any student
    made (``mistakes:newest``)."""
    causes = sorted({cause for r in table.rows for cause in r.mistakes})
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["student", "exercises_solved", "exercises", "quiz_right", "quiz_asked",
                  "by_hand_finished", "by_hand_runs", "by_hand_mistakes",
                  *(f"mistakes:{c}" for c in causes), "trace_checks_matched", "trace_checks",
                  "last"])
    for r in table.rows:
        out.writerow([r.student, len(r.solved), ";".join(r.solved), r.quiz_right,
                      r.quiz_asked, r.runs_finished, r.runs, r.mistake_count,
                      *(r.mistakes.get(c, 0) for c in causes), r.checks_matched, r.checks,
                      r.last])


def run_class_report(options: Options) -> int:
    """Read ``--class-report``'s folder, print its table; 0 (a folder that cannot be read:
    a UsageError, exit 2)."""
    from tui_search.cli.headless import to_json

    folder = options.class_report
    assert folder is not None
    try:
        events, warnings = read_records(folder)
    except RecordsError as exc:
        raise UsageError(f"--class-report {exc}") from None
    for warning in warnings:
        print(f"tui-search: warning: {describe_name(warning)}", file=sys.stderr)
    table = class_table(events)
    if options.gradescope is not None:
        from tui_search.cli.report import write_gradescope

        write_gradescope(options, student_results(table, folder))
    if options.json:
        print(to_json({"folder": folder, **table.as_json(), "warnings": warnings}))
    elif options.csv:
        write_csv(table)
    else:
        n = len(table.rows)
        print(f"Class report of {describe_name(folder)}: {n} student{'s' if n != 1 else ''}, "
              f"{len(events):,} events")
        for line in table_lines(table):
            print(line)
    return 0


def student_results(table: ClassTable, folder: str) -> dict[str, object]:
    """One student's records as Gradescope's results (``--gradescope``: Gradescope grades a
    submission, one student's): a test an exercise tried (a point when solved), and the
    quiz, the runs by hand and the traces checked, each worth what was asked of it.  A
    folder of no student or of several is a UsageError."""
    from tui_search.engine.course.gradescope import graded_test, results, scored_test

    if len(table.rows) != 1:
        names = ", ".join(r.student for r in table.rows[:3]) or "no one"
        raise UsageError(f"--gradescope writes one submission's results: "
                         f"{describe_name(folder)} holds {len(table.rows)} students' records "
                         f"({names}{', ...' if len(table.rows) > 3 else ''})")
    r = table.rows[0]
    tests = [graded_test(f"exercise: {name}", name in r.solved,
                         "solved" if name in r.solved else "not solved") for name in r.tried]
    if r.quiz_asked:
        tests.append(scored_test("quiz: the next node", r.quiz_right, r.quiz_asked,
                                 f"{r.quiz_right} of {r.quiz_asked} right"))
    if r.runs:
        tests.append(scored_test("runs by hand", r.runs_finished, r.runs,
                                 f"{r.runs_finished} of {r.runs} finished; mistakes: "
                                 f"{mistakes_text(r)}"))
    if r.checks:
        tests.append(scored_test("traces checked", r.checks_matched, r.checks,
                                 f"{r.checks_matched} of {r.checks} matched"))
    return results("\n".join(table_lines(table)), tests)


__all__ = ["run_class_report", "student_results", "table_lines", "write_csv"]
