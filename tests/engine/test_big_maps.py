"""Big maps read in a few passes over the text (issue 21: a 64 MB map of ``.`` rows took 77 s
and 6 GB): the file's lines kept as one string (:class:`Lines`), and a plain map read whole
(:func:`tui_search.engine.maps.text._plain_map`), which must give exactly what the line by line
reader gives, grid and error alike.  The memory itself is measured in benchmarks/big_map.py."""

from __future__ import annotations

import random
import tracemalloc
from array import array
from unittest import mock

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tui_search.engine.maps import movingai
from tui_search.engine.maps import text as textmap
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.movingai import parse_movingai_map
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import Lines
from tui_search.engine.maps.terrain import parse_terrain
from tui_search.engine.maps.text import parse_text_map
from tui_search.engine.run.recorded import Run
from tui_search.engine.search import problem
from tui_search.engine.search.choices import Semantics

texts = st.text(alphabet="ab\n\r", max_size=40)


@given(texts, st.integers(min_value=1, max_value=7))
def test_lines_are_the_text_split_on_newlines_at_any_chunk_size(text: str, chunk: int) -> None:
    with mock.patch.object(Lines, "_CHUNK", chunk):
        lines = Lines(text)
    expected = text.split("\n")
    assert list(lines) == expected and len(lines) == len(expected)
    assert [lines[i] for i in range(-len(lines), len(lines))] == expected * 2
    assert lines[1:-1] == expected[1:-1] and lines[::2] == expected[::2]
    assert lines == Lines(text) and lines == expected and lines == tuple(expected)
    assert lines.text == text


def _outcome(text: str, **kw: bool) -> object:
    try:
        grid = parse_text_map(text, "m.txt", terrain=parse_terrain("f 5\nw blocked"), **kw)
    except MapError as err:
        return str(err)
    return grid, grid.costs, grid.source.text() if grid.source else None


cells = "..#SG3fw"
ragged = st.lists(st.text(alphabet=cells, min_size=1, max_size=6), min_size=1, max_size=6)
even = st.integers(1, 6).flatmap(lambda w: st.lists(
    st.text(alphabet=cells, min_size=w, max_size=w), min_size=1, max_size=6))
#: Lines around the rows: comments, blank ones, and some that are neither.
around = st.lists(st.sampled_from(["; c", " ; terrain f 7", "", "  ", "\r", ";é", " S", "S "]),
                  max_size=3)


@given(around, st.one_of(ragged, even), around, st.sampled_from(["", "\n", "\n\n"]),
       st.sampled_from(["\n", "\r\n"]), st.booleans(), st.booleans())
def test_a_plain_map_read_whole_is_the_map_read_line_by_line(
        before: list[str], lines: list[str], after: list[str], end: str, newline: str,
        need_start: bool, need_goal: bool) -> None:
    text = newline.join(before + lines + after) + end
    whole = _outcome(text, need_start=need_start, need_goal=need_goal)
    with mock.patch.object(textmap, "_plain_map", return_value=None) as plain:
        by_line = _outcome(text, need_start=need_start, need_goal=need_goal)
    assert plain.called or isinstance(by_line, str)  # (a bad comment table is named first)
    assert whole == by_line


table_lines = st.lists(st.sampled_from(
    ["; terrain f 5", " ;terrain\tw 2.5 \r", "; terrain f", "; terrain ff 5", "; terrain f 5 x",
     "; terrain f 0", "S.G", "", "\x1c; terrain q 3", "; terrain é 4"]), max_size=6)


@given(table_lines)
def test_a_comment_table_found_in_the_whole_text_is_the_one_found_line_by_line(
        lines: list[str]) -> None:
    def table(source: object) -> object:
        try:
            return textmap.comment_table(source, "m.txt")  # type: ignore[arg-type]
        except MapError as err:
            return str(err)

    assert table(Lines("\n".join(lines))) == table(lines)


mai_cells = "..@TSW"


@given(st.integers(1, 4), st.integers(1, 4), st.data(),
       st.sampled_from(["", "\n", "\n\n", "\n \r\n"]), st.sampled_from(["\n", "\r\n"]))
def test_movingai_rows_read_whole_are_the_rows_read_line_by_line(
        width: int, height: int, data: st.DataObject, end: str, newline: str) -> None:
    even = st.text(alphabet=mai_cells, min_size=width, max_size=width)
    row = st.one_of(even, even, st.text(alphabet=mai_cells + " \r", max_size=5))
    rows = data.draw(st.lists(row, min_size=height - 1, max_size=height + 1))
    text = f"type octile\nheight {height}\nwidth {width}\nmap\n" + newline.join(rows) + end

    def outcome() -> object:
        try:
            grid = parse_movingai_map(text, "m.map", parse_terrain("S 3\nT 5"))
        except MapError as err:
            return str(err)
        return grid, grid.costs, grid.source

    whole = outcome()
    with mock.patch.object(movingai, "_whole_rows", return_value=None) as plain:
        by_line = outcome()
    assert plain.called or isinstance(by_line, str)
    assert whole == by_line


def _read_whole(text: str) -> bool:
    """Does the whole-text reader take ``text`` (rather than leave it to the line reader)?"""
    return textmap._plain_map(Lines(text), textmap.Alphabet(textmap.text_costs(textmap.EMPTY)),
                              "m", need_start=True, need_goal=True) is not None


def test_the_whole_text_reader_takes_the_plain_map_and_leaves_the_rest() -> None:
    big = "S" + "." * 9 + "\n" + (".#" * 5 + "\n") * 1000 + "." * 9 + "G\n"
    assert _read_whole(big)
    grid = parse_text_map(big)
    assert (grid.width, grid.height, grid.start, grid.goal) == (10, 1002, (0, 0), (9, 1001))
    assert grid.source is not None and grid.source.text() == big
    for text in ("; c\nSG\n", "S\r\nG\r\n", "S\r\nG\n", "\n \nSG\n\n; c\n", "SG\n; c"):
        assert _read_whole(text), text
    for text in ("3333\n3\n33", "S..\n.\n.G\n", "S\n; c\nG\n", "S \nG\n", "SG\n\n..\n",
                 "S.\nG\n", "SS\nG.\n", "Sé\nG.\n", "S\rG\n", "SG\n .\n"):
        assert not _read_whole(text), text


def test_a_map_of_millions_of_rows_without_a_start_is_named_at_once() -> None:
    text = ".\n" * 2_000_000
    try:
        parse_text_map(text, "big.txt")
    except MapError as err:
        assert str(err) == "big.txt: no start 'S' in the map"
    else:
        raise AssertionError("no error")


@given(st.integers(1, 40), st.integers(1, 40), st.booleans(), st.randoms(use_true_random=False))
def test_a_map_padded_in_blocks_or_columns_is_the_map_with_a_border(
        width: int, height: int, costed: bool, rnd: random.Random) -> None:
    """Narrow maps are padded a column at a time, wide ones a block of rows at a time (no
    object a row: a map of millions of one-cell rows): the map inside a border either way."""
    blocked = bytearray(rnd.randint(0, 1) for _ in range(width * height))
    costs = array("d", (rnd.choice((1.0, 2.5, 9.0)) for _ in range(width * height)))
    grid = Grid(width, height, blocked, costs=costs if costed else None)
    with mock.patch.object(problem, "_BLOCK_BYTES", rnd.randint(1, 64)):
        walls, terrain = problem.padded(grid)
    stride = width + 2
    inside = [(y + 1) * stride + x + 1 for y in range(height) for x in range(width)]
    assert len(walls) == stride * (height + 2)
    assert [walls[p] for p in inside] == list(blocked)
    assert walls.count(1) == len(walls) - len(inside) + blocked.count(1)
    if grid.costs is None:  # (all 1: a plain map)
        assert terrain is None
    else:
        assert terrain is not None and [terrain[p] for p in inside] == list(costs)
        assert sum(terrain) == sum(costs) + len(walls) - len(inside)


@pytest.mark.parametrize("header", ["", "; a comment first\n"])
def test_a_map_of_one_cell_rows_is_searched_within_ten_times_its_size(header: str) -> None:
    """Issue 42's map, a megabyte of it: ``S``, one-cell rows, ``G``, read and searched one
    step (``--headless --max-steps 1``) in at most ten times its size, where a slice object
    a row once took 143 times (the 64 MB one is benchmarks/big_map.py's)."""
    text = header + "S\n" + ".\n" * 500_000 + "G\n"
    Run(parse_text_map("S.G\n"), "bfs", Semantics(), 1).advance()  # one-off costs first
    tracemalloc.start()
    try:
        run = Run(parse_text_map(text), "bfs", Semantics(), 1)
        run.advance()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert run.grid.height == 500_002 and run.recorded == 1
    assert peak <= 10 * len(text)
