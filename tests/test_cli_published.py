"""The command line's flags for the choices of published code: each reaches the search (its
JSON names it), and a flag that does not apply to ``-a``'s search, or goes with another one
missing, is one line naming it (exit 2)."""

from __future__ import annotations

import json

import pytest

from tests.test_cli import TUTORIAL, run_cli


def semantics_of(capsys, *argv: str) -> dict:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", "--json", *argv)
    assert code == 0 and err == "", err
    return json.loads(out)["semantics"]


def test_each_flag_reaches_the_search(capsys) -> None:
    astar = semantics_of(capsys, "-a", "astar", "--ties", "node", "--reopen", "no",
                         "--cost-tolerance", "0")
    assert (astar["ties"], astar["reopen"], astar["cost_tolerance"]) == ("node", False, 0.0)
    dfs = semantics_of(capsys, "-a", "dfs", "--recursive")
    assert dfs["recursive"] == "neighbours" and dfs["visit"] is None
    assert semantics_of(capsys, "-a", "dfs", "--recursive-lines", "calls")["recursive"] == "calls"
    tree = semantics_of(capsys, "-a", "bfs", "--tree-search", "--no-path-check")
    assert tree["path_check"] is False
    assert semantics_of(capsys, "-a", "bfs", "--mark-start", "no")["mark_start"] is False
    assert semantics_of(capsys, "--visit", "expand-again")["visit"] == "expand-again"
    iddfs = semantics_of(capsys, "-a", "iddfs", "--recursive", "--tree-search")
    assert iddfs["recursive"] == "neighbours" and iddfs["tree_search"]


@pytest.mark.parametrize(("argv", "words"), [
    (["-a", "bfs", "--ties", "node"], "--ties applies to -a ucs, greedy, astar only, not bfs"),
    (["-a", "dfs", "--reopen", "no"], "--reopen applies to -a ucs, greedy, astar only"),
    (["-a", "ucs", "--ties", "low-h"], "ties on h apply to greedy and A*, not UCS"),
    (["-a", "ucs", "--ties", "high-g"], "ties on g do not apply to UCS"),
    (["-a", "bfs", "--recursive"], "--recursive applies to -a dfs, iddfs only, not bfs"),
    (["-a", "dfs", "--recursive", "--visit", "expand"], "--visit does not apply to --recursive"),
    (["--no-path-check"], "--no-path-check goes with --tree-search"),
    (["-a", "bfs", "--tree-search", "--mark-start", "no"], "the start unmarked"),
    (["-a", "astar", "--cost-tolerance", "-1"], "'-1' is not a number 0 or more"),
    (["-a", "astar", "--cost-tolerance", "nan"], "'nan' is not a number 0 or more"),
    (["-a", "astar", "--ties", "random"], "invalid choice: 'random'"),
])
def test_a_flag_that_does_not_apply_is_one_line(capsys, argv: list[str], words: str) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", *argv)
    assert code == 2 and out == ""
    assert words in err and err.count("\n") == 1


def test_the_pseudocode_of_a_recursion_and_of_a_closed_set(capsys) -> None:
    code, out, _ = run_cli(capsys, "-a", "dfs", "--recursive", "--pseudocode")
    assert code == 0 and "function visit(node):" in out and "visit(s)" in out
    code, out, _ = run_cli(capsys, "-a", "greedy", "--reopen", "no", "--ties", "low-g",
                           "--pseudocode")
    assert code == 0 and "close node" in out and "of a tie, the lower g" in out
