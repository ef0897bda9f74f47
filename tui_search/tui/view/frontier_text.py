"""What the frontier panel's lines say, as text (no Textual): a priority queue's figures, the
end hints, what an empty frontier means, the entry a discarded step threw away, the title's
and the legend's wordings.  The panel (:mod:`~tui_search.tui.widgets.
frontier_panel`) lays them out."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.search.registry import PRIORITIES, Algorithm, Frontier
from tui_search.engine.search.state import state_text
from tui_search.tui.view.narration import gave_up_text
from tui_search.tui.view.pieces import Line, Piece

if TYPE_CHECKING:
    from tui_search.engine.run.recorded import Run


#: The frontier's names, shortest last, after its full title (``Frontier.title``).
SHORT_NAMES = {Frontier.FIFO: ("Queue", "Q"), Frontier.LIFO: ("Stack", "S"),
               Frontier.PRIORITY: ("Priority queue", "PQ"), Frontier.ADDED: ("Frontier", "F")}
#: What the title adds while there is room: a replayed trace's frontier is only its order added.
TITLE_NOTES = {Frontier.ADDED: "your trace doesn't say its discipline"}
#: The bottom legend's wordings, longest first (a narrow panel shows a shorter one); in the
#: quiz, whose order is hidden: HIDDEN_LEGENDS.
LEGENDS = ("▶ next out  + just added", "▶ next out + just added", "▶ next + added")
#: A frontier whose next out is not known (a replayed trace's): no ``▶``, and it says why.
ADDED_LEGENDS = ("+ just added · your trace doesn't say its discipline",
                 "your trace doesn't say its discipline", "+ added · no discipline given",
                 "no discipline given")
HIDDEN_LEGENDS = ("+ just added · click picks", "+ added · click picks", "click picks")
#: By hand: the entries as they were added, oldest first, the student taking them.
HAND_LEGENDS = ("oldest first · + just added · click takes", "oldest first · click takes",
                "oldest first")
DISCARDED = "frontier-panel--discarded"
#: Width of the move column: a direction's name (START, longer, is only ever on its own: the
#: frontier holds just the root then).
DIR_W = 2


def titles(algo: Algorithm, hide_order: bool = False, as_added: bool = False,
           order_words: str = "") -> tuple[str, ...]:
    """The panel's title in its wordings, longest first: "Queue (FIFO)", "Queue", "Q";
    a priority queue's says what it orders by as long as it can ("Priority queue (A*: f = g
    + h)" ... "PQ (f)", "PQ"); in the quiz, that the order is hidden ("Queue (FIFO) · order
    hidden", "Queue (FIFO) · hidden", "Queue · hidden", then the plain wordings); by hand
    (``as_added``), that its entries are listed as added ("Queue (FIFO) · as added").
    ``order_words``: what the queue orders by, when not the algorithm's own (weighted A*'s
    "f = g + 2·h")."""
    name, letters = SHORT_NAMES[algo.frontier]
    note = TITLE_NOTES.get(algo.frontier)
    if algo.priority is None:
        plain = [algo.frontier_title, name, letters]
        if note:
            plain.insert(0, f"{algo.frontier_title}: {note}")
    else:
        by, what = algo.priority_name, order_words or PRIORITIES[algo.priority]
        title = (f"{algo.frontier.title} ({algo.short}: {what})" if order_words
                 else algo.frontier_title)
        plain = [title, f"{name} ({what})", f"{name} ({by})", name, f"{letters} ({by})",
                 letters]
        if algo.contours:  # IDA*'s stack: what it cuts off by, not an order
            plain = [f"{algo.frontier.title} ({algo.short}: {what} ≤ limit)",
                     f"{name} ({what} ≤ limit)", f"{name} (f ≤ limit)", name, letters]
    wordings = plain
    if as_added:
        wordings = [f"{text} · as added" for text in plain[:-1]] + plain
    elif hide_order:
        wordings = [f"{plain[0]} · order hidden",
                    *(f"{text} · hidden" for text in plain[:-1]), *plain]
    return _longest_first(wordings)


def legends(kind: Frontier, hide_order: bool, as_added: bool = False) -> tuple[str, ...]:
    """The bottom legend's wordings, longest first."""
    if as_added:
        return HAND_LEGENDS
    return HIDDEN_LEGENDS if hide_order else LEGENDS if kind.next_known else ADDED_LEGENDS


def _longest_first(wordings: list[str]) -> tuple[str, ...]:
    """``wordings`` without those no shorter than one before them (never the first to fit)."""
    kept: list[str] = []
    for text in wordings:
        if not kept or len(text) < len(kept[-1]):
            kept.append(text)
    return tuple(kept)


def figures(run: Run, g: int, width: int) -> list[str]:
    """A priority queue's figures for event ``g``, the priority first, each number ``width``
    wide: "f 6.41", "g 2.41", "h 4.00" (A*), "g 2.41" (UCS), "h 4.00", "g 2.41" (greedy);
    none otherwise."""
    costs = run.nodes.costs(g)
    if costs is None:
        return []
    cost, h, f = costs
    named = {"g": [("g", cost)], "h": [("h", h), ("g", cost)],
             "g+h": [("f", f), ("g", cost), ("h", h)]}[run.algo.priority or "g"]
    return [f"{name} {value:>{width}.2f}" for name, value in named]


def costs_column(run: Run, g: int, width: int, squeeze: int = 0) -> str:
    """The figures as an entry's column: "  f 6.41 g 2.41 h 4.00"; empty for none.  In a
    panel too narrow for them, ``squeeze`` 1: " f 6.41 g 2.41 h 4.00"; 2: " f6.41 g2.41
    h4.00" (no number is ever cut)."""
    shown = figures(run, g, width)
    if squeeze == 2:
        shown = [figure.replace(" ", "", 1) for figure in shown]
    return ("  " if squeeze == 0 else " ") + " ".join(shown) if shown else ""


def discarded_line(run: Run, cost_w: int) -> Line | None:
    """After a discarded step (visit on expand): the entry it threw away, struck out, its
    figures ``cost_w`` wide; None after any other step."""
    if not (run.k and run.steps.is_discarded(run.k)):
        return None
    g = run.steps.expanded_event(run.k)
    where = state_text(run.nodes.cell(g))
    why = "stale, discarded" if run.algo.weighted else "discarded"
    # kept whole: a figure never parted from its name when the line wraps
    shown = [Piece([(figure, DISCARDED)], 0, (" " if i else "  ", DISCARDED))
             for i, figure in enumerate(figures(run, g, cost_w))]
    return Line([Piece([(f"✗  {where} {run.nodes.move(g).ljust(DIR_W)}", DISCARDED)]),
                 *shown, Piece([(why, DISCARDED)], 0, ("  ", DISCARDED))])


def end_hint(kind: Frontier, i: int, n: int) -> str:
    """The hint beside entry ``i`` of ``n``: which end is which."""
    only, next_out, far_end = kind.end_hints
    if n == 1:
        return only
    if i == 0:
        return next_out
    if i == n - 1:
        return far_end
    return ""


def describe_empty(run: Run) -> str:
    """What an empty frontier means at the run's position."""
    if run.k < run.recorded or not run.done:
        f_limits = run.steps.f_limits()
        if f_limits is not None:  # IDA*: the smallest f cut off is the next limit
            return f"empty — iteration over; next: f-limit {f_limits[1]:.2f}"
        if run.algo.iterative:
            limit = run.steps.depth_limit()
            nxt = 1 if limit is None else limit + 1
            return f"empty — iteration over; next: depth limit {nxt}"
        return "empty"
    if run.gave_up:
        return f"empty — {gave_up_text(run)}"
    return "empty" if run.found else "empty — no path"
