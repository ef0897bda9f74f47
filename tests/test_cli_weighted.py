"""Weighted A* on the command line: ``--weight W`` (``-a astar`` only, W 1 or more), the
JSON's ``semantics.weight``, the text's choices, and compare mode's ``astar:w=2``."""

from __future__ import annotations

import json

import pytest

from tests.test_cli import TUTORIAL, run_cli
from tui_search.cli.parse import parse_options

MAZE = ("--generate", "maze", "--size", "41x31", "--seed", "4")


def _json(capsys, *argv: str) -> dict:
    code, out, err = run_cli(capsys, "--headless", "--json", *argv)
    assert code == 0 and err == ""
    result: dict = json.loads(out)
    return result


def test_weight_runs_weighted_astar_and_the_json_says_so(capsys) -> None:
    ucs = _json(capsys, *MAZE, "-a", "ucs")
    plain = _json(capsys, *MAZE, "-a", "astar")
    one = _json(capsys, *MAZE, "-a", "astar", "--weight", "1")
    heavy = _json(capsys, *MAZE, "-a", "astar", "--weight", "2.5")
    assert plain["semantics"]["weight"] == one["semantics"]["weight"] == 1.0
    assert heavy["semantics"]["weight"] == 2.5 and ucs["semantics"]["weight"] is None
    assert one == plain  # a weight of 1 is A*, to the last digit
    assert heavy["found"] and heavy["cost"] <= 2.5 * ucs["cost"] + 1e-9
    assert heavy["expanded"] != plain["expanded"]


def test_the_text_output_names_the_weight(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "astar", "--weight", "3")
    assert code == 0 and "weight 3" in out


@pytest.mark.parametrize(("argv", "said"), [
    (("-a", "ucs", "--weight", "2"), "--weight applies to -a astar, idastar only"),
    (("-a", "bfs", "--weight", "1"), "--weight applies to -a astar, idastar only"),
    (("-a", "astar", "--weight", "0.9"), "'0.9' is not a number 1 or more"),
    (("-a", "astar", "--weight", "nan"), "'nan' is not a number 1 or more"),
    (("-a", "astar", "--weight", "two"), "'two' is not a number 1 or more"),
])
def test_a_weight_that_does_not_apply_is_one_line(capsys, argv: tuple[str, ...], said: str
                                                  ) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", *argv)
    assert code == 2 and out == "" and said in err and len(err.strip().splitlines()) == 1


def test_the_weight_is_an_option() -> None:
    assert parse_options(["-a", "astar", "--weight", "2"]).weight == 2.0
    assert parse_options([]).weight is None


def test_compare_names_weighted_astar(capsys) -> None:
    code, out, err = run_cli(capsys, *MAZE, "--headless", "--compare", "ucs,astar,astar:w=2")
    assert code == 0 and err == ""
    assert "A* (w=2)" in out
    code, _, err = run_cli(capsys, *MAZE, "--headless", "--compare", "ucs:w=2,astar")
    assert code == 2 and "a weight applies to astar only, not ucs" in err
