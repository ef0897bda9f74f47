"""No figure the app writes can meet Python's limit on writing an int in decimal (4,300
digits by default, 640 at least): the tutorial's bound ``7^(d+1)`` beside a path of
``d`` moves is written short.  ``end`` on a 301x301 maze once raised ``ValueError: Exceeds
the limit (4300 digits) for integer string conversion`` from the status line.  Here every
search at its end, on the longest path a test can afford, the largest generated maps, and
the app itself, each at Python's lowest limit."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.engine.test_numbers import int_digits
from tests.tui.test_app import stats, sync, wait_until
from tui_search.engine.maps.generate import generate, generated_text, make_recipe
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.engine.maps.recipes import MAX_SIDE
from tui_search.engine.run.recorded import Run
from tui_search.engine.run.recording import MAX_STEPS
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import ALGORITHMS, get_algorithm
from tui_search.engine.util.numbers import power_text
from tui_search.tui.app import SearchApp
from tui_search.tui.view.narration import result_text
from tui_search.tui.view.pieces import line_text
from tui_search.tui.view.status_lines import search_status

#: Python's lowest limit on the digits of an int written in decimal (``sys.int_info``).
LOWEST_LIMIT = 640


def at_end(run: Run) -> Run:
    run.advance()
    assert run.total is not None
    run.goto(run.total)
    return run


def status_texts(run: Run) -> list[str]:
    """What the status lines say of ``run``, under the panes and in a pane."""
    name = get_algorithm(run.algorithm).short
    return [line_text(line.pieces) for in_pane in (False, True)
            for line in search_status(run, name, in_pane=in_pane).lines]


@pytest.mark.parametrize("key", list(ALGORITHMS))
def test_every_search_at_its_end_writes_its_bound_short(key: str) -> None:
    """A corridor of 800 rows: a bound of 677 digits, over the lowest limit (iterative
    deepening, the dearest, takes some 320,000 steps to its end)."""
    grid = parse_map_text("S\n" + ".\n" * 799 + "G\n")
    with int_digits(LOWEST_LIMIT):
        run = at_end(Run(grid, key, Semantics()))
        texts = status_texts(run)
    assert run.found and len(run.moves() or []) == 800
    assert "of at most 7⁸⁰¹ ≈ 8.3×10⁶⁷⁶" in result_text(run)
    assert any("7⁸⁰¹ ≈ 8.3×10⁶⁷⁶" in text for text in texts)


def serpentine(side: int) -> str:
    """A ``side`` x ``side`` map whose one path winds through every other row: the longest a
    map of that size has, about half its cells."""
    rows = []
    for y in range(side):
        if y % 2 == 0:
            rows.append("." * side)
        else:
            gap = side - 1 if y % 4 == 1 else 0
            rows.append("#" * gap + "." + "#" * (side - 1 - gap))
    rows[0] = "S" + rows[0][1:]
    rows[-1] = rows[-1][:-1] + "G"
    return "\n".join(rows) + "\n"


def test_the_longest_path_of_the_largest_generated_size_at_every_search_s_end() -> None:
    """The generators' largest size, with the longest path it can hold; every search at its
    end (iterative deepening and IDA* give up at their step limit there, as ``end`` does in
    the app)."""
    grid = parse_map_text(serpentine(MAX_SIDE))
    with int_digits(LOWEST_LIMIT):
        for key in ALGORITHMS:
            limit = 10_000 if get_algorithm(key).iterative else MAX_STEPS
            run = at_end(Run(grid, key, Semantics(), limit))
            texts = status_texts(run)
            if get_algorithm(key).iterative:
                assert not run.found and "Gave up" in " ".join(texts)
                continue
            moves = len(run.moves() or [])
            assert moves > MAX_SIDE**2 // 3 and power_text(7, moves + 1) in texts[1], key


def test_the_largest_generated_maze_at_the_end_of_a_breadth_first_search() -> None:
    recipe = make_recipe("maze", f"{MAX_SIDE}x{MAX_SIDE}")
    with int_digits(LOWEST_LIMIT):
        run = at_end(Run(generate(recipe, recipe.title), "bfs", Semantics()))
        text = result_text(run)
    assert power_text(7, len(run.moves() or []) + 1) in text and "≈" in text


@sync
async def test_end_on_a_generated_301x301_maze_shows_the_bound_short(tmp_path: Path) -> None:
    """The issue's map: ``tui-search --generate maze --size 301x301 --seed 1 --output m.txt``,
    then ``tui-search m.txt`` and ``end``."""
    path = tmp_path / "m.txt"
    path.write_text(generated_text(make_recipe("maze", "301x301", "1")), "utf-8")
    app = SearchApp(load_map(path), path=path)
    async with app.run_test(size=(100, 32)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        await wait_until(pilot, lambda: "≈" in " ".join(stats(app)))
        assert len(app.session.run.moves() or []) == 10_295
        assert "of at most 7¹⁰²⁹⁶ ≈ 1.3×10⁸⁷⁰¹" in " ".join(stats(app))
