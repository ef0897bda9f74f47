"""By hand in the app (H, the palette, --by-hand): the student takes each entry off (a click
on the map, or the cursor and enter) and adds its successors (a move's key, or a click), each
step checked at once; a wrong one is named in the panel and not taken; hints, undo, the end's
summary and the record of the run."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.engine.test_hand import MISTAKES
from tests.tui.test_app import TUTORIAL, at, sync, tutorial_app, wait_until
from tests.tui.test_themes import palette_run
from tui_search.cli.main import build_app
from tui_search.cli.parse import parse_options
from tui_search.engine.maps.grid import DELTAS, Cell
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.by_hand_summary import ByHandSummaryScreen
from tui_search.tui.screens.by_hand import ByHandScreen
from tui_search.tui.screens.by_hand_keys import MOVE_KEYS
from tui_search.tui.widgets.by_hand_panel import ByHandPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar

SIZE = (100, 32)
#: A move's key (the number pad's).
KEY_OF = {move: key for key, move in MOVE_KEYS.items() if key.isdigit()}


async def open_hand(pilot) -> ByHandScreen:
    await pilot.press("H")
    await wait_until(pilot, lambda: shown(pilot.app.screen))
    return pilot.app.screen


def shown(screen: object) -> bool:
    """Is ``screen`` the by-hand screen, its map and panel drawn (its title set)?"""
    return (isinstance(screen, ByHandScreen) and bool(screen.query(GridView))
            and bool(screen.panel.border_title))


def panel(screen: ByHandScreen) -> str:
    return screen.query_one(ByHandPanel).text


async def click_cell(pilot, screen: ByHandScreen, cell: Cell) -> None:
    view = screen.query_one(GridView)
    await pilot.click(view, offset=at(view, *cell))


async def add(pilot, screen: ByHandScreen, cell: Cell) -> None:
    """Add ``cell``: its move's key when it is one move from the entry taken off, else a
    click on it."""
    node = screen.by_hand.hand.picked
    assert node is not None
    move = next((m for m, d in DELTAS.items() if (node[0] + d[0], node[1] + d[1]) == cell),
                None)
    if move is None:
        await click_cell(pilot, screen, cell)
    else:
        await pilot.press(KEY_OF[move])


async def play(pilot, screen: ByHandScreen, steps: int) -> None:
    """Make ``steps`` steps right: the entry clicked, its successors by their keys, enter;
    each waited for (the app takes a key or a click in its own time)."""
    hand = screen.by_hand.hand
    made = len(hand.mistakes)
    for _ in range(steps):
        k = hand.k
        await click_cell(pilot, screen, hand.hint_cell())
        await wait_until(pilot, lambda k=k: hand.picked is not None or hand.k > k)
        while hand.k == k and (cell := hand.hint_cell()) is not None:
            marks = len(hand.marks)
            await add(pilot, screen, cell)
            await wait_until(pilot, lambda marks=marks: len(hand.marks) > marks)
        if hand.k == k:
            await pilot.press("enter")
            await wait_until(pilot, lambda k=k: hand.k > k)
    assert len(hand.mistakes) == made


def app_of(key: str, sem: Semantics) -> SearchApp:
    return SearchApp(load_map(TUTORIAL), path=TUTORIAL, algorithm=key, semantics=sem)


@pytest.mark.parametrize(("key", "sem", "made", "move", "cause", "message"), MISTAKES,
                         ids=[m[4] for m in MISTAKES])
@sync
async def test_each_kind_of_mistake_is_named_in_the_panel_at_once(
        key: str, sem: Semantics, made: int, move: tuple[str, object], cause: str,
        message: str) -> None:
    """The mistakes of the engine's test, made with the app's keys and clicks: the panel
    names it (✗ and the sentence), the step is not taken, one mistake is counted."""
    app = app_of(key, sem)
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_hand(pilot)
        await play(pilot, screen, made)
        hand = screen.by_hand.hand
        kind, cell = move
        if kind == "pick":
            screen.move_cursor(cell)  # the cursor on it, and enter
            await pilot.press("enter")
        else:
            await click_cell(pilot, screen, hand.hint_cell())
            if cell is None:
                await pilot.press("enter")
            else:
                await add(pilot, screen, cell)
        await wait_until(pilot, lambda: "Mistakes 1" in panel(screen))
        text = panel(screen)
        assert text.startswith("✗ " + message.split(" ")[0])
        assert " ".join(text.split()).startswith(" ".join(f"✗ {message}".split()))
        assert "Try again · Step" in text
        assert hand.k == made and hand.by_cause() == {cause: 1}


@sync
async def test_a_wrong_step_can_be_tried_again_and_counts_once() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_hand(pilot)
        await play(pilot, screen, 2)
        await click_cell(pilot, screen, (1, 2))  # the newest: a stack's
        assert panel(screen).startswith("✗ step 3: BFS takes (0,2), the oldest")
        await click_cell(pilot, screen, (1, 2))  # again: said again, not counted again
        await click_cell(pilot, screen, (0, 2))  # right
        assert screen.by_hand.hand.picked == (0, 2)
        assert panel(screen).startswith("You took (0,2) off the queue")
        assert "Mistakes 1 " in panel(screen)


@sync
async def test_hints_light_the_entry_then_say_why_and_undo_takes_a_step_back() -> None:
    app = tutorial_app("dfs")
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_hand(pilot)
        await play(pilot, screen, 2)
        hand = screen.by_hand.hand
        want = hand.hint_cell()
        await pilot.press("h")
        assert panel(screen).startswith("Hint: the entry to take is highlighted; h again")
        assert app.session is not screen.session and screen.session.cursor == want
        assert want in screen.by_hand.highlight()
        await pilot.press("h")
        assert panel(screen).startswith("Hint: DFS takes the stack's top, the newest entry: "
                                        f"({want[0]},{want[1]})")
        await pilot.press("enter")  # the cursor is on it: taken
        assert hand.picked == want
        await pilot.press("u")
        assert hand.picked is None and panel(screen).startswith("Put ")
        await pilot.press("u")
        assert hand.k == 1 and panel(screen).startswith("Step 2 undone")
        assert "hints 2" in panel(screen)


@sync
async def test_the_key_bar_and_help_list_the_by_hand_keys() -> None:
    app = tutorial_app()
    async with app.run_test(size=(120, 36)) as pilot:
        assert "By hand" in [desc for _, desc, _ in app.query_one(KeyBar).hints()]
        screen = await open_hand(pilot)
        shown = [desc for _, desc, _ in screen.query_one(KeyBar).hints()]
        assert {"Take", "Hint", "Help", "Leave"} <= set(shown)
        await click_cell(pilot, screen, (0, 0))
        shown = [desc for _, desc, _ in screen.query_one(KeyBar).hints()]
        assert "End step" in shown and "Take" not in shown
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is app.main)
    from tui_search.tui.dialogs.help import KEYS

    assert any(key == "H" and "by hand" in what for key, what in KEYS)


@sync
async def test_the_palette_opens_by_hand() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await palette_run(pilot, "By hand")
        await wait_until(pilot, lambda: isinstance(app.screen, ByHandScreen))


@sync
async def test_a_whole_run_ends_in_its_summary_and_its_record(tmp_path: Path) -> None:
    """--by-hand --records --student: the run starts at once; made to its end with one
    mistake, the summary says the steps, the mistake by kind and the time, and the
    student's records file has the run's line."""
    options = parse_options([str(TUTORIAL), "--by-hand", "--records", str(tmp_path),
                             "--student", "Ada Lovelace"])
    app = build_app(options)
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: shown(app.screen))
        screen = app.screen
        await play(pilot, screen, 2)
        hand = screen.by_hand.hand
        await click_cell(pilot, screen, (1, 2))  # the newest: one mistake
        await wait_until(pilot, lambda: len(hand.mistakes) == 1)
        while not hand.finished:
            await play(pilot, screen, 1)
        await wait_until(pilot, lambda: isinstance(app.screen, ByHandSummaryScreen))
        lines = app.screen.lines
        assert lines[0].startswith(f"{hand.k} steps in 0:") and lines[0].endswith(
            ", 1 mistake")
        assert lines[1] == "  1 × took the newest entry"
        assert lines[-1] == "BFS found a path of 7 moves"
        await pilot.press("r")  # the replay: the run beside BFS, on the main screen
        await wait_until(pilot, lambda: app.screen is app.main)
        replay = app.session.jumps.replay
        assert replay is not None and replay.labels == ["Your run", "BFS"]
        assert [m.cause for m in replay.mistakes] == ["newest"]
    (file,) = tmp_path.iterdir()
    assert file.name == "Ada-Lovelace.jsonl"
    events = [json.loads(line) for line in file.read_text().splitlines()]
    assert [e["event"] for e in events] == ["start", "by_hand"]
    run = events[1]
    assert (run["student"], run["algorithm"], run["finished"], run["steps"], run["mistakes"],
            run["by_cause"]) == ("Ada Lovelace", "bfs", True, hand.k, 1, {"newest": 1})


@sync
async def test_a_by_hand_exercise_opens_on_the_students_own_map() -> None:
    path = Path(__file__).parents[1] / "data" / "exercises" / "bfs-by-hand.toml"
    app = build_app(parse_options(["--exercise", str(path), "--student", "Ada Lovelace"]))
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: shown(app.screen))
        screen = app.screen
        assert screen.panel.border_title == "By hand: BFS · BFS by hand"
        assert "0 of 3 mistakes allowed so far" in panel(screen)
        assert screen.by_hand.run.grid.blocked == app.session.exercise.grid.blocked
