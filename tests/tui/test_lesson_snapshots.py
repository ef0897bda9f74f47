"""Pictures of lessons and of a discarded step in the Code panel (SVG snapshots; look at
every changed one before accepting)."""

from __future__ import annotations

from tests.engine.test_lesson import LESSONS
from tests.tui.test_app import wait_until
from tests.tui.test_lesson import lesson_app
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp


async def at_section_2(pilot) -> None:
    """pgdn, then wait for the section's text (the Markdown widget mounts it in a batch)."""
    await pilot.pause()
    await pilot.press("pagedown")
    panel = pilot.app.main.query_one(".lesson")
    await wait_until(pilot, lambda: "2/10" in str(panel.border_title)
                     and "queue" in " ".join(str(b.source) for b in panel.query("MarkdownBlock")))
    await pilot.pause()


def test_the_tutorial_lesson_at_section_2(snap_compare) -> None:
    """The lesson 'tutorial 2/10' in a bordered column on the right ('pgdn next · pgup back'
    under it): its heading '2. BFS: the first four steps and its queue', the queue's four
    steps as a numbered list. Beside it BFS at step 4: the queue (0,3), (1,3), then (2,2) E
    and (2,1) NE marked + just added; the narration 'Expanded (1,2): added E, NE to the
    queue'; the key bar has 'pgdn pgup Lesson'."""
    assert snap_compare(lesson_app("tutorial"), run_before=at_section_2,
                        terminal_size=(120, 40))


def test_the_tutorial_lesson_at_section_2_at_80_by_24(snap_compare) -> None:
    """The same at 80x24: the lesson's column 32 wide with a scroll bar, the whole map
    still shown, the queue and the tree under it."""
    assert snap_compare(lesson_app("tutorial"), run_before=at_section_2,
                        terminal_size=(80, 24))


def test_dfs_visit_on_expand_at_a_discarded_step_with_the_code_panel(snap_compare) -> None:
    """DFS, visit on expand, on tests/data/lessons/discard.txt at step 4: (3,3) comes off the
    stack already expanded (struck out, "discarded"); the Code panel lights line 4 (the pop) and
    line 5, 'if node is already visited: discard it, go on', with ▶; the narration says it was
    discarded."""
    path = LESSONS / "discard.txt"
    app = SearchApp(load_map(path), path=path, algorithm="dfs",
                    semantics=Semantics(visit="expand"))
    assert snap_compare(app, press=["n", "n", "n", "n", "v"], terminal_size=(100, 32))
