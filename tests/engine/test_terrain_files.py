"""Terrain in map files: a text map's digits, ``--terrain`` tables for text and MovingAI maps,
a text map's own ``; terrain`` comment table, every bad table's message, and what saving keeps
and says."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.engine.map_helpers import MAI_2x3, error_of, write
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import MOVINGAI, TEXT
from tui_search.engine.maps.terrain import MIN_COST, load_terrain, parse_terrain
from tui_search.engine.maps.write import format_map, save_map, save_notes


def costs_of(grid: Grid) -> list[list[float]]:
    return [[grid.cost((x, y)) for x in range(grid.width)] for y in range(grid.height)]


def test_digits_are_free_cells_of_their_cost_and_s_g_dot_cost_1() -> None:
    grid = parse_map_text("S19\n#.G\n")
    assert costs_of(grid) == [[1, 1, 9], [1, 1, 1]]
    assert not grid.is_blocked((2, 0)) and grid.is_blocked((0, 1))


def test_a_plain_map_keeps_no_costs() -> None:
    assert parse_map_text("S.1\n#.G\n").costs is None


def test_a_table_names_a_text_maps_letters() -> None:
    table = parse_terrain("; mud and water\nf 5\nw 0.5\nx blocked\n\n", "t.terrain")
    grid = parse_map_text("Sfw\nx.G\n", terrain=table)
    assert costs_of(grid)[0] == [1, 5, 0.5] and grid.is_blocked((0, 1))
    assert grid.lowest_cost() == 0.5


def test_a_text_map_carries_its_table_in_its_comments() -> None:
    grid = parse_map_text("; terrain f 5\n;terrain w 12\nSfw\n..G\n")
    assert costs_of(grid)[0] == [1, 5, 12]


def test_the_command_lines_table_wins_over_the_comments() -> None:
    grid = parse_map_text("; terrain f 5\nSf.\n..G\n", terrain=parse_terrain("f 2\n"))
    assert grid.cost((1, 0)) == 2


def test_movingai_terrain_letters_take_a_table() -> None:
    """``S`` swamp and ``T`` trees get costs, ``W`` stays blocked, ``.`` is 1."""
    plain = parse_map_text(MAI_2x3)  # .@T / GSW
    assert plain.costs is None and plain.is_blocked((2, 0))
    grid = parse_map_text(MAI_2x3, terrain=parse_terrain("S 3\nT 5\nW blocked\n"))
    assert not grid.is_blocked((2, 0)) and grid.cost((2, 0)) == 5
    assert grid.cost((1, 1)) == 3 and grid.is_blocked((2, 1)) and grid.cost((0, 1)) == 1


@pytest.mark.parametrize(("text", "table", "message"), [
    ("S.x\n..G\n", None, "m.txt:1:3: unknown cell character 'x'"),
    ("S.f\n..G\n", "f 5\nS 3\n",
     ("t.terrain:2:1: a terrain table cannot redefine 'S' in a text map ('.', 'S', 'G' cost "
     "1, '#' is blocked, a digit costs itself)")),
    ("S.f\n..G\n", ". 2\n", "t.terrain:1:1: a terrain table cannot redefine '.'"),
    ("S.f\n..G\n", "# 2\n", "t.terrain:1:1: a terrain table cannot redefine '#'"),
    ("S.f\n..G\n", "G 2\n", "t.terrain:1:1: a terrain table cannot redefine 'G'"),
    ("S.f\n..G\n", "f -1\n",
     "t.terrain:1:3: bad cost '-1': a positive number (0.5, 19) or 'blocked'"),
    ("S.f\n..G\n", "f  abc\n", "t.terrain:1:4: bad cost 'abc'"),
    ("S.f\n..G\n", "f 0\n", "t.terrain:1:3: bad cost '0': it must be above 0"),
    ("S.f\n..G\n", "f 1e99\n", "t.terrain:1:3: bad cost '1e99'"),
    ("S.f\n..G\n", "f 0.001\n", ("t.terrain:1:3: bad cost '0.001': at least 0.01 (costs show "
                              "to 2 decimals: it would show as 0.00)")),
    ("; terrain f 0.0000000001\nS.f\n..G\n", None,
     "m.txt:1:13: bad cost '0.0000000001': at least 0.01"),
    ("S.f\n..G\n", "ff 3\n", "t.terrain:1:1: a terrain names one character, not 'ff'"),
    ("S.f\n..G\n", "f\n", "t.terrain:1:1: expected 'CHAR COST' or 'CHAR blocked', found 'f'"),
    ("S.f\n..G\n", "f 1\n  f 2\n", "t.terrain:2:3: 'f' is given twice (first at line 1)"),
    ("; terrain # 5\nS.f\n..G\n", None, "m.txt:1:11: a terrain table cannot redefine '#'"),
    ("; terrain f x\nS.f\n..G\n", None, "m.txt:1:13: bad cost 'x'"),
])
def test_each_bad_table_names_its_line(text: str, table: str | None, message: str) -> None:
    def parse() -> Grid:
        terrain = parse_terrain(table, "t.terrain") if table is not None else None
        return parse_map_text(text, "m.txt", terrain=terrain)

    error = error_of(parse)
    assert error.startswith(message) and "\n" not in error


def test_a_terrain_file_that_is_missing_is_one_line(tmp_path) -> None:
    assert error_of(load_terrain, str(tmp_path / "none")).endswith("none: no such file")


@given(st.text(max_size=60))
def test_any_text_is_a_table_or_a_map_error(text: str) -> None:
    try:
        parse_terrain(text, "t")
    except MapError as err:
        assert "\n" not in str(err)


# -- saving ---------------------------------------------------------------------------------------


def test_saving_keeps_the_comment_table_and_every_letter(tmp_path) -> None:
    text = "; terrain f 5\n; a comment\nSff7\n.f.G\n"
    path = write(tmp_path, "m.txt", text)
    grid = load_map(path)
    grid.set_blocked((0, 1), True)
    grid.set_cost((2, 1), 5.0)  # a new cell of cost 5: its digit
    grid.set_cost((3, 0), 3.0)  # a digit's cost changed
    save_map(grid, path)
    assert path.read_text() == "; terrain f 5\n; a comment\nSff3\n#f5G\n"
    assert costs_of(load_map(path)) == costs_of(grid)


def test_saving_a_map_read_with_a_table_keeps_its_letters(tmp_path) -> None:
    path = write(tmp_path, "m.txt", "Sw.\n..G\n")
    table = parse_terrain("w 12\n")
    grid = load_map(path, terrain=table)
    grid.set_cost((2, 0), 12.0)
    save_map(grid, path)  # loads again with the table: not refused as unreadable
    assert path.read_text() == "Sww\n..G\n"


def test_a_start_on_a_costed_cell_is_saved_as_s_and_the_save_says_so(tmp_path) -> None:
    grid = parse_map_text("S5.\n..G\n")
    grid.start = (1, 0)
    assert grid.cost(grid.start) == 5
    assert format_map(grid, TEXT).text() == ".S.\n..G\n"
    assert save_notes(grid, TEXT) == [
        "text format: S and G cost 1, so the cost 5 under the start is not kept"]
    assert save_notes(grid, MOVINGAI) == ["no character of this format has cost 5: written as 1"]


def test_a_cost_no_character_writes_is_said(tmp_path) -> None:
    grid = parse_map_text("S..\n..G\n")
    grid.set_cost((1, 0), 2.5)
    assert save_notes(grid, TEXT) == ["no character of this format has cost 2.5: written as 1"]
    assert format_map(grid, TEXT).text() == "S..\n..G\n"
    assert save_notes(parse_map_text("S4.\n..G\n"), TEXT) == []


def test_a_movingai_save_keeps_its_terrain_letters(tmp_path) -> None:
    path = write(tmp_path, "m.map", MAI_2x3)
    table = parse_terrain("S 3\nT 5\n")
    grid = load_map(path, terrain=table)
    grid.set_cost((0, 0), 3.0)  # a new swamp
    save_map(grid, path, MOVINGAI)
    assert path.read_text().endswith("map\nS@T\nGSW\n")
    assert costs_of(load_map(path, terrain=table)) == costs_of(grid)


def test_a_comment_that_only_begins_with_terrain_stays_a_comment() -> None:
    text = "; terrain is rough here\n; terrain f 5\n;terrain\nSf.\n..G\n"
    grid = parse_map_text(text, "m.txt")
    assert grid.costs is not None and grid.costs[1] == 5.0
    with pytest.raises(MapError, match=r"m.txt:1:\d+: bad cost"):
        parse_map_text("; terrain f five\nSf.\n..G\n", "m.txt")


def test_the_least_cost_shows_as_itself_and_a_smaller_one_is_one_line_exit_2(
        tmp_path: Path, capsys) -> None:
    """Every cost is above 0 and the app shows costs to 2 decimals: 0.01 is the least a table
    gives (the JSON's cost is then not 0.0); 1e-10 would show as 0.00, so it is bad input."""
    from tests.test_cli import run_cli

    game = tmp_path / "m.txt"
    game.write_text("SfG\n")
    table = tmp_path / "t.terrain"
    table.write_text(f"f {MIN_COST}\n")
    code, out, _ = run_cli(capsys, str(game), "--terrain", str(table), "--headless", "--json",
                           "-a", "ucs")
    assert code == 0 and json.loads(out)["cost"] == 1.01  # 0.01 into f, 1 into G
    table.write_text("f 0.0000000001\n")
    code, out, err = run_cli(capsys, str(game), "--terrain", str(table), "--headless", "--json")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert f"{table}:1:3: bad cost '0.0000000001': at least 0.01" in err
