"""Pictures of a run by hand (look at each as a PNG before accepting a change)."""

from __future__ import annotations

from tests.tui.test_app import tutorial_app, wait_until
from tui_search.tui.dialogs.by_hand_summary import ByHandSummaryScreen
from tui_search.tui.screens.by_hand import ByHandScreen
from tui_search.tui.widgets.grid_view import GridView


async def _open(pilot) -> ByHandScreen:
    await pilot.press("H")
    await wait_until(pilot, lambda: isinstance(pilot.app.screen, ByHandScreen)
                     and bool(pilot.app.screen.query(GridView)))
    return pilot.app.screen


async def _right_steps(screen: ByHandScreen, steps: int) -> None:
    """``steps`` steps made right (the model's moves: the keys are the other tests')."""
    by_hand = screen.by_hand
    hand = by_hand.hand
    for _ in range(steps):
        by_hand.take(hand.hint_cell())
        while (cell := hand.hint_cell()) is not None:
            by_hand.add(cell)
        by_hand.enter(screen.session.cursor)


async def _a_mistake(pilot) -> None:
    """BFS on the tutorial, two steps made, then the newest entry of the queue, (1,2),
    taken: the mistake named in the panel."""
    screen = await _open(pilot)
    await _right_steps(screen, 2)
    screen.move_cursor((1, 2))
    await pilot.press("enter")
    await wait_until(pilot, lambda: "Mistakes 1" in screen.panel.text)


def test_a_mistake_by_hand_at_80x24(snap_compare) -> None:
    """The by-hand panel over the map at 80x24: '✗ step 3: BFS takes (0,2), the oldest cell
    on its queue; you took (1,2), the newest, as a stack does (a DFS)', then 'Try again ·
    Step 3: take the entry ...' and 'Mistakes 1 · hints 0'; the queue panel titled 'Queue
    (FIFO) · as added' lists (0,2) and (1,2) with no next-out mark; the key bar: Take, Hint,
    Undo, Help, Leave."""
    assert snap_compare(tutorial_app(), run_before=_a_mistake, terminal_size=(80, 24))


def test_a_mistake_by_hand_at_120x40(snap_compare) -> None:
    """As at 80x24, with room: the panel's sentence on fewer lines, the tree beside the
    queue."""
    assert snap_compare(tutorial_app(), run_before=_a_mistake, terminal_size=(120, 40))


async def _the_end(pilot) -> None:
    """BFS by hand on the tutorial to its end with one mistake (the newest entry taken at
    step 3): the summary."""
    screen = await _open(pilot)
    await _right_steps(screen, 2)
    screen.by_hand.take((1, 2))
    while not screen.by_hand.finished:
        await _right_steps(screen, 1)
    screen.by_hand.ended = screen.by_hand.started + 95  # 1:35, not the test's own time
    screen.show_hand()
    screen.action_summary()
    await wait_until(pilot, lambda: isinstance(pilot.app.screen, ByHandSummaryScreen))


def test_the_end_of_a_run_by_hand(snap_compare) -> None:
    """The summary dialog over the finished run: '22 steps in 1:35, 1 mistake', '1 × took
    the newest entry', 'Hints: 0 · steps undone: 0', 'BFS found a path of 7 moves'; the
    buttons Replay beside BFS (r), Again (a), Back (esc)."""
    assert snap_compare(tutorial_app(), run_before=_the_end, terminal_size=(100, 30))
