"""The choices of a course in one word (``--preset cs188``, and the settings screen's button).

``cs188``: Berkeley CS188's Pacman search project, as its problems and its ``util`` module
behave.  Four moves, a cell's successors generated north, south, east, west (the course's
``getSuccessors``: y grows northwards there, as up the screen here); every move costs 1;
graph search, a state counted as visited when it is expanded, the goal tested when a state is
taken off the frontier (a getSuccessors call is an expansion: the goal's is never made); a
priority queue's ties the oldest entry first (its ``PriorityQueue`` orders ``(priority, count,
item)``) and a closed set (a state expanded is never expanded again); A*'s and greedy's
estimate the Manhattan distance (the course's ``manhattanHeuristic``).  The cost-ordered
searches visit on generate here, which expands the same states in the same order as the
course's pushing of every successor not yet expanded: an entry that is not cheaper comes out
after the one before it and is discarded.

Each choice stays a choice: a flag or the settings screen changes it after the preset.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.search.choices import Semantics

if TYPE_CHECKING:
    from tui_search.engine.search.registry import Algorithm

__all__ = ["PRESETS", "PRESET_WORDS", "preset_semantics"]

#: The presets by name, with what each sets, in words (``--help``, the docs).
PRESET_WORDS: dict[str, str] = {
    "cs188": "4 moves, successors N,S,E,W, visit on expand, goal test on expand, graph "
             "search, FIFO ties and a closed set, Manhattan distance, each move costing 1",
}
PRESETS = tuple(PRESET_WORDS)


def preset_semantics(name: str, algorithm: Algorithm | None = None) -> Semantics:
    """The preset's choices, fitted to ``algorithm`` (None: for any, as compare mode fits
    them to each of its searches); ValueError for a name that is no preset."""
    if name != "cs188":
        raise ValueError(f"no preset {name!r}: use {', '.join(PRESETS)}")
    sem = Semantics(order=("N", "S", "E", "W"), visit="expand", goal_test="expand",
                    heuristic="manhattan", ties="fifo", reopen=False)
    return sem if algorithm is None else sem.fitted(algorithm)
