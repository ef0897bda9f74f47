"""The command line: headless results, traces, exit codes, and one-line errors."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers import MAPS, MOVINGAI, ROOT
from tui_search.cli.main import main

TUTORIAL = str(MAPS / "tutorial.txt")


def run_cli(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_headless_json_on_the_tutorial(capsys) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", "--json")
    assert code == 0 and err == ""
    result = json.loads(out)
    assert set(result) == {"algorithm", "found", "path", "moves", "length", "cost", "expanded",
                           "discarded", "generated", "max_frontier", "gave_up", "semantics"}
    assert result["found"] and result["algorithm"] == "bfs"
    assert result["path"][0] == [0, 0] and result["path"][-1] == [5, 2]
    assert result["moves"] == ["S", "SE", "NE", "NE", "E", "SE", "S"]
    assert result["length"] == 7 and result["expanded"] == 22


def test_headless_human_summary(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "dfs")
    assert code == 0
    assert out.splitlines()[0] == f"Depth-first search on {TUTORIAL}: path found"
    assert "expanded:     7" in out and "max frontier: 6" in out


def test_trace_lines_are_the_expansions_in_order(capsys, tmp_path: Path) -> None:
    trace = tmp_path / "trace.jsonl"
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--json", "--trace", str(trace))
    lines = [json.loads(line) for line in trace.read_text().splitlines()]
    assert code == 0 and len(lines) == json.loads(out)["expanded"]
    assert lines[0] == {"step": 1, "node": [0, 0], "successors": [{"dir": "S", "node": [0, 1]}]}
    assert [s["dir"] for s in lines[3]["successors"]] == ["E", "NE"]
    assert [line["step"] for line in lines] == list(range(1, len(lines) + 1))


def test_trace_to_stdout_and_iddfs_depth_limit(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "iddfs", "--trace", "-")
    lines = [json.loads(line) for line in out.splitlines()]
    assert code == 0
    assert lines[0]["depth_limit"] == 0 and lines[-1]["depth_limit"] == 7


def test_no_path_exits_1(capsys) -> None:
    code, out, _ = run_cli(capsys, str(MAPS / "no-path.txt"), "--headless", "--json")
    assert code == 1 and json.loads(out)["path"] is None


def test_start_goal_order_and_corner_options(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--json", "--goal", "2,1",
                           "--order", "N,NE,E,SE,S,SW,W,NW", "--no-corner-cutting")
    # Without corner cutting, (0,1) -> SE and (1,2) -> NE both squeeze past (1,1).
    assert code == 0 and json.loads(out)["moves"] == ["S", "S", "E", "E", "N"]
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--json", "--goal", "2,1")
    assert code == 0 and json.loads(out)["moves"] == ["S", "SE", "NE"]


def test_movingai_map_with_a_scenario_row(capsys) -> None:
    code, out, err = run_cli(capsys, str(MOVINGAI / "arena.map"), "--headless", "--json",
                             "--scen", str(MOVINGAI / "arena.map.scen"), "--scen-row", "5")
    assert code == 0, err
    scen_line = (MOVINGAI / "arena.map.scen").read_text().splitlines()[6].split("\t")
    result = json.loads(out)
    assert result["path"][0] == [int(scen_line[4]), int(scen_line[5])]
    assert result["path"][-1] == [int(scen_line[6]), int(scen_line[7])]


def test_bfs_cost_matches_the_scenario_optimum_when_corners_are_respected(capsys) -> None:
    """MovingAI optimal lengths are octile without corner cutting.  BFS minimises moves, not
    cost, so its cost is at least the optimum -- and equal when every optimal path is
    straight (bucket 0 rows are short)."""
    scen = MOVINGAI / "den312d.map.scen"
    for row in range(10):
        fields = scen.read_text().splitlines()[row + 1].split("\t")
        code, out, _ = run_cli(capsys, str(MOVINGAI / "den312d.map"), "--headless", "--json",
                               "--scen", str(scen), "--scen-row", str(row),
                               "--no-corner-cutting")
        assert code == 0
        assert json.loads(out)["cost"] >= float(fields[8]) - 1e-3


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["nope.txt", "--headless"], "tui-search: nope.txt: "),
        ([TUTORIAL, "--headless", "--bogus"], "tui-search: error: unrecognized arguments"),
        ([TUTORIAL, "--headless", "-a", "dijkstra"], "tui-search: error: argument -a/--algorithm"),
        ([TUTORIAL, "--headless", "--order", "N,UP"], "tui-search: error: --order 'N,UP'"),
        ([TUTORIAL, "--headless", "--start", "x"], "tui-search: error: --start 'x'"),
        ([TUTORIAL, "--headless", "--start", "9,9"], f"tui-search: {TUTORIAL}"),
        ([TUTORIAL, "--headless", "--goal", "1,0"], f"tui-search: {TUTORIAL}"),
        ([TUTORIAL, "--json"], "tui-search: error: --json, --csv, --trace and --check-trace go"),
        ([TUTORIAL, "--headless", "--scen", "x.scen"], "tui-search: error: --scen and --scen-row"),
        ([TUTORIAL, "--headless", "--json", "--trace", "-"], "tui-search: error: --trace -"),
        ([str(MAPS), "--headless"], f"tui-search: {MAPS}"),
        (["--headless", "--start", "1,0"], "tui-search: tutorial.txt: start (1,0) is on an"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(capsys, argv, expected) -> None:
    code, out, err = run_cli(capsys, *argv)
    assert code == 2 and out == ""
    assert err.startswith(expected), err
    assert err.count("\n") == 1, "exactly one line"


def test_malformed_map_names_file_line_and_column(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "x.txt"
    bad.write_text("S..\n.q.\n..G\n")
    code, _, err = run_cli(capsys, str(bad), "--headless")
    assert code == 2 and err == f"tui-search: {bad}:2:2: unknown cell character 'q'\n"


def test_movingai_map_without_start_says_what_to_give(capsys) -> None:
    code, _, err = run_cli(capsys, str(MOVINGAI / "arena.map"), "--headless")
    assert code == 2 and "start" in err and err.count("\n") == 1


def test_version_and_help() -> None:
    for flag, needle in (("--version", "tui-search 0."), ("--help", "--headless")):
        out = subprocess.run([sys.executable, "-m", "tui_search", flag], capture_output=True,
                             text=True, cwd=ROOT, check=False)
        assert out.returncode == 0 and needle in out.stdout


def test_no_argument_headless_uses_the_built_in_tutorial(capsys) -> None:
    code, out, _ = run_cli(capsys, "--headless", "--json")
    assert code == 0 and json.loads(out)["expanded"] == 22


def test_packaged_tutorial_is_the_same_as_maps_tutorial() -> None:
    packaged = ROOT / "tui_search" / "maps" / "tutorial.txt"
    assert packaged.read_bytes() == (MAPS / "tutorial.txt").read_bytes()


def test_headless_does_not_import_textual(tmp_path: Path) -> None:
    code = ("import sys; from tui_search.cli.main import main; rc = main(["
            f"{TUTORIAL!r}, '--headless', '--json']); "
            "bad = [m for m in sys.modules if m.split('.')[0] in ('textual', 'rich')]; "
            "sys.exit(10 if bad else rc)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False)
    assert out.returncode == 0, out.stderr


def test_console_script_headless_exit_codes() -> None:
    exe = Path(sys.executable).with_name("tui-search")
    if not exe.exists():
        pytest.skip("console script not installed in this environment")
    ok = subprocess.run([str(exe), TUTORIAL, "--headless"], capture_output=True, text=True,
                        check=False)
    assert ok.returncode == 0 and "path found" in ok.stdout
    bad = subprocess.run([str(exe), "missing.txt", "--headless"], capture_output=True, text=True,
                         check=False)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr


def test_max_steps_gives_up_with_exit_code_3(capsys) -> None:
    """Iterative deepening needs 85 expansions on the tutorial map; with 30 it gives up."""
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", "-a", "iddfs", "--max-steps", "30",
                             "--json")
    result = json.loads(out)
    assert code == 3 and err == ""
    assert result["gave_up"] and not result["found"] and result["expanded"] == 30
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "iddfs", "--max-steps", "30")
    assert out.splitlines()[0].endswith("gave up at --max-steps 30 (raise it to search on)")
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "iddfs", "--max-steps", "85",
                           "--json")
    assert code == 0 and json.loads(out)["found"] and not json.loads(out)["gave_up"]


@pytest.mark.parametrize("bad", ["0", "-3", "many"])
def test_max_steps_must_be_a_positive_number(capsys, bad) -> None:
    code, _, err = run_cli(capsys, TUTORIAL, "--headless", "--max-steps", bad)
    assert code == 2 and err.count("\n") == 1 and "--max-steps" in err


# -- files of the wrong kind, scenarios for another map, the docs' example ----------------

DATA = ROOT / "tests" / "data" / "movingai"


def test_a_scenario_for_another_map_is_refused_by_name(capsys) -> None:
    """arena.map.scen row 1 on den201d.map: refused for naming arena.map, before its start
    (44,30) is tried on den201d's 37x37 grid (which said "outside the map")."""
    scen = DATA / "arena.map.scen"
    code, out, err = run_cli(capsys, str(DATA / "den201d.map"), "--headless", "--scen",
                             str(scen), "--scen-row", "1")
    assert code == 2 and out == ""
    assert err == f"tui-search: {scen}:3: arena.map.scen is for arena.map, not den201d.map\n"


def test_a_scenario_file_given_as_the_map_says_so(capsys) -> None:
    scen = DATA / "arena.map.scen"
    code, _, err = run_cli(capsys, str(scen), "--headless")
    assert code == 2
    assert err == f"tui-search: {scen}:1: this is a MovingAI scenario file: pass it with --scen\n"


def test_a_movingai_map_without_its_type_line_says_so(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "den201d.map"
    bad.write_text((DATA / "den201d.map").read_text().split("\n", 1)[1])
    code, _, err = run_cli(capsys, str(bad), "--headless")
    assert code == 2
    assert err == (
        f"tui-search: {bad}:1: MovingAI header: expected 'type octile', found 'height 37'\n"
    )


def test_the_docs_error_example_is_what_the_cli_prints(capsys, monkeypatch) -> None:
    """The command line's page shows a bad map's one-line error (docs/02-command-line.md)."""
    docs = (ROOT / "docs" / "02-command-line.md").read_text()
    command = "$ tui-search maps/broken.txt --headless\n"
    assert command in docs
    printed = docs.split(command, 1)[1].split("\n", 1)[0]
    monkeypatch.chdir(ROOT)
    code, out, err = run_cli(capsys, "maps/broken.txt", "--headless")
    assert code == 2 and out == "" and err == printed + "\n"
    assert ":4:7: " in printed  # a line and a column, as the page says


def test_a_file_name_with_escape_sequences_is_shown_escaped_never_run(capsys, tmp_path) -> None:
    good, bad = tmp_path / "ok\x1b[2J\u202e.txt", tmp_path / "bad\x1b[31m.txt"
    good.write_text("S.\n.G\n")
    bad.write_text("S.\n.x\n")
    code, out, _ = run_cli(capsys, str(good), "--headless")
    assert code == 0 and "\x1b" not in out and "\u202e" not in out
    assert "ok\\x1b[2J\\u202e.txt: path found" in out
    code, out, err = run_cli(capsys, str(bad), "--headless", "--exercise", "1")
    assert code == 2 and "\x1b" not in err and "bad\\x1b[31m.txt:2:2: unknown cell" in err


def test_a_map_too_big_for_the_app_is_refused_in_one_line(capsys, monkeypatch) -> None:
    """The app keeps counters a cell: a map of more than APP_MAX_CELLS cells is refused by
    size (issue 42: a 64 MB map of one-cell rows took 24 times its file), and searched
    headless as before."""
    import tui_search.tui.model.boards as boards

    monkeypatch.setattr(boards, "APP_MAX_CELLS", 30)  # the tutorial's 36 cells: too many
    code, out, err = run_cli(capsys, TUTORIAL)
    assert (code, out) == (2, "")
    assert err == (f"tui-search: {TUTORIAL}: 6x6 is 36 cells: the app opens maps of at most 30 "
                   "(it keeps counters a cell); search it with --headless\n")
    assert run_cli(capsys, TUTORIAL, "--headless")[0] == 0
