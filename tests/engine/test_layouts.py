"""Pacman layouts (``.lay``): read as a grid (walls, start, first dot the goal, the course's
y from the bottom), every parser error one line with its place, written back keeping what
was not edited, and ``--preset cs188``'s counts on a maze of our own, held equal to an
independent few-line search in the course's conventions."""

from __future__ import annotations

import heapq
from collections import deque
from pathlib import Path

import pytest

from tests.engine.map_helpers import error_of, write
from tui_search.engine.course.presets import preset_semantics
from tui_search.engine.maps.layouts import course_cell, parse_layout
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import LAY
from tui_search.engine.maps.write import format_map, kind_for_path, save_map
from tui_search.engine.search.reference import stream
from tui_search.engine.search.registry import get_algorithm

ROOT = Path(__file__).resolve().parents[2]
LAYOUTS = ROOT / "examples" / "cs188_style" / "layouts"
TWISTY = LAYOUTS / "twistyMaze.lay"
THREE_DOTS = LAYOUTS / "threeDots.lay"


def test_a_layout_reads_walls_start_and_goal() -> None:
    grid = parse_layout("%%%%%\n%P .%\n%%%%%\n", "t.lay")
    assert (grid.width, grid.height) == (5, 3)
    assert grid.start == (1, 1) and grid.goal == (3, 1)
    assert grid.is_blocked((0, 0)) and not grid.is_blocked((2, 1))
    assert grid.source is not None and grid.source.kind == LAY and grid.source.note == ""


def test_capsules_ghosts_and_digits_are_free_and_the_first_dot_is_the_goal() -> None:
    grid = load_map(THREE_DOTS)
    assert grid.start == (1, 3)
    assert grid.goal == (8, 1)  # the first dot of the file: the top line's
    for cell in ((1, 1), (5, 1), (7, 3)):  # o, G, 1
        assert not grid.is_blocked(cell)
    assert grid.source is not None
    assert grid.source.note == "3 dots: the goal is the first, (8,1) (the course's (8,3))"


def test_the_course_counts_y_from_the_bottom_row() -> None:
    grid = load_map(TWISTY)
    assert course_cell(grid, grid.goal) == (1, 1)  # as the course's mazes put their dot
    assert course_cell(grid, grid.start) == (33, 15)
    assert course_cell(grid, course_cell(grid, (4, 7))) == (4, 7)


@pytest.mark.parametrize(("text", "error"), [
    ("", "t.lay: empty layout: no rows of % walls, P and ."),
    ("%%%\n%P.%\n", "t.lay:2:4: row has 4 cells, expected 3"),
    ("%%%%\n%P.\n", "t.lay:2:4: row has 3 cells, expected 4"),
    ("%%%%\n%Px.\n", "t.lay:2:3: unknown layout character 'x' (use % walls, P the start, . "
     "food, o G digits and spaces free)"),
    ("%P%\n\n%.%\n", "t.lay:2: blank line inside the layout"),
    ("%PP.\n", "t.lay:1:3: a second P (the first is at line 1, column 2)"),
    ("% .%\n", "t.lay: no P: the layout has no start"),
    ("%P %\n", "t.lay: no . (food): the layout has no goal"),
])
def test_each_bad_layout_is_one_line_with_its_place(text: str, error: str) -> None:
    assert error_of(parse_layout, text, "t.lay") == error


def test_flags_give_what_the_layout_lacks_and_terrain_is_refused() -> None:
    grid = parse_map_text("%P %\n", "t.lay", goal=(2, 0))
    assert grid.goal == (2, 0)
    with pytest.raises(MapError, match="a Pacman layout has no terrain"):
        from tui_search.engine.maps.terrain import Terrain

        parse_map_text("%P.%\n", "t.lay", terrain=Terrain({"f": 5.0}, {}))


def test_a_save_rewrites_only_what_changed(tmp_path: Path) -> None:
    path = write(tmp_path, "three.lay", THREE_DOTS.read_text())
    grid = load_map(path)
    grid.set_blocked((2, 3), True)
    grid.goal = (4, 3)  # the dot before the old goal in the file's order: still a dot
    save_map(grid, path, kind_for_path(path))
    assert path.read_text().splitlines() == [
        "%%%%%%%%%%",
        "%o   G   %",  # the old goal's dot came before the new goal: a space now
        "% %%%% % %",
        "%P% .  1.%",  # a wall drawn; the capsule, ghost, ghost 1 and the last dot kept
        "%%%%%%%%%%",
    ]
    again = load_map(path)
    assert again.goal == (4, 3) and again.start == (1, 3) and again.blocked == grid.blocked


def test_a_new_layout_file_is_written_from_the_grid() -> None:
    grid = parse_map_text("S.#\n..G\n", "m.txt")
    assert format_map(grid, LAY).text() == "P %\n  .\n"


# -- the preset's counts, against an independent search in the course's conventions --------

def course_search(lines: list[str], frontier: str, h: bool = False) -> tuple[int, int]:
    """The course's way, written again in a few lines: (x, y) with y from the bottom row,
    successors N, S, E, W, graph search with a closed set, the goal tested when taken off; a
    priority queue's ties by the order pushed.  Returns (getSuccessors calls, moves)."""
    height = len(lines)
    at = {(x, height - 1 - y): c for y, row in enumerate(lines) for x, c in enumerate(row)}
    start = next(cell for cell, c in at.items() if c == "P")
    goal = next(cell for cell, c in at.items() if c == ".")

    def successors(cell: tuple[int, int]) -> list[tuple[int, int]]:
        x, y = cell
        return [n for n in ((x, y + 1), (x, y - 1), (x + 1, y), (x - 1, y)) if at[n] != "%"]

    count, calls, closed = 0, 0, set()
    queue: list = [(0, count, start, 0)]
    line: deque = deque([(start, 0)])
    while queue if frontier == "pq" else line:
        if frontier == "pq":
            _, _, cell, g = heapq.heappop(queue)
        else:
            cell, g = line.popleft() if frontier == "fifo" else line.pop()
        if cell == goal:
            return calls, g
        if cell in closed:
            continue
        closed.add(cell)
        calls += 1
        for n in successors(cell):
            if n not in closed:
                count += 1
                f = g + 1 + (abs(n[0] - goal[0]) + abs(n[1] - goal[1]) if h else 0)
                heapq.heappush(queue, (f, count, n, g + 1))
                line.append((n, g + 1))
    raise AssertionError("no path")


@pytest.mark.parametrize(("key", "frontier", "course", "moves"), [
    ("bfs", "fifo", 200, 58), ("dfs", "lifo", 151, 90), ("ucs", "pq", 200, 58),
    ("astar", "pq", 114, 58),
])
def test_the_presets_counts_on_our_own_maze(key: str, frontier: str, course: int,
                                            moves: int) -> None:
    """The course's counts on its medium maze are BFS 269 expansions for 68 moves, A* with
    Manhattan distance 221 for 68; on our twisty maze (35 by 17, its dot bottom left as
    theirs) these, each held equal to the independent search.  The app counts the goal's step
    as an expansion; the course counts getSuccessors calls, which the goal never gets."""
    grid = load_map(TWISTY)
    algorithm = get_algorithm(key)
    outcome = stream(grid, algorithm, preset_semantics("cs188", algorithm), 10_000)
    lines = TWISTY.read_text().splitlines()
    assert course_search(lines, frontier, h=key == "astar") == (course, moves)
    assert outcome.path is not None
    assert (outcome.expanded - 1, len(outcome.path) - 1) == (course, moves)
