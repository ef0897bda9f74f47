"""The flags of a class: ``--by-hand`` (the student makes the search's steps), ``--records DIR``
(what each student does, recorded there), ``--student NAME`` (whose records, in a terminal),
``--class FILE`` (the served visitors pick their name from it) and ``--class-report DIR`` (the
records read back, a table a student a row); their checks against each other.

With ``--class-report``, ``--gradescope OUT.json`` writes one student's records as Gradescope's
results (:mod:`~tui_search.cli.records_report`); its checks are here.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from tui_search.cli.flags import UsageError

if TYPE_CHECKING:
    from tui_search.cli.options import Options

#: A class list file is at most this big (a name a line).
MAX_CLASS_BYTES = 256 * 1024


def add_class_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--by-hand", action="store_true",
                   help="open the app with the search made by hand: take each entry off the "
                   "frontier, add its successors in order, each step checked at once (in the "
                   "app: H)")
    p.add_argument("--records", metavar="DIR", default=None,
                   help="record what the student does (exercise verdicts, quiz answers, runs "
                   "by hand, trace checks) in DIR, as JSON lines, a file a student: with "
                   "--student NAME, or with --serve (each visitor is asked their name)")
    p.add_argument("--student", metavar="NAME", default=None,
                   help="with --records: whose work it is; with an exercise whose map is each "
                   "student's own (seed = \"student\"): whose map")
    p.add_argument("--class", metavar="FILE", dest="class_list", default=None,
                   help="with --serve --records: the class list, one student a line; each "
                   "visitor picks their name from it")
    p.add_argument("--class-report", metavar="DIR", default=None,
                   help="read a records folder (--records DIR) and print a table, a student a "
                   "row (exercises solved, quiz score, mistakes by hand by kind), and the "
                   "misconceptions; with --csv or --json")


def check_class_flags(options: Options) -> Options:
    """Refuse what makes no sense together; make the records folder (its parent must be
    there); return the options with ``--records`` and ``--class`` as absolute paths (the
    served visitors' apps get them so)."""
    import os

    if options.class_report is not None:
        _report_alone(options)
        return options
    if options.by_hand:
        for flag in ("headless", "compare", "replay", "lesson", "plain", "check_trace",
                     "export", "pseudocode", "output"):
            if getattr(options, flag) not in (None, False):
                raise UsageError(f"--by-hand steps one search in the app: leave out "
                                 f"--{flag.replace('_', '-')}")
    if options.class_list is not None and (not (options.serve or options.served)
                                           or options.records is None):
        raise UsageError("--class FILE goes with --serve --records DIR (the visitors pick "
                         "their name from it)")
    if options.student is not None and options.serve:
        raise UsageError("--student is for one student's terminal: with --serve each visitor "
                         "is asked their name")
    if options.records is not None:
        if options.student is None and not (options.serve or options.served):
            raise UsageError("--records DIR needs --student NAME (whose work it is), or "
                             "--serve (each visitor is asked)")
        if options.headless and options.check_trace is None:
            raise UsageError("--records records the app's work and --check-trace's: not "
                             "another --headless run")
        from tui_search.engine.course.records import RecordsError, open_folder

        try:
            folder = open_folder(options.records)
        except RecordsError as exc:
            raise UsageError(str(exc)) from None
        options = options.replace(records=str(folder))
    if options.student is not None:
        from tui_search.engine.course.records import clean_name

        if not clean_name(options.student):
            raise UsageError("--student: the name is empty")
    if options.class_list is not None:
        read_class_file(options.class_list)
        options = options.replace(class_list=os.path.abspath(options.class_list))
    return options


def _report_alone(options: Options) -> None:
    """``--class-report DIR`` reads a folder: no map, no app."""
    for flag in ("serve", "plain", "by_hand", "records", "exercise", "check_trace",
                 "replay", "lesson", "export", "trace", "compare", "generate"):
        if getattr(options, flag) not in (None, False):
            raise UsageError(f"--class-report reads a records folder: leave out "
                             f"--{flag.replace('_', '-')}")
    if options.maps:
        raise UsageError("--class-report reads a records folder: leave out MAP")
    if options.csv and options.json:
        raise UsageError("--class-report: --csv or --json, not both")
    if options.gradescope is not None:
        import os

        from tui_search.engine.util.filenames import describe_name

        if os.path.lexists(options.gradescope) and not options.force:
            raise UsageError(f"{describe_name(options.gradescope)} exists: --force replaces it")
    elif options.force:
        raise UsageError("--force goes with --gradescope OUT.json (a file replaced)")


def read_class_file(path: str) -> tuple[str, ...]:
    """``--class FILE``'s names; a UsageError (one line) for a file that cannot be read or
    names no one."""
    from tui_search.engine.maps.read import MapError, read_text
    from tui_search.tui.model.class_records import read_class_list

    try:
        names = read_class_list(read_text(path, "a class list", MAX_CLASS_BYTES))
    except MapError as exc:
        raise UsageError(f"--class {exc}") from None
    if not names:
        raise UsageError(f"--class {path}: the file names no one (a student a line)")
    return names


__all__ = ["add_class_arguments", "check_class_flags", "read_class_file"]
