"""The app: the themes, the config file, the screens and start-up.  What is shown lives in a
Textual-free :class:`~tui_search.tui.model.session.Session`; the
:class:`~tui_search.tui.screens.main.MainScreen` shows it, a pane a search, and takes the keys.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from textual.app import App
from textual.command import Provider
from textual.screen import Screen
from textual.theme import Theme

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import MAX_STEPS
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics
from tui_search.engine.search.registry import DEFAULT_ALGORITHM
from tui_search.engine.util.atomic import os_reason
from tui_search.engine.util.filenames import describe_name
from tui_search.tui.config import Config
from tui_search.tui.model.file_rules import FileAccess
from tui_search.tui.model.session import Session
from tui_search.tui.screens.main import MainScreen
from tui_search.tui.view.themes import DEFAULT_THEME, THEMES, map_defaults

if TYPE_CHECKING:
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.course.lesson import Lesson
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.traces.replay import Replay
    from tui_search.tui.model.class_records import RecordsPlan
    from tui_search.tui.screens.export_command import Exporter


def textual_themes() -> list[Theme]:
    """The app's themes (:data:`~tui_search.tui.view.themes.THEMES`, plain data) as Textual's
    :class:`~textual.theme.Theme` objects, to register."""
    return [Theme(name=spec.name, dark=spec.dark, variables=dict(spec.variables), **spec.colours)
            for spec in THEMES.values()]


def _search_commands() -> type[Provider]:
    """The palette's app commands, imported when the palette first opens (start-up time)."""
    from tui_search.tui.commands import SearchCommands

    return SearchCommands


class SearchApp(App[int]):
    """Watch BFS, DFS, iterative deepening, UCS, greedy and A* plan a path on ``board``: a
    grid (its cells) or a graph (its nodes, :class:`~tui_search.engine.maps.graph.Graph`)."""

    CSS_PATH = "app.tcss"
    TITLE = "tui-search"
    COMMANDS = App.COMMANDS | {_search_commands}  # ctrl+p: Textual's commands and the app's

    def __init__(
        self,
        board: Grid | Graph,
        path: Path | None = None,
        algorithm: str = DEFAULT_ALGORITHM,
        semantics: Semantics = DEFAULT_SEMANTICS,
        max_steps: int = MAX_STEPS,
        unsaved_name: str = "untitled",
        theme: str | None = None,
        config: Config | None = None,
        optimal_cost: float | None = None,
        exercise: Exercise | int | None = None,
        compare: str | None = None,
        file_access: FileAccess | None = None,
        lesson: Lesson | None = None,
        replay: Replay | None = None,
        exporter: Exporter | None = None,
        records: RecordsPlan | None = None,
        by_hand: bool = False,
    ) -> None:
        """The session's arguments (:class:`~tui_search.tui.model.session.Session`), and: ``theme``
        for this run only (``--theme``; without it, the one the config file remembers);
        ``config``, the user's file by default (:func:`~tui_search.tui.config.config_path`);
        ``file_access``, where saving and opening may go
        (:class:`~tui_search.tui.model.file_rules.FileAccess`: anywhere by default; the served
        app's is narrower); ``lesson``, a lesson shown beside the panes from its first
        section; ``replay``, a trace beside the search it matches (``--replay``);
        ``exporter``, what the palette's Export command exports with (None: no export);
        ``records``, where what the student does is recorded (``--records``: the student
        named, or asked at start); ``by_hand``, the run by hand at once (``--by-hand``)."""
        super().__init__()
        self.session = Session(board, path, algorithm, semantics, max_steps, unsaved_name,
                               optimal_cost, exercise, compare, replay)
        if lesson is not None:
            from tui_search.tui.model.lesson_play import LessonPlay  # only for a lesson

            self.session.lesson = LessonPlay(lesson)
            self.session.lesson.open(self.session)
        self.file_access = file_access or FileAccess()
        self.exporter = exporter
        self.config = Config.load() if config is None else config
        self._config_noted = False  # a config problem is said once a run
        for own in textual_themes():
            self.register_theme(own)
        chosen = self.get_theme(theme or self.config.theme or DEFAULT_THEME)
        assert chosen is not None, "the command line and the config offer only the app's themes"
        if chosen.dark == self.current_theme.dark:
            # What Textual set up for its default (the ANSI palette, -dark-mode) holds: set the
            # name without the watcher, whose restyle of a stylesheet not read yet would cost
            # the first frame time (benchmarks/README.md, "startup").  (A light theme takes the
            # watcher: it changes those.)
            self.set_reactive(App.theme, chosen.name)
        else:
            self.theme = chosen.name
        self._theme_chosen = True  # the stylesheet's variables are the chosen theme's:
        self.stylesheet.set_variables(self.get_css_variables())
        for name in list(self.available_themes):  # only the app's: their map colours are set
            if name not in THEMES:
                self.unregister_theme(name)
        self._remember_theme = True  # from now on a theme chosen in the app is saved
        self.main = MainScreen(self.session, self.file_access)
        self.records = records
        self.start_by_hand = by_hand or bool(exercise is not None and not isinstance(
            exercise, int) and exercise.by_hand)
        if records is not None and records.student:
            from tui_search.tui.model.class_records import recorder

            self.session.records = recorder(records, records.student)

    def get_default_screen(self) -> Screen[None]:
        return self.main

    def on_mount(self) -> None:
        if self.config.problem:
            self._config_note(self.config.problem)
        if self.records is not None and self.session.records is None:
            from tui_search.tui.dialogs.visitor_name import VisitorNameScreen  # served: asked

            self.push_screen(VisitorNameScreen(self.records.class_list), self._named)
        else:
            self.call_after_refresh(self._started)

    def _named(self, name: str | None) -> None:
        """The visitor said who they are: their records, their own map (an exercise's
        ``seed = "student"``), then what the command line asked for."""
        from tui_search.tui.model.class_records import recorder

        assert self.records is not None
        self.session.records = recorder(self.records, name or "visitor")
        exercise = self.session.exercise
        if exercise is not None and exercise.student_seed:
            self.session.own_exercise(exercise.for_student(self.session.records.student))
            self.main.show_map()
        self.notify(f"Hello, {self.session.records.student}: your work here is recorded for "
                    "your teacher.", title="Records", timeout=8, markup=False)
        self._started()

    def _started(self) -> None:
        """Once the student is known: the records' first line, the run by hand if asked."""
        records = self.session.records
        if records is not None:
            problem = records.start(self.session.map_name, self.session.exercise)
            if problem:
                self.notify(problem, severity="warning", timeout=10, markup=False)
        if self.start_by_hand:
            from tui_search.tui.screens.by_hand import open_by_hand

            open_by_hand(self.main)

    # -- themes ---------------------------------------------------------------------------
    #: False while ``App.__init__`` asks for the variables of Textual's default theme: the
    #: app sets its chosen theme's in their place (``__init__``) before any CSS is read, so
    #: generating those would be wasted (benchmarks/README.md, "startup").
    _theme_chosen = False

    def get_css_variables(self) -> dict[str, str]:
        """Textual's variables for the theme, and the map's own ones it does not set."""
        if not self._theme_chosen:
            return {}
        variables = super().get_css_variables()
        for name, value in map_defaults(variables).items():
            variables.setdefault(name, value)
        self.theme_variables = variables
        return variables

    def action_next_theme(self) -> None:
        names = list(THEMES)
        self.theme = names[(names.index(self.theme) + 1) % len(names)]

    def watch_theme(self, name: str) -> None:
        """A theme chosen in the app (key, palette, Textual's theme picker) is remembered."""
        if getattr(self, "_remember_theme", False):
            problem = self.config.save_theme(name)
            if problem:
                self._config_note(problem)

    # -- the palette's Screenshot ----------------------------------------------------------
    def deliver_screenshot(self, filename: str | None = None, path: str | None = None,
                           time_format: str | None = None) -> str | None:
        """Save an SVG of the screen in the current folder (served: the save folder; with
        none, Textual's way: a download in the browser) and say where, in full."""
        access = self.file_access
        if access.served and access.folder is None:
            return super().deliver_screenshot(filename, path, time_format)
        folder = path or os.fspath(access.folder or Path.cwd())
        try:
            saved = os.path.abspath(self.save_screenshot(filename, folder, time_format))
        except OSError as err:
            self.notify(f"Not saved in {describe_name(folder)}: {os_reason(err)}",
                        title="Screenshot", severity="error", markup=False)
            return None
        where, name = os.path.split(saved)
        self.notify(f"Saved {describe_name(name)} in the folder {describe_name(where)}",
                    title="Screenshot", markup=False)
        return saved

    def _config_note(self, text: str) -> None:
        """Say what is wrong with the config file, once a run (it never stops the app)."""
        if not self._config_noted:
            self._config_noted = True
            self.notify(text, title="Config file", severity="warning", timeout=10)
