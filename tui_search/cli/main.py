"""The command line: argv made into options (:func:`~tui_search.cli.parse.parse_options`), then
the app, the class server or a run without the app (:mod:`tui_search.cli.headless`,
:mod:`tui_search.cli.report`, :mod:`tui_search.cli.traces`).

The headless path never imports Textual or Rich, so scripts and graders start in a fraction of
the app's start-up time.  Every bad input ends in one line on stderr and exit code 2.
"""

from __future__ import annotations

import gc
import sys
from typing import TYPE_CHECKING

from tui_search.cli.flags import (
    EXIT_BAD_INPUT,
    TUTORIAL_NAME,
    UsageError,
    contenders_from,
    map_name,
    semantics_from,
)
from tui_search.cli.options import Options
from tui_search.cli.parse import parse_options
from tui_search.engine.maps.read import MapError
from tui_search.engine.search.loops.compiled import CoreUnavailable
from tui_search.engine.util.collector import collector_held
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Iterator

    from tui_search.tui.app import SearchApp
    from tui_search.tui.model.class_records import RecordsPlan
    from tui_search.tui.model.session import Session

BUILT_IN_TITLE = "tutorial (built-in)"  # the app's title for the map with no file
#: The fork server's process, which ``--serve`` starts: it builds and runs apps this way.
FORK_COMMAND = [sys.executable, "-m", "tui_search.cli.fork_entry"]


def build_app(options: Options) -> SearchApp:
    """The app the command line asks for (Textual imported here: only when it is wanted); a
    map too big for it is refused first, in one line."""
    from tui_search.tui.model.boards import too_big_for_the_app

    board = options.graph or options.grid
    assert board is not None, "the app opens on the map the command line read"
    if options.grid is not None and (why := too_big_for_the_app(options.grid)):
        raise MapError(str(options.path) if options.path else app_title(options), why)

    from tui_search.tui.app import SearchApp
    from tui_search.tui.config import Config
    from tui_search.tui.model.file_rules import FileAccess, NameRefused

    try:
        access = FileAccess.for_app(options.served, options.save_dir, options.visitor)
    except NameRefused as exc:
        raise UsageError(str(exc)) from None
    scenario = options.scenario
    replay = options.replay_read  # its search and choices are the panes'

    return SearchApp(board, path=options.path,
                     algorithm=replay.algorithm if replay else options.algorithm,
                     semantics=replay.semantics if replay else semantics_from(options),
                     max_steps=options.max_steps, replay=replay,
                     unsaved_name=app_title(options), theme=options.theme,
                     optimal_cost=scenario.optimal_length if scenario is not None else None,
                     exercise=options.exercise_read, compare=options.compare,
                     file_access=access,
                     config=Config.in_memory() if options.served else None,
                     lesson=options.lesson_read, exporter=LazyExporter(),
                     records=records_plan(options), by_hand=options.by_hand)


def records_plan(options: Options) -> RecordsPlan | None:
    """``--records``: the folder, the student (or none: the served visitor is asked), the
    visitor's id and the class list they pick from."""
    if options.records is None:
        return None
    from pathlib import Path

    from tui_search.cli.class_flags import read_class_file
    from tui_search.tui.model.class_records import RecordsPlan

    names = read_class_file(options.class_list) if options.class_list is not None else ()
    visitor = options.visitor
    if options.served and visitor is None:  # no folder of their own: an id for the records
        import secrets

        visitor = secrets.token_hex(3)
    return RecordsPlan(Path(options.records), options.student or "", visitor, names)


class LazyExporter:
    """The palette's exporter (:class:`tui_search.export.files.AppExporter`), imported when
    first used: the first frame does without the exports' modules."""

    @staticmethod
    def problem(target: str) -> str | None:
        from tui_search.export.files import AppExporter

        return AppExporter.problem(target)

    @staticmethod
    def targets(target: str) -> list[str]:
        from tui_search.export.files import AppExporter

        return AppExporter.targets(target)

    @staticmethod
    def work(session: Session, target: str, theme: str | None, force: bool
             ) -> Callable[[], list[str]]:
        from tui_search.export.files import AppExporter

        return AppExporter.work(session, target, theme, force)


def app_title(options: Options) -> str:
    """The app's title for a map with no file: a generated map's recipe, a teacher's
    exercise's own map, or the tutorial."""
    test = options.course_test
    if test is not None:  # a layout of a course's test: saved only under a new name
        return f"{describe_name(test.path)}'s layout {test.layout_name}".rstrip()
    if options.graph is not None and options.map is not None:  # a built-in graph
        return f"{options.map} (built-in)"
    name = map_name(options, None)
    return BUILT_IN_TITLE if name == TUTORIAL_NAME else name


def run_app(options: Options) -> int:
    # The collector off for Textual's import, the app's build and its first frame, on again
    # once that frame is drawn (tui_search/engine/util/collector.py).
    with collector_held() as resume:
        app = build_app(options)
        # What is imported and built by now lives as long as the app.  Without this, the
        # cyclic collector's first full pass (over Textual's objects) fell in the first
        # frame's rendering (benchmarks/README.md, "startup").  Objects still go when their
        # last reference does; only cycles among them are left to the end.
        gc.freeze()
        app.call_after_refresh(resume)
        if options.served:
            from tui_search.serve.web import exit_with_server, greet_visitor

            exit_with_server(app)
            greet_visitor(app, options.visitor, options.save_dir)
        app.run()
    return app.return_code or 0


def session_of(options: Options) -> Session:
    """The session the app would show (plain mode's: the same searches, choices and
    exercise), without Textual."""
    from tui_search.tui.model.session import Session

    assert options.grid is not None, "plain mode opens on the map the command line read"
    scenario = options.scenario
    return Session(options.grid, options.path, options.algorithm, semantics_from(options),
                   options.max_steps, app_title(options),
                   optimal_cost=scenario.optimal_length if scenario is not None else None,
                   exercise=options.exercise_read, compare=options.compare)


def run_plain(options: Options) -> int:
    """``--plain``: a command a line from stdin, plain sentences on stdout."""
    from tui_search.plain.mode import run_plain as plain

    session = session_of(options)
    if sys.stdin.isatty():  # a person types: a prompt and line editing
        try:
            import readline  # noqa: F401 -- input() edits lines once it is imported
        except ImportError:  # (not on every system: input() without it)
            pass

        def typed() -> Iterator[str]:
            while True:
                try:
                    yield input("> ")
                except EOFError:
                    print()
                    return

        lines: Iterable[str] = typed()
    else:
        lines = sys.stdin
    return plain(session, lines, lambda line: print(line, flush=True))


def run_export(options: Options) -> int:
    """``--export FILE --headless``: the run, filmed by the app, written to FILE."""
    from tui_search.cli.headless import need_endpoints
    from tui_search.export.files import make_export
    from tui_search.export.job import Job

    grid = options.grid
    assert grid is not None, "an export runs on the map the command line read"
    need_endpoints(grid, map_name(options, options.path))
    if options.compare:
        contenders_from(options)  # bad searches said before the app starts
    export = options.export
    assert export is not None
    from tui_search.export.kinds import DEFAULT_FPS, DEFAULT_HANDOUT_STEPS

    job = Job(export, grid, options.path, app_title(options), options.algorithm,
              semantics_from(options, checked=not options.compare), options.compare,
              options.max_steps, options.theme, options.fps or DEFAULT_FPS,
              options.export_view or "full", options.force,
              DEFAULT_HANDOUT_STEPS if options.handout_steps is None else options.handout_steps)
    try:
        written = make_export(job)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    print("Wrote " + ", ".join(describe_name(name) for name in written))
    return 0


def run_server(options: Options) -> int:
    """``--serve``: the visitors' apps get the flags as typed (not -a's default, which
    --exercise and --compare refuse), the theme the teacher's."""
    from tui_search.cli.parser import build_parser
    from tui_search.cli.serve_flags import read_token, served_args
    from tui_search.serve.web import DEFAULT_HOST, ServeError, serve
    from tui_search.tui.config import Config
    from tui_search.tui.model.file_rules import FileAccess, NameRefused

    theme = options.theme or Config.load().theme  # the teacher's remembered theme, for all
    try:
        folder = FileAccess.served_in(options.save_dir).folder
    except NameRefused as exc:
        raise UsageError(str(exc)) from None
    save_folder = str(folder) if folder is not None else None
    app_args = served_args(build_parser(), options.replace(theme=theme), save_folder)
    token = (read_token(options.token_file, options.host or DEFAULT_HOST)
             if options.token_file is not None else None)
    title = options.path.name if options.path else app_title(options)
    try:
        return serve(app_args, FORK_COMMAND, host=options.host, port=options.port,
                     title=title, save_folder=save_folder,
                     own_folders=not options.shared_save_dir, memory_mb=options.app_memory,
                     token=token, records=options.records)
    except ServeError as exc:
        raise UsageError(str(exc)) from None


def run(options: Options) -> int:
    """What the options ask for, to its exit code."""
    if options.class_report is not None:
        from tui_search.cli.records_report import run_class_report

        return run_class_report(options)
    if options.output is not None:
        from tui_search.cli.flags import write_generated

        return write_generated(options)
    if options.pseudocode:
        from tui_search.cli.headless import print_pseudocode  # the app's start does without

        return print_pseudocode(options)
    if options.lesson is not None and options.lesson_read is None:
        from tui_search.engine.course.lesson import built_in

        lessons = built_in()
        width = max(map(len, lessons), default=0)
        for name, title in lessons.items():
            print(f"{name:{width}}  {title}")
        return 0
    if options.headless and options.exercise:
        from tui_search.cli.report import run_exercise  # not the app's: its start does without

        return run_exercise(options)
    if options.check_trace is not None:
        from tui_search.cli.traces import run_check_trace

        return run_check_trace(options)
    if options.headless and options.check_search_py is not None:
        from tui_search.cli.search_py import run_check_search_py

        return run_check_search_py(options)
    if options.headless and options.course_test is not None:
        from tui_search.cli.course import run_course_test_headless

        return run_course_test_headless(options)
    if options.headless and options.export is not None:
        return run_export(options)
    if options.plain:
        return run_plain(options)
    if options.headless:
        from tui_search.cli.headless import run_compare, run_headless

        return run_compare(options) if options.compare else run_headless(options)
    if options.serve:
        return run_server(options)
    return run_app(options)


def main(argv: list[str] | None = None) -> int:
    try:
        return run(parse_options(argv))
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
