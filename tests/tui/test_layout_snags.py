"""Issue 42's layout snags, each at the size where a new teacher saw it: the comparison table
after a resize, the tutorial's step at 80x24, the trees' fragments, the replay's room, the
Code panel's room, the panes' cells level, the toasts and the key bar."""

from __future__ import annotations

import re
from pathlib import Path

from tests.helpers import TUTORIAL
from tests.textual_internals import composited, settle
from tests.tui.test_app import sync, tutorial_app, wait_until
from tui_search.cli.main import build_app
from tui_search.cli.main import main as cli_main
from tui_search.cli.parse import parse_options
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.model.replay_jumps import LOCKSTEP_SHORT
from tui_search.tui.view.tree_window import CUT_LEFT, CUT_RIGHT
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar
from tui_search.tui.widgets.search_tree import SearchTreePanel


def toasts(app) -> list[str]:
    """The text of each notification on screen now."""
    return [str(toast.render()) for toast in app.screen.query("Toast")]


# -- toasts -----------------------------------------------------------------------------------
@sync
async def test_b_pressed_four_times_shows_one_toast_the_last() -> None:
    """Four presses of b: one toast, saying the brush the last press picked (a note of the
    same kind replaces the one before; they piled up over the map)."""
    app = tutorial_app()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await pilot.press("b", "b", "b", "b")
        brush = app.session.edits.brush
        last = "Terrain brush off" if brush is None else f"cost {brush:g}"
        await wait_until(pilot, lambda: len(toasts(app)) == 1 and last in toasts(app)[0])
        await pilot.press("a", "a")  # another kind: its own toast, replaced in turn
        await wait_until(pilot, lambda: [t for t in toasts(app) if "Cell labels" in t]
                         == ["Cell labels: none"])


# -- the key bar ------------------------------------------------------------------------------
@sync
async def test_the_key_bar_sets_word_keys_apart_and_the_lockstep_line_has_a_verb() -> None:
    """A lesson's section keys read ``pgdn/pgup Lesson`` (they read ``pgdnpgup``); keys of a
    character each still read as a row (``np Step``); the lockstep's short line at 80x24
    says what c does (``c back to one``, not ``c one``) on one row."""
    from tests.tui.test_lesson import lesson_app

    app = lesson_app("choices")
    async with app.run_test(size=(80, 24)) as pilot:
        bar = app.main.query_one(KeyBar)
        await wait_until(pilot, lambda: "pgdn/pgup Lesson" in bar.render_line(0).text)
        assert "np Step" in bar.render_line(0).text
    assert LOCKSTEP_SHORT.endswith("· c back to one") and len(LOCKSTEP_SHORT) <= 78
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    async with app.run_test(size=(80, 24)) as pilot:
        stats = app.main.stats
        await wait_until(pilot, lambda: any("c back to one" in row
                                            for row in stats.shown_lines()))
        assert not any(row.rstrip().endswith("c one") for row in stats.shown_lines())


# -- the comparison table after a resize ------------------------------------------------------
def screen_text(app: SearchApp) -> list[str]:
    """The terminal as painted, a line of text a row."""
    return ["".join(text for text, _ in line) for line in composited(app)]


@sync
async def test_compare_at_the_end_then_a_resize_to_120_by_40_shows_the_table_filled() -> None:
    """``--compare bfs,dfs`` at 80x24 (no room for the table), ``end``, then the window
    dragged to 120x40: the table has its rows at once, and the screen is the one a start at
    120x40 shows (the table was an empty box over a 5-row gap until the next step)."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    fresh = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    async with fresh.run_test(size=(120, 40)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: fresh.session.at_end())
        await settle(pilot)
        expected = screen_text(fresh)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.at_end())
        assert app.main._table.made is None or not app.main.table.display
        await pilot.resize_terminal(120, 40)
        await wait_until(pilot, lambda: app.main._table.made is not None
                         and app.main.table.display and app.main.table.region.height > 0)
        table = app.main.table
        assert [line.split()[0] for line in table.text_lines[1:3]] == ["BFS", "DFS"]
        await settle(pilot)
        await wait_until(pilot, lambda: screen_text(app) == expected)


# -- the replay's room, and the panes' cells level --------------------------------------------
def replay_app(tmp_path: Path) -> SearchApp:
    """``--replay`` of the app's own BFS with the moves E,S,W,N (its ``--trace``), beside
    the BFS of the default order: they part at step 2."""
    trace = tmp_path / "student-bfs-ESWN.jsonl"
    cli_main([str(TUTORIAL), "--headless", "--order", "E,S,W,N", "--trace", str(trace)])
    assert trace.stat().st_size  # (its exit status says its search found no path)
    return build_app(parse_options([str(TUTORIAL), "--replay", str(trace), "-a", "bfs"]))


def blank_map_rows(view: GridView) -> int:
    """The rows of ``view``'s box that draw no cells (the map at cells smaller than the box
    it was sized for)."""
    return view.scrollable_content_region.height - view.geometry.size[1]


@sync
async def test_the_replay_at_120_by_40_keeps_its_cells_and_its_rows(tmp_path: Path) -> None:
    """At 120x40 the trace pane's lines wrap to 4 rows at the end: the maps keep their 4x2
    cells (they dropped to 2x1), the panes' maps start on one row, no row of a map's box is
    blank, before the end, at it and back from it."""
    app = replay_app(tmp_path)
    async with app.run_test(size=(120, 40)) as pilot:
        views = app.main.views
        for keys in ([], ["end"], ["p"], ["end"]):
            await pilot.press(*keys)
            await settle(pilot)
            await wait_until(pilot, lambda: all(v.geometry.level == 2 for v in views)
                             and not any(blank_map_rows(v) for v in views)
                             and len({v.region.y for v in views}) == 1)
            if keys == ["end"]:
                assert max(p.stats.outer_size.height for p in app.main.panes) == 4
            assert all(p.lists.display and not p.tree_panel.has_class("-folded")
                       for p in app.main.panes)


@sync
async def test_the_replay_at_80_by_24_shows_both_frontiers(tmp_path: Path) -> None:
    """At 80x24 the frontier panels show beside each other (a queue against what the trace
    kept is the clue to a stack-versus-queue bug): the panes' own lines fold first, and the
    line under the panes says each one's step and nodes expanded."""
    app = replay_app(tmp_path)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("n", "n", "n", "n")
        panes = app.main.panes
        await wait_until(pilot, lambda: all(p.frontier.region.height >= 5 for p in panes))
        for pane in panes:
            run = pane.frontier.run
            assert run is not None and run.k == 4
            shown = [pane.frontier.render_line(y).text
                     for y in range(pane.frontier.scrollable_content_region.height)]
            assert sum("(" in row for row in shown) == run.now.frontier_len()
        assert "your trace step 4/22 expanded 4" in " ".join(app.main.stats.shown_lines())


@sync
async def test_side_by_side_maps_are_level_when_one_panes_lines_wrap_more() -> None:
    """``--compare bfs,astar`` at 120x40 after 13 steps: A*'s lines wrap to a row more than
    BFS's; the panes' own lines take as many rows each, so the maps' cell rows are level
    (one sat a row lower)."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,astar")
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.press(*["n"] * 13)
        panes = app.main.panes
        await settle(pilot)
        own = [len(p.stats.rows(p.stats.content_size.width)) for p in panes]
        assert own[0] != own[1], own  # the case: one pane's lines wrap more
        await wait_until(pilot, lambda: len({v.region.y for v in app.main.views}) == 1
                         and len({p.stats.outer_size.height for p in panes}) == 1)


@sync
async def test_compare_resized_to_120_by_40_and_back_keeps_no_blank_map_rows() -> None:
    """The window dragged 80x24 -> 120x40 -> 80x24 -> 120x40: at 120x40 the maps have their
    4x2 cells each time (the second time they kept the 2x1 cells of 80x24 in a box sized
    for 4x2: half its rows blank)."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    async with app.run_test(size=(80, 24)) as pilot:
        for size in ((120, 40), (80, 24), (120, 40)):
            await pilot.resize_terminal(*size)
            level = 2 if size == (120, 40) else 1
            await wait_until(pilot, lambda level=level: all(
                v.geometry.level == level and not blank_map_rows(v) for v in app.main.views))


# -- the tutorial's own step at 80x24 ---------------------------------------------------------
def panel_rows(panel) -> list[str]:
    """The rows a line panel shows on screen, as text."""
    return [panel.render_line(y).text for y in range(panel.scrollable_content_region.height)]


@sync
async def test_at_80_by_24_the_tutorials_step_4_shows_every_queue_entry_and_the_push() -> None:
    """The tutorial at 80x24 after n x4 says "added E, NE to the queue": the queue shows all
    its 4 entries, NE the last (it had room for 3 while the tree got 10 rows); with v, still
    all 4 (2 showed), and the Code panel shows the push (line 9) with the visited check the
    narration names (line 8)."""
    app = tutorial_app()
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("n", "n", "n", "n")
        pane = app.main.panes[0]
        assert "added E, NE to the queue" in app.main.stats.narration_text

        def queue_whole() -> bool:
            rows = panel_rows(pane.frontier)
            return sum("(" in row for row in rows) == 4 and "NE" in rows[-1] + rows[-2] \
                and "(2,1) NE" in " ".join(rows)

        await wait_until(pilot, queue_whole)
        assert not pane.tree_panel.has_class("-folded")
        await pilot.press("v")
        await wait_until(pilot, lambda: pane.code_shown and pane.code_panel.lit)
        code = pane.code_panel

        def push_in_sight() -> bool:
            rows = panel_rows(code)
            return any(row.lstrip().startswith("▶  9") for row in rows) \
                and any(row.lstrip().startswith("▶  8") for row in rows)

        await wait_until(pilot, lambda: queue_whole() and push_in_sight())
        assert code.named == [8, 9]


# -- the Code panel's room --------------------------------------------------------------------
@sync
async def test_at_200_by_60_the_code_panel_takes_the_columns_the_map_leaves() -> None:
    """At 200x60 with v, the Code panel's lines do not wrap (they wrapped while 45 columns
    beside the map stayed blank), and the map keeps the cells it had without the panel."""
    app = tutorial_app()
    async with app.run_test(size=(200, 60)) as pilot:
        await pilot.press("n", "n", "n", "n")
        pane = app.main.panes[0]
        await settle(pilot)
        level = pane.view.geometry.level
        await pilot.press("v")
        await wait_until(pilot, lambda: pane.code_shown and pane.code_panel.lit
                         and pane.code_panel.scrollable_content_region.width > 0)
        code = pane.code_panel
        await wait_until(pilot, lambda: all(code.line_rows(n).stop - code.line_rows(n).start
                                            == 1 for n in range(1, len(code.code.lines) + 1)))
        assert pane.view.geometry.level == level and pane.has_class("-beside")
        assert len(panel_rows(code)) >= len(code.code.lines)  # the whole code in sight


@sync
async def test_in_the_choices_lesson_at_120_by_40_the_code_panel_shows_every_lit_line() -> None:
    """The choices lesson at 120x40 opens on DFS at step 4 with the Code panel: every line
    the step ran is in sight (it showed some 6 lines of code, the lit ones cut at line 8,
    under a map at cells bigger than the lesson needs)."""
    from tests.tui.test_lesson import lesson_app

    app = lesson_app("choices")
    async with app.run_test(size=(120, 40)) as pilot:
        pane = app.main.panes[0]
        await wait_until(pilot, lambda: pane.code_shown and pane.code_panel.lit
                         and pane.code_panel.scrollable_content_region.height > 0)
        code = pane.code_panel
        assert sorted(code.lit) == [4, 5, 6, 7, 8, 9, 10]

        def every_lit_line_in_sight() -> bool:
            top, rows = code.scroll_offset.y, code.scrollable_content_region.height
            return all(top <= code.line_rows(n).start and code.line_rows(n).stop <= top + rows
                       for n in code.lit)

        await wait_until(pilot, every_lit_line_in_sight)


# -- the trees' fragments ---------------------------------------------------------------------
NODE = re.compile(r"[●○★◉] (START|[NSEW]{1,2}) \(\d+,\d+\)")


def tree_problems(panel: SearchTreePanel) -> list[str]:
    """What a student would read as a broken tree in ``panel``'s rows: a cell without its
    node's glyph and move (a lone ``(4,0)``), a node cut with no mark saying so, depths that
    do not go down the focused view's chain, or the parent of the node being expanded out of
    sight, or on a row that neither shows it whole nor marks it cut (the listing)."""
    model, rows = panel.model, panel_rows(panel)
    problems = []
    for row in rows[panel.pinned_rows():]:
        whole = list(NODE.finditer(row))
        cells = re.findall(r"\(\d+,\d+\)", row)
        if len(cells) != len(whole):
            problems.append(f"a lone cell: {row!r}")
        if re.search(r"[●○★◉]", row) and not whole and CUT_RIGHT not in row:
            problems.append(f"a node cut without a mark: {row!r}")
    if model.mode == "focus":
        depths = [int(row.split()[0]) for row in rows[panel.pinned_rows():]
                  if row.split() and row.split()[0].isdigit()]
        if depths != sorted(depths) or len(set(depths)) < len(depths) - 2:
            problems.append(f"the depths do not go down the chain: {depths}")
    elif (run := panel.run) is not None and run.k:
        # the line of the parent of the node being expanded, found by its label
        up = run.nodes.parent(run.steps.expanded_event(run.k))
        label = f"{run.nodes.move(up)} {run.nodes.cell(up)}".replace(" ", "") if up >= 0 else ""
        parent = next((y for y in range(model.line_count())
                       if label and model.line_text(y).replace(" ", "").endswith(label)), None)
        if parent is not None:
            row = parent - panel.scroll_offset.y
            if not panel.pinned_rows() <= row < len(rows):
                problems.append("the parent of the node being expanded is out of sight")
            elif not NODE.search(rows[row]) and not (re.search(r"[●○★◉]", rows[row]) and (
                    CUT_LEFT in rows[row] or CUT_RIGHT in rows[row])):
                problems.append(f"its parent's row shows no node: {rows[row]!r}")
    return problems


@sync
async def test_narrow_trees_at_120_by_40_show_no_fragment() -> None:
    """``--compare bfs,dfs,ucs,astar`` at 120x40, at the end: tree panels 11 columns wide.
    Each row shows its node whole or says it is cut (they showed a lone '(4,0)', then
    '● SE' over '└─ ★ S' as if whole)."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs,ucs,astar")
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.at_end())
        await settle(pilot)
        trees = [pane.tree_panel for pane in app.main.panes]
        assert all(tree.scroll_offset.x > 0 for tree in trees)  # the case: scrolled sideways
        await wait_until(pilot, lambda: not any(tree_problems(tree) for tree in trees))
        assert any(CUT_LEFT in " ".join(panel_rows(tree)) for tree in trees)


@sync
async def test_a_deep_dfs_tree_at_80_by_24_reads_as_a_tree() -> None:
    """DFS on a generated 31x21 maze at 80x24, at its end and back (138 levels deep): the
    tree scrolled sideways showed nodes beside their parents' rows as if siblings (the
    listing's guides keep 40 levels), blank rows and lone cells.  Now a tree deeper than
    its guides is shown by its path to the node being expanded, its depths in view; on
    the way down, every row shows its node whole or marked."""
    app = build_app(parse_options(["-a", "dfs", "--generate", "maze", "--size", "31x21",
                                   "--seed", "1"]))
    async with app.run_test(size=(80, 24)) as pilot:
        tree = app.main.panes[0].tree_panel
        for keys in (["n"] * 40, ["end"], ["p"] * 3):
            await pilot.press(*keys)
            await settle(pilot)
            await wait_until(pilot, lambda: not tree_problems(tree))
        assert tree.mode == "focus" and tree.scroll_offset.x > 0
