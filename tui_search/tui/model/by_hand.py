"""By hand: the student is the search.  The app shows the map and the frontier (its entries as
they were added, no next-out mark); the student takes an entry off (the cursor and ``enter``,
or a click on the map or the frontier panel), then adds the successors the search adds, in
its order (a move's key each, or a click on the cell; ``enter`` ends the step).  Each step is
checked at once (:class:`~tui_search.engine.traces.hand.HandRun`); a wrong one is named and
not taken, and counts one mistake however many tries it takes.  Hints come in two levels (the
entry or the cell, highlighted; then why), and a step can be undone.

No Textual: the by-hand screen turns keys into calls here and shows what it says; the end's
summary, the record a class keeps of it (:mod:`~tui_search.engine.course.records`) and the
replay of the run beside its search are made here too.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, NamedTuple

from tui_search.engine.maps.grid import DELTAS, Cell, Grid
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.state import as_cell, state_text
from tui_search.engine.traces.causes import cause_words
from tui_search.engine.traces.hand import HandRun, Told

if TYPE_CHECKING:
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.traces.replay import Replay
    from tui_search.tui.model.class_records import Recorder

#: What the replay of a run by hand calls its pane.
RUN_LABEL = "Your run"


class Summary(NamedTuple):
    """The end of a run by hand: its steps, its mistakes by cause (most first, in words), the
    time it took, the hints and undos asked for, the path it found (None: none), and the
    exercise's verdict ("" no exercise)."""

    steps: int
    mistakes: int
    by_cause: list[tuple[str, int]]
    seconds: float
    hints: int
    undone: int
    path_moves: int | None
    verdict: str


class ByHand:
    """A run of ``algorithm`` under ``semantics`` on ``grid``, stepped by hand.  ``exercise``:
    the by-hand exercise it answers (its allowance of mistakes), if any; ``clock``: seconds,
    for the time taken."""

    def __init__(self, grid: Grid, algorithm: str, semantics: Semantics,
                 exercise: Exercise | None = None, map_name: str = "",
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.hand = HandRun(grid, algorithm, semantics)
        self.exercise = exercise
        self.map_name = map_name
        self._clock = clock
        self.started = clock()
        self.ended: float | None = None
        self.hint_level = 0  # the hints asked for this step (0, 1 the cell, 2 why)
        self.hints = 0  # hints asked for, in all
        self.said = self.prompt()  # what was said last
        self.wrong = False  # ... and whether it names a mistake
        self.recorded = False  # the end's record was written

    # -- what is shown --------------------------------------------------------------------
    @property
    def run(self) -> Any:  # (a Run: the pane shows it at the steps made)
        return self.hand.run

    @property
    def name(self) -> str:
        return self.hand.name

    @property
    def finished(self) -> bool:
        return self.hand.finished

    def prompt(self) -> str:
        """What to do now, in a line."""
        hand = self.hand
        noun = hand.run.algo.frontier.noun
        phase = hand.phase
        if phase == "done":
            return "Done: the search is over (enter: the summary)"
        if phase == "pick":
            return (f"Step {hand.k + 1}: take the entry {hand.name} takes off the {noun} "
                    "(cursor and enter, or a click)")
        assert hand.picked is not None
        added = ", ".join(state_text(c) for c in hand.marks) or "none yet"
        return (f"Step {hand.k + 1}: add the successors of {state_text(hand.picked)} "
                f"in {hand.name}'s order (a move's key, or a click), then "
                f"enter · added so far: {added}")

    def highlight(self) -> list[Cell]:
        """The cells the map marks: the entry taken off, the successors added, and the
        hint's cell once asked for."""
        hand = self.hand
        cells = [as_cell(c) for c in (hand.picked, *hand.marks) if c is not None]
        hinted = as_cell(c) if self.hint_level and (c := hand.hint_cell()) else None
        return cells + ([hinted] if hinted is not None and hinted not in cells else [])

    @property
    def seconds(self) -> float:
        return (self.ended if self.ended is not None else self._clock()) - self.started

    # -- the moves (each says what it came to) -------------------------------------------
    def take(self, cell: Cell) -> Told:
        return self._said(self.hand.pick(cell))

    def add(self, cell: Cell) -> Told:
        return self._said(self.hand.mark(cell))

    def add_move(self, move: str) -> Told | None:
        """Add the cell one ``move`` (N, NE, ...) from the entry taken off (None: none taken
        off; off the map: said, no mistake)."""
        node = self.hand.picked
        if node is None:
            return None
        dx, dy = DELTAS[move]
        x, y = as_cell(node)  # (by hand runs on a grid)
        cell = (x + dx, y + dy)
        if not self.hand.run.grid.in_bounds(cell):
            return self._said(Told(False, f"{move} of ({x},{y}) is off the map"))
        return self.add(cell)

    def click(self, cell: Cell) -> Told:
        """A click on the map: take that entry, or add that cell."""
        return self.add(cell) if self.hand.picked is not None else self.take(cell)

    def enter(self, cursor: Cell) -> Told | None:
        """``enter``: take the cursor's entry, or end the step (None: the run is over)."""
        hand = self.hand
        if hand.phase == "done":
            return None
        if hand.picked is None:
            return self.take(cursor)
        return self._said(hand.end_step())

    def take_back(self) -> Told:
        return self._said(self.hand.take_back())

    def undo(self) -> Told:
        told = self._said(self.hand.undo())
        if told.ok:
            self.ended = None
        return told

    def hint(self) -> str:
        """The next hint of this step: the cell highlighted, then why."""
        hand = self.hand
        if hand.phase == "done":
            return self.said
        self.hint_level = min(2, self.hint_level + 1)
        self.hints += 1
        cell = hand.hint_cell()
        if self.hint_level == 1:
            if cell is None:
                text = "Hint: every successor is added: enter ends the step"
            else:
                what = "entry to take" if hand.picked is None else "next successor"
                text = f"Hint: the {what} is highlighted; h again says why"
        else:
            text = f"Hint: {hand.hint_why()}"
        self.said, self.wrong = text, False
        return text

    def _said(self, told: Told) -> Told:
        """Keep what a move said; a step made or undone: the hints start again; the last
        step made: the clock stops."""
        self.said, self.wrong = told.message, not told.ok and told.mistake is not None
        if told.ok and self.hand.phase == "pick" or self.hand.phase == "done":
            self.hint_level = 0
        if told.ok and self.hand.phase == "done" and self.ended is None:
            self.ended = self._clock()
        if told.ok and not self.wrong:
            self.said = f"{told.message} · {self.prompt()}"
        return told

    # -- the end ----------------------------------------------------------------------------
    @property
    def allowed(self) -> int | None:
        """The exercise's allowance of mistakes (None: no by-hand exercise)."""
        ex = self.exercise
        return ex.mistakes if ex is not None and ex.by_hand else None

    def verdict(self) -> str:
        """The exercise's verdict ("" none): solved once finished within the allowance."""
        allowed = self.allowed
        if allowed is None:
            return ""
        made = len(self.hand.mistakes)
        if made > allowed:
            return f"not solved: {made} mistakes, {allowed} allowed"
        if not self.finished:
            return f"{made} of {allowed} mistakes allowed so far"
        return f"solved ✓ with {made} of {allowed} mistakes allowed"

    @property
    def solved(self) -> bool:
        allowed = self.allowed
        return (allowed is not None and self.finished
                and len(self.hand.mistakes) <= allowed)

    def summary(self) -> Summary:
        hand = self.hand
        by_cause = sorted(hand.by_cause().items(), key=lambda item: (-item[1], item[0]))
        path = hand.run.path() if self.finished else None
        return Summary(hand.k, len(hand.mistakes),
                       [(cause_words(cause), n) for cause, n in by_cause], self.seconds,
                       self.hints, hand.undone, None if path is None else len(path) - 1,
                       self.verdict())

    def event_fields(self) -> dict[str, Any]:
        """The ``by_hand`` event's fields (:mod:`~tui_search.engine.course.records`)."""
        from tui_search.engine.traces.check import choices_text

        hand = self.hand
        run = hand.run
        fields: dict[str, Any] = {
            "algorithm": run.algorithm, "search": choices_text(run.algo, run.semantics),
            "map_name": self.map_name, "finished": self.finished, "steps": hand.k,
            "mistakes": len(hand.mistakes), "by_cause": hand.by_cause(),
            "mistake_steps": [[m.step, m.cause] for m in hand.mistakes],
            "tries": len(hand.tries), "seconds": round(self.seconds, 1),
            "hints": self.hints, "undone": hand.undone}
        if self.exercise is not None:
            fields.update(exercise=self.exercise.title, solved=self.solved,
                          allowed=self.allowed)
        return fields

    def write(self, records: Recorder | None) -> str | None:
        """Write the run's record once (a run with no step made is none); None, or why it
        could not be written."""
        if records is None or self.recorded or not (self.hand.k or self.hand.mistakes):
            return None
        self.recorded = True
        return records.write("by_hand", **self.event_fields())

    def replay(self) -> Replay:
        """The run as made (its trace, in the app's format, read back) beside its search,
        its mistakes each at its step."""
        from tui_search.engine.traces.read import read_trace
        from tui_search.engine.traces.replay import replay_of

        run = self.hand.run
        trace = read_trace(self.hand.trace_text(), run.grid, RUN_LABEL.lower())
        return replay_of(trace, run.grid, run.algorithm, run.semantics, label=RUN_LABEL,
                         mistakes=tuple(self.hand.mistakes))


__all__ = ["RUN_LABEL", "ByHand", "Summary"]
