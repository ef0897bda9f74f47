"""``--replay FILE``: a trace another program wrote beside the search it is matched with, two
runs for the app's lockstep, and where they first part.

The search is ``-a``'s under the choice flags, else the diagnosis's best candidate
(:func:`~tui_search.engine.traces.diagnose.diagnose`); the first difference is the check's
(:func:`~tui_search.engine.traces.check.check_trace`), numbered as the trace numbers its steps.
A run stepped by hand (:mod:`~tui_search.engine.traces.hand`) is replayed the same way, its
mistakes kept beside it, each at its step.
No Textual here: the app's session holds a :class:`Replay` and asks it for its runs, their
names, the cells to mark and the sentence to show.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import PurePath

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import MAX_STEPS, Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.state import State
from tui_search.engine.traces.as_run import TRACE_ALGORITHM, trace_run
from tui_search.engine.traces.check import Verdict, check_trace
from tui_search.engine.traces.hand import Mistake
from tui_search.engine.traces.read import Trace, TraceStep, show
from tui_search.engine.util.filenames import describe_name

#: What the app calls the trace's pane.
TRACE_LABEL = TRACE_ALGORITHM.short


@dataclass(frozen=True)
class Replay:
    """A trace, the search it is replayed beside (``algorithm`` under ``semantics``) and how
    the two compare: ``verdict`` on the trace as the panes step it (the search's discarded
    pops it leaves out put back, so both panes number their steps alike), ``own`` on the trace
    as written (its own steps, as ``--check-trace`` numbers them: what the sentence says); on
    the map as it was read (``where``: its obstacles, start and goal; an edit that changes
    them ends the replay)."""

    trace: Trace
    algorithm: str
    semantics: Semantics
    verdict: Verdict
    where: tuple[bytes, State | None, State | None]
    #: Was the search found by the diagnosis (its order inferred from the trace), not given?
    inferred: bool = False
    own: Verdict | None = None
    #: What the trace's pane is called (a run stepped by hand: "Your run").
    label: str = TRACE_LABEL
    #: A run stepped by hand: the mistakes made on the way, each at its step (the trace, the
    #: steps as finally made, matches its search: these say where it did not at first).
    mistakes: tuple[Mistake, ...] = ()

    @property
    def labels(self) -> list[str]:
        """The panes' names: the trace's, the search's ("DFS (recursive)" for a recursion)."""
        name = get_algorithm(self.algorithm).short
        return [self.label, f"{name} (recursive)" if self.semantics.recursive else name]

    @property
    def order(self) -> tuple[str, ...]:
        """The moves in the order the trace adds them."""
        return self.semantics.order

    def fits(self, grid: Grid | Graph) -> bool:
        """Does the trace still apply to ``grid`` (the same obstacles, start and goal)?"""
        return self.where == _where(grid)

    def runs(self, grid: Grid | Graph, max_steps: int = MAX_STEPS) -> list[Run]:
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
        """The panes' step at which the trace first parts from the search (None: it never
        does)."""
        difference = self.verdict.difference
        return None if difference is None else difference.step

    def marks(self) -> list[State | None]:
        """The cell each pane's run expands (or adds) where they first part: the trace's,
        the search's (None where one has none, or they never part)."""
        difference = self.verdict.difference
        if difference is None:
            return [None, None]
        return [difference.got, difference.expected]

    def sentence(self) -> str:
        """The first difference in a line, numbered by the trace's own steps as the check
        numbers them: "step 9: your trace expands (3,2); BFS expands (2,3)", or that they
        match all through; where the panes number that step otherwise (the search's pops the
        trace leaves out are put back), what step it is there."""
        verdict = self.own or self.verdict
        difference = verdict.difference
        name = self.labels[1]
        if difference is None:
            return (f"{self.label.lower()} matches {verdict.choices} for all {verdict.steps} "
                    "steps")
        if difference.kind == "expand" and difference.got and difference.expected:
            text = (f"step {difference.step}: your trace expands {show(difference.got)}; "
                    f"{name} expands {show(difference.expected)}")
        else:
            text = difference.message
        here = self.step
        if here is not None and here != difference.step:
            text += (f" (the panes' step {here}: {name}'s discarded pops, which your trace "
                     "leaves out, are put back)")
        return text


def _where(board: Grid | Graph) -> tuple[bytes, State | None, State | None]:
    """What an edit changes: the obstacles (a graph's closed nodes), the start and the goal."""
    if isinstance(board, Graph):
        closed = "\n".join(sorted(board.closed)).encode()
        return closed, board.start, board.goals[0] if board.goals else None
    return bytes(board.blocked), board.start, board.goal


def replay_of(trace: Trace, grid: Grid | Graph, algorithm: str | None, semantics: Semantics,
              max_steps: int = MAX_STEPS, label: str = TRACE_LABEL,
              mistakes: tuple[Mistake, ...] = ()) -> Replay:
    """``trace`` beside ``algorithm`` under ``semantics`` (as ``--check-trace -a`` checks
    it), or with no ``algorithm`` beside the diagnosis's best candidate.  The search's
    discarded pops that the trace left out are put back where the search discards them
    (:func:`with_discards`), so that both panes number their steps alike."""
    inferred = algorithm is None
    if algorithm is None:
        from tui_search.engine.traces.diagnose import diagnose

        best = diagnose(trace, grid, max_steps).best[0]
        algorithm, semantics = best.algorithm, best.semantics
    own = check_trace(trace, grid, algorithm, semantics, max_steps)
    aligned = with_discards(with_tree(trace, grid, semantics), own.left_out)
    verdict = own if aligned is trace else check_trace(aligned, grid, algorithm, semantics,
                                                       max_steps)
    return Replay(aligned, algorithm, semantics, verdict, _where(grid), inferred, own, label,
                  mistakes)


def with_tree(trace: Trace, board: Grid | Graph, semantics: Semantics) -> Trace:
    """An expansions-only trace (no line lists successors) with a tree to draw: each step
    adds, unlisted (the check still compares only the order of the expansions), the
    neighbours it reaches first, in the search's order, that a later step expands.  Any
    other trace as it is."""
    if not trace.steps or any(step.listed for step in trace.steps):
        return trace
    later: dict[State, int] = {}
    for at, step in enumerate(trace.steps):
        later[step.node] = at  # its last expansion
    added: set[State] = {trace.steps[0].node}
    steps = []
    for at, step in enumerate(trace.steps):
        new = []
        for cell in _neighbours(board, step.node, semantics):
            if cell not in added and later.get(cell, -1) > at:
                added.add(cell)
                new.append(cell)
        steps.append(step._replace(successors=tuple(new), listed=False))
    return replace(trace, steps=tuple(steps))


def _neighbours(board: Grid | Graph, state: State, semantics: Semantics) -> list[State]:
    """The states a step from ``state`` reaches, in the search's order."""
    if isinstance(board, Graph):
        return [b for b, _, _ in board.successors(str(state), semantics.order == ("name",))]
    from tui_search.engine.maps.grid import DELTAS

    assert isinstance(state, tuple)
    x, y = state
    cells = ((x + DELTAS[d][0], y + DELTAS[d][1]) for d in semantics.order)
    return [c for c in cells if board.in_bounds(c) and not board.is_blocked(c)]


def with_discards(trace: Trace, left_out: tuple[tuple[int, State], ...]) -> Trace:
    """``trace`` with the discarded pops it left out (a verdict's ``left_out``) put in where
    the search discards them, each ``"discarded": true`` on the line of the step it comes
    before (after the last step: its line)."""
    if not left_out:
        return trace
    steps: list[TraceStep] = []
    pending = list(left_out)[::-1]
    for i, step in enumerate((*trace.steps, None)):
        while pending and pending[-1][0] == i:
            line = step.line if step is not None else trace.steps[-1].line
            steps.append(TraceStep(line, pending.pop()[1], (), True, step is None or step.listed))
        if step is not None:
            steps.append(step)
    return replace(trace, steps=tuple(steps))


__all__ = ["TRACE_LABEL", "Replay", "replay_of", "with_discards", "with_tree"]
