"""The pseudocode of a search, generated from its algorithm and its choices, in the textbook's
plain words, one numbered line per line.

Nothing here is a fixed text per algorithm: the frontier's name and its operations come from
the registry (:mod:`tui_search.engine.search.registry`: a queue's "push back" and "pop front", a
stack's "push" and "pop", a priority queue's order by f = g + h, g or h; weighted A*'s by
f = g + W·h), and each search choice (:mod:`tui_search.engine.search.choices`) puts, moves or
removes its own lines: the visit rule moves the visited check below the take-off, the goal
test moves the goal check, tree search trades the visited set for the check "on the path", a
corner rule adds its line, and iterative deepening wraps it all in its loop over depth
limits (IDA*: over limits on f, each the smallest f cut off the time before).  So a student
who flips a choice sees which line moved.

The code says what :mod:`tui_search.engine.search.reference` does, in its order.  Each line has a
``kind``, a name for what it does ("take", "reached", "push" ...), which stays the same
whichever words say it: the app lights lines by kind (:mod:`tui_search.tui.view.code_trace`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from tui_search.engine.search.choices import TIE_WORDS, Semantics, order_words
from tui_search.engine.search.heuristics import CHEAPER_BY
from tui_search.engine.search.registry import Algorithm

#: What a move costs, as the line that adds it to g says it.  Terrain costs land here: the
#: engine's cost of a move, in words (a keyword of :func:`pseudocode`).
MOVE_COST = "the move's cost (1 straight, √2 diagonal)"
#: The same on a map with terrain (a move costs its length times the cost of the cell it enters).
TERRAIN_MOVE_COST = "the move's length (1 straight, √2 diagonal) × the cost of the cell it enters"

#: The lines that may skip a successor, and the lines that end a step early, by kind.
SKIP_KINDS = ("blocked", "corner", "closed", "reached", "on_path")

_CORNER_WORDS = {
    "one": "if s is diagonal between two obstacles (corner rule one): skip s",
    "never": "if s is diagonal past an obstacle's corner (corner rule never): skip s",
}


@dataclass(frozen=True)
class CodeLine:
    """One line of pseudocode: what it does (``kind``), its depth of indentation and its
    words."""

    kind: str
    indent: int
    text: str


@dataclass(frozen=True)
class Pseudocode:
    """A search's pseudocode: its lines in order (numbered from 1)."""

    title: str
    lines: tuple[CodeLine, ...]

    def number(self, kind: str) -> int | None:
        """The number of the line of ``kind`` (None: this code has none)."""
        for i, line in enumerate(self.lines, 1):
            if line.kind == kind:
                return i
        return None

    def numbers(self, kinds: frozenset[str] | set[str]) -> frozenset[int]:
        """The numbers of the lines of ``kinds`` (those this code has)."""
        return frozenset(i for i, line in enumerate(self.lines, 1) if line.kind in kinds)

    def numbered(self, indent: str = "    ") -> list[str]:
        """The lines as printed for a handout: "  7      if s is already visited: skip s"."""
        width = len(str(len(self.lines)))
        return [f"{i:>{width}}  {indent * line.indent}{line.text}"
                for i, line in enumerate(self.lines, 1)]


def pseudocode(algorithm: Algorithm, semantics: Semantics, *,
               move_cost: str = MOVE_COST) -> Pseudocode:
    """The pseudocode of ``algorithm`` under ``semantics`` (``move_cost``: how the line that
    adds a move's cost to g says it)."""
    return _generate(algorithm, semantics, move_cost)


def _marks(tree: bool, weighted: bool, iterative: bool, on_expand: bool, start: bool = True
           ) -> tuple[str, str] | None:
    """What pushing START and pushing a successor record: the best g, the depth reached, or
    "visited"; None when a push records nothing (tree search, visit on expand).  START's is
    "" when the start is left unmarked."""
    if tree or on_expand:
        return None
    if weighted:
        marks = "best g[START] ← 0", "best g[s] ← g"
    elif iterative:
        marks = "mark START reached at depth 0", "mark s reached at depth node's + 1"
    else:
        marks = "mark START visited", "mark s visited"
    return marks if start else ("", marks[1])


def _reached_line(algorithm: Algorithm, semantics: Semantics, recursive: bool = False
                  ) -> tuple[str, str] | None:
    """The line that skips a successor reached already, as ``(kind, text)``; None for tree
    search with no path check (it skips nothing)."""
    if semantics.tree_search:
        if not semantics.path_check:
            return None
        return "on_path", "if s is on the path from START to node: skip s"
    if algorithm.weighted:
        tolerance = semantics.cost_tolerance
        if tolerance == 0:
            return "reached", "if best g[s] ≤ g (compared exactly): reached as cheaply, skip s"
        if tolerance != CHEAPER_BY:
            return "reached", f"if best g[s] ≤ g + {tolerance:g}: reached as cheaply, skip s"
        return "reached", "if best g[s] ≤ g: reached as cheaply, skip s"
    if algorithm.iterative:
        return "reached", "if s was reached at depth ≤ node's + 1: skip s"
    if recursive and semantics.recursive == "calls":
        return "reached", "if s is already visited (maybe by an earlier call): skip s"
    return "reached", "if s is already visited: skip s"


def _successor_lines(algorithm: Algorithm, semantics: Semantics, move_cost: str,
                     marks: tuple[str, str] | None, goal_test: str
                     ) -> list[tuple[str, int, str]]:
    """The loop over a node's successors, as ``(kind, indent, text)``: the checks that skip
    one, its push, what the push records and the goal test on push."""
    weighted = algorithm.weighted
    out = [("for", 1, f"for each successor s of node, moves in order {order_words(semantics)}:"),
           ("blocked", 2, "if s is off the map or an obstacle: skip s")]
    if semantics.corners in _CORNER_WORDS:
        out.append(("corner", 2, _CORNER_WORDS[semantics.corners]))
    if weighted and not semantics.reopen and not semantics.tree_search:
        out.append(("closed", 2, "if s is closed (expanded already): skip s"))
    if weighted:
        out.append(("cost", 2, f"g ← node.g + {move_cost}"))
    reached = _reached_line(algorithm, semantics)
    if reached is not None:
        out.append((reached[0], 2, reached[1]))
    by = semantics.priority_words(algorithm)
    out.append(("push", 2, algorithm.frontier.push_words(by)))
    if marks:
        out.append(("mark_succ", 2, marks[1]))
    if goal_test == "generate":
        out.append(("goal_succ", 2, "goal test: if s is the goal, return its path"))
    return out


@lru_cache(maxsize=64)
def _generate(algorithm: Algorithm, semantics: Semantics, move_cost: str) -> Pseudocode:
    if algorithm.bidirectional:
        from tui_search.engine.search.bidirectional.pseudo import bidirectional_lines

        return Pseudocode(_title(algorithm, semantics), tuple(CodeLine(*line) for line in (
            bidirectional_lines(algorithm, semantics, move_cost))))
    if semantics.recursive:
        from tui_search.engine.search.pseudocode_recursive import recursive_lines

        title = _title(algorithm, semantics)
        return Pseudocode(title, tuple(CodeLine(*line) for line in recursive_lines(
            algorithm, semantics, _reached_line(algorithm, semantics, recursive=True))))
    lines: list[CodeLine] = []
    tree = semantics.tree_search
    weighted = algorithm.weighted
    iterative = algorithm.iterative
    on_expand = semantics.visit != "generate" and not tree and not weighted and not iterative
    goal_test = semantics.goal_test_for(algorithm)
    frontier = algorithm.frontier
    order_name = algorithm.priority_name
    by = semantics.priority_words(algorithm)  # weighted A*'s: f = g + W·h
    order_by = f"{by}, h = {semantics.heuristic} distance" if algorithm.informed else by

    def add(kind: str, indent: int, text: str) -> None:
        lines.append(CodeLine(kind, base + indent, text))

    contours = algorithm.contours
    deepening = _deepening(algorithm, order_by)
    lines += [CodeLine(*line) for line in deepening]
    base = 1 if deepening else 0
    holding = f"a {frontier.noun} by {order_by}, holding START" if algorithm.queued else (
        f"a {frontier.noun} holding START")
    add("init", 0, f"frontier ← {holding}")
    # what a push records, if anything
    marks = _marks(tree, weighted, iterative, on_expand, semantics.mark_start)
    if marks and marks[0]:
        add("mark_start", 0, marks[0])
    if goal_test == "generate":
        add("goal_start", 0, "goal test: if START is the goal, return its path")
    add("while", 0, "while the frontier is not empty:")
    ties = f"; of a tie, the {TIE_WORDS[semantics.ties].replace(' first', '')}" if (
        semantics.ties != "fifo") else ""
    add("take", 1, f"node ← {frontier.take_words(order_name)}{ties}")
    if on_expand:
        if semantics.visit == "expand":
            add("discard", 1, "if node is already visited: discard it, go on")
        add("mark_node", 1, "mark node visited")
    elif weighted and not tree and not semantics.reopen:
        add("discard", 1, "if node is closed (expanded already): discard it, go on")
        add("close_node", 1, "close node (never push it again); node.g ← best g[node]")
    elif weighted and not tree and not contours:
        add("discard", 1, "if node.g > best g[node]: stale, discard it, go on")
    if contours:
        add("cutoff", 1, "if node.f > limit: next ← min(next, node.f); cut off, go on")
    if goal_test == "expand":
        add("goal_node", 1, "goal test: if node is the goal, return its path")
    if iterative and not contours:
        add("cutoff", 1, "if node's depth = the depth limit: cut off, go on")
    for kind, indent, text in _successor_lines(algorithm, semantics, move_cost, marks, goal_test):
        add(kind, indent, text)
    for kind, indent, text in _ends(algorithm):
        add(kind, indent, text)
    return Pseudocode(_title(algorithm, semantics), tuple(lines))


def _deepening(algorithm: Algorithm, order_by: str) -> list[tuple[str, int, str]]:
    """The loop an iterative search wraps around the rest (its lines from indent 0; the
    last, and the rest, one deeper); none for the others."""
    if algorithm.contours:
        return [("limit_init", 0, f"limit ← f of START ({order_by})"), ("deepen", 0, "repeat:"),
                ("next_init", 1, "next ← ∞ (the smallest f cut off)")]
    if algorithm.iterative:
        return [("deepen", 0, "for depth limit ← 0, 1, 2, …:")]
    return []


def _ends(algorithm: Algorithm) -> list[tuple[str, int, str]]:
    """The lines after the loop over the frontier: no path, or the next iteration."""
    if algorithm.contours:
        return [("fail", 0, "if next = ∞ (nothing was cut off): return no path"),
                ("next_limit", 0, "limit ← next")]
    if algorithm.iterative:
        return [("fail", 0, "if nothing was cut off at the limit: return no path")]
    return [("fail", 0, "return no path")]


def _title(algorithm: Algorithm, semantics: Semantics) -> str:
    """"BFS: Breadth-first search (visit on expand)": the search and what differs."""
    title = f"{algorithm.short}: {algorithm.name}"
    differences = semantics.for_algorithm(algorithm).differences(algorithm)
    if differences:
        title += f" ({', '.join(differences)})"
    return title


__all__ = ["MOVE_COST", "SKIP_KINDS", "CodeLine", "Pseudocode", "pseudocode"]
