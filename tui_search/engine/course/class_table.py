"""A class's records (:mod:`~tui_search.engine.course.records`) as a table: a student a row --
the exercises solved, the quiz's score, the runs stepped by hand and their mistakes by cause,
the traces checked -- and the misconceptions, each with how many students showed it ("12 of
30 students took the newest entry in BFS at least once").

The class report (``--class-report DIR``) prints it; the served app's teacher page shows it.
A line that says something unexpected (a later version's, an edited one) counts for what it
does say.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, NamedTuple

from tui_search.engine.course.records import Event
from tui_search.engine.search.registry import ALGORITHMS
from tui_search.engine.traces.causes import cause_words


class Row(NamedTuple):
    """One student: their name, the exercises solved and tried (by name), the quiz's score,
    the runs stepped by hand (finished, all) with their mistakes by cause, the traces checked
    (matching, all), and the time of their latest event."""

    student: str
    solved: tuple[str, ...]
    tried: tuple[str, ...]
    quiz_right: int
    quiz_asked: int
    runs_finished: int
    runs: int
    mistakes: dict[str, int]
    checks_matched: int
    checks: int
    last: str

    @property
    def mistake_count(self) -> int:
        return sum(self.mistakes.values())

    def as_json(self) -> dict[str, Any]:
        return {"student": self.student, "exercises_solved": list(self.solved),
                "exercises_tried": list(self.tried), "quiz_right": self.quiz_right,
                "quiz_asked": self.quiz_asked, "by_hand_finished": self.runs_finished,
                "by_hand_runs": self.runs, "by_hand_mistakes": dict(self.mistakes),
                "trace_checks_matched": self.checks_matched, "trace_checks": self.checks,
                "last": self.last}


class Misconception(NamedTuple):
    """A cause (its code), the search it was made in (a registry key; "" unknown) and the
    students who showed it at least once."""

    cause: str
    algorithm: str
    students: tuple[str, ...]

    def sentence(self, of: int) -> str:
        """"12 of 30 students took the newest entry in BFS at least
        once"."""
        n = len(self.students)
        who = f"{n} of {of} student{'s' if of != 1 else ''}"
        algo = ALGORITHMS.get(self.algorithm)
        where = f" in {algo.short}" if algo is not None else ""
        return f"{who} {cause_words(self.cause)}{where} at least once"

    def as_json(self, of: int) -> dict[str, Any]:
        return {"cause": self.cause, "algorithm": self.algorithm or None,
                "students": len(self.students), "of": of, "names": list(self.students),
                "text": self.sentence(of)}


class ClassTable(NamedTuple):
    rows: list[Row]
    misconceptions: list[Misconception]

    def as_json(self) -> dict[str, Any]:
        of = len(self.rows)
        return {"students": [r.as_json() for r in self.rows],
                "misconceptions": [m.as_json(of) for m in self.misconceptions]}


class _Student:
    """What one student's events add up to, as they are read."""

    def __init__(self) -> None:
        self.solved: dict[str, None] = {}
        self.tried: dict[str, None] = {}
        self.quiz = [0, 0]
        self.runs = [0, 0]
        self.mistakes: dict[str, int] = {}
        self.checks = [0, 0]
        self.last = ""

    def add(self, data: dict[str, Any], causes: list[tuple[str, str]]) -> None:
        kind = data.get("event")
        when = data.get("time")
        if isinstance(when, str) and when > self.last:
            self.last = when
        exercise = _text(data.get("exercise"))
        solved = data.get("solved") is True
        if exercise and kind in ("exercise", "by_hand"):
            self.tried[exercise] = None
            if solved:
                self.solved[exercise] = None
        if kind == "quiz":
            self.quiz[0] += data.get("right") is True
            self.quiz[1] += 1
        elif kind == "by_hand":
            self.runs[0] += data.get("finished") is True
            self.runs[1] += 1
            algorithm = _text(data.get("algorithm"))
            by_cause = data.get("by_cause")
            for cause, n in (by_cause.items() if isinstance(by_cause, dict) else ()):
                if isinstance(n, int) and n > 0:
                    self.mistakes[cause] = self.mistakes.get(cause, 0) + n
                    causes.append((cause, algorithm))
        elif kind == "trace_check":
            self.checks[0] += data.get("verdict") == "match"
            self.checks[1] += 1
            cause = _text(data.get("cause"))
            if cause:
                causes.append((cause, _text(data.get("algorithm"))))


def _text(value: object) -> str:
    return value if isinstance(value, str) else ""


def class_table(events: Iterable[Event]) -> ClassTable:
    """The table of ``events`` (any order): a row a student, by name; the misconceptions,
    the most students first."""
    students: dict[str, _Student] = {}
    shown: dict[tuple[str, str], dict[str, None]] = {}
    for event in events:
        name = event.student
        student = students.setdefault(name, _Student())
        causes: list[tuple[str, str]] = []
        student.add(event.data, causes)
        for key in causes:
            shown.setdefault(key, {})[name] = None
    rows = [Row(name, tuple(s.solved), tuple(s.tried), s.quiz[0], s.quiz[1], s.runs[0],
                s.runs[1], dict(s.mistakes), s.checks[0], s.checks[1], s.last)
            for name, s in sorted(students.items(), key=lambda item: item[0].casefold())]
    misconceptions = sorted(
        (Misconception(cause, algo, tuple(sorted(names, key=str.casefold)))
         for (cause, algo), names in shown.items()),
        key=lambda m: (-len(m.students), m.algorithm, m.cause))
    return ClassTable(rows, misconceptions)


__all__ = ["ClassTable", "Misconception", "Row", "class_table"]
