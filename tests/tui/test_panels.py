"""The frontier panel and the search-tree panel, each alone in a tiny app, on the tutorial's map.

Assertions are on the text of the rendered lines (``render_line(y).text``), so they check what a
student sees: the queue/stack order, the markers, the titles, the tree's edge labels.
"""

from __future__ import annotations

import asyncio
import functools
from collections.abc import Callable, Coroutine
from math import ceil
from types import SimpleNamespace
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from rich.segment import Segment
from textual.app import App, ComposeResult
from textual.geometry import Size
from textual.scrollbar import ScrollBarRender
from textual.widget import Widget

from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tests.textual_internals import settle
from tests.tui.test_tree_model import BFS_AFTER_FOUR
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run
from tui_search.tui.view import tree_listing as tree_model
from tui_search.tui.view import tree_shape
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.line_panel import window_strip
from tui_search.tui.widgets.scrollbars import scrollbar_cells
from tui_search.tui.widgets.search_tree import SearchTreePanel


def sync(test: Callable[..., Coroutine[Any, Any, None]]) -> Callable[..., None]:
    """Run an async test with ``asyncio.run`` (the project pins no async pytest plugin)."""

    @functools.wraps(test)
    def wrapper(*args: Any, **kwargs: Any) -> None:
        asyncio.run(test(*args, **kwargs))

    return wrapper


class PanelApp(App):
    """Just one panel, shown the run at mount."""

    def __init__(self, panel: Widget, run: Run) -> None:
        super().__init__()
        self.panel = panel
        self.run_ = run

    def compose(self) -> ComposeResult:
        yield self.panel

    def on_mount(self) -> None:
        self.panel.show(self.run_)  # type: ignore[attr-defined]


def tutorial_run(algorithm: str, k: int | None = None) -> Run:
    """A run on the tutorial map at step ``k`` (the end when None)."""
    run = Run(grid_from_rows(TUTORIAL_ROWS), algorithm)
    run.advance()
    run.goto(run.recorded if k is None else k)
    return run


def screen_lines(panel: Widget) -> list[str]:
    """The panel's visible lines as plain text, trailing blanks dropped."""
    lines = [panel.render_line(y).text.rstrip() for y in range(panel.size.height)]
    while lines and not lines[-1]:
        lines.pop()
    return lines


def walled_goal_grid(size: int) -> Grid:
    """An open ``size`` x ``size`` map whose goal (the far corner) is walled in, so a search
    explores everything."""
    grid = Grid(size, size, start=(0, 0), goal=(size - 1, size - 1))
    for cell in ((size - 2, size - 1), (size - 2, size - 2), (size - 1, size - 2)):
        grid.set_blocked(cell, True)
    return grid


# -- the frontier panel --------------------------------------------------------------------


@sync
async def test_bfs_queue_follows_the_tutorial() -> None:
    """BFS: START adds S; S adds S, SE; S adds S, SE; SE adds E, NE -- a queue, front first."""
    run = tutorial_run("bfs", 0)
    panel = FrontierPanel()
    async with PanelApp(panel, run).run_test(size=(50, 12)) as pilot:
        assert panel.border_title == "Queue (FIFO)"
        assert screen_lines(panel) == ["1 in the queue", "▶  (0,0) START  ← front and back"]
        expected = {
            1: ["▶+ (0,1) S   ← front and back"],
            2: ["▶+ (0,2) S   ← front (next out)",
                " + (1,2) SE  ← back (newest)"],
            3: ["▶  (1,2) SE  ← front (next out)",
                " + (0,3) S",
                " + (1,3) SE  ← back (newest)"],
            4: ["▶  (0,3) S   ← front (next out)",
                "   (1,3) SE",
                " + (2,2) E",
                " + (2,1) NE  ← back (newest)"],
        }
        for k, lines in expected.items():
            run.goto(k)
            panel.show(run)
            await pilot.pause()
            assert panel.border_title == "Queue (FIFO)"
            assert screen_lines(panel) == [f"{len(lines)} in the queue", *lines], k
        assert panel.border_subtitle == "▶ next out  + just added"


@sync
async def test_dfs_stack_has_ne_on_top() -> None:
    """DFS step 3 expands SE (1,2), pushing SW, S, E, NE: NE on top, the old S at the bottom."""
    run = tutorial_run("dfs", 3)
    panel = FrontierPanel()
    async with PanelApp(panel, run).run_test(size=(50, 12)):
        assert run.now.current_node() == (1, 2)
        assert panel.border_title == "Stack (LIFO)"
        assert screen_lines(panel) == [
            "5 on the stack",
            "▶+ (2,1) NE  ← top (next out)",
            " + (2,2) E",
            " + (1,3) S",
            " + (0,3) SW",
            "   (0,2) S   ← bottom (oldest)",
        ]


@sync
async def test_iddfs_stack_shows_depths_and_iteration_ends() -> None:
    """Iterative deepening: each entry's depth; an emptied stack announces the next limit."""
    run = tutorial_run("iddfs", 5)
    panel = FrontierPanel()
    async with PanelApp(panel, run).run_test(size=(50, 12)) as pilot:
        assert run.steps.depth_limit() == 2
        assert panel.border_title == "Stack (LIFO)"
        assert screen_lines(panel) == [
            "2 on the stack",
            "▶+ (1,2) d=2 SE  ← top (next out)",
            " + (0,2) d=2 S   ← bottom (oldest)",
        ]
        run.goto(3)  # limit 1: S (0,1) expanded at the limit, nothing left
        panel.show(run)
        await pilot.pause()
        assert panel.border_title == "Stack (LIFO)"
        assert screen_lines(panel) == ["empty — iteration over; next: depth limit 2"]


@sync
async def test_empty_frontier_says_no_path() -> None:
    run = Run(grid_from_rows(["S.#.", "..#G"]), "bfs")
    run.advance()
    run.goto(run.recorded)
    assert run.at_end and not run.found
    panel = FrontierPanel()
    async with PanelApp(panel, run).run_test(size=(40, 6)):
        assert panel.border_title == "Queue (FIFO)"
        assert screen_lines(panel) == ["empty — no path"]


@sync
async def test_big_queue_renders_and_scrolls_to_the_end() -> None:
    """BFS on an open 400x400 map after 100 000 steps: lines come from the run on demand."""
    run = Run(walled_goal_grid(400), "bfs")
    run.goto(100_000)
    n = run.now.frontier_len()
    panel = FrontierPanel()
    async with PanelApp(panel, run).run_test(size=(50, 20)) as pilot:
        assert panel.virtual_size.height == 1 + n
        assert screen_lines(panel)[0] == f"{n:,} in the queue".replace(",", " ")
        assert screen_lines(panel)[1].startswith("▶")
        panel.scroll_end(animate=False, immediate=True)
        await pilot.pause()
        last = screen_lines(panel)[-1]
        (g,) = run.now.frontier(n - 1, n)
        x, y = run.nodes.cell(g)
        assert f"({x},{y}) {run.nodes.move(g)}" in last and last.endswith("← back (newest)")
        # one more step: back to the front, the new entries marked at the back
        run.forward()
        panel.show(run)
        await pilot.pause()
        assert panel.scroll_offset.y == 0
        assert panel.line_text(run.now.frontier_len()).startswith(" +")  # the count, then entries


@sync
async def test_stack_of_100_000_entries() -> None:
    """DFS on an open 1000x1000 map: a stack of over 100 000 entries, bottom line reachable."""
    run = Run(walled_goal_grid(1000), "dfs")
    run.goto(80_000)
    n = run.now.frontier_len()
    assert n >= 100_000
    panel = FrontierPanel()
    async with PanelApp(panel, run).run_test(size=(50, 20)) as pilot:
        assert panel.border_title == "Stack (LIFO)"
        assert panel.line_text(0) == f"{n:,} on the stack"
        panel.scroll_end(animate=False, immediate=True)
        await pilot.pause()
        assert screen_lines(panel)[-1].endswith("← bottom (oldest)")
        bottom = screen_lines(panel)[-1].split()
        assert bottom[:2] == ["(0,1)", "S"]  # START's only push sits at the bottom


# -- the search tree -----------------------------------------------------------------------


def reference_tree(run: Run) -> list[str]:
    """The tree at the position in preorder, built from the engine's ``run.now.children()``:
    ``"  S (0,2)"`` (two spaces a level) -- an independent check of the panel's listing."""
    out = []
    todo = [(run.now.tree_root(), 0)]
    while todo:
        g, depth = todo.pop()
        x, y = run.nodes.cell(g)
        out.append(f"{'  ' * depth}{run.nodes.move(g)} ({x},{y})")
        todo.extend((c, depth + 1) for c in reversed(run.now.children(g)))
    return out


def strip_tree(line: str) -> str:
    """A panel line reduced to the reference form: guides to two spaces a level, no glyph,
    no suffix."""
    body = line.split("  ◀")[0].split("  ★")[0].split("  ✂")[0]
    i = 0
    while i < len(body) and body[i] in " │├└─":
        i += 1
    guides, label = body[:i], body[i + 2 :]  # drop "● " / "○ " / "★ "
    return "  " * (len(guides) // 3) + label


@sync
async def test_bfs_tree_after_four_steps() -> None:
    """The tutorial's BFS tree after S, S, SE are expanded; SE (1,2) is being expanded."""
    run = tutorial_run("bfs", 4)
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(50, 14)):
        assert panel.border_title == "Search tree"
        assert panel.mode == "list"
        assert screen_lines(panel) == BFS_AFTER_FOUR  # what the model lists, drawn


@sync
async def test_dfs_tree_after_three_steps_and_current_highlight() -> None:
    """DFS step 3: SE (1,2) expanded, its four successors under it; its line highlighted."""
    run = tutorial_run("dfs", 3)
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(50, 14)):
        lines = screen_lines(panel)
        assert lines == [
            "8 nodes",
            "● START (0,0)",
            "└─ ● S (0,1)",
            "   ├─ ○ S (0,2)",
            "   └─ ● SE (1,2)  ◀ expanding",
            "      ├─ ○ SW (0,3)",
            "      ├─ ○ S (1,3)",
            "      ├─ ○ E (2,2)",
            "      └─ ○ NE (2,1)",
        ]
        assert panel.current_line() == 4
        current = panel.get_component_rich_style("search-tree--current")
        frontier = panel.get_component_rich_style("search-tree--frontier")
        expanded = panel.get_component_rich_style("search-tree--expanded")
        assert len({current, frontier, expanded}) == 3

        def style_of(y: int, text: str):
            return next(s.style for s in panel.render_line(y) if text in s.text)

        assert style_of(4, "SE (1,2)") == current
        assert style_of(2, "S (0,1)") == expanded
        assert style_of(8, "NE (2,1)") == frontier


@sync
async def test_tree_path_highlighted_at_the_end() -> None:
    """Found: the goal S (5,2) under SE (5,1), the whole path START .. goal in the path colour
    (like the grid, the path outranks the "being expanded" highlight at the end)."""
    run = tutorial_run("bfs")
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(50, 40)):
        lines = screen_lines(panel)
        assert "★ goal" in panel.border_subtitle
        goal_line = next(y for y, line in enumerate(lines) if "★ goal" in line)
        assert lines[goal_line].endswith("└─ ★ S (5,2)  ★ goal")
        path_style = panel.get_component_rich_style("search-tree--path")
        on_path = {run.nodes.cell(g) for g in run.nodes.path()}  # the path outranks "current"
        assert len(on_path) == 8
        for y, line in enumerate(lines):
            cell = line.split(" (")[-1].split(")")[0] if "(" in line else None
            styles = [s.style for s in panel.render_line(y) if "(" in s.text]
            if cell and tuple(int(v) for v in cell.split(",")) in on_path:
                assert styles == [path_style], line


@sync
async def test_iddfs_tree_title_and_cutoff() -> None:
    """Iterative deepening: the current iteration's tree, its depth limit in the title, and
    nodes expanded at the limit marked as cut off."""
    run = tutorial_run("iddfs", 7)
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(50, 14)):
        assert run.steps.depth_limit() == 2
        assert panel.border_title == "Search tree · depth limit 2"
        assert screen_lines(panel) == [
            "4 nodes",
            "● START (0,0)",
            "└─ ● S (0,1)",
            "   ├─ ● S (0,2)  ◀ expanding",
            "   └─ ● SE (1,2)  ✂ depth limit",
        ]


@pytest.mark.parametrize("algorithm", ["bfs", "dfs", "iddfs"])
@sync
async def test_tree_listing_matches_the_engine_stepping_both_ways(algorithm: str) -> None:
    """The incrementally kept listing equals a tree built from ``run.now.children()`` at every
    step, forwards, backwards and after jumps."""
    run = tutorial_run(algorithm, 0)
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(60, 50)):
        order = list(range(run.recorded + 1))
        order += order[::-1] + [run.recorded // 2, run.recorded, 0, run.recorded // 3]
        for k in order:
            run.goto(k)
            panel.show(run)
            count, *lines = panel.lines()
            size = run.now.tree_size()
            assert count == f"{size} node{'s' if size != 1 else ''}", k
            assert [strip_tree(line) for line in lines] == reference_tree(run), k


@sync
async def test_big_tree_shows_the_focused_view() -> None:
    """BFS on an open 400x400 map after 100 000 steps: the path to the node being expanded,
    each line one edge, and that node's children, with the node in view."""
    run = Run(walled_goal_grid(400), "bfs")
    run.goto(100_000)
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(90, 20)) as pilot:
        assert panel.mode == "focus"
        size = run.now.tree_size()
        assert panel.border_title == "Search tree"
        note = panel.line_text(0)
        assert note == f"({size:,} nodes; showing the path to the node being expanded)"
        chain = run.nodes.ancestors(run.steps.expanded_event(run.k))
        depth = len(chain) - 1
        kids = list(run.now.added_now())
        assert panel.virtual_size.height == 3 + tree_shape.SHOW_LEVELS + 1 + len(kids)
        assert panel.line_text(1) == "  0 ● START (0,0)"
        hidden = depth - tree_shape.SHOW_LEVELS - 1
        assert panel.line_text(2) == f"    ⋮  {hidden} levels not shown"
        visible = screen_lines(panel)
        current = next(line for line in visible if "◀ expanding" in line)
        x, y = run.now.current_node()  # type: ignore[misc]
        assert current.lstrip().startswith(f"{depth} ")
        assert f"● {run.nodes.move(chain[-1])} ({x},{y})" in current
        # the last lines: the deepest edges, each with its move, then the children
        below = len(visible) - len(kids)
        for g, line in zip(chain[-5:], visible[below - 5 : below], strict=True):
            cx, cy = run.nodes.cell(g)
            assert f"{run.nodes.move(g)} ({cx},{cy})" in line
        for g, line in zip(kids, visible[below:], strict=True):
            cx, cy = run.nodes.cell(g)
            assert f"○ {run.nodes.move(g)} ({cx},{cy})" in line
        # a step forward keeps the new node in view
        run.forward()
        panel.show(run)
        await pilot.pause()
        x, y = run.now.current_node()  # type: ignore[misc]
        assert any("◀ expanding" in line and f"({x},{y})" in line for line in screen_lines(panel))


@sync
async def test_focused_view_on_the_tutorial(monkeypatch: pytest.MonkeyPatch) -> None:
    """The focused view in full on a small tree (forced): START to the last node expanded
    (the search over: no longer "◀ expanding"), sibling counts, depths, and the goal under
    it."""
    monkeypatch.setattr(tree_model, "SMALL_TREE", 3)
    run = tutorial_run("dfs")
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(64, 14)):
        assert panel.mode == "focus"
        assert screen_lines(panel) == [
            "(13 nodes; showing the path to the node being expanded)",
            "0 ● START (0,0)",
            "1 └─ ● S (0,1)  only child",
            "2    └─ ● SE (1,2)  child 2 of 2",
            "3       └─ ● NE (2,1)  child 4 of 4",
            "4          └─ ● NE (3,0)  child 2 of 2",
            "5             └─ ● E (4,0)  only child",
            "6                └─ ● SE (5,1)  only child",
            "7                   └─ ★ S (5,2)  ★ goal",
        ]


@sync
async def test_deep_dfs_chain_is_cut_to_its_deepest_levels() -> None:
    """A depth-first chain thousands of moves deep: START, a "⋮" line, the deepest levels."""
    run = Run(walled_goal_grid(400), "dfs")
    run.goto(20_000)
    panel = SearchTreePanel()
    async with PanelApp(panel, run).run_test(size=(90, 20)):
        assert panel.mode == "focus"
        assert panel.line_text(1).endswith("● START (0,0)")
        assert "⋮" in panel.line_text(2) and "levels not shown" in panel.line_text(2)
        x, y = run.now.current_node()  # type: ignore[misc]
        assert any("◀ expanding" in line and f"({x},{y})" in line for line in screen_lines(panel))


# -- drawing a line's window ---------------------------------------------------------------

texts = st.text(alphabet="ab│├└─●○◀★✂⋮ 漢字", max_size=12)


@settings(max_examples=250, deadline=None)
@given(st.lists(st.tuples(texts, st.sampled_from(["red", "bold", "blue on white"])),
                max_size=6), st.integers(0, 40), st.integers(0, 40))
def test_window_strip_draws_what_crop_extend_draws(pieces, x, width) -> None:
    """The panels' one-Strip window of a line is Textual's crop_extend, cell for cell, wide
    characters (two cells) cut at either edge included."""
    from rich.style import Style
    from textual.strip import Strip

    segments = [Segment(text, Style.parse(style)) for text, style in pieces]
    fill = Style.parse("on black")
    ours = window_strip(segments, x, width, fill)
    textual = Strip(segments).crop_extend(x, x + width, fill)
    assert ours.cell_length == width == textual.cell_length
    def seen(strip: Strip) -> Strip:  # what shows: empty segments dropped, like styles merged
        return Strip([segment for segment in strip if segment.text]).simplify()

    assert seen(ours) == seen(textual)
    assert all(segment.text for segment in ours)  # no empty segments (Textual warns of them)


# -- quiet scrollbars ----------------------------------------------------------------------

def drawn_bar(size: int, virtual: int, window: int, position: float, thickness: int = 1,
              vertical: bool = True) -> list:
    """The segments Textual draws for a bar (as ``ScrollBar._render_bar`` asks), one a cell
    along it: a vertical bar's are one a line, a horizontal bar's its first line."""
    segments = list(ScrollBarRender.render_bar(
        size=size, virtual_size=ceil(virtual), window_size=ceil(window if window < virtual else 0),
        position=position, thickness=thickness, vertical=vertical).segments)
    return segments[:size]


def cell(segment) -> tuple:
    """A scrollbar cell as Textual draws it: glyph, reversed, what a click on it does."""
    style = segment.style
    return (segment.text[:1], bool(style and style.reverse),
            (style.meta.get("@mouse.down") if style and style.meta else None))


bars = st.tuples(st.integers(1, 40), st.integers(0, 3000), st.integers(0, 60),
                 st.integers(0, 3000 * 8).map(lambda p: p / 8), st.booleans())


@settings(max_examples=500, deadline=None)
@given(bars)
def test_scrollbar_cells_are_what_textual_draws(case) -> None:
    """What the panels compare before repainting a scrollbar, cell by cell, is exactly what
    Textual's renderer draws there (so a repaint skipped for an unchanged cell never leaves
    a stale one), vertical and horizontal, at any length, window and position."""
    size, virtual, window, position, vertical = case
    position = min(position, max(0, virtual - window))  # a scroll offset stays in range
    bar = SimpleNamespace(vertical=vertical, size=Size(1, size) if vertical else Size(size, 1),
                          window_virtual_size=virtual, window_size=window, position=position)
    expected = [cell(s) for s in drawn_bar(size, virtual, window, position, vertical=vertical)]
    assert scrollbar_cells(bar) == expected


def queue_panel(k: int) -> tuple[Run, FrontierPanel]:
    """BFS on an open 400x400 map at step ``k`` (a queue longer than the panel), and a panel."""
    run = Run(walled_goal_grid(400), "bfs")
    run.goto(k)
    return run, FrontierPanel()


@sync
async def test_a_step_repaints_a_scrollbar_only_where_its_thumb_moves() -> None:
    """BFS on an open map: the queue's length changes most steps but moves its scrollbar's
    thumb only now and then; the bar repaints exactly then, only the rows whose cells
    changed, and its values and picture are always those of a freshly drawn bar (it spans the
    count line and every entry)."""
    run, panel = queue_panel(100)
    async with PanelApp(panel, run).run_test(size=(50, 20)) as pilot:
        await pilot.pause()
        bar = panel.vertical_scrollbar
        repaints: list[tuple] = []
        original = bar.refresh
        bar.refresh = lambda *a, **k: (repaints.extend(a or [None]), original(*a, **k))  # type: ignore
        lengths, changed = set(), 0
        for _ in range(150):
            before = scrollbar_cells(bar)
            run.forward()
            lengths.add(run.now.frontier_len())
            panel.show(run)
            await settle(pilot)  # handled and painted, without pilot.pause()'s idle wait
            after = scrollbar_cells(bar)
            changed += sum(a != b for a, b in zip(after, before, strict=True))
            assert (bar.window_virtual_size == panel.virtual_size.height
                    == 1 + run.now.frontier_len())
            assert bar.window_size == panel.scrollable_content_region.height
            shown = [cell(s) for strip in bar.render_lines(bar.size.region) for s in strip]
            expected = [cell(s) for s in drawn_bar(bar.size.height, bar.window_virtual_size,
                                                   bar.window_size, bar.position)]
            assert shown == expected
        assert len(lengths) > 5  # the queue's length did change
        assert None not in repaints  # never the whole bar
        assert 0 < changed < 150 and sum(region.height for region in repaints) == changed
