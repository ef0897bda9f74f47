"""Which of the settings' choices apply to the searches they are for: a choice that applies
to none of them is greyed out, and its line says why (the visit rule under iterative deepening,
a priority queue's choices under BFS, a bidirectional search's stopping rule under A*).

Each ``sync_`` function reads the controls of the settings screen (``screen``) and greys out or
brings back those of its choice; the screen calls them as its controls change.
"""

from __future__ import annotations

from textual.dom import DOMNode
from textual.widgets import Checkbox, Input, Label, RadioSet

from tui_search.engine.maps.grid import DEFAULT_ORDER, parse_order
from tui_search.engine.search.choices import EXPLAIN
from tui_search.engine.search.heuristics import INADMISSIBLE, admissible
from tui_search.engine.search.registry import BIDIRECTIONAL, Algorithm
from tui_search.tui.dialogs.settings_controls import picked, ticked_searches

#: The line on the stopping rule and the turn while they apply.
TWO_WAY_EXPLAIN = "first meeting may miss the cheapest path; smaller frontier steps next"


def names(algorithms: list[Algorithm]) -> str:
    """"BFS or DFS"."""
    return " or ".join(a.short for a in algorithms)


def visit_applies(algorithms: list[Algorithm]) -> bool:
    """The visit rule applies to BFS and DFS (in compare mode: to one of the searches); not
    to a search that re-opens cells, nor to a bidirectional one (it marks what it pushes)."""
    return any(not (a.iterative or a.weighted or a.bidirectional) for a in algorithms)


def recursion_applies(algorithms: list[Algorithm]) -> bool:
    """Recursion applies to DFS and iterative deepening (in compare mode: to one)."""
    return any(a.key in ("dfs", "iddfs") for a in algorithms)


def queue_applies(algorithms: list[Algorithm]) -> bool:
    """A priority queue's ties, re-opening and costs apply to UCS, greedy and A* (a
    bidirectional search's halves run under the plain choices)."""
    return any(a.queued and not a.bidirectional for a in algorithms)


def weight_applies(algorithms: list[Algorithm]) -> bool:
    """The weight applies to A* and IDA* (not to bidirectional A*)."""
    return any(a.priority == "g+h" and not a.bidirectional for a in algorithms)


def two_way_applies(screen: DOMNode, algorithms: list[Algorithm]) -> bool:
    """The stopping rule and the turn apply when a bidirectional search is shown, or ticked
    for compare mode."""
    return (any(a.bidirectional for a in algorithms)
            or any(key in BIDIRECTIONAL for key in ticked_searches(screen)))


def sync_visit(screen: DOMNode, algorithms: list[Algorithm]) -> None:
    """The visit rule does not apply to tree search, recursion, iterative deepening, the
    cost-ordered searches, the bidirectional: say so and grey it out."""
    tree = screen.query_one("#tree_search", Checkbox).value
    radios = screen.query_one("#visit", RadioSet)
    first = algorithms[0]
    if visit_applies(algorithms):
        why = ""
    elif all(a.bidirectional for a in algorithms):
        why = (f"does not apply to {names(algorithms)}: it marks a cell reached when it "
               "pushes it")
    elif first.iterative and not first.contours:
        why = f"does not apply to {first.short}: it re-opens cells reached shallower"
    else:
        why = f"does not apply to {names(algorithms)}: it re-opens cells reached with a lower g"
    if not why and tree:
        why = "does not apply to tree search: it has no visited set"
    elif not why and picked(screen, "recursive") != "stack" and recursion_applies(algorithms):
        why = "does not apply to a recursion: it visits a cell when it enters it"
    radios.disabled = bool(why)
    explain = screen.query_one("#visit-explain", Label)
    explain.update(why or EXPLAIN["visit"])
    explain.set_class(bool(why), "-note")


def sync_published(screen: DOMNode, algorithms: list[Algorithm]) -> None:
    """The choices of published code: grey out those that apply to none of the searches
    (the goal test, tree search and the start's mark for bidirectional searches alone; a
    priority queue's; recursion; the path check without tree search; the start's mark where
    nothing is marked on a push; the weight)."""
    tree = screen.query_one("#tree_search", Checkbox).value
    recursive = picked(screen, "recursive") != "stack" and recursion_applies(algorithms)
    queue = queue_applies(algorithms)
    visit = picked(screen, "visit") if visit_applies(algorithms) else "generate"
    one_way = [a for a in algorithms if not a.bidirectional]
    screen.query_one("#tree_search", Checkbox).disabled = not one_way
    screen.query_one("#no_path_check", Checkbox).disabled = not (tree and one_way)
    screen.query_one("#mark_start", Checkbox).disabled = bool(
        not one_way or tree or recursive or (visit != "generate" and not queue))
    screen.query_one("#recursive", RadioSet).disabled = not recursion_applies(algorithms)
    screen.query_one("#goal-test", RadioSet).disabled = not one_way
    screen.query_one("#goal-explain", Label).update(
        EXPLAIN["goal_test"] if one_way else
        f"the goal test does not apply to {names(algorithms)}: it stops when its searches meet")
    for name in ("#ties", "#reopen", "#exact_costs"):
        screen.query_one(name).disabled = not queue
    weighs = weight_applies(algorithms)
    screen.query_one("#weight", Input).disabled = not weighs
    if not weighs:
        screen.query_one("#weight-explain", Label).update(
            "W, weighted A*'s weight (f = g + W·h), applies to A* only")


def sync_two_way(screen: DOMNode, algorithms: list[Algorithm]) -> None:
    """The stopping rule and the turn: greyed out unless a bidirectional search is shown or
    ticked for compare mode, and said so (a line the shortest terminals leave out, as the
    weight's: the greyed-out row says enough there)."""
    applies = two_way_applies(screen, algorithms)
    for name in ("#stop", "#turn"):
        screen.query_one(name, RadioSet).disabled = not applies
    for label in screen.query(".row-label"):  # "stop", "turn": greyed out with their rows
        label.disabled = not applies
    explain = screen.query_one("#two-way-explain", Label)
    explain.update(TWO_WAY_EXPLAIN if applies else
                   f"not {names(algorithms)}'s: a bidirectional search's (tick one below)")


def sync_heuristic(screen: DOMNode, algorithms: list[Algorithm], graph: bool) -> None:
    """The heuristic applies to greedy and A* only; an inadmissible one is named (on a grid:
    ``graph`` False)."""
    radios = screen.query_one("#heuristic", RadioSet)
    radios.disabled = not any(a.informed for a in algorithms)
    if not any(a.weighted for a in algorithms):
        text = f"does not apply to {names(algorithms)}: no estimate, no priority queue"
    elif radios.disabled:
        text = f"the heuristic does not apply to {names(algorithms)}: it uses no estimate"
    elif graph:  # a graph's table or straight line: said when checked
        text = EXPLAIN["heuristic"]
    else:
        name = picked(screen, "heuristic")
        try:
            moves = parse_order(screen.query_one("#order", Input).value)
        except ValueError:
            moves = DEFAULT_ORDER
        text = INADMISSIBLE if not admissible(name, moves) else EXPLAIN["heuristic"]
    explain = screen.query_one("#heuristic-explain", Label)
    explain.update(text)
    explain.set_class(text != EXPLAIN["heuristic"], "-note")


__all__ = ["TWO_WAY_EXPLAIN", "queue_applies", "recursion_applies", "sync_heuristic",
           "sync_published", "sync_two_way", "sync_visit", "two_way_applies", "visit_applies",
           "weight_applies"]
