"""Loading a map of either format: dispatch by content, start and goal overrides, cells on
the command line, and that no text makes the parsers raise anything but MapError."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.engine.map_helpers import TUTORIAL, MAI_2x3, error_of, write
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map, parse_cell, parse_map_text
from tui_search.engine.maps.movingai import parse_movingai_map
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.scenarios import parse_scenarios
from tui_search.engine.maps.text import parse_text_map

# -- dispatch ------------------------------------------------------------------------------


def test_dispatch_is_by_content_not_name(tmp_path: Path) -> None:
    assert load_map(write(tmp_path, "x.txt", MAI_2x3)).width == 3
    assert load_map(write(tmp_path, "x.map", TUTORIAL)).start == (0, 0)


# -- load_map: overrides -------------------------------------------------------------------


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


# -- parse_cell ----------------------------------------------------------------------------


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
