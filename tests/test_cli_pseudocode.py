"""``tui-search --pseudocode``: the code printed without the app, and each choice flag
changing exactly the lines it should."""

from __future__ import annotations

import difflib

import pytest

from tests.test_cli import run_cli


def code_lines(capsys, *argv: str) -> list[str]:
    """The printed code's lines, without their numbers (the title left out)."""
    code, out, err = run_cli(capsys, "--pseudocode", *argv)
    assert code == 0 and err == ""
    _title, *lines = out.splitlines()
    assert lines[0].startswith(" 1  ") and lines[-1].startswith(f"{len(lines)}  ")
    return [line.lstrip().partition("  ")[2] for line in lines]


def changes(before: list[str], after: list[str]) -> tuple[set[str], set[str]]:
    """The lines taken out and the lines put in (their words, unindented)."""
    out, into = set(), set()
    for line in difflib.ndiff(before, after):
        if line.startswith("- "):
            out.add(line[2:].strip())
        elif line.startswith("+ "):
            into.add(line[2:].strip())
    return out, into


MARK = {"mark START visited", "mark s visited"}
GOAL_ON_GENERATE = {"goal test: if START is the goal, return its path",
                    "goal test: if s is the goal, return its path"}

#: flags -> (the default's lines taken out, the lines put in), from BFS's default code
CHANGES: dict[tuple[str, ...], tuple[set[str], set[str]]] = {
    ("--visit", "expand"): (MARK, {"if node is already visited: discard it, go on",
                                   "mark node visited"}),
    ("--goal-test", "expand"): (GOAL_ON_GENERATE,
                                {"goal test: if node is the goal, return its path"}),
    ("--tree-search",): (MARK | {"if s is already visited: skip s"},
                         {"if s is on the path from START to node: skip s"}),
    ("--corners", "never"): (set(), {
        "if s is diagonal past an obstacle's corner (corner rule never): skip s"}),
    ("--no-corner-cutting",): (set(), {
        "if s is diagonal past an obstacle's corner (corner rule never): skip s"}),
    ("--corners", "one"): (set(), {
        "if s is diagonal between two obstacles (corner rule one): skip s"}),
    ("--order", "N,W,S,E"): ({("for each successor s of node, moves in order "
                              "N,NW,W,SW,S,SE,E,NE:")},
                             {"for each successor s of node, moves in order N,W,S,E:"}),
    ("-a", "dfs"): ({"frontier ← a queue holding START",
                     "node ← take off the front of the queue (pop front)",
                     "push s at the back of the queue (push back)"},
                    {"frontier ← a stack holding START",
                     "node ← take off the top of the stack (pop)",
                     "push s on top of the stack (push)"}),
}


@pytest.mark.parametrize("flags", CHANGES, ids=" ".join)
def test_each_choice_changes_exactly_its_lines(capsys, flags: tuple[str, ...]) -> None:
    default = code_lines(capsys, "-a", "bfs")
    assert changes(default, code_lines(capsys, "-a", "bfs", *flags)) == CHANGES[flags]


def test_a_s_heuristic_and_priority_change_only_the_frontier_s_lines(capsys) -> None:
    astar = code_lines(capsys, "-a", "astar")
    assert changes(astar, code_lines(capsys, "-a", "astar", "--heuristic", "manhattan")) == (
        {"frontier ← a priority queue by f = g + h, h = octile distance, holding START"},
        {"frontier ← a priority queue by f = g + h, h = manhattan distance, holding START"})
    out, into = changes(astar, code_lines(capsys, "-a", "ucs"))
    assert {line.split()[0] for line in out | into} == {"frontier", "node", "push"}


def test_iterative_deepening_shows_its_outer_loop(capsys) -> None:
    lines = code_lines(capsys, "-a", "iddfs")
    assert lines[0] == "for depth limit ← 0, 1, 2, …:"
    assert "if node's depth = the depth limit: cut off, go on" in map(str.strip, lines)


@pytest.mark.parametrize(("argv", "error"), [
    (("--compare", "bfs,dfs"), "leave out --compare"),
    (("--lesson", "tutorial"), "leave out --lesson"),
    (("--lesson",), "leave out --lesson"),
    (("--headless",), "leave out --headless"),
    (("-a", "ucs", "--visit", "expand"), "--visit does not apply"),
])
def test_bad_combinations_are_one_line_exit_2(capsys, argv: tuple[str, ...],
                                               error: str) -> None:
    code, out, err = run_cli(capsys, "--pseudocode", *argv)
    assert code == 2 and out == "" and error in err and err.count("\n") == 1


def test_the_code_of_a_search_on_a_map_with_terrain_adds_the_cell_s_cost(capsys) -> None:
    from tests.helpers import MAPS

    code, out, _ = run_cli(capsys, str(MAPS / "terrain-mud.txt"), "--pseudocode", "-a", "ucs")
    assert code == 0 and "× the cost of the cell it enters" in out
    code, out, _ = run_cli(capsys, "--pseudocode", "-a", "ucs")
    assert code == 0 and "cell it enters" not in out and "the move's cost" in out
