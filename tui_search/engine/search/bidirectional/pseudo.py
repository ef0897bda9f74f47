"""A bidirectional search's pseudocode lines, from its choices (the stopping rule moves its
lines): what :mod:`~tui_search.engine.search.bidirectional.loop` does, in its order, as
``(kind, indent, text)`` for :func:`~tui_search.engine.search.pseudocode.pseudocode`."""

from __future__ import annotations

from tui_search.engine.search.choices import STOP_RULES, TURN_RULES, Semantics
from tui_search.engine.search.registry import Algorithm

_CORNER_WORDS = {
    "one": "if s is diagonal between two obstacles (corner rule one): skip s",
    "never": "if s is diagonal past an obstacle's corner (corner rule never): skip s",
}


def bidirectional_lines(algorithm: Algorithm, semantics: Semantics, move_cost: str
                        ) -> list[tuple[str, int, str]]:
    """The lines of ``algorithm`` (bibfs, biucs, biastar) under ``semantics``."""
    weighted, proven = algorithm.weighted, semantics.stop == STOP_RULES[0]
    alternate = semantics.turn == TURN_RULES[0]
    noun = algorithm.frontier.noun
    by = semantics.priority_words(algorithm)
    if algorithm.informed:
        by = (f"{by}, h = {semantics.heuristic} distance to the goal (forward), to START "
              "(backward)")
    holding = f"a {noun} by {by}" if weighted else f"a {noun}"
    cost = "g" if weighted else "depth"
    out = [("init", 0, f"forward ← {holding}, holding START; backward ← the same, holding "
                       "GOAL"),
           ("mark_start", 0, f"{cost}_f[START] ← 0; {cost}_b[GOAL] ← 0  (reached by each)"),
           ("mu", 0, "μ ← ∞; meeting ← none  (the best path found through a cell both "
                     "reached)"),
           ("goal_start", 0, "if START is GOAL: return the path START"),
           ("side", 0, "side ← forward  (then backward, then forward: a step each in turn)"),
           ("while", 0, "while neither frontier is empty:")]
    if not alternate:
        del out[4]  # the side is chosen at each step
    if proven and algorithm.informed:
        out.append(("proven", 1, "if max(smallest f forward, smallest f backward) ≥ μ: "
                                 "return meeting's path  (front-to-end bound)"))
    elif proven:
        out.append(("proven", 1, f"if smallest {cost} forward + smallest {cost} backward "
                                 "≥ μ: return meeting's path"))
    if not alternate:
        out.append(("side", 1, "side ← the side whose frontier is smaller (forward on a tie)"))
    order_name = algorithm.priority_name
    out.append(("take", 1, f"node ← {algorithm.frontier.take_words(order_name)} of side"))
    if weighted:
        out.append(("discard", 1, "if node.g > side's best g[node]: stale, discard it, "
                                  + ("side ← the other, go on" if alternate else "go on")))
    out.append(("for", 1, "for each s one move from node on side's way (backward: the cells "
                          f"whose move reaches node), moves in order {','.join(semantics.order)}:"))
    out.append(("blocked", 2, "if s is off the map or an obstacle: skip s"))
    if semantics.corners in _CORNER_WORDS:
        out.append(("corner", 2, _CORNER_WORDS[semantics.corners]))
    if weighted:
        out.append(("cost", 2, f"g ← node.g + {move_cost}"))
        out.append(("reached", 2, "if side's best g[s] ≤ g: reached as cheaply, skip s"))
    else:
        out.append(("reached", 2, "if side reached s already: skip s"))
    out.append(("push", 2, f"push s on side's {noun}; {cost} of s on side ← "
                           + ("g" if weighted else "node's depth + 1")))
    out.append(("meet", 2, f"if the other side reached s and the two {cost}s of s sum "
                           "below μ: μ ← that sum; meeting ← s"))
    if not proven:
        out.append(("first", 3, "return meeting's path  (first-meeting: the first cell both "
                                "reached, not proven the cheapest)"))
    if alternate:
        out.append(("turn", 1, "side ← the other side"))
    out.append(("fail", 0, "return meeting's path, or no path when there is no meeting"))
    return out


__all__ = ["bidirectional_lines"]
