"""A search stepped by hand: the student takes each entry off the frontier and lists, in order,
the successors the search adds; each step is checked against the search at once, and a wrong
one is named in the words a trace's check uses (:class:`~tui_search.engine.traces.differences.
Causes`, in the hand's voice): the same misconception, the same sentence.

No answer key: the reference is the search itself, recorded on the student's own map
(:class:`~tui_search.engine.run.recorded.Run`), its position the steps the student has made.
A wrong step is not taken: the student tries again, and the step counts one mistake however
many tries it took.  The steps made are a trace in the app's own format (:meth:`HandRun.
trace_text`), so the run can be replayed beside its search.
"""

from __future__ import annotations

from typing import NamedTuple

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, Step
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import Frontier
from tui_search.engine.search.state import State
from tui_search.engine.traces.causes import HAND_VOICE, Difference
from tui_search.engine.traces.differences import Causes
from tui_search.engine.traces.read import Trace, TraceStep, show, trace_line

#: A run stepped by hand gives up after this many steps (a person makes a few hundred).
HAND_MAX_STEPS = 10_000
#: How far ahead a wrong pick's sentence looks for the step the search takes that cell at.
LOOK_AHEAD = 10_000


class Mistake(NamedTuple):
    """A wrong try: the step it was made at (from 1), its cause's code
    (:data:`~tui_search.engine.traces.causes.CAUSES`), its sentence, and the cells the search
    expected and the student gave (None where there is none)."""

    step: int
    cause: str
    message: str
    expected: State | None = None
    got: State | None = None


class Told(NamedTuple):
    """What a move came to: taken or not, what to say, and the mistake it counted (None:
    right, a refusal that is no mistake, or a step that counted one already)."""

    ok: bool
    message: str
    mistake: Mistake | None = None


class HandRun:
    """A search of ``grid`` by ``algorithm`` under ``semantics``, stepped by hand: the moves
    (:meth:`pick`, :meth:`mark`, :meth:`end_step`, :meth:`take_back`, :meth:`undo`), what
    is being done (``phase``, ``picked``, ``marks``), the hints (:meth:`hint_cell`,
    :meth:`hint_why`) and the record of it (``mistakes``, ``tries``, ``steps``)."""

    def __init__(self, grid: Grid, algorithm: str, semantics: Semantics,
                 max_steps: int = HAND_MAX_STEPS) -> None:
        self.run = Run(grid, algorithm, semantics, max_steps)
        self.name = self.run.algo.short
        self.steps: list[TraceStep] = []  # the steps made, as a trace's
        self.picked: State | None = None  # the entry taken off, its successors being listed
        self.marks: list[State] = []  # the successors listed so far, in order
        self.mistakes: list[Mistake] = []  # a step's first wrong try
        self.tries: list[Mistake] = []  # every wrong try
        self.undone = 0  # steps taken back
        self._counted: int | None = None  # the step that has counted its mistake

    # -- where the run is ---------------------------------------------------------------------
    @property
    def k(self) -> int:
        """The steps made."""
        return self.run.k

    def expected(self) -> Step | None:
        """The search's next step (None: the search is over)."""
        run, n = self.run, self.run.k + 1
        if n > run.recorded and not run.done:
            run.advance(n)
        return run.steps.at(n) if n <= run.recorded else None

    @property
    def finished(self) -> bool:
        """Has the student made every step of the search?"""
        return self.expected() is None

    @property
    def phase(self) -> str:
        """``pick`` (take an entry off), ``mark`` (list its successors) or ``done``."""
        if self.picked is not None:
            return "mark"
        return "done" if self.finished else "pick"

    def frontier_cells(self) -> list[State]:
        """The cells on the frontier now, next out first."""
        cell = self.run.nodes.cell
        return [cell(g) for g in self.run.now.frontier()]

    # -- the moves --------------------------------------------------------------------------
    def pick(self, cell: State) -> Told:
        """Take the entry of ``cell`` off the frontier."""
        e = self.expected()
        if e is None or self.picked is not None:
            return Told(False, "The search is over" if e is None else
                        f"{show(self.picked or cell)} is taken off already: list its successors")
        noun = self.run.algo.frontier.noun
        again = self.run.algo.iterative and cell == self.run.grid.start  # a new iteration
        if cell not in self.frontier_cells() and not again:
            return Told(False, f"{show(cell)} is not on the {noun}: take one of its entries")
        if cell != e.node:
            causes = self._causes(cell, ())
            if e.discarded:
                return self._wrong(causes.not_dropped(e.index, e, cell))
            step = TraceStep(e.index, cell, (), listed=False)
            return self._wrong(causes.expansion(e.index, step, e, e.index, self._where(cell)))
        if e.discarded:
            self._made(e)
            return Told(True, f"{show(cell)} was expanded already: {self.name} takes it off "
                        "and drops it")
        if e.found_goal and not e.successors:
            self._made(e)
            return Told(True, f"{show(cell)} is the goal: {self.name} stops as it takes it off")
        self.picked = cell
        return Told(True, f"You took {show(cell)} off the {noun}")

    def mark(self, cell: State) -> Told:
        """Add ``cell`` to the successors of the entry taken off."""
        e = self.expected()
        if e is None or self.picked is None:
            return Told(False, "Take an entry off the frontier first")
        if cell in self.marks:
            return Told(False, f"{show(cell)} is added already (backspace takes the last back)")
        marks = (*self.marks, cell)
        wrong = self._causes(self.picked, marks).successors(
            e.index, TraceStep(e.index, self.picked, marks), e, whole=False)
        if wrong is not None:
            return self._wrong(wrong)
        self.marks.append(cell)
        return Told(True, f"You added {show(cell)}")

    def end_step(self) -> Told:
        """The successors listed are all of them: the step is made if they are."""
        e = self.expected()
        if e is None or self.picked is None:
            return Told(False, "Take an entry off the frontier first")
        marks = tuple(self.marks)
        wrong = self._causes(self.picked, marks).successors(
            e.index, TraceStep(e.index, self.picked, marks), e)
        if wrong is not None:
            return self._wrong(wrong)
        self._made(e)
        added = f"added {', '.join(map(show, marks))}" if marks else "added nothing"
        return Told(True, f"Step {e.index}: {show(e.node)} {added}")

    def take_back(self) -> Told:
        """The last successor listed, taken back."""
        if not self.marks:
            return Told(False, "No successor to take back")
        return Told(True, f"Took back {show(self.marks.pop())}")

    def undo(self) -> Told:
        """The entry taken off put back (and its successors), else the last step undone.
        The mistakes made stay counted."""
        if self.picked is not None:
            cell, self.picked, self.marks = self.picked, None, []
            return Told(True, f"Put {show(cell)} back")
        if not self.steps:
            return Told(False, "No step to undo")
        self.steps.pop()
        self.run.goto(self.run.k - 1)
        self.undone += 1
        self._counted = None
        return Told(True, f"Step {self.run.k + 1} undone")

    # -- hints --------------------------------------------------------------------------------
    def hint_cell(self) -> State | None:
        """The entry to take off, or the next successor to add (None: the step's successors
        are all listed, or the search is over)."""
        e = self.expected()
        if e is None:
            return None
        if self.picked is None:
            return e.node
        want = [c for _, c in e.successors]
        return want[len(self.marks)] if len(self.marks) < len(want) else None

    def hint_why(self) -> str:
        """Why that entry, or that successor, in a sentence."""
        e = self.expected()
        if e is None:
            return "The search is over"
        name, algo = self.name, self.run.algo
        if self.picked is None:
            where = self._causes(e.node, ())._next_words()
            if e.discarded:
                return (f"{name} takes {show(e.node)} off, {where}: it was expanded already, "
                        "so it is dropped")
            age = {Frontier.FIFO: ", the oldest entry", Frontier.LIFO: ", the newest entry"}
            return f"{name} takes {where}{age.get(algo.frontier, '')}: {show(e.node)}"
        cut = self._causes(e.node, ())._cut_off(e)
        if cut:  # IDA*: over the limit, nothing added
            return f"{name} adds nothing from {show(self.picked)}: {cut}; enter ends the step"
        cell = self.hint_cell()
        adds = (f"{name} adds the cells one move from {show(self.picked)}, in the order "
                f"{','.join(self.run.semantics.order)}, {self._skips()}")
        if cell is None:
            return f"{adds}: they are all added, enter ends the step"
        return f"{adds}: next {show(cell)}"

    def _skips(self) -> str:
        """What the search leaves out of a node's successors, in a few words."""
        sem, algo = self.run.semantics, self.run.algo
        skips = ["obstacles"]
        if sem.corners != "always":
            skips.append("corners its rule refuses")
        if sem.tree_search:
            skips.append("cells on the node's own path" if sem.path_check else "")
        elif algo.weighted:
            skips.append("cells reached as cheaply already")
        elif algo.iterative:
            skips.append("cells reached no deeper already")
        elif sem.visit == "generate":
            skips.append("cells added already")
        else:
            skips.append("cells expanded already")
        words = [s for s in skips if s]
        return "leaving out " + (" and ".join(words) if len(words) < 3
                                 else ", ".join(words[:-1]) + " and " + words[-1])

    # -- the record ------------------------------------------------------------------------
    def trace(self, name: str = "your run") -> Trace:
        """The steps made, as a trace."""
        grid = self.run.grid
        return Trace(name, tuple(self.steps), grid.start, grid.goal)

    def trace_text(self) -> str:
        """The steps made in the app's own trace format (``--trace``'s lines), its first line
        the start and the goal, its last the path once the search is done."""
        import json

        grid = self.run.grid
        lines = [json.dumps({"start": list(grid.start or (0, 0)),
                             "goal": list(grid.goal or (0, 0))}) + "\n"]
        lines += [trace_line(self.run.steps.at(k)) for k in range(1, self.run.k + 1)]
        if self.finished:
            path = self.run.path()
            lines.append(json.dumps({"path": None if path is None else
                                     [list(c) for c in path]}) + "\n")
        return "".join(lines)

    def by_cause(self) -> dict[str, int]:
        """The mistakes counted, by cause."""
        out: dict[str, int] = {}
        for m in self.mistakes:
            out[m.cause] = out.get(m.cause, 0) + 1
        return out

    # -- inside -------------------------------------------------------------------------------
    def _causes(self, node: State, marks: tuple[State, ...]) -> Causes:
        """The causes of a difference at the next step (``node`` taken off, ``marks``
        added), from the steps made."""
        trace = Trace("by hand", (*self.steps, TraceStep(self.k + 1, node, marks)))
        return Causes(trace, self.run, self.name, HAND_VOICE)

    def _where(self, cell: State) -> str:
        """When the search takes ``cell`` off (for a wrong pick's sentence)."""
        run = self.run
        for n in range(run.k + 2, run.k + 2 + LOOK_AHEAD):
            if n > run.recorded and not run.done:
                run.advance(n)
            if n > run.recorded:
                return f"which {self.name} never expands"
            step = run.steps.at(n)
            if step.node == cell and not step.discarded:
                return f"which {self.name} would expand at step {n}"
        return f"which {self.name} does not expand in its next {LOOK_AHEAD:,} steps"

    def _wrong(self, difference: Difference) -> Told:
        """A wrong try: said, and counted once a step."""
        self.run.goto(len(self.steps))  # the causes may have moved it to look
        mistake = Mistake(difference.step, difference.cause or "out-of-turn",
                          difference.message, difference.expected, difference.got)
        self.tries.append(mistake)
        if self._counted == mistake.step:
            return Told(False, difference.message)
        self._counted = mistake.step
        self.mistakes.append(mistake)
        return Told(False, difference.message, mistake)

    def _made(self, e: Step) -> None:
        """The search's step ``e`` made: one step on."""
        self.steps.append(TraceStep(e.index, e.node, tuple(c for _, c in e.successors),
                                    e.discarded))
        self.picked, self.marks = None, []
        self.run.goto(e.index)


__all__ = ["HAND_MAX_STEPS", "HandRun", "Mistake", "Told"]
