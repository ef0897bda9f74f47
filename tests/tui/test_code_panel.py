"""The Code panel: ``v`` (or the palette's command) shows the search's pseudocode in the
search tree's place, the step's lines lit with ``▶``; each compare pane shows its own search's
code; the narration names the lines while it is shown."""

from __future__ import annotations

import re

import pytest

from tests.textual_internals import notifications
from tests.tui.test_app import SIZE, sync, tutorial_app, wait_until
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.pseudocode import pseudocode
from tui_search.engine.search.registry import ALGORITHMS
from tui_search.tui.app import SearchApp
from tui_search.tui.view.code_trace import focus_line, lit_lines
from tui_search.tui.view.layout import CODE_MIN_HEIGHT, TREES_MIN_HEIGHT
from tui_search.tui.view.narration import narrate
from tui_search.tui.widgets.code_panel import LIT_MARK, CodePanel, code_rows
from tui_search.tui.widgets.run_pane import RunPane


def shown(pane: RunPane) -> bool:
    panel = pane.code_panel
    return bool(panel.display and not panel.has_class("-folded") and panel.region.area)


def lit_numbers(panel: CodePanel) -> set[int]:
    """The numbers of the lines the panel shows lit, read off its rows' text."""
    return {int(panel.line_text(y).split()[1]) for y in panel.lit_rows()}


@sync
async def test_v_shows_the_code_in_the_tree_s_place_and_lights_the_step() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        pane = app.main.panes[0]
        await pilot.press("n", "n", "n", "n")
        assert not shown(pane)
        await pilot.press("v")
        await wait_until(pilot, lambda: shown(pane))
        assert not pane.tree_panel.display or pane.tree_panel.has_class("-folded")
        panel = pane.code_panel
        assert lit_numbers(panel) == set(lit_lines(app.session.run)) == {4, 5, 6, 7, 8, 9, 10}
        assert panel.line_text(panel.lit_rows()[0]).startswith(LIT_MARK)
        assert "line 8: (0,1), (0,2), (0,3) and (1,3) are already visited" in (
            app.main.stats.narration_text)
        await pilot.press("p", "p", "p")  # back to step 1: nothing was visited yet
        await wait_until(pilot, lambda: app.session.run.k == 1 and 8 not in lit_numbers(panel))
        assert lit_numbers(panel) == {4, 5, 6, 7, 9, 10}
        await pilot.press("v")
        await wait_until(pilot, lambda: not shown(pane) and pane.tree_panel.region.area > 0)
        assert "line 8" not in app.main.stats.narration_text


@sync
async def test_each_compare_pane_shows_its_own_search_s_code() -> None:
    app = SearchApp(tutorial_app().session.grid, compare="bfs,astar")
    async with app.run_test(size=(120, 40)) as pilot:
        await wait_until(pilot, lambda: len(app.main.panes) == 2)
        await pilot.press("n", "v")
        await wait_until(pilot, lambda: all(shown(p) for p in app.main.panes))
        bfs, astar = (p.code_panel for p in app.main.panes)
        assert bfs.code.lines[0].text == "frontier ← a queue holding START"
        assert "f = g + h" in astar.code.lines[0].text
        assert " ".join(" ".join(astar.lines()).split()).startswith("1 frontier ← a priority")
        assert app.main.panes[1].stats.narration_text  # its own narration


@sync
async def test_the_palette_offers_the_code_panel() -> None:
    from tui_search.tui.commands import SearchCommands

    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        commands = {name: (run, help_text)
                    for name, run, help_text in SearchCommands(app.screen).commands()}
        name = next(n for n in commands if n.startswith("Code panel"))
        assert "(key v)" in commands[name][1]
        await commands[name][0]()  # the main screen's run_action
        await wait_until(pilot, lambda: shown(app.main.panes[0]))


def test_a_long_line_wraps_under_its_own_words_and_keeps_its_light() -> None:
    code = pseudocode(ALGORITHMS["bfs"], Semantics())
    rows = code_rows(code, frozenset({6}), 30)
    texts = ["".join(text for text, _ in row) for row in rows]
    assert all(len(text) <= 30 for text in texts)
    start = next(i for i, text in enumerate(texts) if text.startswith(f"{LIT_MARK}  6 "))
    assert texts[start + 1].startswith("      ") and "N,NW" in " ".join(texts[start:start + 4])
    assert all(cls == "code-panel--lit" for _, cls in rows[start + 1])
    assert sum(text.startswith(LIT_MARK) for text in texts) == 1


def in_view(panel: CodePanel, number: int) -> bool:
    """Line ``number``'s first row is among the rows the panel shows."""
    top, rows = panel.scroll_offset.y, panel.scrollable_content_region.height
    line = panel.line_rows(number)
    return bool(line) and top <= line.start < top + rows


def lit_in_view(panel: CodePanel) -> bool:
    """The lit line the panel keeps in view (the most specific, else the first) is among the
    rows it shows, with a row besides it."""
    lit = sorted(panel.lit)
    focus = panel.focus_number if panel.focus_number is not None else lit[0] if lit else 0
    return focus in panel.lit and in_view(panel, focus) \
        and panel.scrollable_content_region.height >= 2


@sync
@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
async def test_in_each_choices_section_the_line_the_narration_names_is_in_view(
        size: tuple[int, int]) -> None:
    from tests.tui.test_lesson import lesson_app

    app = lesson_app("choices")
    async with app.run_test(size=size) as pilot:
        panel = app.main.query_one(".lesson")
        for section in range(1, 6):
            while f"{section}/5" not in str(panel.border_title):
                await pilot.press("pagedown")
                await pilot.pause()
            run, code = app.session.runs[0], app.main.panes[0].code_panel
            await wait_until(pilot, lambda run=run, code=code: shown(app.main.panes[0])
                             and code.lit == lit_lines(run) and code.scrollable_content_region)
            # the line the lesson's text names: the first the narration names (section 2:
            # the corner, before the visited check), else the goal test that found the goal
            named = [int(n) for n in re.findall(r"line (\d+)", narrate(run, True))]
            focus = focus_line(run)
            assert focus is not None and (not named or focus in named), section
            await wait_until(pilot, lambda code=code, focus=focus: in_view(code, focus))


@sync
async def test_at_80x24_each_compare_pane_shows_its_code_in_fewer_lines_than_a_tree() -> None:
    app = SearchApp(tutorial_app().session.grid, compare="bfs,dfs")
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: len(app.main.panes) == 2)
        await pilot.press("n", "n", "v")
        await wait_until(pilot, lambda: all(shown(p) for p in app.main.panes))
        for pane, run in zip(app.main.panes, app.session.runs, strict=True):
            panel = pane.code_panel
            assert CODE_MIN_HEIGHT <= panel.outer_size.height < TREES_MIN_HEIGHT
            await wait_until(pilot, lambda panel=panel: lit_in_view(panel))
            assert panel.lit == lit_lines(run) and pane.frontier.region.area > 0
        # step 4: the narration names the lines that skipped, shortened to keep the panels
        await pilot.press("n", "n")
        await wait_until(pilot, lambda: all(p.stats.narration_text.count("line 8") == 1
                                            for p in app.main.panes))
        await wait_until(pilot, lambda: all(shown(p) and p.frontier.region.area > 0
                                            for p in app.main.panes))
        for pane in app.main.panes:
            assert pane.stats.outer_size.height <= 3 and lit_in_view(pane.code_panel)
            rows = pane.stats.rows(pane.stats.content_region.width)
            assert "line 8 skipped" in "".join(text for text, _ in rows[-1])
        await pilot.press("v")  # the trees have no room: the frontier alone, as before
        await wait_until(pilot, lambda: not any(shown(p) for p in app.main.panes))
        assert all(not p.tree_panel.region.area for p in app.main.panes)


@sync
async def test_at_80x24_beside_the_tutorial_lesson_the_code_shows() -> None:
    from tests.tui.test_lesson import lesson_app

    app = lesson_app("tutorial")
    async with app.run_test(size=(80, 24)) as pilot:
        panel = app.main.query_one(".lesson")
        await pilot.press("pagedown")  # section 2: BFS at step 4
        await wait_until(pilot, lambda: "2/10" in str(panel.border_title))
        pane = app.main.panes[0]
        await pilot.press("v")
        await wait_until(pilot, lambda: shown(pane) and lit_in_view(pane.code_panel))
        assert pane.code_panel.lit == lit_lines(app.session.runs[0])


def no_room_said(app: SearchApp) -> bool:
    return any("No room for the Code panel" in n.message for n in notifications(app))


def big_map() -> Grid:
    """An open 60x40 map: two panes of it at 80x20 leave no lines for the lists (at 80x24,
    side by side, they leave five: the Code panel's least)."""
    big = Grid(60, 40)
    big.start, big.goal = (0, 0), (59, 39)
    return big


@sync
async def test_where_no_pane_has_room_for_the_code_v_says_so() -> None:
    app = SearchApp(big_map(), compare="bfs,dfs")
    async with app.run_test(size=(80, 20)) as pilot:
        await wait_until(pilot, lambda: len(app.main.panes) == 2)
        await pilot.press("n", "v")
        await wait_until(pilot, lambda: no_room_said(app))
        assert not any(shown(p) for p in app.main.panes)


@sync
async def test_a_code_panel_folded_by_a_smaller_terminal_says_so() -> None:
    app = SearchApp(tutorial_app().session.grid, compare="bfs,dfs")
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: len(app.main.panes) == 2)
        await pilot.press("n", "v")
        await wait_until(pilot, lambda: all(shown(p) for p in app.main.panes))
        await pilot.resize_terminal(80, 20)
        await wait_until(pilot, lambda: no_room_said(app))
        assert not any(shown(p) for p in app.main.panes) and app.session.show_code


@sync
async def test_a_code_panel_unfolded_by_a_bigger_terminal_shows_the_run_at_once() -> None:
    app = SearchApp(big_map(), compare="bfs,astar")
    async with app.run_test(size=(80, 20)) as pilot:
        await wait_until(pilot, lambda: len(app.main.panes) == 2)
        await pilot.press("n", "n", "v")  # no room for the panels at 80x20: folded
        await wait_until(pilot, lambda: app.session.show_code)
        assert not any(shown(p) for p in app.main.panes)
        await pilot.resize_terminal(120, 40)
        await wait_until(pilot, lambda: all(shown(p) for p in app.main.panes))
        bfs, astar = (p.code_panel for p in app.main.panes)
        assert bfs.code is not None and "queue" in bfs.code.lines[0].text
        assert astar.code is not None and "f = g + h" in astar.code.lines[0].text
        assert bfs.lit == lit_lines(app.session.runs[0])  # lit for the run's step 2


def test_on_a_map_with_terrain_g_adds_the_cost_of_the_cell_entered() -> None:
    from tests.helpers import MAPS
    from tui_search.engine.maps.load import load_map
    from tui_search.engine.run.recorded import Run
    from tui_search.tui.view.code_trace import code_of

    mud = load_map(MAPS / "terrain-mud.txt")
    text = "\n".join(line.text for line in code_of(Run(mud, "ucs")).lines)
    assert "× the cost of the cell it enters" in text
    plain = "\n".join(line.text for line in code_of(tutorial_app().session.runs[0]).lines)
    assert "cell it enters" not in plain
