"""The main screen's file commands: saving, save-as, opening a map, and never losing unsaved
edits -- quitting or replacing the map asks first.

Saving writes the file the map was read from back with only the edited cells changed (see
:class:`~tui_search.engine.maps.source.MapSource`), in its own format: ctrl+s on a MovingAI
``.map`` saves it in place as a ``.map`` (which has no start or goal, and the notification
says so).  A new name picks the format by its ending: ``.map`` MovingAI, anything else text.
A save the engine refuses loses nothing: a file changed on disk or with hard links is asked
about (:mod:`~tui_search.tui.screens.save_questions`), a read-only one opens save-as with the
reason, any other refusal is one line.

Where files may be read and written is the app's ``file_access``
(:class:`~tui_search.tui.model.file_rules.FileAccess`): anywhere in a terminal; served to browsers,
nowhere (each action says so in one line) or names in one folder.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from textual.app import App
from textual.notifications import SeverityLevel
from textual.screen import Screen

from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import MOVINGAI, TEXT
from tui_search.engine.maps.terrain import Terrain
from tui_search.engine.maps.write import (
    ChangedOnDisk,
    HardLinked,
    ReadOnlyFile,
    kind_for_path,
    save_map,
    save_notes,
)
from tui_search.engine.util.filenames import describe_name
from tui_search.tui.model.file_rules import FileAccess, one_line
from tui_search.tui.model.session import Session
from tui_search.tui.screens.save_questions import (
    Done,
    ask_in_place,
    changed_in_prompt,
    changed_on_ctrl_s,
)

if TYPE_CHECKING:
    from tui_search.engine.maps.generate import Recipe
    from tui_search.tui.dialogs.confirm_quit import Leaving

# The screens are imported when first needed: their widgets (Input, Button) would add to the
# app's start-up time for nothing.

NO_ENDPOINTS_IN_MAP = "MovingAI format: the start and goal are not part of a .map file"
#: A generated map of more cells is made in a thread (the biggest take seconds), the status
#: line saying "Generating ..." meanwhile; a smaller one at once (benchmarks/README.md,
#: "limits").
GENERATE_AT_ONCE_CELLS = 40_000


class Host(Protocol):
    """What the file commands need of the screen they serve."""

    session: Session
    file_access: FileAccess

    @property
    def app(self) -> App[Any]: ...

    def notify(self, message: str, *, title: str = "", severity: SeverityLevel = "information",
               timeout: float | None = None, markup: bool = True) -> None: ...

    def show_map(self) -> None:
        """Show the session's map anew (after a new map or a save)."""

    def show_status(self) -> None:
        """Show the status lines anew (the session's note changed)."""


#: What saving says while a graph is shown (its file is not written from the app).
GRAPH_NOT_SAVED = ("A graph's start, goal and closed nodes are not saved to its file: they "
                   "last until you quit (ctrl+z undoes them)")


class FileCommands:
    """ctrl+s saves, w saves as, ctrl+o opens a map, ctrl+n generates one; q and a new map ask
    first when there are unsaved edits (:meth:`confirm_discard`, :meth:`replace_map`)."""

    def __init__(self, host: Host) -> None:
        self.host = host

    @property
    def file_access(self) -> FileAccess:
        return self.host.file_access

    @property
    def dirty(self) -> bool:
        return self.host.session.dirty

    def notify(self, message: str, **options: Any) -> None:
        self.host.notify(message, **options)

    def push_screen(self, screen: Screen[Any], callback: Callable[[Any], None]) -> None:
        self.host.app.push_screen(screen, callback)

    def _files_off(self) -> bool:
        """When the served app may not touch files: say so (one line) and return True."""
        off = self.file_access.off
        if off is not None:
            self.notify(off, title="Not available", severity="warning", timeout=8)
        return off is not None

    # -- saving ---------------------------------------------------------------------------
    def _graph_unsaved(self) -> bool:
        """A graph is shown: its edits are not saved to a file (yet); say so, return True."""
        if self.host.session.graph is None:
            return False
        self.notify(GRAPH_NOT_SAVED, title="Not saved", severity="warning", timeout=8)
        return True

    def save_own(self) -> None:
        if self._graph_unsaved():
            return
        own = self.host.session.map_path
        if own is None or not self.file_access.may_save_over(own):
            self.ask_save_as()
        else:
            self.save(own)

    def save_as(self) -> None:
        self.ask_save_as()

    def _own_kind(self) -> str:
        """The format of the map's own file: the one it was read in."""
        source = self.host.session.grid.source
        if source is not None:
            return source.kind
        map_path = self.host.session.map_path
        return kind_for_path(map_path) if map_path is not None else TEXT

    def write_map(self, path: Path, kind: str, done: Done, *, in_prompt: bool = False,
                  overwrite: bool = False, in_place: bool = False) -> None:
        """Save the map to ``path`` in format ``kind``, atomically, then ``done(None)``; or
        ``done(error)`` with the MapError saying why not (the old file is then untouched).

        A file changed on disk since it was read or saved, or one with hard links, is asked
        about first (:mod:`~tui_search.tui.screens.save_questions`); ``done`` is not called when the
        answer leaves the map unsaved (cancel, reload), and is called once it is saved under
        another name chosen then.  ``in_prompt``: asked from the save-as prompt, whose own
        name field is the way to another name."""
        try:
            source = save_map(self.host.session.grid, path, kind, overwrite=overwrite,
                              in_place=in_place)
        except ChangedOnDisk:
            ask = changed_in_prompt if in_prompt else changed_on_ctrl_s
            ask(self, path, kind, done, in_place=in_place)
            return
        except HardLinked:
            ask_in_place(self, path, kind, done, in_prompt=in_prompt, overwrite=overwrite)
            return
        except MapError as exc:
            done(exc)
            return
        except (OSError, ValueError) as exc:  # what no name may do: end the app
            done(MapError(os.fsdecode(path), f"cannot save: {exc}"))
            return
        notes = ([NO_ENDPOINTS_IN_MAP] if kind == MOVINGAI else []) + save_notes(
            self.host.session.grid, kind)
        self.host.session.grid.source = source
        self.host.session.saved(Path(path))
        note = f" ({'; '.join(notes)})" if notes else ""
        self.notify(f"Saved {describe_name(str(path))}{note}", timeout=6 if note else 3,
                    markup=False)
        self.host.show_map()
        done(None)

    def save(self, path: Path, then: Callable[[], None] | None = None) -> None:
        """ctrl+s: save to the map's own file, then ``then``.  A read-only file opens the
        save-as prompt with the reason; any other failure is said in a notification."""

        def done(error: MapError | None) -> None:
            if error is None:
                if then is not None:
                    then()
            elif isinstance(error, ReadOnlyFile):
                self.ask_save_as(then, error=one_line(error))
            else:
                self.notify(one_line(error), title="Not saved", severity="error", timeout=8,
                            markup=False)

        self.write_map(path, self._own_kind(), done)

    def _save_as(self, path: Path, answer: Callable[[str | None], None]) -> None:
        map_path = self.host.session.map_path
        own = map_path is not None and path.resolve() == map_path.resolve()

        def done(error: MapError | None) -> None:
            answer(None if error is None else one_line(error))

        self.write_map(path, self._own_kind() if own else kind_for_path(path), done,
                       in_prompt=True)

    def ask_save_as(self, then: Callable[[], None] | None = None, error: str = "") -> None:
        """The save-as prompt; ``then`` runs once the map is saved (not on cancel);
        ``error``, the reason the map could not be saved where it was, shown in it."""
        if self._files_off() or self._graph_unsaved():
            return
        from tui_search.tui.dialogs.save_as import SaveAsScreen

        path = self.host.session.map_path
        access = self.file_access
        suggestion = access.suggestion(path)

        def saved(result: Path | None) -> None:
            if result is not None and then is not None:
                then()

        self.push_screen(SaveAsScreen(self._save_as, suggestion, own=path,
                                      to_path=access.path_for, folder=access.folder_for(path),
                                      flat=access.served, error=error), saved)

    def reload(self, path: Path) -> None:
        """Read the map's file again, dropping the app's edits (the caller asked first)."""
        source = self.host.session.grid.source
        given = source.terrain if source is not None else ()  # --terrain's table, if any
        try:
            grid = load_map(path, terrain=Terrain(dict(given), {}) if given else None)
        except MapError as exc:
            self.notify(one_line(exc), title="Not reloaded", severity="error", timeout=8,
                        markup=False)
            return
        from tui_search.tui.model.boards import too_big_for_the_app

        too_big = too_big_for_the_app(grid)
        if too_big:
            self.notify(too_big, title="Not reloaded", severity="error", timeout=8,
                        markup=False)
            return
        self._use_map(grid, path)
        self.notify(f"Reloaded {describe_name(str(path))}", timeout=3, markup=False)

    # -- leaving a map with edits ---------------------------------------------------------
    def confirm_discard(self, then: Callable[[], None], leaving: Leaving | None = None) -> None:
        """Run ``then`` (which leaves the map: quit, or replace it) at once when nothing is
        unsaved; else ask first: save then go on, go on without saving, or stay.

        ``leaving`` is a :class:`~tui_search.tui.dialogs.confirm_quit.Leaving` (the words);
        quitting's by default.
        """
        if not self.host.session.dirty:
            then()
            return
        from tui_search.tui.dialogs.confirm_quit import QUIT, QUITTING, SAVE, ConfirmQuitScreen

        def answer(choice: str | None) -> None:
            if choice == QUIT:
                then()
            elif choice == SAVE:
                own = self.host.session.map_path
                if own is None or not self.file_access.may_save_over(own):
                    self.ask_save_as(then)
                else:
                    self.save(own, then)

        name = describe_name(self.host.session.map_name)
        self.push_screen(ConfirmQuitScreen(name, leaving or QUITTING), answer)

    def quit(self) -> None:
        self.confirm_discard(lambda: self.host.app.exit(0))

    # -- opening a map --------------------------------------------------------------------
    def open(self) -> None:
        if self._files_off():
            return
        from tui_search.tui.dialogs.open_map import OpenMapScreen

        access = self.file_access
        suggestion = access.open_suggestion(self.host.session.map_path)

        def opened(result: tuple[Grid, Path] | None) -> None:
            if result is not None:
                self.replace_map(*result)

        self.push_screen(OpenMapScreen(suggestion, access.path_for,
                                       folder=access.folder_for(self.host.session.map_path),
                                       flat=access.served),
                         opened)

    def replace_map(self, grid: Grid, path: Path | None, name: str | None = None) -> None:
        """Show ``grid`` (read from ``path``, None for a map made in code) instead of the
        current map -- asking first when the current one has unsaved edits.  What opens a
        file or an exercise calls this; ``name`` is what the question calls the new map."""
        from tui_search.tui.dialogs.confirm_quit import replacing

        new_name = name or (describe_name(path.name) if path is not None else "the new map")
        self.confirm_discard(lambda: self._use_map(grid, path), replacing(new_name))

    def _use_map(self, grid: Grid, path: Path | None, untitled: str | None = None) -> None:
        self.host.session.use_map(grid, path, untitled)
        self.host.show_map()

    # -- generating a map -----------------------------------------------------------------
    def generate(self) -> None:
        """``ctrl+n``: ask for a recipe (the current one's next seed suggested), then show its
        map, untitled -- asking first when the current map has unsaved edits."""
        from tui_search.engine.maps.generate import make_recipe, next_recipe, recipe_of
        from tui_search.tui.dialogs.confirm_quit import generating
        from tui_search.tui.dialogs.generate_map import GenerateScreen

        shown = self.host.session.board
        now = recipe_of(shown) if isinstance(shown, Grid) else None  # a generated map's
        nxt = make_recipe("maze") if now is None else next_recipe(now)

        def chosen(recipe: Recipe | None) -> None:
            if recipe is not None:
                self.confirm_discard(lambda: self._generate(recipe), generating(recipe.title))

        self.push_screen(GenerateScreen(f"{nxt.spec} {nxt.width}x{nxt.height} {nxt.seed}"),
                         chosen)

    def _generate(self, recipe: Recipe) -> None:
        """Show ``recipe``'s map: made at once when small, else in a thread, the UI going on
        meanwhile (a later ctrl+n's map replaces this one's)."""
        from tui_search.engine.maps.generate import generate  # only when a map is generated

        if recipe.width * recipe.height <= GENERATE_AT_ONCE_CELLS:
            self._use_map(generate(recipe), None, recipe.title)
            return
        from textual.worker import get_current_worker

        session = self.host.session
        session.note = generating_note(recipe)
        self.host.show_status()
        app = self.host.app

        def work() -> None:
            grid = generate(recipe)
            if not get_current_worker().is_cancelled:
                app.call_from_thread(self._generated, recipe, grid)

        app.run_worker(work, thread=True, exclusive=True, group="generate")

    def _generated(self, recipe: Recipe, grid: Grid) -> None:
        """(Back from the thread.)  Show the generated map -- asking first, should the map
        have been edited meanwhile."""
        from tui_search.tui.dialogs.confirm_quit import generating

        session = self.host.session
        if session.note == generating_note(recipe):
            session.note = ""
            self.host.show_status()
        self.confirm_discard(lambda: self._use_map(grid, None, recipe.title),
                             generating(recipe.title))


def generating_note(recipe: Recipe) -> str:
    """The status line while ``recipe``'s map is made in a thread."""
    return f"Generating {recipe.title}…"

