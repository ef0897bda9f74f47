"""argv made into the frozen :class:`~tui_search.cli.options.Options`, once: the flags parsed
and checked against each other, then what they name read -- the exercise, the lesson, the
generated map's recipe, the map and its scenario, the replay -- so that a bad file is reported
before anything starts.  Every bad input is a :class:`~tui_search.cli.flags.UsageError` or a
:class:`~tui_search.engine.maps.read.MapError`: one line, exit 2.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from tui_search.cli.class_flags import check_class_flags
from tui_search.cli.flags import (
    UsageError,
    changed_choice_flags,
    contenders_from,
    load_problem,
    semantics_from,
)
from tui_search.cli.graphs import names_a_graph
from tui_search.cli.options import Options
from tui_search.cli.parser import build_parser
from tui_search.cli.serve_flags import check_serve_flags
from tui_search.engine.maps.recipes import DEFAULT_SEED, DEFAULT_SIZE
from tui_search.engine.search.registry import DEFAULT_ALGORITHM

if TYPE_CHECKING:
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.course.lesson import Lesson
    from tui_search.engine.maps.generate import Recipe


def parse_options(argv: Sequence[str] | None = None) -> Options:
    """The command line ``argv`` (None: the process's) as options, checked, with what they
    name read.  A run that reads no map (``--output``, ``--pseudocode``, the list of
    lessons, the class report) has no grid; the others have theirs."""
    args = build_parser().parse_args(argv)
    check_serve_flags(args)
    given = args.algorithm is not None
    options = Options.made(vars(args), maps=tuple(args.maps), algorithm_given=given,
                           algorithm=args.algorithm or DEFAULT_ALGORITHM)
    options = check_class_flags(options)
    if options.class_report is not None:
        return options  # a records folder: no map
    _refuse_with_traces(options)
    _check_outputs(options)
    _check_export(options)
    _check_plain(options)
    options = options.replace(exercise_read=_own_exercise(options, _exercise_of(options)),
                              recipe=_generated_recipe(options))
    _check_bidirectional(options)
    if options.output is not None or options.pseudocode:
        return options
    if options.lesson is not None:
        options = options.replace(lesson_read=_lesson_of(options))
        if options.lesson_read is None:  # --lesson alone: the list of lessons
            return options
    if options.headless and options.exercise:  # the class report reads its maps one by one
        return options
    exercise = options.exercise_read
    on_graph = exercise is not None and exercise.graph is not None
    if options.map is not None and options.map.endswith(".test"):  # the course's test file
        from tui_search.cli.course import with_course_test

        options = with_course_test(options)
    elif names_a_graph(options.map) or (on_graph and options.map is None):
        options = _with_graph(options)
    else:
        grid, path, scenario = load_problem(options)
        options = options.replace(grid=grid, path=path, scenario=scenario)
    if options.check_search_py is not None:
        from tui_search.cli.search_py import check_options, student_replay

        options = check_options(options)
        if options.headless:
            return options
        semantics_from(options)
        return options.replace(replay_read=student_replay(options))
    if options.headless or options.check_trace is not None:
        return options  # their searches' choices are checked as they run
    semantics_from(options)  # report bad choices before the screen changes
    if options.compare:
        contenders_from(options)
    if options.replay is not None:
        from tui_search.cli.traces import read_replay  # the traces' modules: only then

        options = options.replace(replay_read=read_replay(options))
    return options


def _with_graph(options: Options) -> Options:
    """The options with the graph MAP names read (``romania``, ``FILE.graph``), and what a
    graph does not do yet refused by name."""
    from pathlib import Path

    from tui_search.cli.graphs import load_graph_problem  # only for a graph
    from tui_search.engine.maps.graph_file import BUILT_IN

    exercise = options.exercise_read
    on_graph = exercise is not None and exercise.graph is not None
    for flag, given in (("--export", options.export), ("--plain", options.plain),
                        ("--exercise", options.exercise and not on_graph)):
        if given:
            raise UsageError(f"{flag} runs on a grid; on a graph use the app, --headless or "
                             "--check-trace")
    if options.map is None:  # an exercise on a graph starts on its own graph
        assert exercise is not None and exercise.graph is not None
        return options.replace(graph=exercise.graph.copy(), path=None)
    graph = load_graph_problem(options)
    path = None if options.map in BUILT_IN else Path(str(options.map))
    return options.replace(graph=graph, path=path)


def _refuse_with_traces(options: Options) -> None:
    """``--check-trace`` and ``--replay`` take one trace and one search: no ``--exercise`` or
    ``--compare``; ``--replay`` is the app's, and not a lesson's either."""
    if options.check_trace is not None and (options.exercise or options.compare):
        raise UsageError("--check-trace checks one trace against one search: leave out "
                         f"--{'exercise' if options.exercise else 'compare'}")
    if options.replay is None:
        return
    for flag in ("exercise", "compare", "lesson", "check_trace", "trace", "headless", "serve"):
        if getattr(options, flag) not in (None, False):
            raise UsageError("--replay shows one trace beside one search in the app: leave "
                             f"out --{flag.replace('_', '-')}")


def _check_bidirectional(options: Options) -> None:
    """The bidirectional searches run everywhere but beside a replayed trace (its check
    is ``--check-trace -a bibfs``, headless) and by hand."""
    from tui_search.engine.search.registry import BIDIRECTIONAL

    keys = [options.algorithm]
    if options.compare:
        keys += [part.split(":")[0].strip() for part in options.compare.split(",")]
    named = next((key for key in keys if key in BIDIRECTIONAL), None)
    if named is not None and options.replay is not None:
        raise UsageError(f"--replay shows a trace beside a one-way search; {named}'s trace is "
                         f"checked by --check-trace FILE -a {named} --headless")


def _check_outputs(options: Options) -> None:
    """What the headless outputs go with, and what goes with neither."""
    if ((options.json or options.trace or options.csv or options.check_trace)
            and not options.headless):
        raise UsageError("--json, --csv, --trace and --check-trace go with --headless (--json "
                         "and --csv also with --class-report)")
    if options.csv and (options.json or not options.exercise):
        raise UsageError("--csv is for --exercise E --headless, without --json")
    if options.trace_format != "jsonl" and not options.trace:
        raise UsageError("--trace-format goes with --trace FILE")
    if options.theme and options.headless and options.export is None:
        raise UsageError("--theme is for the app and --export, not --headless alone")


#: What an export is made of: one run (or a comparison) on one map, none of these.
_NOT_EXPORTED = ("json", "csv", "trace", "check_trace", "exercise", "lesson", "replay",
                 "pseudocode", "output")


def _check_gradescope(options: Options) -> None:
    """``--gradescope OUT.json`` goes with the class report or ``--check-search-py``, headless;
    an existing file is replaced only with ``--force`` (checked again when it is written)."""
    import os

    from tui_search.engine.util.filenames import describe_name

    target = options.gradescope
    if target is None:
        return
    if not options.headless or not (options.exercise or options.check_search_py):
        raise UsageError("--gradescope goes with --exercise E --headless MAP... (the class "
                         "report) or --check-search-py FILE ... --headless")
    if options.export is not None:
        raise UsageError("--gradescope and --export: one file at a time")
    if os.path.lexists(target) and not options.force:
        raise UsageError(f"{describe_name(target)} exists: --force replaces it")


def _check_export(options: Options) -> None:
    """``--export`` writes a file from a headless run; its companions go with it, and an
    existing file is replaced only with ``--force`` (checked again when it is written)."""
    _check_gradescope(options)
    if options.export is None:
        for flag in ("fps", "export_view", "handout_steps", "force"):
            if flag == "force" and options.gradescope is not None:
                continue  # --force goes with --gradescope too
            if getattr(options, flag) not in (None, False):
                raise UsageError(f"--{flag.replace('_', '-')} goes with --export FILE")
        return
    from tui_search.export.kinds import kind_of, refuse_existing  # only with --export

    if not options.headless:
        raise UsageError("--export writes a file from a run without the app: add --headless "
                         "(in the app: the palette's Export command, ctrl+p)")
    for flag in _NOT_EXPORTED:
        if getattr(options, flag) not in (None, False):
            raise UsageError(f"--export writes one run (or a comparison): leave out "
                             f"--{flag.replace('_', '-')}")
    try:
        kind = kind_of(options.export)
        if options.handout_steps is not None and kind != "md":
            raise ValueError("--handout-steps goes with a handout, --export FILE.md")
        refuse_existing(options.export, kind, options.force)
    except ValueError as exc:
        raise UsageError(str(exc)) from None


def _check_plain(options: Options) -> None:
    """``--plain`` is the app's other face: a map, its searches and choices, an exercise;
    not a headless run, a lesson, a replay or a theme."""
    if not options.plain:
        return
    for flag in ("headless", "lesson", "replay", "theme", "export"):
        if getattr(options, flag) not in (None, False):
            raise UsageError(f"--plain is the app in plain lines: leave out "
                             f"--{flag.replace('_', '-')}")


def _exercise_of(options: Options) -> Exercise | None:
    """Refuse the combinations of --compare, --exercise and the rest that make no sense;
    then ``--exercise``'s exercise, read (None without it)."""
    if options.compare and options.exercise is not None:
        searches = " and ".join(c.label for _, c in _read_exercise(options.exercise).searches)
        raise UsageError(f"--compare and --exercise: choose one (the exercise compares "
                         f"{searches} itself)")
    for mode in ("compare", "exercise"):
        if getattr(options, mode) is None:
            continue
        flag = f"--{mode}"
        if options.algorithm_given:
            raise UsageError(f"{flag} chooses the searches: leave out -a")
        if options.trace:
            raise UsageError(f"--trace is for one search, not {flag}")
    if options.exercise is None:
        return None
    exercise = _read_exercise(options.exercise)
    changed = changed_choice_flags(options)
    if changed:
        raise UsageError(f"--exercise grades under the exercise's own rules: leave out "
                         f"{', '.join(changed)} (an exercise file sets its rules: "
                         "docs/04-exercises.md)")
    return exercise


def _own_exercise(options: Options, exercise: Exercise | None) -> Exercise | None:
    """An exercise whose map is each student's own (``seed = "student"``) on ``--student``'s
    map; a by-hand exercise is for the app."""
    if exercise is None:
        return None
    if exercise.by_hand and (options.headless or options.plain):
        raise UsageError(f"--exercise {options.exercise}: it is done by hand, in the app "
                         "(leave out --headless)")
    if not exercise.student_seed:
        return exercise
    if options.student is not None:
        return exercise.for_student(options.student)
    if options.serve or options.served:
        return exercise  # each visitor is asked their name
    if options.headless and options.maps:
        return exercise  # a class's maps: each graded against its own (its recipe line)
    raise UsageError(f"--exercise {options.exercise}: its map is each student's own (seed = "
                     "\"student\"): give --student NAME")


def _read_exercise(name: str) -> Exercise:
    """``--exercise``'s exercise: 1, 2 or a file (a bad file: MapError, exit 2)."""
    from tui_search.engine.course.exercise_file import find_exercise

    if not name.strip():
        raise UsageError("--exercise: the name is empty (give 1, 2 or an exercise file)")
    try:
        return find_exercise(name)
    except ValueError as exc:
        raise UsageError(f"--exercise {name}: {exc} (or give an exercise file)") from None


def _generated_recipe(options: Options) -> Recipe | None:
    """``--generate``'s recipe (None without it); its companions without it, or a MAP with
    it, are a UsageError."""
    if options.generate is None:
        for flag in ("size", "seed", "output"):
            if getattr(options, flag) is not None:
                raise UsageError(f"--{flag} goes with --generate")
        return None
    if options.map is not None:
        raise UsageError("--generate makes the map: leave out MAP")
    if options.output is not None:
        for flag in ("headless", "pseudocode", "serve", "exercise", "compare"):
            if getattr(options, flag) not in (None, False):
                raise UsageError(f"--output writes the map and exits: leave out --{flag}")
    for flag, what in (("size", "WxH, as 40x20"), ("seed", "a number or a word")):
        value = getattr(options, flag)
        if value is not None and not value.strip():
            raise UsageError(f"--{flag} is empty: give {what}")
    try:
        from tui_search.engine.maps.generate import make_recipe  # only with --generate

        return make_recipe(options.generate,
                           DEFAULT_SIZE if options.size is None else options.size,
                           DEFAULT_SEED if options.seed is None else options.seed)
    except ValueError as exc:
        raise UsageError(f"--generate: {exc}") from None


def _lesson_of(options: Options) -> Lesson | None:
    """``--lesson``'s lesson, read (a bad one is a MapError: exit 2); None for ``--lesson``
    alone, which lists the built-in lessons."""
    from tui_search.engine.course.lesson import find_lesson, read_lesson

    if options.headless or options.serve:
        raise UsageError("--lesson is for the app, not --headless or --serve")
    for flag in ("compare", "exercise"):  # a section sets the searches and the exercise
        if getattr(options, flag) is not None:
            raise UsageError(f"--lesson sets the searches itself, section by section: leave "
                             f"out --{flag}")
    name = options.lesson
    if not name:
        return None
    return read_lesson(find_lesson(name), None if name.endswith(".md") else name)
