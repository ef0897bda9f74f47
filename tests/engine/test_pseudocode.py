"""The pseudocode generated for every algorithm and every combination of choices has the same
shape: a loop that takes a node off the frontier, a loop over its successors with the checks
that skip one, a push; the lines are where the indentation says."""

from __future__ import annotations

import itertools

import pytest

from tui_search.engine.search.choices import CORNER_RULES, GOAL_TESTS, VISIT_RULES, Semantics
from tui_search.engine.search.heuristics import HEURISTICS
from tui_search.engine.search.pseudocode import SKIP_KINDS, Pseudocode, pseudocode
from tui_search.engine.search.registry import ALGORITHMS, Algorithm

ORDERS = (("N", "NW", "W", "SW", "S", "SE", "E", "NE"), ("N", "W", "S", "E"))


def combinations() -> list[tuple[Algorithm, Semantics]]:
    """Every algorithm under every combination of choices it accepts."""
    out = []
    for algorithm in ALGORITHMS.values():
        heuristics = list(HEURISTICS) if algorithm.informed else ["octile"]
        for order, corners, visit, goal, tree, heuristic in itertools.product(
                ORDERS, CORNER_RULES, VISIT_RULES, GOAL_TESTS, (False, True), heuristics):
            try:
                semantics = Semantics(order, corners, visit, goal, tree, heuristic)
                semantics.check(algorithm)
            except ValueError:
                continue
            out.append((algorithm, semantics))
    return out


def parse(code: Pseudocode) -> list[tuple[str, list]]:
    """The code as a tree, read from its printed lines by their indentation alone: (kind,
    children) for each line.  A line that opens a block ends in ':' and the next line is one
    level in; no other line is followed by a deeper one."""
    printed = code.numbered(indent="    ")
    root: list[tuple[str, list]] = []
    stack = [(-1, root)]
    previous_opens, previous_level = True, -1
    for i, (text, line) in enumerate(zip(printed, code.lines, strict=True), 1):
        number, _, body = text.lstrip().partition("  ")
        assert int(number) == i
        level = (len(body) - len(body.lstrip(" "))) // 4
        body = body.strip()
        assert body == line.text and level == line.indent
        if previous_opens:
            assert level == previous_level + 1, (i, text)
        else:
            assert level <= previous_level, (i, text)
        while stack[-1][0] >= level:
            stack.pop()
        node: tuple[str, list] = (line.kind, [])
        stack[-1][1].append(node)
        stack.append((level, node[1]))
        previous_opens, previous_level = body.endswith(":"), level
    assert not previous_opens
    return root


def kinds(tree: list[tuple[str, list]]) -> list[str]:
    return [kind for kind, _ in tree]


def find(tree: list[tuple[str, list]], kind: str) -> list[tuple[str, list]]:
    (children,) = [children for k, children in tree if k == kind]
    return children


@pytest.mark.parametrize(("algorithm", "semantics"), combinations())
def test_every_combination_parses_as_the_same_structure(algorithm: Algorithm,
                                                        semantics: Semantics) -> None:
    code = pseudocode(algorithm, semantics)
    tree = parse(code)
    every = [line.kind for line in code.lines]
    assert len(every) == len(set(every)), "a kind is on one line"
    if algorithm.contours:  # IDA*: its first limit, then the loop over limits on f
        assert kinds(tree) == ["limit_init", "deepen"]
        tree = find(tree, "deepen")
        assert kinds(tree)[0] == "next_init" and kinds(tree)[-1] == "next_limit"
        tree = tree[1:-1]
    elif algorithm.iterative:  # the loop over depth limits holds the search
        assert kinds(tree) == ["deepen"]
        tree = find(tree, "deepen")
    top = kinds(tree)
    assert top[0] == "init" and top[-1] == "fail" and "while" in top
    body = find(tree, "while")
    assert kinds(body)[0] == "take" and kinds(body)[-1] == "for"
    successors = find(body, "for")
    inner = kinds(successors)
    assert inner[0] == "blocked" and "push" in inner
    checks = [k for k in inner if k in SKIP_KINDS]
    assert max(inner.index(k) for k in checks) < inner.index("push")
    for kind, children in successors:  # a flat block: each line one statement
        assert children == []
        line = code.lines[code.number(kind) - 1]
        assert line.text.endswith("skip s") == (kind in SKIP_KINDS)
    assert ("on_path" in inner) == semantics.tree_search
    assert ("reached" in inner) != semantics.tree_search
    assert ("corner" in inner) == (semantics.corners != "always")
    assert ",".join(semantics.order) in code.lines[code.number("for") - 1].text


def test_the_frontier_s_words_come_from_the_registry() -> None:
    default = Semantics()
    for algorithm in ALGORITHMS.values():
        code = pseudocode(algorithm, default)
        text = "\n".join(code.numbered())
        assert algorithm.frontier.noun in code.lines[code.number("init") - 1].text
        assert algorithm.frontier.take_words(algorithm.priority_name) in text
    bfs, dfs, astar = (pseudocode(ALGORITHMS[k], default) for k in ("bfs", "dfs", "astar"))
    assert "queue" in bfs.lines[0].text and "pop front" in bfs.lines[bfs.number("take") - 1].text
    assert "push back" in bfs.lines[bfs.number("push") - 1].text
    assert "stack" in dfs.lines[0].text and "(pop)" in dfs.lines[dfs.number("take") - 1].text
    assert "f = g + h" in astar.lines[0].text and "lowest f" in "\n".join(astar.numbered())
    ucs = pseudocode(ALGORITHMS["ucs"], default)
    assert "by g," in ucs.lines[0].text


def test_the_move_s_cost_is_a_hook_for_terrain() -> None:
    code = pseudocode(ALGORITHMS["ucs"], Semantics(), move_cost="the cell's terrain cost")
    assert code.lines[code.number("cost") - 1].text == "g ← node.g + the cell's terrain cost"
    assert pseudocode(ALGORITHMS["bfs"], Semantics()).number("cost") is None


def test_the_bfs_handout() -> None:
    assert pseudocode(ALGORITHMS["bfs"], Semantics()).numbered() == [
        " 1  frontier ← a queue holding START",
        " 2  mark START visited",
        " 3  goal test: if START is the goal, return its path",
        " 4  while the frontier is not empty:",
        " 5      node ← take off the front of the queue (pop front)",
        " 6      for each successor s of node, moves in order N,NW,W,SW,S,SE,E,NE:",
        " 7          if s is off the map or an obstacle: skip s",
        " 8          if s is already visited: skip s",
        " 9          push s at the back of the queue (push back)",
        "10          mark s visited",
        "11          goal test: if s is the goal, return its path",
        "12  return no path",
    ]


def published_combinations() -> list[tuple[Algorithm, Semantics]]:
    """Every algorithm under the choices of published code it accepts, one at a time."""
    out = []
    for algorithm in ALGORITHMS.values():
        for change in ({"ties": "node"}, {"ties": "low-h"}, {"cost_tolerance": 0.0},
                       {"reopen": False}, {"recursive": "neighbours"}, {"recursive": "calls"},
                       {"recursive": "calls", "tree_search": True},
                       {"tree_search": True, "path_check": False}, {"mark_start": False},
                       {"visit": "expand-again"}):
            for goal in GOAL_TESTS:
                semantics = Semantics(goal_test=goal, **change)  # type: ignore[arg-type]
                if not semantics.refusal(algorithm):
                    out.append((algorithm, semantics))
    return out


@pytest.mark.parametrize(("algorithm", "semantics"), published_combinations())
def test_the_published_choices_put_their_own_lines(algorithm: Algorithm,
                                                   semantics: Semantics) -> None:
    """Each parses (one kind a line, blocks where the indentation says) and says its choice:
    a recursion is a function that calls itself, a closed set closes, a tie names its rule,
    exact costs say so, no path check has no path line, an unmarked start no mark."""
    code = pseudocode(algorithm, semantics)
    tree = parse(code)
    every = [line.kind for line in code.lines]
    assert len(every) == len(set(every))
    text = "\n".join(code.numbered())
    if semantics.recursive:
        assert "function visit(node):" in text and "visit(s)" in text
        assert "frontier" not in text
        assert ("calls ←" in text) == (semantics.recursive == "neighbours")
        body = find(tree, "while")
        assert "recurse" in kinds(find(body, "for") if semantics.recursive == "calls"
                                  else find(body, "take"))
        return
    loop = find(tree, "deepen") if algorithm.iterative else tree
    assert kinds(find(loop, "while"))[0] == "take"
    if not semantics.reopen:
        assert "close node" in text and "if s is closed" in text
    if semantics.ties != "fifo":
        assert "of a tie" in code.lines[code.number("take") - 1].text
    if semantics.cost_tolerance == 0:
        assert "compared exactly" in text
    if not semantics.path_check:
        assert code.number("on_path") is None and code.number("reached") is None
    if not semantics.mark_start:
        assert code.number("mark_start") is None and code.number("mark_succ") is not None
    if semantics.visit == "expand-again":
        assert code.number("discard") is None and code.number("mark_node") is not None


def test_the_recursive_dfs_handout() -> None:
    sem = Semantics(order=("N", "W", "S", "E"), recursive="calls")
    assert pseudocode(ALGORITHMS["dfs"], sem).numbered() == [
        " 1  visited ← nothing; visit(START)",
        " 2  return no path",
        " 3  function visit(node):",
        " 4      mark node visited",
        " 5      for each successor s of node, moves in order N,W,S,E:",
        " 6          if s is off the map or an obstacle: skip s",
        " 7          if s is already visited (maybe by an earlier call): skip s",
        " 8          add s to node's line (a call made)",
        " 9          goal test: if s is the goal, return its path",
        "10          visit(s)",
    ]
