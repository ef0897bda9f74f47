"""The search tree scrolled sideways (issue 20, audit gap 4): a tree deeper than its panel is
wide scrolls to a word boundary, never into a label, and its count stays in view.

The checks read the terminal as painted (every row of each tree panel), against the panel's
whole lines: each word shown is a whole word of its line at that column.
"""

from __future__ import annotations

import re

import pytest
from rich.cells import cell_len

from tests.helpers import TUTORIAL
from tests.textual_internals import repainted
from tests.tui.test_app import sync, wait_until
from tests.tui.test_replay import replay_app
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.view.tree_window import CUT_LEFT, CUT_RIGHT, label_span, tree_window
from tui_search.tui.widgets.line_panel import words_from
from tui_search.tui.widgets.search_tree import SearchTreePanel, scroll_column

START = "● START (0,0)"


def cells(segments: list[tuple]) -> str:
    """A painted line as one character a cell (a wide character's second cell: "")."""
    out: list[str] = []
    for text, _ in segments:
        for char in text:
            out.append(char)
            out.extend([""] * (cell_len(char) - 1))
    return "".join(c or " " for c in out)


def tree_rows(screen: list[list[tuple]], panel: SearchTreePanel) -> list[str]:
    """The rows of ``panel``'s list as the terminal shows them."""
    r = panel.scrollable_content_region
    return [cells(screen[y])[r.x : r.right] for y in range(r.y, r.bottom)]


def check_tree(panel: SearchTreePanel, rows: list[str]) -> None:
    """Whole words only, the count on the first row, the node being expanded in view, and
    no sideways scroll when its label and its children's fit the panel.  A row whose node
    the window's edges cut (issue 42) shows it from the left edge after ``◂``, or its words
    that fit before ``▸``: what :func:`tree_window` says, and every cell on a row is a whole
    node's (its glyph and move before it)."""
    model = panel.model
    width = panel.scrollable_content_region.width
    count = panel.line_text(0)
    if len(count) <= width:
        assert rows[0].rstrip() == count  # pinned and whole
    for y, shown in enumerate(rows):
        line = panel.line_text(panel.row_line(y))
        x = 0 if y < panel.pinned_rows() else round(panel.scroll_x)
        cut = tree_window(model.line(panel.row_line(y)), x, width)
        for cell in re.finditer(r"\(\d+,\d+\)", shown):
            assert re.search(r"[●○★◉] \S+ $", shown[:cell.start()]), f"a lone cell: {shown!r}"
        if cut is not None:
            assert shown.rstrip() == "".join(text for text, _ in cut).rstrip(), (shown, cut)
            assert shown.startswith(CUT_LEFT) or CUT_RIGHT in shown, shown
            continue
        for word in re.finditer(r"\S+", shown):
            at, end = x + word.start(), x + word.end()
            assert line[at:end] == word.group(), (y, shown, line)
            assert at == 0 or line[at - 1] == " ", f"cut at the left: {shown!r} of {line!r}"
            assert end == len(line) or line[end] == " ", f"cut at the right: {shown!r}"
    current = model.current_line()
    start, end = label_span(model.line(current))
    label = panel.line_text(current)[start:end]
    if len(label) <= width:  # (a panel narrower than a label shows what words fit)
        assert any(label in row for row in rows), (label, rows)
    kids = [label_span(model.line(current + i)) for i in range(1 + len(model.kids))]
    if max(e for _, e in kids) <= width:
        assert panel.scroll_x == 0, "scrolled sideways though the labels fit"
        assert START in rows[1] or panel.scroll_y > 0, rows


async def check_trees(pilot) -> list[tuple[float, list[str]]]:
    """Check every tree panel on screen; their sideways scroll and rows."""
    screen = await repainted(pilot)
    panels = [p for p in pilot.app.screen.query(SearchTreePanel) if p.display]
    assert panels
    seen = []
    for panel in panels:
        rows = tree_rows(screen, panel)
        check_tree(panel, rows)
        seen.append((panel.scroll_x, rows))
    return seen


@sync
async def test_replay_at_its_end_at_160_by_48_shows_whole_words() -> None:
    """The replay beside BFS at 160x48, at the end: the deepest node is wider than the panel,
    so the trees scroll to a guide boundary; shallower labels show no half word (this showed
    '0,0)' and ',1)'), and "22 nodes" stays on the first row."""
    app = replay_app()
    async with app.run_test(size=(160, 48)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: all(run.at_end for run in app.session.runs))
        for scroll_x, rows in await check_trees(pilot):
            assert scroll_x % 3 == 0 and scroll_x > 0  # a guide boundary
            assert rows[0].startswith("22 nodes")


@pytest.mark.parametrize(("size", "fits"), [((120, 40), False), ((160, 48), True)])
@sync
async def test_three_searches_after_three_steps_show_whole_words(size, fits) -> None:
    """Three searches at 120x40 after n n n (panels 14 columns wide: the tree showed 'RT
    (0,0)' and 'es'), and at 160x48, where the trees fit and show START whole at x = 0."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs,astar")
    async with app.run_test(size=size) as pilot:
        for _ in range(3):
            await pilot.press("n")
        await wait_until(pilot, lambda: [run.k for run in app.session.runs] == [3, 3, 3])
        for scroll_x, rows in await check_trees(pilot):
            assert (scroll_x == 0) == fits
            if fits:
                assert START in rows[1]


def test_scroll_column_keeps_to_zero_then_guide_boundaries_then_the_label() -> None:
    """0 while the node's and its children's labels fit; else the first guide boundary
    (every 3 columns, after the focused view's depth column) from which they fit; else the
    node's link to its parent (``├─``) beside its label; else the label's start."""
    node = [("│  │  ├─ ", "guide"), ("● S (0,4)", "current"), ("  ◀ expanding", "current")]
    kid = [("│  │  │  └─ ", "guide"), ("○ SE (1,5)", "frontier")]
    assert label_span(node) == (9, 18) and label_span(kid) == (12, 22)
    assert scroll_column([node, kid], 22) == 0
    assert scroll_column([node, kid], 21) == 3
    assert scroll_column([node, kid], 17) == 6
    assert scroll_column([node, kid], 12) == 6  # the node's link to its parent, its label
    assert scroll_column([node, kid], 8) == 9  # only from the label's start
    assert scroll_column([node], 5) == 9
    focused = [("12 ", "detail"), ("   └─ ", "guide"), ("● E (2,2)", "current")]
    assert scroll_column([focused], 15) == 3  # after the depth column
    assert scroll_column([focused], 12) == 6
    assert scroll_column([focused], 10) == 9
    assert scroll_column([[("● START (0,0)", "current")]], 5) == 0  # nowhere to go


def test_words_from_blanks_the_word_the_left_edge_cuts() -> None:
    parts = [("└─ ", "guide"), ("● START (0,0)", "expanded")]
    assert words_from(parts, 0) == parts
    assert words_from(parts, 3) == parts  # a word's start
    assert words_from(parts, 6) == [("└─ ", "guide"), ("● S     (0,0)", "expanded")]
    assert words_from(parts, 1) == [("└  ", "guide"), ("● START (0,0)", "expanded")]
    assert words_from(parts, 10) == parts  # after a space


def test_a_row_shows_its_node_whole_or_says_it_is_cut() -> None:
    """Issue 42: a window that starts right of a node shows it at its left edge after ◂
    (it showed a lone '(19,4)', or nothing); a label past the right edge keeps its whole
    words before ▸ (it showed '└─ ★ NE' as if whole); a label whole in the window, and a
    line with no node, are left to the usual cut at word boundaries (None)."""
    node = [("│  ├─ ", "guide"), ("● NE (19,4)", "expanded")]
    kid = [("│  │  └─ ", "guide"), ("★ NE (6,4)", "path"), ("  ★ goal", "path")]
    assert tree_window(node, 0, 30) is None and tree_window(kid, 3, 30) is None
    assert tree_window([("8 nodes", "note")], 4, 5) is None
    said = ["".join(text for text, _ in tree_window(line, x, width) or [])
            for line, x, width in ((node, 9, 20), (node, 30, 12), (kid, 0, 15), (kid, 3, 8),
                                   (kid, 0, 9), (node, 6, 5))]
    assert said == ["◂● NE (19,4)", "◂● NE (19,4)", "│  │  └─ ★ NE ▸", "│  └─ ▸",
                    "│  │  └─▸", "● ▸"]
    # the roles go with the text (the node's colour, the marks as guides)
    assert tree_window(node, 9, 20) == [(CUT_LEFT, "guide"), ("● NE (19,4)", "expanded")]
