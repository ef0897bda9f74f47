"""The command line with terrain: ``--terrain`` in the help, the JSON's cost with terrain, a bad
table as one line and exit 2, the teaching maps' lessons, a scenario's optimum left out."""

from __future__ import annotations

import json

import pytest

from tests.helpers import MAPS, MOVINGAI
from tests.test_cli import run_cli
from tui_search.cli.parser import build_parser


def test_the_help_names_terrain() -> None:
    assert "--terrain FILE" in build_parser().format_help()


def _json(capsys, *argv: str) -> dict:
    code, out, err = run_cli(capsys, *argv, "--headless", "--json")
    assert code == 0, err
    return json.loads(out)


def test_the_json_cost_includes_terrain(capsys, tmp_path) -> None:
    table = tmp_path / "mud.terrain"
    table.write_text("; mud\nm 9\n")
    plain = tmp_path / "plain.txt"
    plain.write_text("S.m.G\n")
    got = _json(capsys, str(plain), "--terrain", str(table), "-a", "bfs")
    assert got["cost"] == 12.0 and got["length"] == 4
    inline = tmp_path / "inline.txt"
    inline.write_text("; terrain m 9\nS.m.G\n")
    assert _json(capsys, str(inline), "-a", "bfs") == got


@pytest.mark.parametrize(("name", "algorithms", "detour"), [
    ("terrain-mud.txt", ("ucs", "astar"), "bfs"),
    ("terrain-swamp.txt", ("astar", "ucs"), "greedy"),
])
def test_the_teaching_maps_part_the_cheapest_path_from_the_other(capsys, name, algorithms,
                                                                 detour) -> None:
    """The mud: BFS crosses it, UCS and A* go round; the swamp: greedy walks into it."""
    cheap = [_json(capsys, str(MAPS / name), "-a", key) for key in algorithms]
    other = _json(capsys, str(MAPS / name), "-a", detour)
    assert cheap[0]["cost"] == cheap[1]["cost"] < 15
    assert other["cost"] > 3 * cheap[0]["cost"]
    text = (MAPS / name).read_text()
    crossed = [text.splitlines()[y + 4][x] for x, y in other["path"]]  # 4 comment lines
    assert set("ms") & set(crossed)
    assert not set("ms") & {text.splitlines()[y + 4][x] for p in cheap for x, y in p["path"]}


def test_a_bad_table_is_one_line_and_exit_2(capsys, tmp_path) -> None:
    table = tmp_path / "bad.terrain"
    table.write_text("f 5\nS 3\n")
    code, out, err = run_cli(capsys, str(MAPS / "tutorial.txt"), "--terrain", str(table),
                             "--headless")
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        (f"tui-search: {table}:2:1: a terrain table cannot redefine 'S' in a text map ('.', "
        "'S', 'G' cost 1, '#' is blocked, a digit costs itself)")]


def test_movingai_letters_with_a_table_and_no_scenario_optimum(capsys, tmp_path) -> None:
    table = tmp_path / "t.terrain"
    table.write_text("T 5\nS 3\nW blocked\n")
    argv = [str(MOVINGAI / "arena.map"), "--scen", str(MOVINGAI / "arena.map.scen"),
            "--scen-row", "5", "--corners", "never", "-a", "ucs"]
    plain = _json(capsys, *argv)
    assert "optimal" in plain
    costed = _json(capsys, *argv, "--terrain", str(table))
    assert "optimal" not in costed  # the row's optimum is for a map without terrain
