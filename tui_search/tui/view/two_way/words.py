"""What the status lines say of a bidirectional search (no Textual or Rich): its counts (the
two halves' side by side, and the best meeting μ) and its narration -- whose turn it was,
what that half's step did, when the two searches met, and at the end why it stopped: "both
searches reached (7,3): with first-meeting this is the path, cost 14.24; it is not the
cheapest (lowest 13.66)"."""

from __future__ import annotations

from typing import TYPE_CHECKING
from weakref import WeakKeyDictionary

from tui_search.engine.search.choices import STOP_RULES, TURN_RULES
from tui_search.engine.util.numbers import group_digits
from tui_search.tui.view.narration import (
    LOWEST_COST_CELLS,
    cell_text,
    costs_text,
    frontier_word,
    gave_up_text,
    lowest_cost,
    node_text,
    what_the_step_did,
)

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.run.recorded import Run

#: Each direction as the lines name it, and its arrow.
NAMES = {"forward": "Forward", "backward": "Backward"}
ARROWS = {"forward": "→", "backward": "←"}


def directed(titles: tuple[str, ...], direction: str) -> tuple[str, ...]:
    """A panel's title wordings (longest first) for one half of a bidirectional search:
    "→ Forward: Queue (FIFO)" ... then "→ Queue"; as they are for a one-way search ("")."""
    if not direction:
        return titles
    arrow, name = ARROWS[direction], NAMES[direction]
    return (*(f"{arrow} {name}: {t}" for t in titles), *(f"{arrow} {t}" for t in titles))


def mu_text(run: BiRun, mu: float) -> str:
    """μ as the search counts it: a cost to two places, BiBFS's moves whole."""
    return f"{mu:.2f}" if run.algo.weighted else f"{mu:g}"


def turn_words(run: BiRun) -> str:
    """How the two halves take turns, as the narration says it."""
    if run.semantics.turn == TURN_RULES[1]:
        return "the one with the smaller frontier steps next (forward on a tie)"
    return "they take a step each in turn, forward first"


def stop_words(run: BiRun) -> str:
    """The stopping rule, in a few words."""
    if run.semantics.stop == STOP_RULES[1]:
        return "stop: first meeting (the trap: not always the cheapest)"
    return "stop: proven (the best meeting, once nothing cheaper is left)"


def two_way_parts(run: BiRun) -> list[tuple[str, str]]:
    """The counts as (label, value) pairs: the step, each half's expansions and frontier,
    and the best meeting so far."""
    total = run.total
    digits = group_digits
    ahead, behind = run.halves
    parts = [
        ("step", f"{digits(run.k)}/{digits(total) if total is not None else '?'}"),
        ("expanded", f"{digits(ahead.now.expanded + behind.now.expanded)} "
                     f"(→ {digits(ahead.now.expanded)} ← {digits(behind.now.expanded)})"),
        (frontier_word(ahead) + "s",
         f"→ {digits(ahead.now.frontier_len())} ← {digits(behind.now.frontier_len())}"),
    ]
    if run.algo.queued:
        parts.append(("discarded", digits(ahead.now.discarded + behind.now.discarded)))
    mu, meeting = run.mu(), run.meeting()
    parts.append(("μ", "not met" if meeting is None else
                  f"{mu_text(run, mu)} at {cell_text(meeting)}"))
    return parts


def two_way_narration(run: BiRun, brief: bool = False) -> str:
    """One line about the step just taken (at step 0, how the two searches will go), and at
    the end why the search stopped (``brief``: a pane's own lines, beside others: at the
    end, only why)."""
    k = run.k
    if brief and run.at_end and k:
        return _ended(run, "").removeprefix(". ")
    if k == 0:
        text = (f"START {cell_text(run.start)} is on the forward {frontier_word(run.halves[0])}"
                f", the goal {cell_text(run.goal)} on the backward one: {turn_words(run)}")
        return _ended(run, text) if run.at_end else f"{text}. Press n for the first step."
    direction = run.direction(k)
    half = run.halves[direction != "forward"]
    expanded = half.steps.expanded_event(half.k)
    node = node_text(half, expanded)
    if direction != "forward" and node.startswith("START"):  # the backward half's root
        node = "GOAL" + node[len("START"):]
    costs = costs_text(half, expanded)
    if costs:
        node = f"{node} {costs}"
    did = what_the_step_did(half, node, expanded, frontier_word(half), None)
    text = f"{ARROWS[direction]} {NAMES[direction]}: {did[0].lower()}{did[1:]}"
    meeting, mu = run.meeting(), run.mu()
    if meeting is not None and mu < run.mu(k - 1):
        other = "backward" if direction == "forward" else "forward"
        text += (f"; {cell_text(meeting)} was reached by the {other} search too: a path of "
                 f"{'cost' if run.algo.weighted else 'moves'} {mu_text(run, mu)}, "
                 "the best meeting so far (μ)")
    return _ended(run, text) if run.at_end else text


def _ended(run: BiRun, text: str) -> str:
    """``text`` and why the search stopped (it is at its end)."""
    if run.gave_up:
        return f"{text}. {gave_up_text(run.halves[0]).capitalize()}"
    why = run.why()
    lowest = _lowest(run)
    if run.semantics.stop == STOP_RULES[1] and run.found and lowest is not None:
        mine = run.path_cost() if run.algo.weighted else float(len(run.moves() or []))
        if mine > lowest * (1 + 1e-9):
            why = why.replace("nothing proves it the cheapest",
                              f"it is not the cheapest (lowest {mu_text(run, lowest)})")
        else:
            why = why.replace("nothing proves it the cheapest",
                              "here it is the cheapest, by luck")
    return f"{text}. Stopped: {why}"


def _lowest(run: BiRun) -> float | None:
    """The cheapest path's cost (BiBFS: its fewest moves), where the map is small enough to
    search again."""
    ahead: Run = run.halves[0]
    if run.algo.weighted:
        return lowest_cost(ahead)
    from tui_search.engine.run.recorded import Run as OneWay

    board, graph = run.board, run.graph
    size = len(graph) if graph is not None else run.grid.width * run.grid.height
    if size > LOWEST_COST_CELLS:
        return None
    if run not in _FEWEST:
        path = OneWay(board, "bfs", ahead.semantics).outcome().path
        _FEWEST[run] = None if path is None else float(len(path) - 1)
    return _FEWEST[run]


_FEWEST: WeakKeyDictionary[BiRun, float | None] = WeakKeyDictionary()


def two_way_result(run: BiRun) -> str:
    """The answer at the end: the path's moves and cost through its meeting cell."""
    if not run.at_end:
        return ""
    if not run.found:
        return "no path"
    moves, cost = run.moves() or [], run.path_cost()
    meeting = cell_text(run.meeting())
    return f"path: {group_digits(len(moves))} moves, cost {cost:.2f}, met at {meeting}"


__all__ = ["ARROWS", "NAMES", "directed", "mu_text", "stop_words", "turn_words",
           "two_way_narration",
           "two_way_parts", "two_way_result"]
