"""The search tree's model, without Textual: what the tree panel lists, line by line, with
roles instead of styles -- tested directly, like the narration."""

from __future__ import annotations

import subprocess
import sys

from hypothesis import given, settings
from hypothesis import strategies as st

from tests.engine.test_core import semantics
from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.run.recorded import Run
from tui_search.tui.view import tree_listing as tree_model
from tui_search.tui.view.tree_listing import TreeModel


def lines(model: TreeModel) -> list[str]:
    return [model.line_text(y) for y in range(model.line_count())]


def at(algorithm: str, k: int, sem=None) -> tuple[Run, TreeModel]:
    run = Run(grid_from_rows(TUTORIAL_ROWS), algorithm, *(sem,) if sem else ())
    run.goto(k)
    model = TreeModel()
    model.update(run)
    return run, model


def test_the_model_imports_without_textual() -> None:
    code = ("import sys, tui_search.tui.view.tree_listing; "
            "print(any(m.split('.')[0] in ('textual', 'rich') for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


#: The tutorial's BFS tree after S, S, SE are expanded; SE (1,2) is being expanded.
BFS_AFTER_FOUR = [
    "8 nodes",
    "● START (0,0)",
    "└─ ● S (0,1)",
    "   ├─ ● S (0,2)",
    "   │  ├─ ○ S (0,3)",
    "   │  └─ ○ SE (1,3)",
    "   └─ ● SE (1,2)  ◀ expanding",
    "      ├─ ○ E (2,2)",
    "      └─ ○ NE (2,1)",
]


def test_the_tutorials_bfs_tree_after_four_steps() -> None:
    _, model = at("bfs", 4)
    assert model.mode == "list"
    assert lines(model) == BFS_AFTER_FOUR
    assert model.current_line() == 6
    roles = {role for y in range(model.line_count()) for _, role in model.line(y)}
    assert roles == {"note", "guide", "expanded", "frontier", "current"}


def test_the_path_is_its_own_role_at_the_end() -> None:
    run, model = at("dfs", 10**6)
    assert model.path_shown
    path_lines = [model.line_text(y) for y in range(model.line_count())
                  if any(role == "path" for _, role in model.line(y))]
    assert len(path_lines) == len(run.path())
    assert "★ S (5,2)" in path_lines[-1]


def test_a_big_tree_is_focused_on_the_node_being_expanded(monkeypatch) -> None:
    monkeypatch.setattr(tree_model, "SMALL_TREE", 3)
    _run, model = at("bfs", 6)
    assert model.mode == "focus"
    text = lines(model)
    assert text[0].startswith("(") and "showing the path to the node being expanded" in text[0]
    assert any("◀ expanding" in line for line in text)


@settings(max_examples=120, deadline=None)
@given(random_grids(max_side=6), semantics(), st.lists(st.integers(0, 300), max_size=6))
def test_the_model_kept_in_step_equals_one_built_afresh(grid, choice, targets) -> None:
    """Stepping the model along (forwards, backwards, jumps) lists exactly what a new model
    lists at the same position, under every search choice."""
    key, sem = choice
    run = Run(grid, key, sem, 300)
    run.advance()
    kept = TreeModel()
    for t in targets:
        run.goto(t % (run.total + 1))
        kept.update(run)
        fresh = TreeModel()
        fresh.update(run)
        assert [kept.line(y) for y in range(kept.line_count())] == [
            fresh.line(y) for y in range(fresh.line_count())]


def test_at_the_end_no_node_is_still_expanding() -> None:
    """The last node expanded says "◀ expanding" while the search runs, not once it ended
    (the goal found, or no path): the listing and the focused view of a big tree alike."""
    run, model = at("bfs", 21)
    assert sum("◀ expanding" in line for line in lines(model)) == 1
    run.goto(10**6)
    model.update(run)
    assert run.at_end and not any("◀ expanding" in line for line in lines(model))
    walled = grid_from_rows(["S#.", "##.", "..G"])
    blocked = Run(walled, "dfs")
    blocked.goto(10**6)
    model = TreeModel()
    model.update(blocked)
    assert not blocked.found and not any("◀" in line for line in lines(model))


def test_a_deep_tree_s_depths_are_grouped_in_thousands() -> None:
    """The focused view of a tree some 1,300 deep (tree search down a corridor): its depth
    column reads 1,299, as every count the app shows groups its digits."""
    from tui_search.engine.maps.grid import Grid
    from tui_search.engine.search.choices import Semantics

    run = Run(Grid(3, 2000, start=(1, 0), goal=(1, 1999)), "dfs", Semantics(tree_search=True))
    run.goto(1500)
    model = TreeModel()
    model.update(run)
    text = lines(model)
    assert text[3].startswith("1,299 └─ ● S (2,1298)"), text[:4]
    assert text[1] == "    0 ● START (1,0)"
