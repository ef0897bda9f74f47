"""The palette's Screenshot saves an SVG of the screen in the current folder (served with a
save folder, in that folder) and says where, in full; a folder it cannot write is one line."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.textual_internals import notifications
from tests.tui.test_app import SIZE, sync, tutorial_app, wait_until
from tests.tui.test_files import TUTORIAL
from tests.tui.test_themes import palette_run
from tui_search.engine.maps.load import load_map
from tui_search.engine.util.filenames import describe_name
from tui_search.tui.app import SearchApp
from tui_search.tui.model.file_rules import FileAccess


def svgs(folder: Path) -> list[Path]:
    return sorted(folder.glob("*.svg"))


@sync
async def test_screenshot_saves_in_the_current_folder_and_says_where(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """No ~/Downloads needed: HOME is a folder without one."""
    folder = tmp_path / "here [b]\x1b"
    folder.mkdir()
    monkeypatch.chdir(folder)
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await palette_run(pilot, "Screenshot", best=True)
        await wait_until(pilot, lambda: len(svgs(folder)) == 1)
        (shot,) = svgs(folder)
        await wait_until(pilot, lambda: any(n.title == "Screenshot" for n in notifications(app)))
        (note,) = [n for n in notifications(app) if n.title == "Screenshot"]
        assert note.message == (f"Saved {describe_name(shot.name)} in the folder "
                                f"{describe_name(str(folder))}") and "\\x1b" in note.message
    assert shot.read_text().startswith("<svg")


@sync
async def test_served_the_screenshot_goes_to_the_save_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    save_dir, elsewhere = tmp_path / "saves", tmp_path / "cwd"
    save_dir.mkdir()
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    app = SearchApp(load_map(TUTORIAL), file_access=FileAccess.served_in(save_dir))
    async with app.run_test(size=SIZE):
        saved = app.deliver_screenshot()
        assert saved is not None and Path(saved).parent == save_dir
        assert svgs(save_dir) == [Path(saved)] and svgs(elsewhere) == []


@sync
async def test_a_folder_it_cannot_write_is_one_line(tmp_path: Path) -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        assert app.deliver_screenshot(path=str(tmp_path / "missing")) is None
        await wait_until(pilot, lambda: any(n.title == "Screenshot" for n in notifications(app)))
        (note,) = [n for n in notifications(app) if n.title == "Screenshot"]
        assert note.message == f"Not saved in {tmp_path / 'missing'}: no such file"
        assert note.severity == "error"


@sync
async def test_the_help_names_the_screenshot_and_where_it_goes() -> None:
    """The palette's Screenshot, in ``?``'s keys (under ctrl+p): what it saves, and where."""
    from tests.textual_internals import repainted
    from tests.tui.test_app import screen_shown
    from tui_search.tui.dialogs.help import HelpScreen

    app = tutorial_app()
    async with app.run_test(size=(120, 80)) as pilot:
        await pilot.press("question_mark")
        await screen_shown(pilot, HelpScreen)
        keys = app.screen.query_one("#help-keys")
        await wait_until(pilot, lambda: keys.region.area > 0)
        screen = ["".join(text for text, _ in line) for line in await repainted(pilot)]
        at = next(i for i, row in enumerate(screen) if "Screenshot" in row)
        # the help's own text: the widest part between borders (the panels behind have some)
        said = " ".join(" ".join(max(row.split("│"), key=len).split())
                        for row in screen[at:at + 2])
        assert "ctrl+p" in screen[at - 1] and "current folder, which a note names" in said
