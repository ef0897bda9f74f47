"""MovingAI ``.map`` files: letters, header errors, and the real MovingAI maps."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.engine.map_helpers import MAI_2x3, error_of, write, write_512_map
from tests.helpers import MOVINGAI
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.engine.maps.movingai import parse_movingai_map

#: (width, height) and scenario row counts of the real MovingAI files copied into
#: tests/data/movingai (their SOURCES.md names where each came from).
MAP_SIZES = {
    "room-32-32-4.map": (32, 32),
    "den201d.map": (37, 37),
    "arena.map": (49, 49),
    "den312d.map": (65, 81),
    "lak303d.map": (194, 194),
    "Berlin_0_256.map": (256, 256),
    "64room_005.map": (512, 512),
    "maze512-1-0.map": (512, 512),
    "random512-40-5.map": (512, 512),
}


# -- MovingAI .map -------------------------------------------------------------------------


def test_movingai_letters() -> None:
    grid = parse_map_text(MAI_2x3)
    assert (grid.width, grid.height, grid.start, grid.goal) == (3, 2, None, None)
    # . @ T / G S W: ".", "G", "S" passable; "@", "O", "T", "W" blocked.
    assert grid.blocked == bytearray([0, 1, 1, 0, 0, 1])
    assert parse_movingai_map("type octile\nheight 1\nwidth 1\nmap\nO").blocked == bytearray([1])


def test_movingai_crlf_missing_final_newline_and_header_order() -> None:
    text = "type octile\r\nwidth 3\r\nheight 2\r\nmap\r\n.@T\r\nGSW"
    assert parse_map_text(text) == parse_map_text(MAI_2x3)
    assert parse_map_text("\n\n" + MAI_2x3 + "\n\n") == parse_map_text(MAI_2x3)


def mai(height: int, width: int) -> str:
    """A MovingAI header."""
    return f"type octile\nheight {height}\nwidth {width}\nmap\n"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (mai(2, 3) + ".@T\n", "m.map:2: the header says height 2 but the map has 1 row"),
        (mai(3, 3) + "...\n...", "m.map:2: the header says height 3 but the map has 2 rows"),
        (mai(1, 3) + "...\n...\n", "m.map:6: more rows than the height (1) in the header"),
        (mai(2, 3) + "...\n....\n", "m.map:6: row has 4 cells, expected 3"),
        (mai(2, 3) + "...\n..\n", "m.map:6: row has 2 cells, expected 3"),
        (mai(2, 3) + "...\n\n...\n", "m.map:6: blank line inside the map"),
        (mai(2, 3) + "...\n.#.\n", "m.map:6:2: unknown cell character '#'"),
        (mai(1, 3).replace("\n", "\r\n") + "..x\r\n", "m.map:5:3: unknown cell character 'x'"),
        ("type octile\nwidth 3\nmap\n...\n", "m.map:3: the header has no height"),
        ("type octile\nheight 1\nmap\n...\n", "m.map:3: the header has no width"),
        (mai(2, 3).replace("2", "x"), "m.map:2: expected 'height N', found 'height x'"),
        (mai(1, -3), "m.map:3: expected 'width N', found 'width -3'"),
        (mai(1, 3).replace(" 1", ""), "m.map:2: expected 'height N', found 'height'"),
        (mai(0, 3), "m.map:2: height must be at least 1"),
        ("type octile\nheight 1\nheight 1\n", "m.map:3: height is given twice"),
        (mai(1, int("9" * 50)), "m.map:3: width is too large: '999999999999...'"),
        (mai(1, 3).replace("map\n", "...\n"),
         ("m.map:4: expected 'height', 'width' or 'map', found '...'")),
        ("type octile\nheight 1\nwidth 3\n", "m.map:3: the header has no 'map' line"),
        ("type octile\n", "m.map:1: the header has no 'map' line"),
    ],
)
def test_movingai_errors(text: str, expected: str) -> None:
    assert error_of(parse_map_text, text, "m.map") == expected
    assert error_of(parse_movingai_map, text, "m.map") == expected


def test_movingai_parser_wants_a_type_line() -> None:
    assert error_of(parse_movingai_map, "\n...\n", "m.map") == (
        "m.map:2: expected 'type octile' on the first line"
    )
    assert error_of(parse_movingai_map, "", "m.map") == (
        "m.map:1: expected 'type octile' on the first line"
    )


# -- the real MovingAI maps ----------------------------------------------------------------


def naive_blocked(path: Path) -> tuple[int, int, bytearray]:
    """An independent, slow reading of a MovingAI file: height/width lines, then rows."""
    lines = path.read_text().replace("\r\n", "\n").split("\n")
    height = int(lines[1].split()[1])
    width = int(lines[2].split()[1])
    assert lines[0].startswith("type") and lines[3] == "map"
    rows = lines[4 : 4 + height]
    return width, height, bytearray(int(ch in "@OTW") for row in rows for ch in row)


@pytest.mark.parametrize("name", sorted(MAP_SIZES))
def test_real_maps_parse(name: str) -> None:
    path = MOVINGAI / name
    grid = load_map(path)
    assert (grid.width, grid.height) == MAP_SIZES[name]
    assert (grid.start, grid.goal) == (None, None)
    assert (grid.width, grid.height, grid.blocked) == naive_blocked(path)


def test_a_crlf_map_without_a_final_newline_reads_as_its_lf_original(tmp_path: Path) -> None:
    """Berlin_0_256.map (a street map; test_real_maps_parse reads the copy) has CRLF line ends
    and no newline after its last row: a real map written that way reads exactly as the
    original."""
    original = MOVINGAI / "arena.map"
    data = original.read_bytes().rstrip(b"\n").replace(b"\n", b"\r\n")
    path = write(tmp_path, "arena.map", data)
    assert data.count(b"\r\n") == 49 + 4 - 1 and not data.endswith(b"\n")  # guards the test
    grid = load_map(path)
    assert grid == load_map(original) and (grid.width, grid.height) == (49, 49)
    assert (grid.width, grid.height, grid.blocked) == naive_blocked(path)


def test_a_512x512_map_parses(tmp_path: Path) -> None:
    path, _ = write_512_map(tmp_path)
    grid = load_map(path)
    assert (grid.width, grid.height) == (512, 512)
    assert (grid.start, grid.goal) == (None, None)
    assert (grid.width, grid.height, grid.blocked) == naive_blocked(path)
