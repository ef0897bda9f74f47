"""Saving maps: atomic writes that keep the old file on failure, and saving that keeps the
file (comments, headers, letters, line ends) with only the edited cells changed."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.map_helpers import TUTORIAL, MAI_2x3, error_of, grids, write
from tests.helpers import MAPS, MOVINGAI
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.movingai import parse_movingai_map
from tui_search.engine.maps.source import MOVINGAI as MAI_KIND
from tui_search.engine.maps.source import TEXT as TEXT_KIND
from tui_search.engine.maps.text import parse_text_map
from tui_search.engine.maps.write import (
    format_map,
    format_text_map,
    kind_for_path,
    save_map,
    save_text_map,
)
from tui_search.engine.util import atomic

# -- save_text_map -------------------------------------------------------------------------


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

    monkeypatch.setattr(atomic.os, failing, broken)
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

    monkeypatch.setattr(atomic.os, "open", read_only_folder)
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


# -- saving keeps the file: MapSource ------------------------------------------------------


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
    differ = {i for i, (a, b) in enumerate(zip(text, saved, strict=True)) if a != b}
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
    changed = [i for i, (a, b) in enumerate(zip(old, new, strict=True)) if a != b]
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
    differ = [i for i, (a, b) in enumerate(zip(original, path.read_bytes(), strict=True)) if a != b]
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
