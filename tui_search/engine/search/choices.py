"""The search choices that textbooks, courses and the peers quietly disagree on, as one value.

* ``order``: the moves tried from a cell, in the order their successors are generated -- any
  ordered, non-empty subset of the eight directions (``N,W,S,E`` is the 4-connected grid).
* ``corners``: may a diagonal pass blocked corners?  ``always`` (the tutorial's SE node has an NE
  successor beside an obstacle); ``one``: refused when *both* side cells are blocked;
  ``never``: refused when *either* is blocked (MovingAI's rule).
* ``visit``: when a cell counts as visited.  ``generate``: when it is pushed, so it is never
  pushed twice; ``expand``: when it is taken off and expanded, so a cell may sit on the frontier
  several times, and taking off a cell already expanded is a *discarded* step.
* ``goal_test``: ``generate`` stops as soon as the goal is pushed; ``expand`` when it is taken
  off the frontier (that step counts as expanded).  ``None`` is the algorithm's own
  (:attr:`~tui_search.engine.search.registry.Algorithm.goal_test`): on generation for BFS, DFS and
  iterative deepening, on expansion for the cost-ordered searches.
* ``tree_search``: no visited set at all; a successor is skipped only when it lies on the path
  from the root to the node being expanded.  ``visit`` does not apply.
* ``heuristic``: greedy best-first's and A*'s estimate of the cost to the goal
  (:mod:`tui_search.engine.search.heuristics`); the other searches use none.
* ``weight``: weighted A*'s W, 1 or more: the priority is f = g + W·h, and with an
  admissible h the path costs at most W times the optimum.  1 (the default) is A* itself, the
  very same floats; A* only.
* ``stop``: when a bidirectional search stops
  (:mod:`~tui_search.engine.search.bidirectional.loop`): ``proven`` once its best meeting is
  proven the cheapest, ``first-meeting`` as soon as the two searches reach a cell in common
  (the trap: not the cheapest path, for costs).
* ``turn``: whose step a bidirectional search takes next: ``alternate`` (forward, backward,
  forward, ...) or ``smaller`` (the search whose frontier is smaller; forward on a tie).

On a graph (:mod:`tui_search.engine.search.space`), ``order`` is one word of
:data:`GRAPH_ORDERS` (``file``: the roads as the file lists them; ``name``: by the names they
reach), ``heuristic`` ``table`` (the file's ``h`` lines), ``euclidean`` (by the nodes' places)
or ``zero``, and ``corners`` does not apply.

What published code and students' code differ on besides (docs/08-semantics.md):

* ``visit`` ``expand-again``: a cell is marked visited when taken off, but the node taken off
  is never checked, so a cell on the frontier twice is expanded twice (the commonest bug).
* ``ties``: which entry of a priority queue's tie comes out first: ``fifo`` the oldest,
  ``lifo`` the newest, ``node`` the smallest cell (x, then y: ``heapq`` on ``(f, (x, y))``
  tuples), ``low-h``/``high-h`` the lower/higher h, ``low-g``/``high-g`` the lower/higher g;
  then the oldest.  Uniform-cost, greedy and A* only (h ties: greedy and A*; g ties: not
  uniform-cost, whose priority is g).
* ``cost_tolerance``: how much lower a new g must be to count as cheaper (the default
  ``CHEAPER_BY``; 0: compared exactly, as code comparing floats with ``<`` does).
* ``reopen``: may a cost-ordered search push a cell it has expanded again, for a lower g?
  False: a closed set, as much published greedy and A* code keeps.
* ``recursive``: DFS or iterative deepening written as recursion: ``neighbours`` (a line lists
  the neighbours not yet visited on entry; the recursion skips those visited meanwhile) or
  ``calls`` (a line lists the cells the call recursed into); "" a stack.
* ``path_check``: tree search skips a successor on the node's own path (False: skips nothing,
  not even the parent, as textbook tree-search code).
* ``mark_start``: is the start marked reached when it is pushed?  False: it can be pushed
  again, as some library code does.
* ``flip_even``: the order reversed on every other cell, those whose x + y is even (a grid's
  only), as a popular tutorial's grid does so that a straight path zigzags rather than bends
  once (Red Blob Games' "Implementation of A*": east, west, north, south, reversed there).

The defaults are the tutorial's semantics.  A combination that makes no sense is refused by
:meth:`Semantics.check` with a one-line ``ValueError``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import DEFAULT_ORDER, DELTAS
from tui_search.engine.search.heuristics import CHEAPER_BY, DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.registry import PRIORITIES, Algorithm, Frontier
from tui_search.engine.util.frozen import Frozen

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph

CORNER_RULES: tuple[str, ...] = ("always", "one", "never")
#: A graph's orders of successors (one word, alone): its roads as the file lists them, or by
#: the names they reach.
GRAPH_ORDERS: tuple[str, ...] = ("file", "name")
#: The estimate a graph gives in its file (its ``h`` lines); the others are worked out.
TABLE = "table"
#: The heuristics a graph may use: its table, the straight line between places, or none.
GRAPH_HEURISTICS: tuple[str, ...] = (TABLE, "euclidean", "zero")


def graph_heuristics(graph: Graph) -> list[str]:
    """The heuristics ``graph`` can give, its default first: its table when it has one, the
    straight line when its nodes have places, and zero."""
    return [h for h in GRAPH_HEURISTICS
            if (h != TABLE or graph.has_table) and (h != "euclidean" or graph.has_places)]
VISIT_RULES: tuple[str, ...] = ("generate", "expand", "expand-again")
GOAL_TESTS: tuple[str, ...] = ("generate", "expand")
TIE_RULES: tuple[str, ...] = ("fifo", "lifo", "node", "low-h", "high-h", "low-g", "high-g")
RECURSIVE_FORMS: tuple[str, ...] = ("neighbours", "calls")
#: A bidirectional search's stopping rules (the first is the default).
STOP_RULES: tuple[str, ...] = ("proven", "first-meeting")
#: Whose step a bidirectional search takes next (the first is the default).
TURN_RULES: tuple[str, ...] = ("alternate", "smaller")
#: The tie rules, in the words a student would say them.
TIE_WORDS: dict[str, str] = {
    "fifo": "oldest first", "lifo": "newest first", "node": "smallest cell first",
    "low-h": "lower h first", "high-h": "higher h first", "low-g": "lower g first",
    "high-g": "higher g first",
}

#: One line per choice, for the settings screen and the help.
EXPLAIN: dict[str, str] = {
    "order": "the moves tried from a cell, in the order their successors are added",
    "corners": "may a diagonal squeeze past blocked cells beside it?",
    "visit": "when a cell counts as visited: when pushed, or when taken off and expanded",
    "goal_test": "stop when the goal is pushed, or when it is taken off the frontier",
    "tree_search": "no visited set: only cells on the node's own path are skipped",
    "heuristic": "greedy's and A*'s estimate of the cost from a cell to the goal",
    "ties": "which entry of a priority tie comes out first",
    "cost_tolerance": "how much lower a new g must be to count as cheaper (0: exactly)",
    "reopen": "may a cell expanded be pushed again, reached with a lower g?",
    "recursive": "DFS as recursion: a line lists the unvisited neighbours, or the calls made",
    "path_check": "tree search skips the cells on the node's own path (off: skips nothing)",
    "mark_start": "is the start marked reached when pushed (off: it can be pushed again)?",
    "weight": "weighted A*: f = g + W·h, a path at most W × the optimum (1: A*)",
    "flip_even": "the order reversed on every other cell (x + y even), as some tutorials' grids",
    "stop": "bidirectional: stop once the best meeting is proven, or at the first meeting",
    "turn": "bidirectional: a step each in turn, or the smaller frontier's step next",
}

def weight_text(weight: float) -> str:
    """A weight as a student writes it: "2", "1.5"."""
    return f"{weight:g}"


def check_weight(weight: float | str) -> float:
    """``weight`` (a number, or typed) as a float, or a one-line ``ValueError``: a number 1
    or more (not inf, not NaN)."""
    try:
        value = float(weight)
    except (TypeError, ValueError):
        raise ValueError(f"weight {weight!r}: a number 1 or more") from None
    if not (1.0 <= value < float("inf")):  # NaN fails too
        raise ValueError(f"weight {weight!r}: a number 1 or more (f = g + W·h)")
    return value


class Semantics(Frozen):
    """Every choice that changes what a search does, with the tutorial's defaults.  A
    :class:`~tui_search.engine.util.frozen.Frozen` value (not a frozen dataclass, which every
    start would pay for: benchmarks/README.md, "startup");
    :meth:`~tui_search.engine.util.frozen.Frozen.replace` makes a changed copy."""

    __slots__ = _FIELDS = ("order", "corners", "visit", "goal_test", "tree_search", "heuristic",
                           "ties", "cost_tolerance", "reopen", "recursive", "path_check",
                           "mark_start", "weight", "flip_even", "stop", "turn")

    order: tuple[str, ...]
    corners: str
    visit: str
    goal_test: str | None  # None: the algorithm's own
    tree_search: bool
    heuristic: str
    ties: str
    cost_tolerance: float
    reopen: bool
    recursive: str  # "": a stack
    path_check: bool
    mark_start: bool
    weight: float  # weighted A*'s W (1: A*)
    flip_even: bool  # the order reversed on cells whose x + y is even
    stop: str  # a bidirectional search's stopping rule
    turn: str  # whose step a bidirectional search takes next

    def __init__(self, order: tuple[str, ...] = DEFAULT_ORDER, corners: str = "always",
                 visit: str = "generate", goal_test: str | None = None,
                 tree_search: bool = False, heuristic: str = DEFAULT_HEURISTIC,
                 ties: str = "fifo", cost_tolerance: float = CHEAPER_BY, reopen: bool = True,
                 recursive: str = "", path_check: bool = True, mark_start: bool = True,
                 weight: float = 1.0, flip_even: bool = False, stop: str = STOP_RULES[0],
                 turn: str = TURN_RULES[0]) -> None:
        graph_order = len(order) == 1 and order[0] in GRAPH_ORDERS
        if not graph_order and (not order or any(d not in DELTAS for d in order)
                                or len(set(order)) != len(order)):
            raise ValueError(f"bad move order {order!r}")
        for name, value, allowed in (
            ("corners", corners, CORNER_RULES),
            ("visit", visit, VISIT_RULES),
            ("goal test", goal_test or GOAL_TESTS[0], GOAL_TESTS),
            ("heuristic", heuristic, (*HEURISTICS, TABLE)),
            ("ties", ties, TIE_RULES),
            ("recursive", recursive or RECURSIVE_FORMS[0], RECURSIVE_FORMS),
            ("stopping rule", stop, STOP_RULES),
            ("turn", turn, TURN_RULES),
        ):
            if value not in allowed:
                raise ValueError(f"{name} {value!r}: use {', '.join(allowed)}")
        if not (cost_tolerance >= 0 and cost_tolerance != float("inf")):  # NaN fails too
            raise ValueError(f"cost tolerance {cost_tolerance!r}: a number 0 or more")
        weight = check_weight(weight)
        if flip_even and graph_order:
            raise ValueError("the order reversed on every other cell is a grid's: a graph's "
                             "successors come in the file's order or by name")
        if tree_search and visit != "generate":
            raise ValueError("tree search has no visited set: the visit rule does not apply")
        if recursive and visit != "generate":
            raise ValueError("a recursive search visits a cell when it enters it: the visit "
                             "rule does not apply")
        if not path_check and not tree_search:
            raise ValueError("the path check is tree search's: graph search has a visited set")
        if not mark_start and (tree_search or recursive or visit != "generate"):
            raise ValueError("only a search that marks what it pushes can leave the start "
                             "unmarked")
        self._assign(order=order, corners=corners, visit=visit, goal_test=goal_test,
                     tree_search=tree_search, heuristic=heuristic, ties=ties,
                     cost_tolerance=float(cost_tolerance), reopen=reopen, recursive=recursive,
                     path_check=path_check, mark_start=mark_start, weight=weight,
                     flip_even=bool(flip_even), stop=stop, turn=turn)

    def check(self, algorithm: Algorithm) -> None:
        """Refuse the combinations that make no sense for ``algorithm`` (``ValueError``)."""
        why = self.refusal(algorithm)
        if why:
            raise ValueError(why)

    def refusal(self, algorithm: Algorithm) -> str:
        """Why these choices make no sense for ``algorithm`` ("" when they do)."""
        name = algorithm.short
        if algorithm.bidirectional and self._both_ways_refusal(name):
            return self._both_ways_refusal(name)
        if algorithm.iterative and self.visit != "generate":
            return (f"the visit rule does not apply to {name} (it re-opens a cell reached at "
                    "a smaller depth)")
        if algorithm.weighted and self.visit != "generate":
            return (f"the visit rule does not apply to {name} (it re-opens a cell reached with "
                    "a lower g)")
        if not algorithm.queued:
            for field, words in (("ties", "ties"), ("cost_tolerance", "the cost tolerance"),
                                 ("reopen", "re-opening")):
                if getattr(self, field) != getattr(DEFAULT_SEMANTICS, field):
                    return (f"{words} apply to a priority queue's search (UCS, greedy, A*), "
                            f"not {name}")
        if self.ties in ("low-h", "high-h") and not algorithm.informed:
            return f"ties on h apply to greedy and A*, not {name} (it uses no h)"
        if self.ties in ("low-g", "high-g") and algorithm.priority == "g":
            return f"ties on g do not apply to {name}: its priority is g itself"
        if self.recursive and (algorithm.frontier is not Frontier.LIFO or algorithm.contours):
            return f"recursion is a depth-first search's (DFS, IDDFS), not {name}'s"
        if self.weight != 1.0 and (algorithm.priority != "g+h" or algorithm.bidirectional):
            return f"a weight applies to A* and IDA* (f = g + W·h), not {name}"
        if (self.stop, self.turn) != (STOP_RULES[0], TURN_RULES[0]) and not (
                algorithm.bidirectional):
            return f"a stopping rule or a turn applies to a bidirectional search, not {name}"
        return ""

    def _both_ways_refusal(self, name: str) -> str:
        """Why a bidirectional search cannot run under these choices ("" when it can)."""
        if self.tree_search or self.recursive:
            return f"{name} is a graph search: no tree search, no recursion"
        if self.goal_test is not None:
            return f"{name} stops when its two searches meet: no goal test applies"
        if self.visit != "generate":
            return f"{name} marks a cell reached when pushed: the visit rule does not apply"
        if not self.plain:
            return (f"{name} runs under the plain choices (ties oldest first, re-opening, "
                    "the start marked, the default cost tolerance, one order everywhere)")
        return ""

    def fitted(self, algorithm: Algorithm) -> Semantics:
        """These choices with those that do not apply to ``algorithm`` put back to their
        defaults (the app's settings apply to every pane where they can)."""
        out = self
        if algorithm.iterative or algorithm.weighted:
            out = out.replace(visit="generate")
        if algorithm.bidirectional:
            out = out.replace(visit="generate", tree_search=False, path_check=True,
                              goal_test=None, recursive="", mark_start=True, ties="fifo",
                              cost_tolerance=CHEAPER_BY, reopen=True, flip_even=False)
        if not algorithm.queued:
            out = out.replace(ties="fifo", cost_tolerance=CHEAPER_BY, reopen=True)
        if out.ties in ("low-h", "high-h") and not algorithm.informed:
            out = out.replace(ties="fifo")
        if out.ties in ("low-g", "high-g") and algorithm.priority == "g":
            out = out.replace(ties="fifo")
        if (algorithm.frontier is not Frontier.LIFO or algorithm.contours) and out.recursive:
            out = out.replace(recursive="")
        if (algorithm.priority != "g+h" or algorithm.bidirectional) and out.weight != 1.0:
            out = out.replace(weight=1.0)
        if not algorithm.bidirectional:
            out = out.replace(stop=STOP_RULES[0], turn=TURN_RULES[0])
        return out

    def goal_test_for(self, algorithm: Algorithm) -> str:
        """The goal test in force for ``algorithm``: the one chosen, or the algorithm's own."""
        return self.goal_test or algorithm.goal_test

    def for_algorithm(self, algorithm: Algorithm) -> Semantics:
        """The same choices with a goal test equal to ``algorithm``'s own written as None, so
        that what differs from its defaults is what :meth:`differences` names."""
        if self.goal_test == algorithm.goal_test:
            return self.replace(goal_test=None)
        return self

    @property
    def is_default(self) -> bool:
        return self == Semantics()

    @property
    def plain(self) -> bool:
        """Are the choices published code differs on all at their defaults (none of ties,
        cost tolerance, re-opening, recursion, no path check, an unmarked start, visit
        expand-again, an order reversed on every other cell)?  The compiled core and the fast
        loops serve these."""
        return (self.ties == "fifo" and self.cost_tolerance == CHEAPER_BY and self.reopen
                and not self.recursive and self.path_check and self.mark_start
                and self.visit != "expand-again" and not self.flip_even)

    def differences(self, algorithm: Algorithm | None = None) -> list[str]:
        """What differs from the defaults (``algorithm``'s, when given), in a few words each
        ("visit on expand")."""
        out = []
        graph = self.order[0] in GRAPH_ORDERS  # a graph's: file order and its table by default
        if graph and self.order != GRAPH_ORDERS[:1]:
            out.append(f"successors by {self.order[0]}")
        elif not graph and self.order != DEFAULT_ORDER:
            out.append(f"moves {','.join(self.order)}")
        if self.flip_even:
            out.append(FLIP_WORDS)
        if self.corners != "always":
            out.append(f"corners: {self.corners}")
        if self.recursive:
            out.append(f"recursive ({RECURSIVE_WORDS[self.recursive]})")
        if self.tree_search:
            out.append("tree search" if self.path_check else "tree search, no path check")
        elif self.visit != "generate":
            out.append(VISIT_WORDS[self.visit])
        if self.goal_test is not None and (
            algorithm is None or self.goal_test != algorithm.goal_test
        ):
            out.append(f"goal test on {self.goal_test}")
        if (self.heuristic != (TABLE if graph else DEFAULT_HEURISTIC)
                and (algorithm is None or algorithm.informed)):
            out.append(f"heuristic {self.heuristic}")
        if self.weight != 1.0 and (algorithm is None or algorithm.priority == "g+h"):
            out.append(f"weight {weight_text(self.weight)}")
        if self.stop != STOP_RULES[0] and (algorithm is None or algorithm.bidirectional):
            out.append("stop at the first meeting")
        if self.turn != TURN_RULES[0] and (algorithm is None or algorithm.bidirectional):
            out.append("the smaller frontier first")
        out += self.published_words()
        return out

    def published_words(self) -> list[str]:
        """The choices of published code that are not the defaults, in a student's words:
        "ties: smallest cell first", "no re-opening", "exact costs", "start not marked"."""
        out = []
        if self.ties != "fifo":
            out.append(f"ties: {TIE_WORDS[self.ties]}")
        if not self.reopen:
            out.append("no re-opening")
        if self.cost_tolerance != CHEAPER_BY:
            out.append("exact costs" if self.cost_tolerance == 0
                       else f"cost tolerance {self.cost_tolerance:g}")
        if not self.mark_start:
            out.append("start not marked")
        return out

    def priority_words(self, algorithm: Algorithm) -> str:
        """What ``algorithm``'s priority queue orders by, in the textbook's words: "f = g +
        h", weighted A*'s "f = g + 2·h", "g", "h" ("" for none)."""
        words = PRIORITIES.get(algorithm.priority or "", "")
        if algorithm.priority == "g+h" and self.weight != 1.0:
            return f"f = g + {weight_text(self.weight)}·h"
        return words

    @property
    def branching(self) -> int:
        """The most successors a node can have: the number of moves."""
        return len(self.order)

    def bound(self, depth: int) -> int:
        """The tutorial's bound on nodes generated to reach depth ``d``: ``(b-1)^(d+1)`` with
        ``b`` moves (``7^(d+1)`` for eight; one move leads back where the node came from)."""
        nodes: int = max(1, self.branching - 1) ** (depth + 1)  # int ** int types as Any
        return nodes

    def as_json(self, algorithm: Algorithm | None = None) -> dict[str, object]:
        """Every choice by name; the visit rule is null where it does not apply (tree search,
        recursion, iterative deepening, the cost-ordered searches), the heuristic where none
        is used, the priority queue's choices where there is none, and the weight but for
        A*."""
        no_visit = self.tree_search or bool(self.recursive) or (
            algorithm is not None and (algorithm.iterative or algorithm.weighted))
        goal_test: str | None = (self.goal_test_for(algorithm) if algorithm
                                 else self.goal_test or "generate")
        if algorithm is not None and algorithm.bidirectional:
            goal_test = None  # its two searches meet: no goal test
        queue = algorithm is None or algorithm.queued
        return {
            "order": list(self.order),
            "corners": None if self.order[0] in GRAPH_ORDERS else self.corners,  # a grid's
            "visit": None if no_visit else self.visit,
            "goal_test": goal_test,
            "tree_search": self.tree_search,
            "heuristic": self.heuristic if algorithm is None or algorithm.informed else None,
            "ties": self.ties if queue else None,
            "cost_tolerance": self.cost_tolerance if queue else None,
            "reopen": self.reopen if queue else None,
            "recursive": self.recursive or None,
            "path_check": self.path_check if self.tree_search else None,
            "mark_start": self.mark_start,
            "weight": self.weight if algorithm is None or algorithm.priority == "g+h" else None,
            "flip_even": None if self.order[0] in GRAPH_ORDERS else self.flip_even,
            **({"stop": self.stop, "turn": self.turn}
               if algorithm is not None and algorithm.bidirectional else {}),
        }


#: The order reversed on every other cell, in a few words.
FLIP_WORDS = "reversed where x + y is even"


def order_words(semantics: Semantics) -> str:
    """The moves' order in a student's words: "N,E,S,W", "E,W,N,S, reversed where x + y is
    even"."""
    flipped = f", {FLIP_WORDS}" if semantics.flip_even else ""
    return f"{','.join(semantics.order)}{flipped}"

#: The visit rules, and the recursive forms, in a few words.
VISIT_WORDS = {"generate": "visit on generate", "expand": "visit on expand",
               "expand-again": "visit on expand, expanded again"}
RECURSIVE_WORDS = {"neighbours": "a line lists the neighbours", "calls": "a line lists the calls"}


DEFAULT_SEMANTICS = Semantics()


def corner_allowed(corners: str, side_a_free: bool, side_b_free: bool) -> bool:
    """May a diagonal move pass between two side cells with these states?"""
    if corners == "always":
        return True
    if corners == "one":
        return side_a_free or side_b_free
    return side_a_free and side_b_free
