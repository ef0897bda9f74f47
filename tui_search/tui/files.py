"""Saving the map and quitting with unsaved edits: the app's file actions, kept apart from its
search actions (a mixin of :class:`~tui_search.tui.app.SearchApp`)."""

from __future__ import annotations

from pathlib import Path

from tui_search.engine.grid import Grid
from tui_search.engine.mapfile import MapError, save_text_map

# The screens are imported when first needed: their widgets (Input, Button) would add to the
# app's start-up time for nothing.


def needs_a_name(path: Path | None) -> bool:
    """No file yet, or a MovingAI ``.map`` (never overwritten with the text format)."""
    return path is None or path.suffix.lower() == ".map"


class FileActions:
    """ctrl+s saves (asking for a name when needed); q asks first when there are edits."""

    grid: Grid
    map_path: Path | None
    map_name: str  # what the title calls the map
    dirty: bool

    def action_save(self) -> None:
        path = self.map_path
        if needs_a_name(path):
            from tui_search.tui.screens.save_as import SaveAsScreen

            stem = path.stem if path is not None else "map"
            self.push_screen(SaveAsScreen(f"{stem}.txt"), self._save_chosen)
        else:
            self.save(path)

    def _save_chosen(self, path: Path | None) -> None:
        if path is not None:
            self.save(path)

    def save(self, path: Path) -> bool:
        """Save the map atomically; on failure the old file is untouched and we say why."""
        try:
            save_text_map(self.grid, path)
        except MapError as exc:
            self.notify(str(exc), title="Not saved", severity="error", timeout=8)
            return False
        self.map_path = Path(path)
        self.dirty = False
        self.notify(f"Saved {path}", timeout=3)
        self._show(changed=[])
        return True

    async def action_quit(self) -> None:
        if not self.dirty:
            self.exit(0)
            return
        from tui_search.tui.screens.confirm_quit import ConfirmQuitScreen

        self.push_screen(ConfirmQuitScreen(self.map_name), self._quit_answer)

    def _quit_answer(self, answer: str | None) -> None:
        from tui_search.tui.screens.confirm_quit import QUIT, SAVE
        from tui_search.tui.screens.save_as import SaveAsScreen

        if answer == QUIT:
            self.exit(0)
        elif answer == SAVE:
            if needs_a_name(self.map_path):
                self.push_screen(SaveAsScreen(), self._save_then_quit)
            elif self.save(self.map_path):
                self.exit(0)

    def _save_then_quit(self, path: Path | None) -> None:
        if path is not None and self.save(path):
            self.exit(0)
