"""The search settings in plain mode: said in a sentence (the app's ``,``) and changed by a
typed line -- ``set order N,W,S,E``, ``set corners never``, ``set visit expand``,
``set goal-test expand``, ``set tree-search on``, ``set heuristic manhattan``,
``set compare bfs,ucs`` -- each checked as the app's settings screen checks it.
"""

from __future__ import annotations

from tui_search.engine.maps.grid import parse_order
from tui_search.engine.search.choices import (
    CORNER_RULES,
    EXPLAIN,
    GOAL_TESTS,
    VISIT_RULES,
    Semantics,
)
from tui_search.engine.search.compare import parse_compare
from tui_search.engine.search.heuristics import HEURISTICS
from tui_search.engine.search.registry import get_algorithm
from tui_search.tui.model.searches import normal_spec, searches_of
from tui_search.tui.model.session import Session

#: What ``set`` takes: the name typed, the choice's field, and what it may be.
SETTINGS = {
    "order": ("order", "the moves, e.g. N,W,S,E"),
    "corners": ("corners", " or ".join(CORNER_RULES)),
    "visit": ("visit", " or ".join(VISIT_RULES)),
    "goal-test": ("goal_test", " or ".join((*GOAL_TESTS, "default"))),
    "tree-search": ("tree_search", "on or off"),
    "heuristic": ("heuristic", " or ".join(HEURISTICS)),
    "compare": ("compare", "two to four searches, e.g. bfs,dfs"),
}


def settings_lines(session: Session) -> list[str]:
    """The settings in force, a line each, and how to change one."""
    sem = session.semantics
    algorithm = get_algorithm(session.contenders[0].algorithm if session.contenders
                              else session.algorithm)
    goal = sem.goal_test or f"the search's own ({algorithm.goal_test})"
    compared = ", ".join(c.label for c in parse_compare(session.comparison, sem))
    return [
        f"Settings ({'; '.join(sem.differences()) or 'the tutorial' + chr(39) + 's'}):",
        f"order {','.join(sem.order)}: {EXPLAIN['order']}.",
        f"corners {sem.corners}: {EXPLAIN['corners']}",
        f"visit {sem.visit}: {EXPLAIN['visit']}.",
        f"goal-test {goal}: {EXPLAIN['goal_test']}.",
        f"tree-search {'on' if sem.tree_search else 'off'}: {EXPLAIN['tree_search']}.",
        f"heuristic {sem.heuristic}: {EXPLAIN['heuristic']}.",
        f"compare {session.comparison}: c compares {compared}.",
        "Change one with set NAME VALUE, for example set order N,W,S,E.",
    ]


def apply_setting(session: Session, name: str, value: str) -> str:
    """``set NAME VALUE`` on the session; what changed, or why nothing did (one line)."""
    if name not in SETTINGS:
        return f"No setting {name!r}: set takes {', '.join(SETTINGS)}."
    field, allowed = SETTINGS[name]
    if not value:
        return f"set {name} needs a value: {allowed}."
    try:
        if field == "compare":
            spec = normal_spec(value.lower())
            searches_of(spec, session.semantics)
            session.choose_settings(session.semantics, spec)
            return f"c now compares {spec}."
        sem = _changed(session.semantics, field, value)
        shown = [get_algorithm(c.algorithm) for c in session.contenders]
        if field == "visit" and shown and all(a.iterative or a.weighted for a in shown):
            names = " or ".join(a.short for a in shown)
            raise ValueError(f"the visit rule does not apply to {names}")
        searches_of(session.spec, sem)  # what the app's screen refuses, refused
    except ValueError as exc:
        return f"Not changed: {exc}."
    if sem == session.semantics:
        return f"{name} is {value} already."
    session.choose_settings(sem, session.comparison)
    return f"{name} is now {value}: the searches start again from step 0."


def _changed(sem: Semantics, field: str, value: str) -> Semantics:
    """``sem`` with ``field`` set from the typed ``value`` (a ValueError saying why not)."""
    text = value.strip().lower()
    if field == "order":
        return sem.replace(order=parse_order(value))
    if field == "tree_search":
        if text not in ("on", "off"):
            raise ValueError("tree-search is on or off")
        on = text == "on"
        return sem.replace(tree_search=on, visit="generate" if on else sem.visit)
    if field == "goal_test":
        if text not in (*GOAL_TESTS, "default"):
            raise ValueError(f"goal-test is {', '.join(GOAL_TESTS)} or default")
        return sem.replace(goal_test=None if text == "default" else text)
    if field == "visit" and sem.tree_search:
        raise ValueError("tree search has no visited set: set tree-search off first")
    return sem.replace(**{field: text})
