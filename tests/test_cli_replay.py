"""``--replay FILE`` on the command line: the app opened on the trace beside its search (the
diagnosis's best, or ``-a``'s), and every bad input one line and exit 2, as --check-trace's."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_cli_trace import MAP, TUTORIAL, run_cli, student_trace  # noqa: F401 (a fixture)
from tui_search.cli import main as cli


@pytest.fixture
def opened(monkeypatch) -> list:
    """What the app would have been opened on (the app itself is not run)."""
    apps: list = []
    monkeypatch.setattr(cli, "run_app", lambda options: apps.append(
        cli.build_app(options)) or 0)
    return apps


def test_replay_opens_the_app_beside_the_search_the_trace_matches(
        capsys, opened, student_trace: Path) -> None:  # noqa: F811
    assert run_cli(capsys, MAP, "--replay",
                   str(student_trace))[0] == 0
    (app,) = opened
    session = app.session
    assert session.labels == ["your trace", "BFS"]
    assert session.jumps.replay is not None and session.jumps.replay.verdict.matches


def test_with_a_and_choices_it_replays_beside_that_search(capsys, opened,
                                                          student_trace: Path) -> None:  # noqa: F811
    assert run_cli(capsys, MAP, "--replay", str(student_trace), "-a", "dfs", "--order",
                   "N,W,S,E")[0] == 0
    replay = opened[0].session.jumps.replay
    assert replay.algorithm == "dfs" and replay.semantics.order == ("N", "W", "S", "E")
    assert replay.sentence().startswith(f"step {replay.step}: your trace expands ")


#: --replay with a mode that is not one trace beside one search in the app.
REFUSED = "tui-search: error: --replay shows one trace beside one search in the app: leave out "


@pytest.mark.parametrize("argv, expected", [
    (["--replay", "T"], "tui-search: T:2:10: not JSON: Expecting value"),
    (["--replay", "missing.jsonl"], "tui-search: missing.jsonl: no such file"),
    (["--replay", "T", "--compare", "bfs,dfs"], REFUSED + "--compare"),
    (["--replay", "T", "--exercise", "1"], REFUSED + "--exercise"),
    (["--replay", "T", "--lesson", "tutorial"], REFUSED + "--lesson"),
    (["--replay", "T", "--headless"], REFUSED + "--headless"),
    (["--replay", "T", "--visit", "expand"], ("tui-search: error: without -a, --replay replays "
     "beside the search it matches best: give -a to replay beside --visit")),
])
def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path: Path, monkeypatch, opened, argv,
                                          expected) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "T").write_text('{"node": [0, 0], "successors": []}\n{"node": \n')
    code, out, err = run_cli(capsys, TUTORIAL, *argv)
    assert code == 2 and out == "" and not opened
    assert err.startswith(expected), err
    assert err.count("\n") == 1
