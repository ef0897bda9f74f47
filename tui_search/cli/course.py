"""The CS188 autograder's ``.test`` files on the command line: opened as the map with their
search and choices, and ``FILE.test --headless``: the path and the expanded states in the
course's words, checked against the ``.solution`` beside it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.cli.flags import EXIT_GAVE_UP, UsageError
from tui_search.engine.util.filenames import describe_name

if TYPE_CHECKING:
    from tui_search.cli.options import Options
    from tui_search.engine.course.autograder_check import CourseRun
    from tui_search.engine.course.autograder_files import CourseTest

__all__ = ["EXIT_AGREE", "EXIT_DISAGREE", "with_course_test", "run_course_test_headless"]

EXIT_AGREE, EXIT_DISAGREE = 0, 1


def with_course_test(options: Options) -> Options:
    """The options with the ``.test`` MAP read: its graph or layout as the map, its search as
    ``-a`` (unless given: then they must agree), ``--preset cs188`` unless another is given."""
    from pathlib import Path

    from tui_search.engine.course.autograder_files import read_course_test

    assert options.map is not None
    test = read_course_test(options.map)
    if options.algorithm_given and options.algorithm != test.algorithm:
        raise UsageError(f"-a {options.algorithm}: {describe_name(options.map)} tests "
                         f"{test.course_name} (leave -a out)")
    for flag in ("compare", "exercise", "export", "plain", "scen", "terrain"):
        if getattr(options, flag):
            raise UsageError(f"--{flag} does not go with a course test file")
    heuristic = options.heuristic
    if heuristic is None and test.heuristic is not None and test.algorithm == "astar":
        heuristic = test.heuristic
    grid = test.grid.copy() if test.grid is not None else None
    if test.cost_fn != "1" and options.cost_tolerance is None and test.algorithm in (
            "ucs", "astar"):
        options = options.replace(cost_tolerance=0.0)  # .5 ** x: costs compared exactly
    # a layout's file is the test: never saved over (ctrl+s asks for a name)
    path = Path(test.path) if test.graph is not None else None
    return options.replace(course_test=test, graph=test.graph, grid=grid,
                           path=path, algorithm=test.algorithm,
                           preset=options.preset or "cs188", heuristic=heuristic,
                           order=options.order if test.graph is None else "file")


def _verdict(test: CourseTest, run: CourseRun, rev: CourseRun) -> tuple[str, bool | None]:
    """What the ``.solution`` says of the runs: a sentence, and whether they agree (None: no
    ``.solution``)."""
    answer = test.solution
    if not answer:
        return "no .solution beside the test", None
    graph = test.kind == "GraphSearchTest"
    key = "expanded_states" if graph else "expanded_nodes"
    for names, got in ((("solution", key), run), (("rev_solution", "rev_" + key), rev)):
        if names[0] not in answer or names[1] not in answer:
            continue
        states = got.expanded if graph else [str(len(got.expanded))]
        if (got.solution is not None and answer[names[0]].split() == got.solution
                and answer[names[1]].split() == states):
            return f"agrees with the .solution's {names[0]} and {names[1]}", True
    if "solution" not in answer or key not in answer:
        return f"the .solution has no solution or {key} to compare", None
    return (f"disagrees with the .solution: it expects {key} {answer[key]!r}"
            + (f" (or reversed {answer['rev_' + key]!r})" if "rev_" + key in answer else "")
            + f" and solution {answer['solution']!r}"), False


def run_course_test_headless(options: Options) -> int:
    from tui_search.cli.flags import semantics_from
    from tui_search.cli.headless import to_json
    from tui_search.engine.course.autograder_check import run_course_test
    from tui_search.engine.search.registry import get_algorithm

    test = options.course_test
    assert test is not None
    if options.trace or options.check_trace:
        raise UsageError("--trace and --check-trace do not go with a course test file")
    sem = semantics_from(options)
    run = run_course_test(test, sem, options.max_steps)
    rev = run_course_test(test, sem, options.max_steps, reverse=True)
    verdict, agrees = _verdict(test, run, rev)
    graph = test.kind == "GraphSearchTest"
    if options.json:
        out: dict[str, object] = {
            "test": test.path, "class": test.kind, "algorithm": test.course_name,
            "solution": run.solution, "expanded_states": run.expanded,
            "expanded_nodes": len(run.expanded), "rev_solution": rev.solution,
            "rev_expanded_states": rev.expanded, "agrees": agrees, "verdict": verdict,
            "semantics": sem.as_json()}
        print(to_json(out))
    else:
        where = describe_name(test.path)
        what = f"layout {test.layout_name}" if test.layout_name else (
            "a layout" if not graph else "a graph")
        print(f"{test.kind} {where}: {test.course_name} on {what}")
        words = sem.differences(get_algorithm(test.algorithm))
        print(f"  semantics:       {' · '.join(words) or 'the defaults'}")
        solution = "no path" if run.solution is None else " ".join(run.solution) or "(none)"
        print(f"  solution:        {solution}")
        if graph:
            print(f"  expanded_states: {' '.join(run.expanded)}")
            print(f"  rev_expanded:    {' '.join(rev.expanded)}")
        else:
            print(f"  expanded_nodes:  {len(run.expanded)} (rev {len(rev.expanded)})")
        print(f"  the .solution:   {verdict}")
    if run.gave_up:
        return EXIT_GAVE_UP
    return EXIT_DISAGREE if agrees is False else EXIT_AGREE

