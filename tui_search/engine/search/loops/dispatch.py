"""Which fast loop runs an algorithm under given choices: the compiled core's, or a table of
the Python loops, from the loop's family and the rules in force.

The family is the algorithm's frontier (a queue, a stack, a priority queue), or iterative
deepening; the rules are tree search, graph search under the tutorial's rules with no corner
rule (the hot paths), or graph search under any other choice.  The choices of published code
that neither core makes are recorded from the reference loop
(:mod:`~tui_search.engine.search.loops.published`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from functools import cache, partial
from typing import Any

from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.loops.compiled import compiled_loop
from tui_search.engine.search.problem import corner_free
from tui_search.engine.search.record import Record
from tui_search.engine.search.registry import Algorithm

Loop = Callable[[Any, Record, int], Iterator[int]]  # a grid's Problem, or a GraphProblem

@cache
def python_loops() -> dict[tuple[str, str], Callable[..., Iterator[int]]]:
    """The Python loop of each (family, rules): the family is a frontier's value or
    "iterative", the rules "tutorial", "graph" or "tree" (:func:`rules`).  A priority queue's
    loop is also given the algorithm's priority."""
    # Imported here: a start whose searches run in the compiled core does without them.
    from tui_search.engine.search.loops.best_first import best_first, best_first_tree
    from tui_search.engine.search.loops.general import general
    from tui_search.engine.search.loops.iddfs import iddfs
    from tui_search.engine.search.loops.tree import tree
    from tui_search.engine.search.loops.tutorial import bfs, dfs

    return {
        ("fifo", "tutorial"): bfs,
        ("lifo", "tutorial"): dfs,
        ("fifo", "graph"): partial(general, lifo=False),
        ("lifo", "graph"): partial(general, lifo=True),
        ("fifo", "tree"): partial(tree, lifo=False),
        ("lifo", "tree"): partial(tree, lifo=True),
        ("priority", "tutorial"): best_first,
        ("priority", "graph"): best_first,
        ("priority", "tree"): best_first_tree,
        ("iterative", "tutorial"): iddfs,
        ("iterative", "graph"): iddfs,
        ("iterative", "tree"): iddfs,
    }


def family(algorithm: Algorithm) -> str:
    """The key of ``algorithm``'s loops: its frontier's value, or "iterative"."""
    return "iterative" if algorithm.iterative else algorithm.frontier.value


def rules(algorithm: Algorithm, semantics: Semantics) -> str:
    """"tree" for tree search; "tutorial" for graph search with a cell visited when generated,
    the goal tested when generated and no corner rule in force; "graph" otherwise."""
    if semantics.tree_search:
        return "tree"
    tutorial_rules = (semantics.visit == "generate"
                      and semantics.goal_test_for(algorithm) == "generate")
    return "tutorial" if tutorial_rules and corner_free(semantics) else "graph"


def loop_for(algorithm: Algorithm, semantics: Semantics, graph: bool = False) -> Loop:
    """The fastest loop that implements ``algorithm`` under ``semantics``: for the choices of
    published code the fast loops do not make (ties, a cost tolerance, a closed set,
    recursion, ...: :attr:`~tui_search.engine.search.choices.Semantics.plain` False) the loop
    that records the reference (:mod:`~tui_search.engine.search.loops.published`); else the
    compiled core's when it runs (:mod:`~tui_search.engine.search.loops.compiled`), else the
    table's (:func:`python_loops`).  A ``graph`` is searched by the loop of node numbers
    (:mod:`~tui_search.engine.search.loops.graph_best_first`) under the plain choices of a
    priority queue's graph search, else by the reference's loop."""
    if (graph and semantics.plain and algorithm.priority is not None and algorithm.queued
            and not semantics.tree_search):
        from tui_search.engine.search.loops.graph_best_first import graph_best_first

        return partial(graph_best_first, priority=algorithm.priority)
    # A choice only the reference's loop records; and IDA*, which has no loop of its own (its
    # steps are mostly re-expansions of small contours: docs/11-performance.md).
    if graph or not semantics.plain or algorithm.contours:
        from tui_search.engine.search.loops.published import published

        return partial(published, algorithm=algorithm)
    compiled = compiled_loop(algorithm)
    if compiled is not None:
        return compiled
    loop = python_loops()[family(algorithm), rules(algorithm, semantics)]
    if algorithm.priority is not None:
        return partial(loop, priority=algorithm.priority)
    return loop
