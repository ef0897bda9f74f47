"""The map generators: perfect mazes are trees, random maps join S and G, a recipe gives the
same bytes every time (pinned by golden files), and bad recipes are one-line errors."""

from __future__ import annotations

import hashlib
from collections import deque
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import ROOT
from tui_search.engine.maps.generate import (
    KINDS,
    generate,
    generated_text,
    make_recipe,
    next_recipe,
    parse_recipe,
    recipe_of,
)
from tui_search.engine.maps.grid import Grid
from tui_search.engine.util.prng import SplitMix64, seed_value

GOLDEN = ROOT / "tests" / "data" / "generated"
PERFECT = [k for k, kind in KINDS.items() if kind.perfect]
SEEDS = st.one_of(st.integers(-(10**20), 10**20).map(str),
                  st.text(st.characters(blacklist_categories=["Cc", "Cs", "Zl", "Zp"]),
                          min_size=1, max_size=12)
                  .filter(lambda s: s.strip() == s and s.isprintable() and s != ""))


def open_cells(grid: Grid) -> set[tuple[int, int]]:
    return {(x, y) for y in range(grid.height) for x in range(grid.width)
            if not grid.is_blocked((x, y))}


def reachable(grid: Grid, start: tuple[int, int]) -> set[tuple[int, int]]:
    """The free cells reachable from ``start`` under the four moves."""
    seen = {start}
    todo = deque([start])
    while todo:
        x, y = todo.popleft()
        for n in ((x, y - 1), (x + 1, y), (x, y + 1), (x - 1, y)):
            if grid.in_bounds(n) and not grid.is_blocked(n) and n not in seen:
                seen.add(n)
                todo.append(n)
    return seen


def edges(cells: set[tuple[int, int]]) -> int:
    return sum((x + 1, y) in cells for x, y in cells) + sum((x, y + 1) in cells for x, y in cells)


def test_splitmix64_gives_the_reference_numbers() -> None:
    rng = SplitMix64(0)  # the reference implementation's first outputs for seed 0
    assert [rng.next() for _ in range(3)] == [
        0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4, 0x06C45D188009454F]


def test_seeds_are_whole_numbers_or_the_sha256_of_text() -> None:
    assert seed_value("7") == seed_value("007") == seed_value(" +7 ") == 7
    assert seed_value("-1") == 2**64 - 1
    digest = hashlib.sha256(b"alice").digest()
    assert seed_value("alice") == int.from_bytes(digest[:8], "big") == 0x2BD806C97F0E00AF


def test_below_is_in_range_and_every_value_comes() -> None:
    rng = SplitMix64(1)
    assert {rng.below(5) for _ in range(200)} == set(range(5))


@settings(max_examples=60, deadline=None)
@given(kind=st.sampled_from(PERFECT), w=st.integers(3, 31), h=st.integers(3, 31), seed=SEEDS)
def test_a_perfect_maze_is_a_tree_with_s_and_g_at_far_corners(kind: str, w: int, h: int,
                                                              seed: str) -> None:
    grid = generate(make_recipe(kind, f"{w}x{h}", seed))
    cells = open_cells(grid)
    assert reachable(grid, (0, 0)) == cells  # connected ...
    assert edges(cells) == len(cells) - 1  # ... and without a cycle: a tree
    assert grid.start == (0, 0)
    assert grid.goal == (w - 1 - (w % 2 == 0), h - 1 - (h % 2 == 0))


@settings(max_examples=40, deadline=None)
@given(w=st.integers(9, 40), h=st.integers(9, 40), seed=SEEDS)
def test_rooms_reach_every_room_from_the_start(w: int, h: int, seed: str) -> None:
    grid = generate(make_recipe("rooms", f"{w}x{h}", seed))
    assert reachable(grid, (0, 0)) == open_cells(grid)
    assert grid.goal in open_cells(grid)


@settings(max_examples=60, deadline=None)
@given(p=st.integers(0, 100), w=st.integers(2, 30), h=st.integers(2, 30), seed=SEEDS)
def test_random_maps_join_start_and_goal(p: int, w: int, h: int, seed: str) -> None:
    grid = generate(make_recipe(f"random:{p}", f"{w}x{h}", seed))
    assert (grid.start, grid.goal) == ((0, 0), (w - 1, h - 1))
    assert grid.goal in reachable(grid, (0, 0))


@pytest.mark.parametrize("p", [0, 10, 30, 45, 60, 90, 100])
def test_random_keeps_within_3_points_of_p_on_100x100(p: int) -> None:
    grid = generate(make_recipe(f"random:{p}", "100x100", "7"))
    blocked = sum(grid.blocked) / 100
    assert abs(blocked - p) <= 3


@settings(max_examples=30, deadline=None)
@given(kind=st.sampled_from(["random:35", *PERFECT, "rooms"]), seed=SEEDS)
def test_the_same_recipe_gives_the_same_bytes_and_says_so(kind: str, seed: str) -> None:
    recipe = make_recipe(kind, "23x17", seed)
    text = generated_text(recipe)
    assert generated_text(recipe) == text
    assert text.splitlines()[0] == f"; generated: {recipe.title}"
    assert recipe_of(generate(recipe)) == recipe  # made again from its first line
    assert generated_text(next_recipe(recipe)).splitlines()[1:] != text.splitlines()[1:]


@pytest.mark.parametrize("golden", sorted(GOLDEN.glob("*.txt")), ids=lambda p: p.stem)
def test_golden_files_pin_the_bytes(golden) -> None:
    data = golden.read_bytes()
    recipe = parse_recipe(data.decode("utf-8").splitlines()[0].removeprefix("; generated:"))
    assert generated_text(recipe).encode("utf-8") == data


def test_there_is_a_golden_file_for_every_kind() -> None:
    kinds = {parse_recipe(p.read_text("utf-8").splitlines()[0][13:]).kind
             for p in GOLDEN.glob("*.txt")}
    assert kinds == set(KINDS)


def test_recipes_read_back_and_next_seeds() -> None:
    r = parse_recipe("random:12.5 9x5 seed my seed")
    assert (r.kind, r.percent, r.width, r.height, r.seed) == ("random", Fraction(25, 2), 9, 5,
                                                             "my seed")
    assert r.title == "random:12.5 9x5 seed my seed"
    assert next_recipe(make_recipe("maze", "5x5", "7")).seed == "8"
    assert next_recipe(make_recipe("maze", "5x5", "alice9")).seed == "alice10"
    assert next_recipe(make_recipe("maze", "5x5", "alice")).seed == "alice2"


@pytest.mark.parametrize(("kind", "size", "seed", "message"), [
    ("blob", "9x9", "1",
     "unknown kind 'blob' (kinds: random:P, maze, prim, kruskal, division, rooms)"),
    ("random", "9x9", "1", "random needs its percentage of obstacles: random:P, e.g. random:30"),
    ("random:101", "9x9", "1", "random:101: P must be a number from 0 to 100"),
    ("random:-1", "9x9", "1", "random:-1: P must be a number from 0 to 100"),
    ("maze:3", "9x9", "1", "maze takes no ':3'"),
    ("maze", "9by9", "1", "size '9by9': expected WIDTHxHEIGHT, e.g. 15x15"),
    ("maze", "2x9", "1", "size 2x9: maze needs at least 3x3"),
    ("rooms", "9x8", "1", "size 9x8: rooms needs at least 9x9"),
    ("maze", "1000x9", "1", "size 1000x9: at most 999x999"),
    ("maze", "9x9", " ", "the seed is empty: a whole number or any text"),
    ("maze", "9x9", "a\x1bb", "the seed must be printable text of at most 100 characters"),
])
def test_bad_recipes_say_what_is_wrong(kind: str, size: str, seed: str, message: str) -> None:
    with pytest.raises(ValueError) as err:
        make_recipe(kind, size, seed)
    assert str(err.value) == message
