"""What the map file tests share: small maps, the error a call raises, writing a test file,
random grids and a random 512x512 MovingAI map."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import strategies as st

from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import MapError

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


def write_512_map(tmp_path: Path) -> tuple[Path, list[str]]:
    """A seeded random 512x512 MovingAI map (the size of maze512-1-0, random512-40-5 and
    64room_005) of every MovingAI letter, and its rows."""
    rng = random.Random(512)
    rows = ["".join(rng.choices(".G@OTSW", k=512)) for _ in range(512)]
    path = write(tmp_path, "big512.map",
                 "type octile\nheight 512\nwidth 512\nmap\n" + "\n".join(rows) + "\n")
    return path, rows
