"""The text format: exact error locations, round trips, and other formats' files given as a
text map named as such."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given

from tests.engine.map_helpers import TUTORIAL, error_of, grids, write
from tests.helpers import MOVINGAI
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.engine.maps.text import parse_text_map
from tui_search.engine.maps.write import format_text_map

# -- text format ---------------------------------------------------------------------------


def test_text_map_parses_the_tutorial() -> None:
    grid = parse_text_map(TUTORIAL)
    assert (grid.width, grid.height) == (6, 6)
    assert grid.start == (0, 0) and grid.goal == (5, 2)
    assert grid.is_blocked((1, 0)) and grid.is_blocked((5, 0)) and not grid.is_blocked((0, 1))
    assert not grid.is_blocked(grid.start) and not grid.is_blocked(grid.goal)
    assert grid.free_count() == TUTORIAL.count(".") + 2


def test_text_map_tolerates_comments_crlf_trailing_space_and_blank_ends() -> None:
    text = "\ufeff\n; a comment\nS#. \r\n;; another\r\n..G\t\r\n\n\n  \n"
    grid = parse_text_map(text)
    assert (grid.width, grid.height, grid.start, grid.goal) == (3, 2, (0, 0), (2, 1))
    assert grid.blocked == bytearray([0, 1, 0, 0, 0, 0])


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("S.\n.q\n", "m.txt:2:2: unknown cell character 'q'"),
        ("; one\nS.\n; two\n.G\n; three\n.q\n", "m.txt:6:2: unknown cell character 'q'"),
        ("S. .\n", "m.txt:1:3: unknown cell character ' '"),
        ("S.\n .G\n", "m.txt:2:1: unknown cell character ' '"),
        ("S@G\n", "m.txt:1:2: unknown cell character '@'"),
        ("S.\n.G.\n", "m.txt:2: row has 3 cells, expected 2"),
        ("S..\n.G\n...\n", "m.txt:2: row has 2 cells, expected 3"),
        ("S.\n\n.G\n", "m.txt:2: blank line inside the map"),
        ("S.\n\n; c\n.G\n", "m.txt:2: blank line inside the map"),
        (
            "S.\nG.\n.S\n",
            "m.txt:3:2: a second start 'S' (the first is at line 1, column 1)",
        ),
        ("G.SS\n", "m.txt:1:4: a second start 'S' (the first is at line 1, column 3)"),
        (
            ";\n.G\nS.\nG.\n",
            "m.txt:4:1: a second goal 'G' (the first is at line 2, column 2)",
        ),
        ("..\n.G\n", "m.txt: no start 'S' in the map"),
        ("S.\n..\n", "m.txt: no goal 'G' in the map"),
        ("", "m.txt: the map is empty"),
        ("\n\n  \n", "m.txt: the map is empty"),
        ("; only\n;comments\n", "m.txt: the map is empty"),
    ],
)
def test_text_map_errors(text: str, expected: str) -> None:
    assert error_of(parse_map_text, text, "m.txt") == expected
    assert error_of(parse_text_map, text, "m.txt") == expected


@pytest.mark.parametrize(
    "text",
    [
        TUTORIAL,
        "SG\n",
        "S\nG\n",
        "#S#\n#.#\n#G#\n",
        "G.....#####\n#####.....S\n",
    ],
)
def test_text_map_round_trip(text: str) -> None:
    assert format_text_map(parse_text_map(text)) == text


def test_format_writes_what_the_grid_holds() -> None:
    """No start/goal: no letter; a start on an obstacle is written as S (comes back free)."""
    grid = Grid(3, 1, bytearray([1, 0, 0]))
    assert format_text_map(grid) == "#..\n"
    grid.start = (0, 0)
    assert format_text_map(grid) == "S..\n"


@given(grids())
def test_arbitrary_grids_round_trip(grid: Grid) -> None:
    text = format_text_map(grid)
    assert parse_map_text(text) == grid
    assert format_text_map(parse_text_map(text)) == text


# -- a file of another kind given as the map -----------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("version 1\n0\tarena.map\t49\t49\t1\t1\t2\t2\t1.4\n",
         "m.map:1: this is a MovingAI scenario file: pass it with --scen"),
        ("\n\nVersion 1\n", "m.map:3: this is a MovingAI scenario file: pass it with --scen"),
        ("height 2\nwidth 3\nmap\n...\n...\n",
         "m.map:1: MovingAI header: expected 'type octile', found 'height 2'"),
        ("; c\nwidth 3\n", "m.map:2: MovingAI header: expected 'type octile', found 'width 3'"),
        ("map\n...\n", "m.map:1: MovingAI header: expected 'type octile', found 'map'"),
        ("typeoctile\nheight 1\n",
         "m.map:1: MovingAI header: expected 'type octile', found 'typeoctile'"),
        ("S.\nheight 2\n", "m.map:2:1: unknown cell character 'h'"),  # not the first row
        ("Sversion\n", "m.map:1:2: unknown cell character 'v'"),
    ],
)
def test_another_kind_of_file_given_as_the_map_is_named(text: str, expected: str) -> None:
    assert error_of(parse_map_text, text, "m.map") == expected


def test_the_real_scenario_file_given_as_the_map() -> None:
    path = MOVINGAI / "arena.map.scen"
    assert error_of(load_map, path) == (
        f"{path}:1: this is a MovingAI scenario file: pass it with --scen"
    )


def test_the_real_map_without_its_type_line(tmp_path: Path) -> None:
    text = (MOVINGAI / "arena.map").read_text()
    path = write(tmp_path, "arena.map", text.split("\n", 1)[1])
    assert error_of(load_map, path) == (
        f"{path}:1: MovingAI header: expected 'type octile', found 'height 49'"
    )
