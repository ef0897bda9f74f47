"""Big maps read in a few passes over the text (issue 21: a 64 MB map of ``.`` rows took 77 s
and 6 GB): the file's lines kept as one string (:class:`Lines`), and a plain map read whole
(:func:`tui_search.engine.maps.text._plain_map`), which must give exactly what the line by line
reader gives, grid and error alike.  The memory itself is measured in benchmarks/big_map.py."""

from __future__ import annotations

from unittest import mock

from hypothesis import given
from hypothesis import strategies as st

from tui_search.engine.maps import text as textmap
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import Lines
from tui_search.engine.maps.terrain import parse_terrain
from tui_search.engine.maps.text import parse_text_map

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


@given(st.one_of(ragged, even), st.sampled_from(["", "\n", "\n\n"]),
       st.booleans(), st.booleans())
def test_a_plain_map_read_whole_is_the_map_read_line_by_line(
        lines: list[str], end: str, need_start: bool, need_goal: bool) -> None:
    text = "\n".join(lines) + end
    whole = _outcome(text, need_start=need_start, need_goal=need_goal)
    with mock.patch.object(textmap, "_plain_map", return_value=None) as plain:
        by_line = _outcome(text, need_start=need_start, need_goal=need_goal)
    assert plain.called
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
    for text in ("3333\n3\n33", "S..\n.\n.G\n", "; c\nSG\n", "S\r\nG\n", "S \nG\n", "SG\n\n..\n",
                 "S.\nG\n", "\nSG\n", "SS\nG.\n", "Sé\nG.\n"):
        assert not _read_whole(text), text


def test_a_map_of_millions_of_rows_without_a_start_is_named_at_once() -> None:
    text = ".\n" * 2_000_000
    try:
        parse_text_map(text, "big.txt")
    except MapError as err:
        assert str(err) == "big.txt: no start 'S' in the map"
    else:
        raise AssertionError("no error")
