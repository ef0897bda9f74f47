"""``--check-search-py search.py MAP -a bfs``: a student's ``search.py`` run in a fenced
process (:mod:`tui_search.engine.traces.sandbox`) on the problem the app gives it, each
``getSuccessors`` call an expansion, then checked as any expansions-only trace: which search
it is, or where it first parts from ``-a``'s under ``--preset cs188`` (or the choice flags).
Without ``--headless`` the app opens with the student's run replayed beside the search."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.cli.flags import EXIT_BAD_INPUT, UsageError, semantics_from
from tui_search.engine.maps.grid import Grid
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.cli.options import Options
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.traces.check import Verdict
    from tui_search.engine.traces.read import Trace
    from tui_search.engine.traces.replay import Replay
    from tui_search.engine.traces.sandbox import StudentRun

__all__ = ["StudentFailed", "check_options", "run_check_search_py", "student_replay"]


class StudentFailed(Exception):
    """The student's code gave no answer: its one-line reason (exit 2, as a bad trace)."""


def check_options(options: Options) -> Options:
    """The options of ``--check-search-py``: ``-a`` one of the course's four searches (the
    test's own for a ``.test``; BFS when not given), ``--preset cs188`` unless another preset
    or a choice flag is given."""
    from tui_search.cli.flags import changed_choice_flags
    from tui_search.engine.traces.student_search import FUNCTIONS

    if options.algorithm not in FUNCTIONS:
        raise UsageError(f"-a {options.algorithm}: a student's search.py has "
                         f"{', '.join(FUNCTIONS.values())} (-a {', '.join(FUNCTIONS)})")
    for flag in ("compare", "exercise", "check_trace", "trace", "replay", "export", "plain",
                 "serve"):
        if getattr(options, flag):
            raise UsageError(f"--check-search-py checks one search: leave out "
                             f"--{flag.replace('_', '-')}")
    if options.preset is None and not changed_choice_flags(options):
        options = options.replace(preset="cs188")
    return options


def _board(options: Options) -> tuple[Grid | Graph, str]:
    from tui_search.cli.headless import board_of

    board, where = board_of(options)
    if isinstance(board, Grid) and board.costs is not None and options.course_test is None:
        raise UsageError(f"{where}: the course's problem has every move costing 1; this map "
                         "has terrain")
    return board, where


def _run(options: Options, board: Grid | Graph) -> tuple[StudentRun, Trace | None, str]:
    """The student's run, its trace (None: it never called getSuccessors), and the student's
    file as the messages name it."""
    from tui_search.engine.maps.read import MapError, read_text
    from tui_search.engine.traces import sandbox
    from tui_search.engine.traces.student_search import as_trace, student_problem

    assert options.check_search_py is not None
    shown = describe_name(options.check_search_py)
    text = read_text(options.check_search_py, "a search.py", sandbox.MAX_STUDENT_BYTES)
    sem = semantics_from(options)
    test = options.course_test
    heuristic = sem.heuristic if options.algorithm == "astar" else "zero"
    problem = student_problem(board, options.algorithm, heuristic,
                              test.actions if test is not None else None,
                              test.cost_fn if test is not None else "1")
    run = sandbox.run_student(text, problem, options.time_limit, options.memory_limit)
    note = sandbox.unfenced(run.landlock)
    if note is not None:
        import sys

        print(f"tui-search: note: {note}", file=sys.stderr)
    if run.status != "ok":
        function = problem["function"]
        if run.about == "missing":
            raise StudentFailed(f"{shown} has no function {function}")
        where = f"{shown}:{run.line}" if run.line else shown
        where += f":{run.col}" if run.line and run.col else ""
        if run.about == "file":
            raise StudentFailed(f"{where}: {run.message}")
        raise StudentFailed(f"{where}: {function} {run.message}")
    if not run.expanded:
        return run, None, shown
    try:
        trace = as_trace(board, run.expanded, shown)
    except MapError as exc:
        raise StudentFailed(f"{shown}: its calls of getSuccessors are no search of this "
                            f"problem: {exc.message}") from None
    return run, trace, shown


def student_replay(options: Options) -> Replay:
    """The app's ``--replay`` of the student's run (its reason, one line, when it gave
    none: a UsageError, exit 2)."""
    from tui_search.engine.traces.replay import replay_of

    board, _ = _board(options)
    try:
        _, trace, _ = _run(options, board)
    except StudentFailed as exc:
        raise UsageError(str(exc)) from None
    if trace is None:
        from tui_search.engine.traces.student_search import FUNCTIONS

        raise UsageError(f"{expanded_nothing(FUNCTIONS[options.algorithm], board)}: nothing "
                         "to replay")
    return replay_of(trace, board, options.algorithm, semantics_from(options),
                     options.max_steps)


def expanded_nothing(function: str, board: Grid | Graph) -> str:
    """What a search that never asked for a state's successors is: right where the start is
    a goal (the course's searches take it off and return), else a difference."""
    start_is_goal = (board.start == board.goal if isinstance(board, Grid)
                     else board.start in board.goals)
    if start_is_goal:
        return f"your {function} is right to expand nothing: the start is a goal"
    return f"your {function} never called getSuccessors: it expanded nothing"


def verdict_words(verdict: Verdict, function: str) -> str:
    """The check's text in the student's words: "your breadthFirstSearch is BFS (...), for
    all 200 expansions", or where it parts from the search."""
    text = verdict.text()
    first, _, rest = text.partition("\n")
    if verdict.matches and first.startswith("matches "):
        body = first.removeprefix("matches ")
        head, _, steps = body.rpartition(" for all ")
        first = f"your {function} is {head}, for all {steps.replace('steps', 'expansions')}"
    else:
        first = f"your {function}: {first}"
    rest = rest.replace(
        "your trace lists no successors: only the order of its expansions is checked, not "
        "what each step added",
        "each getSuccessors call is an expansion: their order is checked, not what was "
        "pushed").replace(
        "your trace leaves out the goal's pop, this search's last step (a trace may)",
        "the goal's successors are never asked for: the search's last step, its goal taken "
        "off, is not one").replace("your trace", f"your {function}")
    first = first.replace("your trace", f"your {function}")
    return first + ("\n" + rest if rest else "")


def _gradescope(options: Options, function: str, where: str, words: str,
                passed: bool | None, path: str) -> None:
    """``--gradescope OUT.json``: a test for which search it is, one for its path (both
    failed, with the reason, when it gave no answer)."""
    if options.gradescope is None:
        return
    from tui_search.cli.report import write_gradescope
    from tui_search.engine.course.gradescope import graded_test, results
    from tui_search.engine.traces.student_search import path_found

    answered = passed is not None
    first = words.splitlines()[0]
    tests = [graded_test(f"{function} on {where}: the search", answered and first.startswith(
                 f"your {function} is "), words),
             graded_test(f"{function} on {where}: its path", answered and path_found(path),
                         path)]
    write_gradescope(options, results(first, tests))


def run_check_search_py(options: Options) -> int:
    """Run the student's function, check it, print the verdict (exit 0 a match, 1 a
    difference, 2 no answer: the reason in one line)."""
    import sys

    from tui_search.cli.headless import to_json
    from tui_search.engine.traces.causes import Voice
    from tui_search.engine.traces.check import check_trace
    from tui_search.engine.traces.sandbox import isolation
    from tui_search.engine.traces.student_search import FUNCTIONS, path_found, path_words

    board, where = _board(options)
    function = FUNCTIONS[options.algorithm]
    try:
        run, trace, shown = _run(options, board)
    except StudentFailed as exc:
        _gradescope(options, function, where, str(exc), None, str(exc))
        print(f"tui-search: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    test = options.course_test
    returned = path_words(board, run.actions or [], test.actions if test is not None else None)
    if trace is None:
        return _expanded_nothing(options, run, (function, where, shown), board, returned)
    semantics = semantics_from(options)
    voice = Voice(f"your {function}", f"your {function}", (), True)
    verdict = check_trace(trace, board, options.algorithm, semantics,
                          max_steps=options.max_steps, voice=voice)
    reached = path_found(returned)
    _gradescope(options, function, where, verdict_words(verdict, function),
                verdict.matches and reached, returned)
    if options.json:
        print(to_json({"search_py": shown, "map": where, "function": function,
                       "expansions": len(run.expanded), "returned": run.actions,
                       "path": returned, "isolation": isolation(run.landlock),
                       **verdict.as_json()}))
    else:
        print(verdict_words(verdict, function))
        difference = verdict.difference
        if difference is not None and difference.cause == "tie":
            print("  note: a tie of the priority taken another way; PriorityQueue.update keeps "
                  "a lowered entry's place among equal priorities, where a re-push (the "
                  "course's search) puts it last")
        if isinstance(board, Grid) and not verdict.matches:
            print(f"  note: cells are the app's (x,y), y from the top row; in your code's "
                  f"states (x, y) y counts from the bottom: y there is {board.height - 1} - y")
        print(f"  returned: {returned}")
    return 0 if verdict.matches else 1


def _expanded_nothing(options: Options, run: StudentRun, names: tuple[str, str, str],
                      board: Grid | Graph, returned: str) -> int:
    """A search that never called getSuccessors (``names``: its function, the map, the
    student's file): a difference (exit 1) unless the start is a goal (exit 0)."""
    from tui_search.cli.headless import to_json
    from tui_search.engine.traces.sandbox import isolation
    from tui_search.engine.traces.student_search import path_found

    function, where, shown = names
    words = expanded_nothing(function, board)
    right = words.startswith(f"your {function} is ")
    _gradescope(options, function, where, words, right and path_found(returned), returned)
    if options.json:
        print(to_json({"search_py": shown, "map": where, "function": function,
                       "expansions": 0, "returned": run.actions, "path": returned,
                       "isolation": isolation(run.landlock),
                       "verdict": "match" if right else "difference",
                       "algorithm": options.algorithm, "steps": 0, "matched_steps": 0,
                       "first_difference": None if right else {
                           "step": 1, "kind": "no-expansion", "message": words}}))
    else:
        print(words)
        print(f"  returned: {returned}")
    return 0 if right else 1
