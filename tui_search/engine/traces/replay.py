"""``--replay FILE``: a trace another program wrote beside the search it is matched with, two
runs for the app's lockstep, and where they first part.

The search is ``-a``'s under the choice flags, else the diagnosis's best candidate
(:func:`~tui_search.engine.traces.diagnose.diagnose`); the first difference is the check's
(:func:`~tui_search.engine.traces.check.check_trace`), numbered as the trace numbers its steps.
No Textual here: the app's session holds a :class:`Replay` and asks it for its runs, their
names, the cells to mark and the sentence to show.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import PurePath

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.run.recorded import MAX_STEPS, Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.traces.as_run import TRACE_ALGORITHM, trace_run
from tui_search.engine.traces.check import Verdict, check_trace
from tui_search.engine.traces.read import Trace, show
from tui_search.engine.util.filenames import describe_name

#: What the app calls the trace's pane.
TRACE_LABEL = TRACE_ALGORITHM.short
#: What it calls the search's pane when the trace is matched against a recursive DFS's
#: pattern (a stack DFS that visits on expand and pushes the moves in reverse order).
RECURSIVE_LABEL = "DFS (recursive)"


@dataclass(frozen=True)
class Replay:
    """A trace, the search it is replayed beside (``algorithm`` under ``semantics``) and how
    the two compare (``verdict``), on the map as it was read (``where``: its obstacles, start
    and goal; an edit that changes them ends the replay)."""

    trace: Trace
    algorithm: str
    semantics: Semantics
    verdict: Verdict
    where: tuple[bytes, Cell | None, Cell | None]
    #: Was the search found by the diagnosis (its order inferred from the trace), not given?
    inferred: bool = False

    @property
    def recursive(self) -> bool:
        """Is the trace matched against a recursive DFS's pattern (the diagnosis's
        :func:`~tui_search.engine.traces.diagnose.mirrored` match), not a search of the app?"""
        return bool(self.verdict.label)

    @property
    def labels(self) -> list[str]:
        """The panes' names: the trace's, the search's."""
        return [TRACE_LABEL,
                RECURSIVE_LABEL if self.recursive else get_algorithm(self.algorithm).short]

    @property
    def order(self) -> tuple[str, ...]:
        """The moves in the order the trace adds them (a recursive DFS's: the stack DFS's,
        which pushes them in reverse, reversed)."""
        return self.semantics.order[::-1] if self.recursive else self.semantics.order

    def fits(self, grid: Grid) -> bool:
        """Does the trace still apply to ``grid`` (the same obstacles, start and goal)?"""
        return self.where == _where(grid)

    def runs(self, grid: Grid, max_steps: int = MAX_STEPS) -> list[Run]:
        """The trace as a run, and the search's run, each at step 0."""
        return [trace_run(self.trace, grid, self.algorithm, self.semantics, max_steps,
                          self.notes()),
                Run(grid, self.algorithm, self.semantics, max_steps)]

    def notes(self) -> tuple[str, ...]:
        """What the trace's status line says of it: its file's name, and the order of the
        moves when the diagnosis inferred it from the trace ("order N,W,S,E inferred").  Not
        the search's choices: the trace never declares them (the search's pane says those)."""
        name = describe_name(PurePath(self.trace.name).name)
        if not self.inferred:
            return (name,)
        return (name, f"order {','.join(self.order)} inferred")

    @property
    def step(self) -> int | None:
        """The trace's step at which it first parts from the search (None: it never does)."""
        difference = self.verdict.difference
        return None if difference is None else difference.step

    def marks(self) -> list[Cell | None]:
        """The cell each pane's run expands (or adds) where they first part: the trace's,
        the search's (None where one has none, or they never part)."""
        difference = self.verdict.difference
        if difference is None:
            return [None, None]
        return [difference.got, difference.expected]

    def sentence(self) -> str:
        """The first difference in a line: "step 9: your trace expands (3,2); BFS expands
        (2,3)", or that they match all through; matched against a recursive DFS's pattern,
        it says so, and what the search beside the trace is."""
        difference = self.verdict.difference
        name = self.labels[1]
        if difference is None:
            text = f"your trace matches {self.verdict.choices} for all {self.verdict.steps} steps"
        elif difference.kind == "expand" and difference.got and difference.expected:
            text = (f"step {difference.step}: your trace expands {show(difference.got)}; "
                    f"{name} expands {show(difference.expected)}")
        else:
            text = difference.message
        if not self.recursive:
            return text
        matched = "" if difference is None else f"matched against {self.verdict.label}: "
        return (f"{text} · {matched}beside it, the stack DFS that expands as a recursive one "
                f"does (visit on expand, order {','.join(self.semantics.order)}: your order "
                f"reversed)")


def _where(grid: Grid) -> tuple[bytes, Cell | None, Cell | None]:
    return bytes(grid.blocked), grid.start, grid.goal


def replay_of(trace: Trace, grid: Grid, algorithm: str | None, semantics: Semantics,
              max_steps: int = MAX_STEPS) -> Replay:
    """``trace`` beside ``algorithm`` under ``semantics`` (as ``--check-trace -a`` checks
    it), or with no ``algorithm`` beside the diagnosis's best candidate.  The search's
    discarded pops that the trace left out are put back where the search discards them
    (:func:`with_discards`), so that both panes number their steps alike."""
    inferred, label = algorithm is None, ""
    if algorithm is None:
        from tui_search.engine.traces.diagnose import diagnose

        best = diagnose(trace, grid, max_steps).best[0]
        algorithm, semantics, label = best.algorithm, best.semantics, best.label
    aligned = with_discards(trace, _check(trace, grid, algorithm, semantics, label,
                                          max_steps).left_out)
    verdict = _check(aligned, grid, algorithm, semantics, label, max_steps)
    return Replay(aligned, algorithm, semantics, verdict, _where(grid), inferred)


def _check(trace: Trace, grid: Grid, algorithm: str, semantics: Semantics, label: str,
           max_steps: int) -> Verdict:
    """:func:`~tui_search.engine.traces.check.check_trace`; for a recursive DFS (``label``
    names it) the trace mirrored, as the diagnosis matched it, the verdict named so."""
    if not label:
        return check_trace(trace, grid, algorithm, semantics, max_steps)
    from tui_search.engine.traces.diagnose import mirrored

    return replace(check_trace(mirrored(trace), grid, algorithm, semantics, max_steps),
                   label=label)


def with_discards(trace: Trace, left_out: tuple[tuple[int, Cell], ...]) -> Trace:
    """``trace`` with the discarded pops it left out (a verdict's ``left_out``) put in where
    the search discards them, each ``"discarded": true`` on the line of the step it comes
    before (after the last step: its line)."""
    if not left_out:
        return trace
    steps = trace.steps.empty()
    pending = list(left_out)[::-1]
    for i, step in enumerate((*trace.steps, None)):
        while pending and pending[-1][0] == i:
            line = step.line if step is not None else trace.steps[-1].line
            steps.add(line, pending.pop()[1], (), discarded=True)
        if step is not None:
            steps.add(step.line, step.node, step.successors, step.discarded)
    return replace(trace, steps=steps)


__all__ = ["RECURSIVE_LABEL", "TRACE_LABEL", "Replay", "replay_of", "with_discards"]
