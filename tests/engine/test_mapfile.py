"""Map and scenario files: exact error locations, round trips, the real MovingAI files,
atomic saving, and that no text makes the parsers raise anything but MapError."""

from __future__ import annotations

import os
import pickle
import random
import stat
import threading
import tracemalloc
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.helpers import MAPS, MOVINGAI
from tui_search.engine import mapfile
from tui_search.engine.grid import Grid
from tui_search.engine.mapfile import (
    MAX_MAP_BYTES,
    MapError,
    Scenario,
    check_scenario_matches,
    format_map,
    format_text_map,
    kind_for_path,
    load_map,
    load_scenario,
    parse_cell,
    parse_map_text,
    parse_movingai_map,
    parse_scenarios,
    parse_text_map,
    read_scenarios,
    save_map,
    save_text_map,
)
from tui_search.engine.mapfile import MOVINGAI as MAI_KIND
from tui_search.engine.mapfile import TEXT as TEXT_KIND

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
SCEN_ROWS = {
    "room-32-32-4-random-1.scen": 341,
    "den201d.map.scen": 100,
    "arena.map.scen": 130,
    "den312d.map.scen": 290,
    # trimmed to a spread of rows (SOURCES.md): the 2011 kind, and the maze's out of order
    "lak303d.map.scen": 10,
    "Berlin_0_256.map.scen": 6,
    "64room_005.map.scen": 3,
    "maze512-1-0.map.scen": 4,
    "random512-40-5.map.scen": 4,
}

TUTORIAL = "S#...#\n.#.##.\n...##G\n..#.#.\n....##\n......\n"
MAI_2x3 = "type octile\nheight 2\nwidth 3\nmap\n.@T\nGSW\n"


def error_of(func, *args, **kwargs) -> str:
    """``str`` of the MapError that ``func`` raises (and fail if it raises none)."""
    with pytest.raises(MapError) as info:
        func(*args, **kwargs)
    return str(info.value)


def write(tmp_path: Path, name: str, content: str | bytes) -> Path:
    path = tmp_path / name
    if isinstance(content, str):
        path.write_bytes(content.encode("utf-8"))
    else:
        path.write_bytes(content)
    return path


# -- MapError ---------------------------------------------------------------------------


def test_map_error_str_and_attributes() -> None:
    err = MapError("a.txt", "bad", 3, 7)
    assert (err.path, err.message, err.line, err.col) == ("a.txt", "bad", 3, 7)
    assert str(err) == "a.txt:3:7: bad"
    assert str(MapError("a.txt", "bad", 3)) == "a.txt:3: bad"
    assert str(MapError("a.txt", "bad")) == "a.txt: bad"


def test_map_error_pickles() -> None:
    """Errors may cross a process boundary (workers); they must survive pickling."""
    err = pickle.loads(pickle.dumps(MapError("a.txt", "bad", 3, 7)))
    assert str(err) == "a.txt:3:7: bad" and err.col == 7


# -- text format --------------------------------------------------------------------------


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


@st.composite
def grids(draw: st.DrawFn) -> Grid:
    width = draw(st.integers(1, 12))
    height = draw(st.integers(1, 12))
    if width * height < 2:
        width = 2
    cells = [(x, y) for y in range(height) for x in range(width)]
    start, goal = draw(st.lists(st.sampled_from(cells), min_size=2, max_size=2, unique=True))
    blocked = bytearray(draw(st.lists(st.integers(0, 1), min_size=width * height,
                                      max_size=width * height)))
    for x, y in (start, goal):
        blocked[y * width + x] = 0
    return Grid(width, height, blocked, start, goal)


@given(grids())
def test_arbitrary_grids_round_trip(grid: Grid) -> None:
    text = format_text_map(grid)
    assert parse_map_text(text) == grid
    assert format_text_map(parse_text_map(text)) == text


# -- MovingAI .map ----------------------------------------------------------------------


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


def test_dispatch_is_by_content_not_name(tmp_path: Path) -> None:
    assert load_map(write(tmp_path, "x.txt", MAI_2x3)).width == 3
    assert load_map(write(tmp_path, "x.map", TUTORIAL)).start == (0, 0)


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


# -- load_map: files and overrides ---------------------------------------------------------


def test_load_map_reads_a_file(tmp_path: Path) -> None:
    path = write(tmp_path, "t.txt", TUTORIAL)
    assert load_map(path) == parse_text_map(TUTORIAL)
    assert load_map(str(path)) == parse_text_map(TUTORIAL)


def test_load_map_errors_name_the_file(tmp_path: Path) -> None:
    path = write(tmp_path, "t.txt", "S.\n.q\n")
    assert error_of(load_map, path) == f"{path}:2:2: unknown cell character 'q'"


def test_load_map_missing_file(tmp_path: Path) -> None:
    path = tmp_path / "nope.txt"
    assert error_of(load_map, path) == f"{path}: no such file"
    inside_a_file = write(tmp_path, "t.txt", TUTORIAL) / "x"
    assert error_of(load_map, inside_a_file) == f"{inside_a_file}: no such file"


def test_load_map_directory(tmp_path: Path) -> None:
    assert error_of(load_map, tmp_path) == f"{tmp_path}: is a directory, not a map file"


def test_load_map_permission_denied(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Simulated, because root (CI containers) can read a chmod 000 file."""
    path = write(tmp_path, "t.txt", TUTORIAL)

    def denied(*args: object, **kwargs: object) -> None:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(mapfile, "open", denied, raising=False)
    assert error_of(load_map, path) == f"{path}: permission denied"


def test_load_map_permission_denied_by_stat(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A folder on the way that may not be searched: ``os.stat`` itself is refused (simulated:
    root, as in CI, may search any folder)."""
    path = write(tmp_path, "t.txt", TUTORIAL)

    def denied(*args: object, **kwargs: object) -> None:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(mapfile.os, "stat", denied)
    assert error_of(load_map, path) == f"{path}: permission denied"


def test_load_map_too_big_is_refused_before_reading(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "huge.map"
    with open(path, "wb") as handle:  # sparse: no disk used
        handle.truncate(MAX_MAP_BYTES + 1)

    def no_reading(*args: object, **kwargs: object) -> None:
        raise AssertionError("the file was opened")

    monkeypatch.setattr(mapfile, "open", no_reading, raising=False)
    assert error_of(load_map, path) == f"{path}: file is 64.1 MB; a map may be at most 64 MB"
    with open(path, "r+b") as handle:
        handle.truncate(200 * 1024 * 1024)
    assert error_of(load_map, path) == f"{path}: file is 200.0 MB; a map may be at most 64 MB"


def test_load_map_just_under_the_limit_is_read(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(mapfile, "MAX_MAP_BYTES", len(TUTORIAL))
    assert load_map(write(tmp_path, "t.txt", TUTORIAL)).width == 6
    path = write(tmp_path, "u.txt", TUTORIAL + "\n")
    assert "a map may be at most" in error_of(load_map, path)


def test_loading_a_small_map_allocates_little() -> None:
    """A read capped at 64 MB must not ask for 64 MB: ``read(n)`` allocates ``n`` bytes first,
    which made loading the six-line tutorial map peak at 67 MB."""
    load_map(MAPS / "tutorial.txt")  # once first, so one-off caches do not count
    tracemalloc.start()
    try:
        grid = load_map(MAPS / "tutorial.txt")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert (grid.width, grid.height) == (6, 6)
    assert peak < 256 * 1024


def fifo_fed(path: Path, data: bytes) -> tuple[Path, threading.Thread]:
    """A named pipe at ``path`` (``os.stat`` says 0 bytes) that a thread fills with ``data``."""
    os.mkfifo(path)

    def feed() -> None:
        with open(path, "wb") as pipe:
            try:
                pipe.write(data)
            except BrokenPipeError:  # the reader stopped at the cap
                pass

    thread = threading.Thread(target=feed, daemon=True)
    thread.start()
    return path, thread


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no named pipes on this system")
def test_a_map_longer_than_stat_said_is_read_in_chunks_up_to_the_cap(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A pipe or a growing file holds more than ``os.stat`` said: the rest is read in bounded
    chunks, and never more than the cap plus one byte."""
    monkeypatch.setattr(mapfile, "_READ_CHUNK", 5)
    path, thread = fifo_fed(tmp_path / "pipe.txt", TUTORIAL.encode())
    assert load_map(path) == parse_text_map(TUTORIAL)
    thread.join(10)
    monkeypatch.setattr(mapfile, "MAX_MAP_BYTES", 1024 * 1024)
    reads: list[int] = []
    real_open = open

    def spying_open(*args: object, **kwargs: object):  # type: ignore[no-untyped-def]
        handle = real_open(*args, **kwargs)  # type: ignore[call-overload]
        read = handle.read
        handle.read = lambda n=-1: reads.append(n) or read(n)  # type: ignore[method-assign]
        return handle

    monkeypatch.setattr(mapfile, "open", spying_open, raising=False)
    monkeypatch.setattr(mapfile, "_READ_CHUNK", 64 * 1024)
    path, thread = fifo_fed(tmp_path / "big.txt", b"." * (3 * 1024 * 1024))
    assert error_of(load_map, path) == f"{path}: file is 1.1 MB; a map may be at most 1 MB"
    assert max(reads) <= 64 * 1024 and sum(reads) == 1024 * 1024 + 1
    thread.join(10)


@pytest.mark.parametrize(
    "content",
    [b"S.\n.G\x00\n", b"\x89PNG\r\n\x1a\n", "S.\n.G\n".encode("utf-16"), b"S.\n\xff\xfe\n"],
)
def test_load_map_binary(tmp_path: Path, content: bytes) -> None:
    path = write(tmp_path, "b.map", content)
    assert error_of(load_map, path) == f"{path}: binary file, not a text map"


def test_overrides_win_and_make_s_and_g_optional(tmp_path: Path) -> None:
    tutorial = write(tmp_path, "t.txt", TUTORIAL)
    grid = load_map(tutorial, start=(0, 5), goal=(2, 0))
    assert (grid.start, grid.goal) == ((0, 5), (2, 0))
    bare = write(tmp_path, "bare.txt", "...\n.#.\n")
    assert error_of(load_map, bare) == f"{bare}: no start 'S' in the map"
    assert error_of(load_map, bare, start=(0, 0)) == f"{bare}: no goal 'G' in the map"
    assert load_map(bare, start=(0, 0), goal=(2, 1)).goal == (2, 1)
    only_s = write(tmp_path, "s.txt", "S..\n...\n")
    assert load_map(only_s, goal=(2, 1)).start == (0, 0)


def test_movingai_needs_overrides_for_start_and_goal(tmp_path: Path) -> None:
    path = write(tmp_path, "m.map", MAI_2x3)
    grid = load_map(path)
    assert (grid.start, grid.goal) == (None, None)
    grid = load_map(path, start=(0, 0), goal=(1, 1))
    assert (grid.start, grid.goal) == ((0, 0), (1, 1))
    assert load_map(path, goal=(0, 1)).start is None


@pytest.mark.parametrize(
    ("start", "goal", "expected"),
    [
        ((9, 9), None, "start (9,9) is outside the 6x6 map"),
        (None, (6, 0), "goal (6,0) is outside the 6x6 map"),
        ((-1, 0), None, "start (-1,0) is outside the 6x6 map"),
        ((1, 1), None, "start (1,1) is on an obstacle"),
        (None, (1, 1), "goal (1,1) is on an obstacle"),
    ],
)
def test_override_errors(tmp_path: Path, start, goal, expected: str) -> None:
    path = write(tmp_path, "t.txt", TUTORIAL)
    assert error_of(load_map, path, start=start, goal=goal) == f"{path}: {expected}"


# -- parse_cell -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "cell"), [("3,4", (3, 4)), (" 3 , 4 ", (3, 4)), ("(0,12)", (0, 12)), ("007,1", (7, 1))]
)
def test_parse_cell(text: str, cell: tuple[int, int]) -> None:
    assert parse_cell(text) == cell


@pytest.mark.parametrize("text", ["", "3", "3,4,5", "a,b", "3;4", "-1,2", "3.5,4", "1,2)x"])
def test_parse_cell_rejects(text: str) -> None:
    with pytest.raises(ValueError) as info:
        parse_cell(text)
    assert "\n" not in str(info.value) and str(info.value)


@given(st.text())
def test_parse_cell_raises_only_value_error(text: str) -> None:
    try:
        x, y = parse_cell(text)
    except ValueError as err:
        assert "\n" not in str(err)
    else:
        assert x >= 0 and y >= 0


# -- robustness: only MapError, always one line --------------------------------------------

TOKENS = [
    "type octile", "type", "height ", "width ", "map", "version 1", "0", "1", "2", "3", "12",
    ".", "#", "S", "G", "@", "O", "T", "W", "q", " ", "\t", "\n", "\n", "\n", "\r\n", "\r",
    ";", "\ufeff", "\x00", "\x0c", "\u2028", "é", "-", "99999999999",
]  # fmt: skip


def check_only_map_error(text: str) -> None:
    for parse in (parse_map_text, parse_text_map, parse_movingai_map, parse_scenarios):
        try:
            result = parse(text, "f")
        except MapError as err:
            assert str(err).startswith("f") and "\n" not in str(err)
        else:
            if isinstance(result, Grid):
                assert len(result.blocked) == result.width * result.height >= 1


@settings(max_examples=300)
@given(st.text())
def test_arbitrary_text_raises_only_map_error(text: str) -> None:
    check_only_map_error(text)


@settings(max_examples=300)
@given(st.lists(st.sampled_from(TOKENS), max_size=60).map("".join))
def test_map_alphabet_text_raises_only_map_error(text: str) -> None:
    check_only_map_error(text)


@settings(max_examples=200)
@given(
    st.integers(1, 5),
    st.integers(1, 5),
    st.lists(st.text(alphabet=".@TSGOW#\n\r ", max_size=8), max_size=7),
)
def test_movingai_shaped_text_raises_only_map_error(h: int, w: int, rows: list[str]) -> None:
    check_only_map_error(f"type octile\nheight {h}\nwidth {w}\nmap\n" + "\n".join(rows))


@settings(max_examples=200)
@given(st.lists(st.lists(st.sampled_from(["0", "a.map", "5", "-1", "x", "1.5", "nan", " ",
                                          "99999999999"]), max_size=10).map("\t".join),
                max_size=5))
def test_scenario_shaped_text_raises_only_map_error(rows: list[str]) -> None:
    check_only_map_error("version 1\n" + "\n".join(rows))


# -- scenarios ------------------------------------------------------------------------------

SCEN = (
    "version 1\n"
    "0\tt.txt\t6\t6\t0\t0\t5\t2\t9.41421356\n"
    "\n"
    "2\tsub/dir/t.txt\t6\t6\t0\t5\t3\t0\t8.00000000\n"
)


def test_read_scenarios(tmp_path: Path) -> None:
    path = write(tmp_path, "t.scen", SCEN)
    rows = read_scenarios(path)
    assert rows == [
        Scenario(0, "t.txt", 6, 6, (0, 0), (5, 2), 9.41421356, 2),
        Scenario(2, "sub/dir/t.txt", 6, 6, (0, 5), (3, 0), 8.0, 4),
    ]
    assert load_scenario(path, 1) == rows[1]
    assert load_scenario(str(path), 0) == rows[0]


@pytest.mark.parametrize(
    "text",
    [
        SCEN.replace("version 1", "version 1.0"),
        SCEN.replace("\n", "\r\n"),
        SCEN.replace("\t", "   "),
        SCEN.replace("\t", " \t "),
        SCEN.rstrip("\n"),
        SCEN + "\n\n",
    ],
)
def test_scenario_variants(text: str) -> None:
    assert parse_scenarios(text) == parse_scenarios(SCEN)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("", "s.scen:1: expected 'version 1' on the first line, found an empty line"),
        ("\nversion 1\n", "s.scen:1: expected 'version 1' on the first line, found an empty line"),
        ("verison 1\n", "s.scen:1: expected 'version 1' on the first line, found 'verison 1'"),
        ("version one\n", "s.scen:1: expected 'version 1' on the first line, found 'version one'"),
        (
            "version 1\n\n0\ta.map\t6\t6\t0\t0\t5\n",
            ("s.scen:3: expected 9 fields (bucket, map, map width, map height, start x, "
             "start y, goal x, goal y, optimal length), found 7"),
        ),
        (
            "version 1\n0\ta.map\t6\tsix\t0\t0\t5\t2\t3\n",
            "s.scen:2: map height is not a whole number >= 0: 'six'",
        ),
        (
            "version 1\n0\ta.map\t6\t6\t-1\t0\t5\t2\t3\n",
            "s.scen:2: start x is not a whole number >= 0: '-1'",
        ),
        (
            "version 1\n0\ta.map\t6\t6\t0\t0\t5\t2\tlong\n",
            "s.scen:2: optimal length is not a number >= 0: 'long'",
        ),
        (
            "version 1\n0\ta.map\t6\t6\t0\t0\t5\t2\tnan\n",
            "s.scen:2: optimal length is not a number >= 0: 'nan'",
        ),
        ("version 1\n0\ta.map\t0\t6\t0\t0\t0\t0\t1\n", "s.scen:2: map size 0x6 is empty"),
        (
            "version 1\n0\ta.map\t6\t6\t0\t0\t6\t2\t3\n",
            "s.scen:2: goal (6,2) is outside the 6x6 map",
        ),
    ],
)
def test_scenario_errors(tmp_path: Path, text: str, expected: str) -> None:
    assert error_of(parse_scenarios, text, "s.scen") == expected
    path = write(tmp_path, "s.scen", text)
    assert error_of(read_scenarios, path) == expected.replace("s.scen", str(path), 1)


def test_scenario_file_errors(tmp_path: Path) -> None:
    assert error_of(read_scenarios, tmp_path / "no.scen") == f"{tmp_path / 'no.scen'}: no such file"
    path = write(tmp_path, "b.scen", b"version 1\n\x00")
    assert error_of(read_scenarios, path) == f"{path}: binary file, not a text map"


def test_load_scenario_missing_row(tmp_path: Path) -> None:
    path = write(tmp_path, "t.scen", SCEN)
    assert error_of(load_scenario, path, 2) == f"{path}: no row 2: the file has 2 rows (0 to 1)"
    assert error_of(load_scenario, path, -1) == f"{path}: no row -1: the file has 2 rows (0 to 1)"
    one = write(tmp_path, "one.scen", SCEN.split("\n\n")[0])
    assert error_of(load_scenario, one, 1) == f"{one}: no row 1: the file has 1 row (row 0)"
    empty = write(tmp_path, "e.scen", "version 1\n")
    assert error_of(load_scenario, empty, 0) == f"{empty}: no row 0: the file has no scenario rows"


def test_check_scenario_matches(tmp_path: Path) -> None:
    grid = parse_text_map(TUTORIAL)
    scen_path = str(tmp_path / "t.scen")
    map_path = str(tmp_path / "t.txt")
    good = Scenario(0, "t.txt", 6, 6, (0, 0), (5, 2), 9.4, 7)
    check_scenario_matches(good, grid, scen_path, map_path)
    # Matched by basename, whatever directory the scenario names (either separator).
    for name in ("maps/dao/t.txt", "maps\\dao\\t.txt"):
        check_scenario_matches(
            Scenario(0, name, 6, 6, (0, 0), (5, 2), 9.4, 7), grid, scen_path, Path(map_path)
        )

    def check(scen: Scenario) -> str:
        return error_of(check_scenario_matches, scen, grid, scen_path, map_path)

    prefix = f"{scen_path}:7: "
    assert check(Scenario(0, "maps/u.txt", 6, 6, (0, 0), (5, 2), 1, 7)) == (
        prefix + "t.scen is for u.txt, not t.txt"
    )
    assert check(Scenario(0, "t.txt", 6, 7, (0, 0), (5, 2), 1, 7)) == (
        prefix + "scenario says the map is 6x7, but t.txt is 6x6"
    )
    assert check(Scenario(0, "t.txt", 6, 6, (6, 0), (5, 2), 1, 7)) == (
        prefix + "start (6,0) is outside the 6x6 map"
    )
    assert check(Scenario(0, "t.txt", 6, 6, (0, 0), (1, 0), 1, 7)) == (
        prefix + "goal (1,0) is on an obstacle"
    )


# -- the real MovingAI files ------------------------------------------------------------------


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


def write_512_map(tmp_path: Path) -> tuple[Path, list[str]]:
    """A seeded random 512x512 MovingAI map (the size of maze512-1-0, random512-40-5 and
    64room_005) of every MovingAI letter, and its rows."""
    rng = random.Random(512)
    rows = ["".join(rng.choices(".G@OTSW", k=512)) for _ in range(512)]
    path = write(tmp_path, "big512.map",
                 "type octile\nheight 512\nwidth 512\nmap\n" + "\n".join(rows) + "\n")
    return path, rows


def test_a_512x512_map_parses(tmp_path: Path) -> None:
    path, _ = write_512_map(tmp_path)
    grid = load_map(path)
    assert (grid.width, grid.height) == (512, 512)
    assert (grid.start, grid.goal) == (None, None)
    assert (grid.width, grid.height, grid.blocked) == naive_blocked(path)


def test_a_big_scenario_file_out_of_bucket_order_with_a_blank_last_line(tmp_path: Path) -> None:
    """maze512-1-0.map.scen (12,120 rows; the copy here is trimmed) starts with its last bucket and
    ends with a blank line: thousands of such rows on a 512x512 map parse, in file order, and
    match the map."""
    map_path, rows = write_512_map(tmp_path)
    free = [(x, y) for y, row in enumerate(rows) for x, ch in enumerate(row) if ch in ".GS"]
    rng = random.Random(12120)
    buckets = [1211, *range(1211)] * 2
    lines = ["version 1"]
    for bucket in buckets:
        (sx, sy), (gx, gy) = rng.sample(free, 2)
        lines.append(f"{bucket}\tbig512.map\t512\t512\t{sx}\t{sy}\t{gx}\t{gy}\t{bucket * 4}.5")
    scen_path = write(tmp_path, "big512.map.scen", "\n".join(lines) + "\n\n")
    scens = read_scenarios(scen_path)
    assert [s.bucket for s in scens] == buckets and len(scens) == 2424
    assert scens[-1].line == 2425 and scens[0].optimal_length == 4844.5
    grid = load_map(map_path)
    for scen in (scens[0], scens[-1], load_scenario(scen_path, len(scens) // 2)):
        check_scenario_matches(scen, grid, scen_path, map_path)
    assert error_of(load_scenario, scen_path, len(scens)).endswith(
        "the file has 2424 rows (0 to 2423)"
    )


@pytest.mark.parametrize("name", sorted(SCEN_ROWS))
def test_real_scenarios_parse_and_match_their_maps(name: str) -> None:
    scen_path = MOVINGAI / name
    rows = read_scenarios(scen_path)
    assert len(rows) == SCEN_ROWS[name]
    map_name = rows[0].map_name.rsplit("/", 1)[-1]
    map_path = MOVINGAI / map_name
    grid = load_map(map_path)
    for scen in (rows[0], rows[-1], load_scenario(scen_path, len(rows) // 2)):
        check_scenario_matches(scen, grid, scen_path, map_path)
    assert all(scen.map_name.endswith(map_name) for scen in rows)
    assert rows[0].line == 2
    assert error_of(load_scenario, scen_path, len(rows)).endswith(
        f"the file has {len(rows)} rows (0 to {len(rows) - 1})"
    )


def test_real_scenario_values() -> None:
    first = load_scenario(MOVINGAI / "den312d.map.scen", 0)
    assert first == Scenario(0, "den312d.map", 65, 81, (61, 72), (60, 72), 1.0, 2)
    last = load_scenario(MOVINGAI / "arena.map.scen", 129)
    assert last == Scenario(12, "arena.map", 49, 49, (4, 32), (47, 19), 48.38477631, 131)


def test_a_2011_scenario_file_names_a_path_and_matches_by_basename(tmp_path: Path) -> None:
    """lak303d.map.scen (the copy here is trimmed) is the older 2011 HOG2 kind: its map field is a
    path (`maps/dao/lak303d.map`) and its lengths have 6 significant digits (`1.41421`, `3`).
    The real arena.map.scen written that way parses and matches arena.map by its basename."""
    real = (MOVINGAI / "arena.map.scen").read_text().split("\n")
    lines = [real[0]]
    for line in filter(None, real[1:]):
        fields = line.split("\t")
        fields[1] = "maps/dao/" + fields[1]
        fields[8] = f"{float(fields[8]):.6g}"
        lines.append("\t".join(fields))
    scen_path = write(tmp_path, "arena.map.scen", "\n".join(lines) + "\n")
    assert "\t3\n" in scen_path.read_text() and "\t1.41421\n" in scen_path.read_text()
    rows = read_scenarios(scen_path)
    assert {scen.map_name for scen in rows} == {"maps/dao/arena.map"}
    assert [s.optimal_length for s in rows] == [
        float(f"{s.optimal_length:.6g}") for s in read_scenarios(MOVINGAI / "arena.map.scen")
    ]
    assert rows[0].optimal_length == 3.0 and 1.41421 in {s.optimal_length for s in rows}
    grid = load_map(MOVINGAI / "arena.map")
    for scen in rows:
        check_scenario_matches(scen, grid, scen_path, MOVINGAI / "arena.map")
    with pytest.raises(MapError) as info:
        check_scenario_matches(rows[0], grid, scen_path, MOVINGAI / "den201d.map")
    assert str(info.value) == (
        f"{scen_path}:2: arena.map.scen is for arena.map, not den201d.map"
    )


# -- save_text_map ----------------------------------------------------------------------------


def test_save_and_load_back(tmp_path: Path) -> None:
    grid = parse_text_map(TUTORIAL)
    path = tmp_path / "saved.txt"
    save_text_map(grid, path)
    assert path.read_text() == TUTORIAL
    assert load_map(path) == grid
    assert os.listdir(tmp_path) == ["saved.txt"]
    if os.name == "posix":
        umask = os.umask(0)
        os.umask(umask)
        assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask


def test_save_replaces_and_keeps_the_mode(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", "old\n")
    path.chmod(0o640)
    save_text_map(parse_text_map(TUTORIAL), str(path))
    assert path.read_text() == TUTORIAL
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert os.listdir(tmp_path) == ["m.txt"]


@pytest.mark.parametrize("failing", ["replace", "fsync"])
def test_failed_save_leaves_the_old_file_and_no_temp_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, failing: str
) -> None:
    path = write(tmp_path, "m.txt", "old\n")

    def broken(*args: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(mapfile.os, failing, broken)
    assert error_of(save_text_map, parse_text_map(TUTORIAL), path) == (
        f"{path}: cannot save: no space left on device"
    )
    monkeypatch.undo()
    assert path.read_text() == "old\n"
    assert os.listdir(tmp_path) == ["m.txt"]


def test_save_onto_a_directory_fails_cleanly(tmp_path: Path) -> None:
    target = tmp_path / "d"
    target.mkdir()
    (target / "keep").write_text("x")
    assert error_of(save_text_map, parse_text_map(TUTORIAL), target) == (
        f"{target}: cannot save: is a directory"
    )
    assert sorted(os.listdir(tmp_path)) == ["d"] and os.listdir(target) == ["keep"]


def test_save_into_a_missing_folder(tmp_path: Path) -> None:
    target = tmp_path / "missing" / "m.txt"
    assert error_of(save_text_map, parse_text_map(TUTORIAL), target) == (
        f"{target}: cannot save: the folder does not exist"
    )
    assert os.listdir(tmp_path) == []


def test_save_into_a_read_only_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The temporary file cannot be created beside the target (simulated: root, as in CI,
    may write into a chmod 555 folder)."""
    path = write(tmp_path, "m.txt", "old\n")
    real_open = os.open

    def read_only_folder(name: str, flags: int, *args: object) -> int:
        if flags & os.O_CREAT:
            raise PermissionError(13, "Permission denied")
        return real_open(name, flags, *args)

    monkeypatch.setattr(mapfile.os, "open", read_only_folder)
    assert error_of(save_text_map, parse_text_map(TUTORIAL), path) == (
        f"{path}: cannot save: permission denied"
    )
    monkeypatch.undo()
    assert path.read_text() == "old\n"
    assert os.listdir(tmp_path) == ["m.txt"]


@settings(max_examples=30, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(grids())
def test_saved_grids_load_back(tmp_path: Path, grid: Grid) -> None:
    path = tmp_path / "g.txt"
    save_text_map(grid, path)
    assert load_map(path) == grid


# -- saving keeps the file: MapSource -------------------------------------------------------

#: The repository's own copies of MovingAI files (see tests/data/movingai/SOURCES.md).
TEXT_LETTERS = {"S", "G", "#", "."}


def cell_letters(grid: Grid) -> dict[tuple[int, int], str]:
    """What the text format writes for every cell (an independent spelling of it)."""
    out = {}
    for y in range(grid.height):
        for x in range(grid.width):
            cell = (x, y)
            out[cell] = ("S" if cell == grid.start else "G" if cell == grid.goal
                         else "#" if grid.is_blocked(cell) else ".")
    return out


comment_text = st.text(
    alphabet=st.characters(blacklist_characters="\n", blacklist_categories=("Cs",)), max_size=12
)


@st.composite
def text_files(draw: st.DrawFn) -> tuple[str, dict[tuple[int, int], int]]:
    """A text map file as people write them -- comments and blank lines before it, comments
    between rows, trailing spaces, LF or CRLF per line, maybe no final newline, maybe a BOM --
    and where in the text every cell is (its character offset)."""
    grid = draw(grids())
    rows = format_text_map(grid).split("\n")[:-1]
    parts: list[str] = ["\ufeff"] if draw(st.booleans()) else []
    ending = st.sampled_from(["\n", "\r\n"])
    for _ in range(draw(st.integers(0, 3))):
        parts.append(draw(st.sampled_from(["", "  "])) if draw(st.booleans())
                     else draw(st.sampled_from(["", " "])) + ";" + draw(comment_text))
        parts.append(draw(ending))
    where: dict[tuple[int, int], int] = {}
    for y, row in enumerate(rows):
        if y and draw(st.integers(0, 3)) == 0:
            parts += [";" + draw(comment_text), draw(ending)]
        offset = len("".join(parts))
        where.update({(x, y): offset + x for x in range(len(row))})
        parts += [row, draw(st.sampled_from(["", " ", "\t "])), draw(ending)]
    if draw(st.booleans()):
        parts.pop()  # no final newline
    elif draw(st.booleans()):
        parts += ["; the end", draw(ending), "\n"]
    return "".join(parts), where


@settings(max_examples=200)
@given(text_files())
def test_a_text_file_saved_without_edits_is_the_same_text(file) -> None:
    text, _ = file
    assert format_text_map(parse_text_map(text)) == text


@settings(max_examples=200)
@given(text_files(), st.data())
def test_an_edit_changes_exactly_the_edited_cells(file, data: st.DataObject) -> None:
    """Obstacles toggled and S/G moved: the saved text differs from the file at exactly the
    cells whose letter changed (the old S becomes '.', the new one 'S'), nowhere else."""
    text, where = file
    grid = parse_text_map(text)
    before = cell_letters(grid)
    cells = sorted(before)
    for cell in data.draw(st.lists(st.sampled_from(cells), max_size=6)):
        if cell not in (grid.start, grid.goal):
            grid.set_blocked(cell, not grid.is_blocked(cell))
    for what in ("start", "goal"):
        free = [c for c in cells if not grid.is_blocked(c) and c not in (grid.start, grid.goal)]
        if free and data.draw(st.booleans()):
            setattr(grid, what, data.draw(st.sampled_from(free)))
    after = cell_letters(grid)
    saved = format_text_map(grid)
    assert len(saved) == len(text)
    differ = {i for i, (a, b) in enumerate(zip(text, saved)) if a != b}
    assert differ == {where[c] for c in cells if before[c] != after[c]}
    assert all(saved[where[c]] == after[c] for c in cells)
    assert parse_text_map(saved) == grid


@st.composite
def movingai_files(draw: st.DrawFn) -> str:
    width, height = draw(st.integers(1, 8)), draw(st.integers(1, 8))
    ending = draw(st.sampled_from(["\n", "\r\n"]))
    rows = ["".join(draw(st.lists(st.sampled_from(".GS@OTW"), min_size=width, max_size=width)))
            for _ in range(height)]
    text = ending.join(["type octile", f"height {height}", f"width {width}", "map", *rows])
    return text + (ending if draw(st.booleans()) else "")


@settings(max_examples=200)
@given(movingai_files(), st.data())
def test_a_movingai_file_keeps_its_header_and_letters(text: str, data: st.DataObject) -> None:
    """No edit: the same bytes.  A newly blocked cell becomes '@', a freed one '.', every
    other cell keeps its letter (T stays a tree); the header lines stay as they were."""
    grid = parse_movingai_map(text)
    assert format_map(grid, MAI_KIND).text() == text
    cells = [(x, y) for y in range(grid.height) for x in range(grid.width)]
    toggled = set(data.draw(st.lists(st.sampled_from(cells), max_size=5, unique=True)))
    for cell in toggled:
        grid.set_blocked(cell, not grid.is_blocked(cell))
    saved = format_map(grid, MAI_KIND).text()
    old_lines, new_lines = text.split("\n"), saved.split("\n")
    assert old_lines[:4] == new_lines[:4] and len(old_lines) == len(new_lines)
    for (x, y) in cells:
        old, new = old_lines[4 + y][x], new_lines[4 + y][x]
        if (x, y) in toggled:
            assert new == ("@" if grid.is_blocked((x, y)) else ".")
        else:
            assert new == old
    assert [line[grid.width :] for line in old_lines] == [line[grid.width :] for line in new_lines]
    assert parse_movingai_map(saved) == grid


def test_saving_the_tutorial_keeps_its_comments_byte_for_byte(tmp_path: Path) -> None:
    """The issue's case: maps/tutorial.txt, goal moved, saved: the comments are still there."""
    path = tmp_path / "tutorial.txt"
    path.write_bytes((MAPS / "tutorial.txt").read_bytes())
    grid = load_map(path)
    grid.source = save_map(grid, path)
    assert path.read_bytes() == (MAPS / "tutorial.txt").read_bytes()
    grid.goal = (5, 1)
    grid.source = save_map(grid, path)
    old = (MAPS / "tutorial.txt").read_text().split("\n")
    new = path.read_text().split("\n")
    changed = [i for i, (a, b) in enumerate(zip(old, new)) if a != b]
    assert len(old) == len(new) and len(changed) == 2
    assert old[changed[0]].startswith(".#.##.") and new[changed[0]].startswith(".#.##G")
    assert old[changed[1]].startswith("...##G") and new[changed[1]].startswith("...##.")
    assert load_map(path) == grid


def test_saving_a_real_movingai_map_in_place(tmp_path: Path) -> None:
    path = tmp_path / "arena.map"
    original = (MOVINGAI / "arena.map").read_bytes()
    path.write_bytes(original)
    grid = load_map(path)
    assert save_map(grid, path, MAI_KIND).text().encode() == original
    assert path.read_bytes() == original
    tree = next((x, y) for y in range(grid.height) for x in range(grid.width)
                if grid.source.lines[grid.source.rows[y]][x] == "T")
    free = next(c for c in ((x, 1) for x in range(grid.width)) if not grid.is_blocked(c))
    grid.set_blocked(tree, False)
    grid.set_blocked(free, True)
    grid.source = save_map(grid, path, MAI_KIND)
    lines = path.read_text().split("\n")
    assert lines[:4] == original.decode().split("\n")[:4]
    assert lines[4 + tree[1]][tree[0]] == "." and lines[4 + free[1]][free[0]] == "@"
    differ = [i for i, (a, b) in enumerate(zip(original, path.read_bytes())) if a != b]
    assert len(differ) == 2 and len(path.read_bytes()) == len(original)
    # The next save compares with the file as saved: freeing the cell again writes '.'.
    grid.set_blocked(free, False)
    save_map(grid, path, MAI_KIND)
    assert path.read_text().split("\n")[4 + free[1]][free[0]] == "."


def test_a_movingai_map_saved_as_text_and_a_text_map_as_movingai() -> None:
    grid = parse_movingai_map(MAI_2x3)
    grid.start, grid.goal = (0, 0), (1, 1)
    assert format_map(grid, TEXT_KIND).text() == "S##\n.G#\n"
    text_grid = parse_text_map("; c\nS#\n.G\n")
    assert format_map(text_grid, MAI_KIND).text() == "type octile\nheight 2\nwidth 2\nmap\n.@\n..\n"
    assert (kind_for_path("a/b.MAP"), kind_for_path("b.txt"), kind_for_path("map")) == (
        MAI_KIND, TEXT_KIND, TEXT_KIND)


def test_a_grid_built_in_code_saves_as_a_fresh_file() -> None:
    grid = Grid(2, 1, bytearray([0, 1]), (0, 0))
    assert format_text_map(grid) == "S#\n"
    other = parse_text_map("S.G\n")  # a source of another size is not used
    grid.source = other.source
    assert format_text_map(grid) == "S#\n"


# -- a file of another kind given as the map ------------------------------------------------


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
