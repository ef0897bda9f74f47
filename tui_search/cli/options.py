"""The command line as one frozen, typed value: every flag as typed (``-a``'s default
resolved), and what the flags named, read: the exercise, the lesson, the generated map's
recipe, the map, its scenario and the replay.

:func:`tui_search.cli.parse.parse_options` makes it, once; nothing changes it after (a changed
copy is :meth:`~tui_search.engine.util.frozen.Frozen.replace`'s), and nothing below the
command line sees argparse.  A :class:`~tui_search.engine.util.frozen.Frozen` value, not a
frozen dataclass: it is made at every start (CONTRIBUTING.md, "Start-up").
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from tui_search.engine.util.frozen import Frozen

if TYPE_CHECKING:
    from tui_search.engine.course.autograder_files import CourseTest
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.course.lesson import Lesson
    from tui_search.engine.maps.generate import Recipe
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.maps.grid import Grid
    from tui_search.engine.maps.scenarios import Scenario
    from tui_search.engine.traces.replay import Replay

#: The flags, by argparse's names for them (the parser's ``dest``s; a test holds the two equal).
FLAGS = (
    "map", "algorithm", "start", "goal", "terrain", "scen", "scen_row", "order", "corners",
    "no_corner_cutting", "visit", "goal_test", "heuristic", "tree_search", "no_path_check",
    "recursive", "recursive_lines", "ties", "cost_tolerance", "weight", "reopen", "mark_start",
    "flip_even", "preset", "stop", "turn", "compare",
    "exercise", "generate", "size", "seed", "output", "max_steps", "theme", "pseudocode",
    "lesson", "headless", "json", "csv", "trace", "trace_format", "check_trace",
    "check_search_py", "time_limit", "memory_limit", "gradescope", "replay",
    "serve", "host", "port", "save_dir", "shared_save_dir", "app_memory", "token_file",
    "served", "visitor", "export", "fps", "export_view", "force", "handout_steps", "plain",
    "by_hand", "records", "student", "class_list", "class_report",
)
#: What the command line worked out or read from the flags.
READ = ("maps", "algorithm_given", "exercise_read", "lesson_read", "recipe", "grid", "graph",
        "path", "scenario", "replay_read", "course_test")


class Options(Frozen):
    """Every flag as typed (``map`` the one MAP, ``maps`` every MAP given, ``algorithm``
    ``-a``'s search or the default, ``algorithm_given`` whether ``-a`` was given), then what
    they named, read (None where a flag was not given or the run does not read it)."""

    __slots__ = _FIELDS = FLAGS + READ

    # -- the flags, as typed
    map: str | None
    algorithm: str
    start: str | None
    goal: str | None
    terrain: str | None
    scen: str | None
    scen_row: int | None
    order: str
    corners: str | None
    no_corner_cutting: bool
    visit: str | None
    goal_test: str | None
    heuristic: str | None
    tree_search: bool
    no_path_check: bool
    recursive: bool
    recursive_lines: str | None
    ties: str | None
    cost_tolerance: float | None
    weight: float | None
    stop: str | None
    turn: str | None
    reopen: str | None
    mark_start: str | None
    flip_even: bool
    preset: str | None  # --preset cs188: a course's choices, each flag changing one after
    compare: str | None
    exercise: str | None
    generate: str | None
    size: str | None
    seed: str | None
    output: str | None
    max_steps: int
    theme: str | None
    pseudocode: bool
    lesson: str | None  # "": list the built-in lessons
    headless: bool
    json: bool
    csv: bool
    trace: str | None
    trace_format: str
    check_trace: str | None
    check_search_py: str | None  # a student's search.py, run fenced and checked
    time_limit: float  # its run's time limit in seconds
    memory_limit: int  # its process's memory limit in MB
    gradescope: str | None  # Gradescope's results.json written there
    replay: str | None
    serve: bool
    host: str | None
    port: int | None
    save_dir: str | None
    shared_save_dir: bool | None
    app_memory: int | None
    token_file: str | None
    served: bool
    visitor: str | None
    export: str | None
    fps: float | None
    export_view: str | None
    force: bool
    handout_steps: int | None
    plain: bool
    by_hand: bool
    records: str | None  # made absolute, the folder made (cli/class_flags.py)
    student: str | None
    class_list: str | None  # --class FILE, made absolute
    class_report: str | None
    # -- what they named, read
    maps: tuple[str, ...]
    algorithm_given: bool
    exercise_read: Exercise | None
    lesson_read: Lesson | None
    recipe: Recipe | None
    grid: Grid | None  # the map to search (None: a graph, several maps, or none read)
    graph: Graph | None  # the graph to search (``romania``, ``FILE.graph``), else None
    path: Path | None  # its file (None: built in, generated, an exercise's own)
    scenario: Scenario | None  # --scen's row, while it holds for the map as read
    course_test: CourseTest | None  # a CS188 autograder's FILE.test given as the MAP
    replay_read: Replay | None

    def __init__(self, **values: Any) -> None:
        given = set(values)
        if given != set(self._FIELDS):
            missing = sorted(set(self._FIELDS) - given)
            unknown = sorted(given - set(self._FIELDS))
            raise TypeError(f"Options: missing {missing}, unknown {unknown}")
        self._assign(**values)

    @classmethod
    def made(cls, flags: dict[str, Any], **read: Any) -> Options:
        """Options from the flags as parsed (argparse's names) and what was read (the rest
        None, ``maps`` empty, ``algorithm_given`` False)."""
        values: dict[str, Any] = dict.fromkeys(READ)
        values.update(maps=(), algorithm_given=False)
        values.update({name: flags[name] for name in FLAGS})
        values.update(read)
        return cls(**values)
