"""ctrl+o on a hostile file: the open prompt stays up with the one-line error, and the app
goes on with its map (the readers' cases are tests/engine/test_untrusted_files.py's)."""

from __future__ import annotations

from pathlib import Path

from tests.tui.test_app import SIZE, screen_shown, sync, wait_until
from tests.tui.test_files import TUTORIAL, type_name, untitled
from tui_search.engine.maps.load import load_map
from tui_search.tui.dialogs.open_map import OpenMapScreen


@sync
async def test_opening_a_hostile_map_shows_its_error_and_keeps_the_app(tmp_path: Path) -> None:
    huge, nul, deep = tmp_path / "huge.txt", tmp_path / "nul.txt", tmp_path / "deep.txt"
    with open(huge, "wb") as handle:
        handle.truncate(2**30)
    nul.write_bytes(b"S.#\n..\x00G\n")
    deep.write_text("[" * 200_000 + "]" * 200_000)
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        prompt = await screen_shown(pilot, OpenMapScreen)
        for path, error in (
                (huge, f"{huge}: file is 1024.0 MB; a map may be at most 64 MB"),
                (nul, f"{nul}:2:3: binary file (a NUL byte), not a map"),
                (deep, f"{deep}:1:1: unknown cell character '['")):
            await type_name(pilot, str(path))
            assert app.screen is prompt and prompt.error == error
        await pilot.press("escape")
        await wait_until(pilot, lambda: not isinstance(app.screen, OpenMapScreen))
        assert app.session.grid == load_map(TUTORIAL) and app.is_running
