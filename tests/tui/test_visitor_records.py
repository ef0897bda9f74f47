"""A served app with records asks its visitor who they are before anything else, then writes
their own file (a name the app makes: no ``/``, ``..`` or control characters); the quiz's
answers and an exercise's verdicts go there too."""

from __future__ import annotations

import json
from pathlib import Path

from tests.tui.test_app import TUTORIAL, sync, wait_until
from tui_search.cli.main import build_app
from tui_search.cli.parse import parse_options
from tui_search.tui.dialogs.visitor_name import VisitorNameScreen

SIZE = (100, 30)


def served_app(folder: Path, *extra: str):
    return build_app(parse_options([str(TUTORIAL), "--served", "--records", str(folder),
                                    "--visitor", "a1b2c3", *extra]))


def lines(path: Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text().splitlines()]


@sync
async def test_a_visitor_gives_a_name_cleaned_and_their_answers_are_recorded(tmp_path) -> None:
    app = served_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, VisitorNameScreen))
        await pilot.press("enter")  # no name: asked again
        assert isinstance(app.screen, VisitorNameScreen)
        await pilot.press(*"../Ada\x07/..", "enter")
        await wait_until(pilot, lambda: app.screen is app.main)
        await pilot.press("n", "n", "i", "enter")  # a quiz answer
        await wait_until(pilot, lambda: app.session.quiz.asked == 1)
    (file,) = tmp_path.iterdir()
    assert file.name == "Ada.a1b2c3.jsonl" and file.parent == tmp_path
    events = lines(file)
    assert [e["event"] for e in events] == ["start", "quiz"]
    assert events[0]["student"] == "../Ada/.." and events[0]["visitor"] == "a1b2c3"
    assert events[1]["right"] is False and events[1]["algorithm"] == "bfs"


@sync
async def test_with_a_class_list_the_visitor_picks_their_name(tmp_path) -> None:
    names = tmp_path / "class.txt"
    names.write_text("Ada Lovelace\nAlan Turing\n# a comment\nGrace Hopper\n")
    records = tmp_path / "records"
    app = served_app(records, "--class", str(names))
    assert app.records is not None and app.records.class_list == (
        "Ada Lovelace", "Alan Turing", "Grace Hopper")
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, VisitorNameScreen))
        await pilot.press(*"hop", "enter")
        await wait_until(pilot, lambda: app.screen is app.main)
    (file,) = records.iterdir()
    assert file.name == "Grace-Hopper.a1b2c3.jsonl"
    assert lines(file)[0]["student"] == "Grace Hopper"
