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

The defaults are the tutorial's semantics.  A combination that makes no sense is refused by
:meth:`Semantics.check` with a one-line ``ValueError``.
"""

from __future__ import annotations

from tui_search.engine.maps.grid import DEFAULT_ORDER, DELTAS
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.registry import Algorithm
from tui_search.engine.util.frozen import Frozen

CORNER_RULES: tuple[str, ...] = ("always", "one", "never")
VISIT_RULES: tuple[str, ...] = ("generate", "expand")
GOAL_TESTS: tuple[str, ...] = ("generate", "expand")

#: One line per choice, for the settings screen and the help.
EXPLAIN: dict[str, str] = {
    "order": "the moves tried from a cell, in the order their successors are added",
    "corners": "may a diagonal squeeze past blocked cells beside it?",
    "visit": "when a cell counts as visited: when pushed, or when taken off and expanded",
    "goal_test": "stop when the goal is pushed, or when it is taken off the frontier",
    "tree_search": "no visited set: only cells on the node's own path are skipped",
    "heuristic": "greedy's and A*'s estimate of the cost from a cell to the goal",
}


class Semantics(Frozen):
    """Every choice that changes what a search does, with the tutorial's defaults.  A
    :class:`~tui_search.engine.util.frozen.Frozen` value (not a frozen dataclass, which every
    start would pay for: benchmarks/README.md, "startup");
    :meth:`~tui_search.engine.util.frozen.Frozen.replace` makes a changed copy."""

    __slots__ = _FIELDS = ("order", "corners", "visit", "goal_test", "tree_search", "heuristic")

    order: tuple[str, ...]
    corners: str
    visit: str
    goal_test: str | None  # None: the algorithm's own
    tree_search: bool
    heuristic: str

    def __init__(self, order: tuple[str, ...] = DEFAULT_ORDER, corners: str = "always",
                 visit: str = "generate", goal_test: str | None = None,
                 tree_search: bool = False, heuristic: str = DEFAULT_HEURISTIC) -> None:
        if not order or any(d not in DELTAS for d in order) or len(set(order)) != len(order):
            raise ValueError(f"bad move order {order!r}")
        for name, value, allowed in (
            ("corners", corners, CORNER_RULES),
            ("visit", visit, VISIT_RULES),
            ("goal test", goal_test or GOAL_TESTS[0], GOAL_TESTS),
            ("heuristic", heuristic, tuple(HEURISTICS)),
        ):
            if value not in allowed:
                raise ValueError(f"{name} {value!r}: use {', '.join(allowed)}")
        if tree_search and visit != "generate":
            raise ValueError("tree search has no visited set: the visit rule does not apply")
        self._assign(order=order, corners=corners, visit=visit, goal_test=goal_test,
                     tree_search=tree_search, heuristic=heuristic)

    def check(self, algorithm: Algorithm) -> None:
        """Refuse the combinations that make no sense for ``algorithm`` (``ValueError``)."""
        if algorithm.iterative and self.visit != "generate":
            raise ValueError(
                f"the visit rule does not apply to {algorithm.short} "
                "(it re-opens a cell reached at a smaller depth)"
            )
        if algorithm.weighted and self.visit != "generate":
            raise ValueError(
                f"the visit rule does not apply to {algorithm.short} "
                "(it re-opens a cell reached with a lower g)"
            )

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

    def differences(self, algorithm: Algorithm | None = None) -> list[str]:
        """What differs from the defaults (``algorithm``'s, when given), in a few words each
        ("visit on expand")."""
        out = []
        if self.order != DEFAULT_ORDER:
            out.append(f"moves {','.join(self.order)}")
        if self.corners != "always":
            out.append(f"corners: {self.corners}")
        if self.tree_search:
            out.append("tree search")
        elif self.visit != "generate":
            out.append(f"visit on {self.visit}")
        if self.goal_test is not None and (
            algorithm is None or self.goal_test != algorithm.goal_test
        ):
            out.append(f"goal test on {self.goal_test}")
        if self.heuristic != DEFAULT_HEURISTIC and (algorithm is None or algorithm.informed):
            out.append(f"heuristic {self.heuristic}")
        return out

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
        iterative deepening, the cost-ordered searches), the heuristic where none is used."""
        no_visit = self.tree_search or (
            algorithm is not None and (algorithm.iterative or algorithm.weighted))
        goal_test = self.goal_test_for(algorithm) if algorithm else self.goal_test or "generate"
        return {
            "order": list(self.order),
            "corners": self.corners,
            "visit": None if no_visit else self.visit,
            "goal_test": goal_test,
            "tree_search": self.tree_search,
            "heuristic": self.heuristic if algorithm is None or algorithm.informed else None,
        }


DEFAULT_SEMANTICS = Semantics()


def corner_allowed(corners: str, side_a_free: bool, side_b_free: bool) -> bool:
    """May a diagonal move pass between two side cells with these states?"""
    if corners == "always":
        return True
    if corners == "one":
        return side_a_free or side_b_free
    return side_a_free and side_b_free
