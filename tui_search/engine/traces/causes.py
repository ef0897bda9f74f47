"""The causes a difference names, as data: who the sentences speak of (a trace's author, or a
student stepping a search by hand), each cause's code with the words a summary counts it by
("took the newest entry"), and the :class:`Difference` that carries one.

One vocabulary for both: a student whose BFS code takes the newest entry and one who takes it
by hand hold the same misconception, and are told it in the same words
(:mod:`~tui_search.engine.traces.differences` writes the sentences); the class report counts
both under one code (:mod:`~tui_search.engine.course.records`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

from tui_search.engine.search.state import State, state_json


class Voice(NamedTuple):
    """Whom a difference's sentence speaks of: ``who`` and the form of each verb
    (:meth:`says`), and whether the sentence ends with the flags that would explain it
    (``--visit expand``: a program's author can change those; a student stepping by hand
    cannot)."""

    who: str
    searcher: str  # the subject where the sentence speaks of the whole search
    verbs: tuple[tuple[str, str], ...]  # a verb as a trace's sentence says it -> as said here
    flags: bool

    def says(self, verb: str, search: bool = False) -> str:
        """The subject and the verb: "your trace takes", "you took"."""
        said = dict(self.verbs).get(verb, verb)
        return f"{self.searcher if search else self.who} {said}"

    def flag(self, words: str) -> str:
        """`` (words)``, the flags that would explain a difference, or nothing."""
        return f" ({words})" if self.flags else ""


#: A trace another program wrote: "your trace takes (1,3) ... (a DFS: -a dfs)".
TRACE_VOICE = Voice("your trace", "your search", (), True)
#: A student stepping the search by hand: "you took (1,3) ... (a DFS)".
HAND_VOICE = Voice("you", "you", (
    ("takes", "took"), ("expands", "took"), ("added", "added"), ("adds", "added"),
    ("pushes", "added"), ("does not", "did not"), ("stops", "stopped"),
    ("expanded", "took"), ("discards", "dropped")), False)

#: Each cause a difference may name: its code (in the JSON, the records and the class
#: report) and what a student who made it did, as the class report's summary says it
#: ("12 of 30 students took the newest entry in BFS at least once").
CAUSES = {
    # an entry taken out of turn
    "newest": "took the newest entry",
    "oldest": "took the oldest entry",
    "first-listed": "took the first cell a step listed",
    "recursion": "took a cell the last step added",
    "tie": "broke a tie of the priority another way",
    "out-of-turn": "took an entry out of turn",
    "visit-on-expand": "marked cells visited when it took them off",
    "twice": "expanded a cell twice",
    "not-dropped": "left on the frontier an entry expanded already",
    "discarded": "discarded a cell the search expands",
    # a step's successors
    "added-twice": "added a cell twice",
    "after-goal": "went on adding after the goal",
    "obstacle": "added an obstacle",
    "off-map": "added a cell off the map",
    "not-a-move": "added a cell more than one move away",
    "move-not-allowed": "added a move the search does not make",
    "corner": "cut a blocked corner",
    "on-path": "added a cell on the node's own path",
    "start-again": "pushed the start again",
    "reached": "added a cell reached already",
    "reached-shallower": "added a cell reached already no deeper",
    "visited": "added a cell visited deeper down",
    "expanded": "added a cell expanded already",
    "reopened": "re-opened a closed cell",
    "rounding": "called a path cheaper by rounding only",
    "not-cheaper": "added a cell reached no cheaper",
    "cut-off": "expanded a node over IDA*'s limit on f",
    "not-reopened": "did not re-open a cell reached cheaper",
    "rounding-missed": "called a path cheaper by rounding no cheaper",
    "stopped-at-goal": "stopped on adding the goal",
    "calls": "listed the calls, not the neighbours",
    "left-out": "left out a successor",
    "order": "added the successors in another order",
    "flip-even": "added the successors in the reverse order on every other cell",
    # the ends of a trace
    "goes-on": "went on after the search stopped",
    "ends": "stopped before the search did",
}


def cause_words(code: str) -> str:
    """What a student who made cause ``code`` did (an unknown code: the code itself, from
    a records file of a later version)."""
    return CAUSES.get(code, code)


#: The choices a difference suggests, as ``(field, value)`` pairs of
#: :class:`~tui_search.engine.search.choices.Semantics`.
Suggestion = tuple[tuple[str, object], ...]
#: A cause in words: the sentence, the choices that would explain it, its code.
Said = tuple[str, tuple[Suggestion, ...], str]


@dataclass(frozen=True)
class Difference:
    """The first place the trace parts from the search: its step (the trace's numbering), the
    trace line, what kind (``expand``, ``successors``, ``ends``, ``goes_on``), the sentence, and
    the cells the search expected and the trace had (None where it has none)."""

    step: int
    line: int | None
    kind: str
    message: str
    expected: State | None = None
    got: State | None = None
    #: The search parts from the trace at a tie of its priority: "h" where the trace took
    #: the lower or higher h of an f tie, "entry" where it took another entry; "" no tie.
    tie: str = ""
    #: The choices that would explain it, each a change the diagnosis tries.
    suggest: tuple[Suggestion, ...] = ()
    #: What it is, as a code of :data:`~tui_search.engine.traces.causes.CAUSES` ("newest").
    cause: str = ""

    def as_json(self) -> dict[str, object]:
        return {"step": self.step, "line": self.line, "kind": self.kind,
                "cause": self.cause or None, "message": self.message,
                "expected": None if self.expected is None else state_json(self.expected),
                "got": None if self.got is None else state_json(self.got),
                "tie": self.tie or None}


__all__ = ["CAUSES", "HAND_VOICE", "TRACE_VOICE", "Difference", "Said", "Suggestion", "Voice",
           "cause_words"]
