"""The palette's Export command: ctrl+p, "Export", a file name, enter -- the run written as
``--export`` writes it (made by the exporter the command line gives the app), a file that
exists replaced only after the question, a name of no kind refused in the prompt, and an app
with no exporter saying so."""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.widgets import Input

from tests.export.test_exports import svg_frames
from tests.textual_internals import notifications
from tests.tui.test_app import sync, tutorial_app, wait_until
from tests.tui.test_themes import palette_run
from tui_search.cli.main import LazyExporter
from tui_search.tui.dialogs.confirm_overwrite import ConfirmOverwriteScreen
from tui_search.tui.dialogs.export_prompt import ExportScreen
from tui_search.tui.screens.export_command import NO_EXPORTER


async def typed(pilot, name: str) -> None:
    field = pilot.app.screen.query_one("#filename", Input)
    field.value = name
    await pilot.press("enter")
    await pilot.pause()


def said(app) -> list[str]:
    return [str(n.message) for n in notifications(app)]


@sync
async def test_the_palette_exports_the_run_as_the_command_line_does(tmp_path: Path) -> None:
    app = tutorial_app("dfs")
    app.exporter = LazyExporter()
    target = tmp_path / "run.svg"
    async with app.run_test(size=(100, 32)) as pilot:
        await palette_run(pilot, "Export the run")
        assert isinstance(app.screen, ExportScreen)
        assert app.screen.query_one("#filename", Input).value == "tutorial-dfs.svg"
        await typed(pilot, str(tmp_path / "run.txt"))
        assert app.screen.error == (f"{tmp_path / 'run.txt'}: the kind is the file's ending, "
                                    "one of .svg, .cast, .gif, .md, .trace.json, .trace.yaml")
        await typed(pilot, str(target))
        assert not isinstance(app.screen, ExportScreen)
        await wait_until(pilot, lambda: f"Exported {target}" in said(app), seconds=240)
        frames = svg_frames(target.read_text())
        assert len(frames) == 8 and "step 7/7" in "\n".join(frames[-1])  # DFS: 7 steps
        # again: the file is there, so the question first
        target.write_text("mine")
        await palette_run(pilot, "Export the run")
        await typed(pilot, str(target))
        assert isinstance(app.screen, ConfirmOverwriteScreen)
        await pilot.press("n")  # another name: nothing written
        await pilot.pause()
        assert isinstance(app.screen, ExportScreen) and target.read_text() == "mine"
        await typed(pilot, str(target))
        await pilot.press("y")
        await wait_until(pilot, lambda: target.read_text().startswith("<svg"), seconds=240)


@sync
async def test_an_app_with_no_exporter_says_so() -> None:
    app = tutorial_app()
    async with app.run_test(size=(100, 32)) as pilot:
        await app.main.run_action("export")
        await pilot.pause()
        assert NO_EXPORTER in said(app)


@sync
async def test_the_help_says_how_to_use_plain_mode_and_the_exports() -> None:
    from textual.widgets import Static

    from tui_search.tui.dialogs.help import HelpScreen

    app = tutorial_app()
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("question_mark")
        await pilot.pause()
        assert isinstance(app.screen, HelpScreen)
        text = str(app.screen.query_one("#help-elsewhere", Static).render())
        assert "tui-search --plain MAP" in text and "Export the run" in text
        assert "--headless --export FILE" in text


@pytest.mark.parametrize("size", [(80, 24), (200, 60)])
@sync
async def test_the_export_prompt_and_its_question_fit_the_terminal(size, tmp_path: Path) -> None:
    from tests.tui.test_app import click_shown
    from tests.tui.test_dialogs_fit import assert_fits

    app = tutorial_app()
    app.exporter = LazyExporter()
    there = tmp_path / "there.md"
    there.write_text("keep me\n")
    async with app.run_test(size=size) as pilot:
        await app.main.run_action("export")
        prompt = await assert_fits(pilot, ExportScreen)
        await typed(pilot, str(there))
        await assert_fits(pilot, ConfirmOverwriteScreen)
        await click_shown(pilot, "#another")
        await wait_until(pilot, lambda: app.screen is prompt)
        await pilot.press("escape")
        await wait_until(pilot, lambda: not isinstance(app.screen, ExportScreen))
        assert there.read_text() == "keep me\n"


@sync
async def test_the_palette_exports_a_posthoc_trace_and_its_map(tmp_path: Path) -> None:
    from tui_search.engine.traces.posthoc import load_any_trace

    app = tutorial_app("dfs")
    app.exporter = LazyExporter()
    target = tmp_path / "run.trace.yaml"
    async with app.run_test(size=(100, 32)) as pilot:
        await palette_run(pilot, "Export the run")
        await typed(pilot, str(target))
        assert not isinstance(app.screen, ExportScreen)
        await wait_until(pilot, lambda: f"Exported {target}" in "\n".join(said(app)),
                         seconds=60)
        run = app.session.runs[0]
        trace = load_any_trace(str(target), run.grid)
        assert [s.node for s in trace.steps] == [s.node for s in run.steps.all()]
        assert (tmp_path / "run.map").read_text().startswith("type octile\n")
