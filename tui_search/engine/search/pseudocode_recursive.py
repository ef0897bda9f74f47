"""The pseudocode of a recursive search (``--recursive``): DFS or iterative deepening as a
function that calls itself, in the two forms a line of its trace can take.

*neighbours*: the call lists the neighbours it will try (those not visited on entry), then
calls itself on each in turn, skipping one visited meanwhile, deeper down.  *calls*: the call
tries each neighbour in turn and calls itself on it at once; its line lists the calls made.
Iterative deepening calls it again and again with a growing depth limit.  The lines' kinds are
those of the stack's code (:mod:`~tui_search.engine.search.pseudocode`), so the app lights them
alike (:mod:`tui_search.tui.view.code_trace`): "take" is where a call comes to the next
neighbour, "recurse" the call itself, "discard" the neighbour skipped as visited meanwhile.
"""

from __future__ import annotations

from tui_search.engine.search.choices import Semantics, order_words
from tui_search.engine.search.registry import Algorithm

_CORNER_WORDS = {
    "one": "if s is diagonal between two obstacles (corner rule one): skip s",
    "never": "if s is diagonal past an obstacle's corner (corner rule never): skip s",
}


def recursive_lines(algorithm: Algorithm, semantics: Semantics,
                    reached: tuple[str, str] | None) -> list[tuple[str, int, str]]:
    """The code as ``(kind, indent, text)`` lines; ``reached``: the line that skips a
    neighbour reached already (None: tree search with no path check skips none)."""
    tree, iterative = semantics.tree_search, algorithm.iterative
    calls = semantics.recursive == "calls"
    goal_test = semantics.goal_test_for(algorithm)
    out: list[tuple[str, int, str]] = []
    base = 0
    if iterative:
        out.append(("deepen", 0, "for depth limit ← 0, 1, 2, …:"))
        base = 1
    keep = "" if tree else ("visited ← nothing; " if not iterative
                            else "reached ← START at depth 0; ")
    out.append(("init", base, f"{keep}visit(START)"))
    if iterative:
        out.append(("fail", base, "if nothing was cut off at the limit: return no path"))
    else:
        out.append(("fail", 0, "return no path"))
    out.append(("while", 0, "function visit(node):"))
    if not (tree or iterative):
        out.append(("mark_node", 1, "mark node visited"))
    if goal_test == "expand":
        out.append(("goal_node", 1, "goal test: if node is the goal, return its path"))
    if iterative:
        out.append(("cutoff", 1, "if node's depth = the depth limit: cut off, return"))
    if not calls:
        out.append(("calls", 1, "calls ← an empty list"))
    out.append(("for", 1, f"for each successor s of node, moves in order "
                          f"{order_words(semantics)}:"))
    out.append(("blocked", 2, "if s is off the map or an obstacle: skip s"))
    if semantics.corners in _CORNER_WORDS:
        out.append(("corner", 2, _CORNER_WORDS[semantics.corners]))
    if reached is not None:
        out.append((reached[0], 2, reached[1]))
    if calls:
        out.append(("push", 2, "add s to node's line (a call made)"))
        if iterative and not tree:
            out.append(("mark_succ", 2, "mark s reached at depth node's + 1"))
        if goal_test == "generate":
            out.append(("goal_succ", 2, "goal test: if s is the goal, return its path"))
        out.append(("recurse", 2, "visit(s)"))
        return out
    out.append(("push", 2, "append s to calls"))
    if iterative and not tree:
        out.append(("mark_succ", 2, "mark s reached at depth node's + 1"))
    if goal_test == "generate":
        out.append(("goal_succ", 2, "goal test: if s is the goal, return its path"))
    out.append(("take", 1, "for each s in calls, in order:"))
    if not (tree or iterative):
        out.append(("discard", 2, "if s is visited by now (deeper down): skip s"))
    out.append(("recurse", 2, "visit(s)"))
    return out


__all__ = ["recursive_lines"]
