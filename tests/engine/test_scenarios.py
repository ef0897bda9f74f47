"""MovingAI ``.scen`` files: rows, variants, exact errors, matching a scenario to its map, and
the real MovingAI scenario files."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.engine.map_helpers import TUTORIAL, error_of, write, write_512_map
from tests.helpers import MOVINGAI
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.scenarios import (
    Scenario,
    _parse_row,
    _read_rows,
    check_scenario_matches,
    load_scenario,
    parse_scenarios,
    read_scenarios,
)
from tui_search.engine.maps.text import parse_text_map

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


# -- scenarios -----------------------------------------------------------------------------


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
    assert error_of(read_scenarios, path) == (
        f"{path}:2:1: binary file (a NUL byte), not a scenario file")


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


# -- the real MovingAI scenario files ------------------------------------------------------


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


# -- the quick path for plain rows ---------------------------------------------------------

# Mostly plain words (the quick path's rows), some odd ones (the rows it leaves to the rest).
_PLAIN = ["0", "5", "6", "7", "00", "007", "512"]
_ODD = ["-1", "x", "", " 6", "1234567890", "0001234567", "12345678901", "1e2", "inf", "nan"]
_NUMBER = st.sampled_from(_PLAIN * 6 + _ODD)
_NAME = st.sampled_from(["a.map"] * 6 + ["", " a.map", "a.map ", "sub dir/a.map", "6"])
_LENGTH = st.sampled_from(["3", "9.41421356", "0.5"] * 4 + ["1e2", "nan", "-1", "x", "5."])
# now and then a field fewer or more
_ROW = st.tuples(_NUMBER, _NAME, *[_NUMBER] * 6, _LENGTH, st.integers(-1, 1)).map(
    lambda t: [*t[:8 + min(t[9], 0) + 1], *['1'] * max(t[9], 0)])


@given(st.lists(_ROW, max_size=6), st.sampled_from(["\t"] * 4 + [" ", "\t\t"]))
@settings(max_examples=300, deadline=None)
def test_plain_rows_read_as_every_row_is_read(rows: list[list[str]], sep: str) -> None:
    """Rows the quick path reads (tab-separated, plain numbers) give the same problems, and
    other rows the same errors, as reading every row field by field does."""
    text = "version 1\n" + "".join(sep.join(row) + "\n" for row in rows)
    lines = text.splitlines()

    def field_by_field() -> list[Scenario]:
        return [_parse_row(line.rstrip(), n, "s.scen")
                for n, line in enumerate(lines[1:], start=2) if line.strip()]

    try:
        expected: list[Scenario] | str = field_by_field()
    except MapError as exc:
        expected = str(exc)
    try:
        got: list[Scenario] | str = parse_scenarios(text, "s.scen")
    except MapError as exc:
        got = str(exc)
    assert got == expected
    if isinstance(expected, list):
        for row, scen in enumerate(expected):
            assert _read_rows(text, "s.scen", row) == ([scen], len(expected))
