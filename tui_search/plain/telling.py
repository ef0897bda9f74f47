"""What a step did, in plain sentences: the narration in the tutorial's own words, the
frontier in order, the search tree's new edges and, at the end, the path -- what plain mode
prints after a key, and the handout's steps.

The tutorial tells BFS on its map as "Start is taken out of the queue and expanded. South is
the only successor so it is added to the queue. South is taken out of the queue and expanded.
S and SE are the successors and they are added to the queue. S is taken out of the queue and
expanded adding S and SE to the queue. Next SE is expanded adding E and NE to the queue."
:func:`tutorial_words` says every step of a queue or a stack that way, by the tutorial's own
rules: the first two expansions told at length, then one sentence each, "Next" for the sibling
of the node expanded just before; a node named by the move that reached it ("SE"), in full when
it is its parent's only successor ("South"), "Start" for the start.  Where the tutorial has no
words (a priority queue, iterative deepening, a discarded step, the goal found), the app's own
narration (:func:`~tui_search.tui.view.narration.narrate`) says it.
"""

from __future__ import annotations

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.registry import Frontier
from tui_search.tui.view.frontier_text import SHORT_NAMES
from tui_search.tui.view.narration import cell_text, narrate

#: The moves' names in full, for a node that is its parent's only successor.
FULL_NAMES = {"N": "North", "S": "South", "E": "East", "W": "West", "NE": "North East",
              "NW": "North West", "SE": "South East", "SW": "South West"}
#: Frontier entries said at most (the rest counted).
FRONTIER_SAID = 20
#: The expansions told at length, as the tutorial tells its first two.
AT_LENGTH = 2


def listed(names: list[str]) -> str:
    """``A``, ``A and B``, ``A, B and C``."""
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"


def node_name(run: Run, g: int) -> str:
    """Event ``g`` as the tutorial names a node: "Start", its move in full when its parent
    had no other successor ("South"), else its move ("SE")."""
    parent = run.nodes.parent(g)
    if parent < 0:
        return "Start"
    move = run.nodes.move(g)
    only = len(run.now.children(parent)) == 1
    return FULL_NAMES.get(move, move) if only else move


def tutorial_words(run: Run) -> str | None:
    """The step the run is at in the tutorial's words; None where the tutorial has none."""
    algo = run.algo
    if algo.weighted or algo.iterative or run.replayed or algo.frontier not in (
            Frontier.FIFO, Frontier.LIFO):
        return None
    word, k = algo.frontier.noun, run.k
    if k == 0:
        return None if run.at_end else f"We begin with the START node and add it to the {word}."
    if run.steps.is_discarded(k) or (run.at_end and run.found):
        return None
    expanded = run.steps.expanded_event(k)
    name = node_name(run, expanded)
    added = [node_name(run, h) for h in run.now.added_now()]
    if not added:
        return f"{name} is taken out of the {word} and expanded: it has no new successors."
    if k <= AT_LENGTH:
        if len(added) == 1:
            return (f"{name} is taken out of the {word} and expanded. {added[0]} is the only "
                    f"successor so it is added to the {word}.")
        return (f"{name} is taken out of the {word} and expanded. {listed(added)} are the "
                f"successors and they are added to the {word}.")
    before = run.steps.expanded_event(k - 1)
    if not run.steps.is_discarded(k - 1) and run.nodes.parent(before) == run.nodes.parent(
            expanded):
        return f"Next {name} is expanded adding {listed(added)} to the {word}."
    return f"{name} is taken out of the {word} and expanded adding {listed(added)} to the {word}."


def step_sentence(run: Run, name: str = "") -> str:
    """"Step 4: Next SE is expanded adding E and NE to the queue." (``name``: the search's,
    where several are shown: "BFS step 4: ...")."""
    said = tutorial_words(run) or _sentence(narrate(run))
    head = f"{name} step" if name else "Step"
    return f"{head} {run.k}: {said}"


def _sentence(text: str) -> str:
    return text if text.endswith((".", "!", "?")) else text + "."


def frontier_sentence(run: Run, hide_order: bool = False) -> str:
    """"Queue, front first: (0,2), (2,1)." -- the frontier in the order it comes out (a
    priority queue's priorities said); ``hide_order`` (the quiz): in cell order instead."""
    kind = run.algo.frontier
    title = SHORT_NAMES[kind][0]
    n = run.now.frontier_len()
    if n == 0:
        return f"{title}: empty."
    events = run.now.frontier(0, None if hide_order else FRONTIER_SAID)
    if hide_order:
        order = "in cell order (the quiz hides which comes next)"
        events = sorted(events, key=lambda g: run.nodes.cell(g)[::-1])[:FRONTIER_SAID]
    elif kind is Frontier.PRIORITY:
        order = f"lowest {run.algo.priority_name} first"
    else:
        order = f"{kind.next_end} first"
    items = [cell_text(run.nodes.cell(g)) + _priority(run, g, hide_order) for g in events]
    more = f", and {n - len(items)} more" if n > len(items) else ""
    return f"{title}, {order}: {', '.join(items)}{more}."


def _priority(run: Run, g: int, hidden: bool) -> str:
    costs = run.nodes.costs(g)
    if costs is None or hidden:
        return ""
    value = {"g": costs[0], "h": costs[1]}.get(run.algo.priority or "", costs[2])
    return f" {run.algo.priority_name} {value:.2f}"


def tree_sentence(run: Run) -> str:
    """The search tree's new edges: "New in the tree: (1,2) to (2,2) by E, (1,2) to (2,1) by
    NE." ("" when the step added none)."""
    added = run.now.added_now()
    if not run.k or not len(added):
        return ""
    parent = cell_text(run.nodes.cell(run.steps.expanded_event(run.k)))
    edges = [f"{parent} to {cell_text(run.nodes.cell(h))} by {run.nodes.move(h)}" for h in added]
    return f"New in the tree: {', '.join(edges)}."


def result_sentence(run: Run) -> str:
    """At the run's end: the path, its moves and cost, or that there is none ("" before)."""
    if not run.at_end:
        return ""
    counts = (f"Expanded {run.now.expanded}, generated {run.now.generated}, the largest "
              f"{run.algo.frontier.noun} {run.steps.peak_frontier()}.")
    if not run.found:
        return f"No path. {counts}"
    moves = run.moves() or []
    path = run.path() or []
    cost = run.path_cost()
    said = ", ".join(moves) if moves else "none: the start is the goal"
    return (f"Path: {len(moves)} moves, cost {cost:.2f}, from {cell_text(path[0])} to "
            f"{cell_text(path[-1])}: {said}. {counts}")


def step_report(run: Run, name: str = "", hide_order: bool = False) -> list[str]:
    """What plain mode prints of a run after a key: the step, the tree's new edges, the
    frontier, and at the end the path."""
    lines = [step_sentence(run, name), tree_sentence(run), frontier_sentence(run, hide_order),
             result_sentence(run)]
    return [line for line in lines if line]


#: Nodes the tree command lists at most.
TREE_SAID = 200


def tree_lines(run: Run) -> list[str]:
    """The search tree at the run's position, a node a line in preorder, indented by depth:
    "  SE (1,2), expanded, 2 children"."""
    lines: list[str] = []
    stack = [(run.now.tree_root(), 0)]
    while stack and len(lines) < TREE_SAID:
        g, depth = stack.pop()
        kids = run.now.children(g)
        step = run.nodes.expanded_at(g)
        state = ("being expanded" if step == run.k and run.k else
                 "expanded" if step is not None and step <= run.k else "on the frontier")
        what = f", {len(kids)} {'child' if len(kids) == 1 else 'children'}" if len(kids) else ""
        lines.append(f"{'  ' * depth}{run.nodes.move(g)} {cell_text(run.nodes.cell(g))}, "
                     f"{state}{what}")
        stack.extend((h, depth + 1) for h in reversed(kids))
    size = run.now.tree_size()
    head = f"Search tree, {size} {'node' if size == 1 else 'nodes'}:"
    more = [f"and {size - len(lines)} more."] if size > len(lines) else []
    return [head, *lines, *more]
