"""IDA* on the command line: ``-a idastar`` headless on a grid and on a graph, its JSON, its
``--trace`` lines with ``f_limit`` (checked back with ``--check-trace``), its limit on steps,
compare mode and the flags that do not apply to it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.test_cli import TUTORIAL, run_cli

ROMANIA = str(Path(__file__).parents[1] / "maps" / "graphs" / "romania.graph")


def test_idastar_on_the_tutorial_and_on_romania(capsys) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "-a", "idastar", "--headless", "--json")
    result = json.loads(out)
    assert (code, err) == (0, "") and result["algorithm"] == "idastar"
    assert (result["cost"], result["expanded"], result["length"]) == (8.656854, 97, 7)
    assert result["semantics"]["ties"] is None and result["semantics"]["weight"] == 1.0
    code, out, err = run_cli(capsys, ROMANIA, "-a", "idastar", "--headless")
    assert code == 0 and "Arad, Sibiu, Rimnicu, Pitesti, Bucharest" in out
    assert "cost:         418" in out


def test_the_trace_says_each_steps_f_limit_and_checks_back(capsys, tmp_path) -> None:
    trace = tmp_path / "ida.jsonl"
    code, _, _ = run_cli(capsys, TUTORIAL, "-a", "idastar", "--headless", "--trace",
                         str(trace))
    lines = [json.loads(line) for line in trace.read_text().splitlines()]
    assert code == 0 and len(lines) == 97
    assert sorted({line["f_limit"] for line in lines}) == [
        5.828427, 6.414214, 7.0, 7.242641, 7.828427, 8.071068, 8.414214, 8.656854]
    assert lines[1] == {"step": 2, "node": [0, 1], "successors": [], "f_limit": 5.828427}
    code, out, _ = run_cli(capsys, TUTORIAL, "-a", "idastar", "--headless", "--check-trace",
                           str(trace))
    assert code == 0 and "for all 97 steps" in out
    # a student's IDA* that expands a node over the limit is told so
    bad = tmp_path / "bad.jsonl"
    rows = lines[:1] + [{"node": [0, 1], "successors": [[0, 2]]}]
    bad.write_text("".join(json.dumps(row) + "\n" for row in rows))
    code, out, _ = run_cli(capsys, TUTORIAL, "-a", "idastar", "--headless", "--check-trace",
                           str(bad))
    assert code == 1 and "its f = 6.41 is over the limit 5.83, so IDA* cuts it off" in out


def test_it_gives_up_at_max_steps_and_compares(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "-a", "idastar", "--tree-search", "--headless",
                           "--max-steps", "50")
    assert code == 3 and "gave up at --max-steps 50" in out
    code, out, _ = run_cli(capsys, TUTORIAL, "--compare", "astar,idastar,idastar:w=2",
                           "--headless")
    assert code == 0 and "A* expanded 16 nodes, IDA* 97, IDA* (w=2) 10" in out


@pytest.mark.parametrize(("flag", "said"), [
    (("--ties", "lifo"), "--ties applies to -a ucs, greedy, astar only, not idastar"),
    (("--reopen", "no"), "--reopen applies to -a ucs, greedy, astar only, not idastar"),
    (("--recursive",), "--recursive applies to -a dfs, iddfs only, not idastar"),
])
def test_the_priority_queues_flags_and_recursion_are_refused(capsys, flag, said) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "-a", "idastar", "--headless", *flag)
    assert (code, out) == (2, "") and said in err
