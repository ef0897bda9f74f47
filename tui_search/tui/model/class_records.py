"""What the app records of a student (``--records DIR``; no Textual): who they are, and the
events of :mod:`~tui_search.engine.course.records` as they happen -- an exercise's verdict
when it changes (with the map), each quiz answer, a run by hand when it ends or is left.

The terminal app knows the student from ``--student NAME``; the served app asks the visitor
(a name, or one of ``--class FILE``'s) before anything else, and writes their own file.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, NamedTuple

from tui_search.engine.course.records import Writer, clean_name, map_field
from tui_search.engine.search.state import State, state_json

if TYPE_CHECKING:
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.course.grading import Verdict
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.maps.grid import Grid
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.run.recorded import Run
    from tui_search.tui.model.quiz import Quiz

#: At most this many names are read from a class list (one a line).
MAX_CLASS = 2000


class RecordsPlan(NamedTuple):
    """Where the records go and whose they are: the folder, the student (""): asked at
    start), the served visitor's id, and the class list the visitor picks from (empty: they
    type a name)."""

    folder: Path
    student: str = ""
    visitor: str | None = None
    class_list: tuple[str, ...] = ()


def read_class_list(text: str) -> tuple[str, ...]:
    """A class list's names: one a line, cleaned, blank lines and ``#`` comments left out,
    each once, at most :data:`MAX_CLASS`."""
    names: dict[str, None] = {}
    for line in text.splitlines():
        name = clean_name(line)
        if name and not name.startswith("#"):
            names[name] = None
    return tuple(names)[:MAX_CLASS]


class Recorder:
    """A student's records: the file's writer and what was last written of each exercise."""

    def __init__(self, writer: Writer) -> None:
        self.writer = writer
        self._verdicts: dict[str, bool] = {}

    @property
    def student(self) -> str:
        return self.writer.student

    def write(self, event: str, **fields: Any) -> str | None:
        return self.writer.write(event, **fields)

    def start(self, map_name: str, exercise: Exercise | None) -> str | None:
        return self.write("start", map_name=map_name,
                          exercise=None if exercise is None else exercise.title)

    def quiz(self, run: Run | BiRun, node: State, guess: State, quiz: Quiz) -> str | None:
        return self.write("quiz", algorithm=run.algorithm, step=run.k, node=state_json(node),
                          guess=state_json(guess), right=node == guess,
                          score=[quiz.right, quiz.asked])

    def verdict(self, verdict: Verdict, grid: Grid | Graph) -> str | None:
        """An exercise's verdict, when it is the first of that exercise or differs from the
        last written (an edit solved it, or unsolved it), with the map (a graph's: its start,
        goals and closed nodes, its roads being the exercise's)."""
        from tui_search.engine.maps.graph import Graph
        from tui_search.engine.maps.text import text_rows

        exercise = verdict.exercise
        if self._verdicts.get(exercise.title) == verdict.solved:
            return None
        self._verdicts[exercise.title] = verdict.solved
        said = {"exercise": exercise.title, "solved": verdict.solved,
                "verdict": verdict.status, "reason": verdict.said}
        if isinstance(grid, Graph):
            ends = [f"start {grid.start}", *(f"goal {g}" for g in grid.goals),
                    *(f"closed {c}" for c in sorted(grid.closed))]
            return self.write("exercise", **said, graph="".join(f"{e}\n" for e in ends))
        text = "".join(f"{row}\n" for row in text_rows(grid))
        return self.write("exercise", **said, **map_field(text, grid.width, grid.height))


def recorder(plan: RecordsPlan, name: str) -> Recorder:
    """``name``'s records, in the plan's folder (a served visitor's: their own file)."""
    return Recorder(Writer(plan.folder, name, plan.visitor))


__all__ = ["MAX_CLASS", "Recorder", "RecordsPlan", "read_class_list", "recorder"]
