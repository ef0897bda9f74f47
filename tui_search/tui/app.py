"""The app: owns the map, its file, the algorithm and the current :class:`Run`; the widgets are
told what to show and post messages back (attributes down, messages up).

A new ``Run`` is made whenever the map is edited, the algorithm changes or ``r`` is pressed, so
no search state survives from one run to the next.  Playback is a paused interval timer whose
ticks do what ``n`` does, several steps per tick at high speeds; ``end`` on a big map records and
moves in time-boxed slices so keys are still answered.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path
from time import perf_counter, sleep
from typing import ClassVar

from textual import events
from textual.app import App, ComposeResult
from textual.binding import Binding, BindingType
from textual.command import Provider
from textual.containers import Grid as GridBox
from textual.containers import Vertical
from textual.widgets import Static
from textual.worker import get_current_worker

from tui_search.engine.algorithms import ALGORITHMS, DEFAULT_ALGORITHM, get_algorithm
from tui_search.engine.compare import Contender, parse_compare
from tui_search.engine.exercises import (
    LIVE_CELLS,
    Verdict,
    check,
    tutorial_grid,
)
from tui_search.engine.grid import Cell, Grid
from tui_search.engine.run import MAX_STEPS, Run
from tui_search.engine.semantics import DEFAULT_SEMANTICS, Semantics
from tui_search.tui import playback
from tui_search.tui.config import Config
from tui_search.tui.editing import EditActions
from tui_search.tui.file_access import FileAccess
from tui_search.tui.files import FileActions
from tui_search.tui.narration import group_digits
from tui_search.tui.quiz import QuizActions
from tui_search.tui.readout import describe, describe_each
from tui_search.tui.screens.settings_choice import SettingsChoice
from tui_search.tui.themes import DEFAULT_THEME, THEMES, map_defaults, textual_themes
from tui_search.tui.widgets.cell_readout import CellReadout
from tui_search.tui.widgets.challenge import ChallengePanel
from tui_search.tui.widgets.compare_table import CompareTable
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar
from tui_search.tui.widgets.legend import Legend
from tui_search.tui.widgets.run_pane import RunPane, show_run
from tui_search.tui.widgets.search_tree import SearchTreePanel
from tui_search.tui.widgets.stats import Stats

MIN_WIDTH, MIN_HEIGHT = 60, 20
#: Compare mode: the searches ``c`` compares until the settings pick others.
DEFAULT_COMPARE = "bfs,dfs"
#: Compare mode's panes stand side by side while each is at least this wide (else in a grid
#: of fewer columns, one above the other at the narrowest), and fold their search trees away
#: when shorter than PANE_TREE_HEIGHT lines.
PANE_MIN_WIDTH, PANE_TREE_HEIGHT = 50, 24
#: The height at which a pane shows its map and frontier (a pane shorter than this favours
#: more columns).
PANE_MIN_HEIGHT = 16
LOCKSTEP = ("Lockstep: n steps every search not done yet, p steps back the latest, "
            "end runs them all to the end · 1-6 add or take out a search · c one search")
NEEDS_ENDPOINTS = "Place a start (s) and a goal (g) to search"
#: On a map too big to check an exercise at each edit, the check waits for the edits to pause
#: this long (seconds): a mouse stroke is an edit a cell.
EXERCISE_PAUSE = 0.3
#: What the key bar keeps when it is too narrow for every hint: the highest; help and quit
#: always (the bar drops the lowest first).
KEY_IMPORTANCE = {
    "help": 10, "quit": 10, "stop_seek": 9, "next": 8, "play": 7, "pause": 7, "algorithm": 6,
    "compare": 6, "settings": 5, "reset": 4, "save": 3, "quiz": 2, "overview": 2, "zoom": 1,
    "pick": 7,  # the frontier panel's, while it has the focus in the quiz
}
STEP = Binding.Group("Step", compact=True)
ZOOM = Binding.Group("Zoom", compact=True)
ALGO = Binding.Group("/".join(a.tag for a in ALGORITHMS.values()), compact=True)


def normal_spec(spec: str) -> str:
    """``bfs, dfs,`` as ``bfs,dfs``: the searches of a compare spec, no blanks."""
    return ",".join(part.strip() for part in spec.split(",") if part.strip())


def pane_grid(n: int, width: int, height: int) -> tuple[int, int]:
    """Columns and rows for ``n`` panes in ``width`` x ``height``: side by side while each
    gets PANE_MIN_WIDTH columns; else the grid whose panes come closest to that width and to
    PANE_MIN_HEIGHT lines (two by two, or one above the other in a narrow terminal, beside
    each other again in a short one)."""
    if width // n >= PANE_MIN_WIDTH:
        return n, 1

    def fit(columns: int) -> float:
        rows = -(-n // columns)
        return min(width / columns / PANE_MIN_WIDTH, height / rows / PANE_MIN_HEIGHT)

    columns = max(range(1, n + 1), key=lambda c: (fit(c), -abs(c - -(-n // c))))
    return columns, -(-n // columns)


def _search_commands() -> type[Provider]:
    """The palette's app commands, imported when the palette first opens (start-up time)."""
    from tui_search.tui.commands import SearchCommands

    return SearchCommands


class SearchApp(EditActions, FileActions, QuizActions, App[int]):
    """Watch BFS, DFS and iterative deepening plan a path on ``grid``."""

    CSS_PATH = "app.tcss"
    TITLE = "tui-search"
    COMMANDS = App.COMMANDS | {_search_commands}  # ctrl+p: Textual's commands and the app's
    AUTO_FOCUS = "GridView"

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("up,k", "move(0,-1)", "Cursor up", show=False),
        Binding("down,j", "move(0,1)", "Cursor down", show=False),
        Binding("left,h", "move(-1,0)", "Cursor left", show=False),
        Binding("right,l", "move(1,0)", "Cursor right", show=False),
        Binding("n", "next", "Next", group=STEP, tooltip="Next step (one expansion)"),
        Binding("p", "prev", "Prev", group=STEP, tooltip="Previous step"),
        # One key, two hints: "Play" while paused, "Pause" while playing (check_action hides
        # the other, and a key runs the first of its bindings that is enabled).
        Binding("space", "play", "Play", tooltip="Play (at the last step: again from step 0)"),
        Binding("space", "pause", "Pause", tooltip="Pause"),
        Binding("plus", "faster", "Faster", show=False, key_display="+", tooltip="Faster"),
        Binding("minus", "slower", "Slower", show=False, key_display="-", tooltip="Slower"),
        Binding("home", "first", "First", show=False, tooltip="First step"),
        Binding("end", "last", "Last", show=False, tooltip="Last step: the answer"),
        Binding("escape", "stop_seek", "Stop", key_display="esc",
                tooltip="Stop computing the last step"),
        *(Binding(a.app_key, f"algorithm({a.key!r})", a.short, group=ALGO, tooltip=a.name)
          for a in ALGORITHMS.values()),
        Binding("s", "place('start')", "Start", show=False, tooltip="Start at the cursor"),
        Binding("g", "place('goal')", "Goal", show=False, tooltip="Goal at the cursor"),
        Binding("o", "toggle_wall", "Wall", show=False, tooltip="Obstacle on/off at the cursor"),
        Binding("c", "compare", "Compare",
                tooltip="Compare searches side by side in lockstep (again: one search)"),
        Binding("f", "fold_trees", "Trees", show=False,
                tooltip="Compare mode: fold the search trees away (again: show them)"),
        Binding("r", "reset", "Reset", tooltip="Restart the search at step 0"),
        Binding("comma", "settings", "Settings", key_display=",",
                tooltip="Search settings: moves, corners, visited, goal test, tree search"),
        Binding("z", "overview", "Whole map",
                tooltip="Overview: the whole map at once, a character a block of cells"),
        Binding("right_square_bracket", "zoom(1)", "Zoom in", group=ZOOM, key_display="]",
                tooltip="Bigger cells (the cursor's cell stays in view)"),
        Binding("left_square_bracket", "zoom(-1)", "Zoom out", group=ZOOM, key_display="[",
                tooltip="Smaller cells (out of the smallest: the whole map)"),
        Binding("a", "labels", "Labels", show=False,
                tooltip="Cell labels: arrows and depth/cost, depth/cost only, none"),
        Binding("pageup", "page(-1)", "Page up", show=False, key_display="pgup",
                tooltip="Cursor a page up"),
        Binding("pagedown", "page(1)", "Page down", show=False, key_display="pgdn",
                tooltip="Cursor a page down"),
        Binding("S", "jump('start')", "To start", show=False, tooltip="Cursor to the start"),
        Binding("G", "jump('goal')", "To goal", show=False, tooltip="Cursor to the goal"),
        Binding("e", "jump('current')", "To node", show=False,
                tooltip="Cursor to the node being expanded"),
        Binding("i", "quiz", "Quiz", tooltip="Predict the next node: a quiz (again to stop)"),
        Binding("enter", "answer", "Answer", show=False,
                tooltip="Quiz: the node under the cursor (or the frontier entry picked) "
                "comes off next"),
        Binding("x", "exercise", "Exercise", show=False,
                tooltip="The tutorial's exercises as live challenges: 1, 2, off"),
        Binding("t", "next_theme", "Theme", show=False,
                tooltip="Next colour theme: " + ", ".join(t.title.lower() for t in THEMES.values())),
        Binding("ctrl+s", "save", "Save", tooltip="Save the map"),
        Binding("w", "save_as", "Save as", show=False, tooltip="Save the map as a new file"),
        Binding("ctrl+o", "open", "Open", show=False, tooltip="Open a map…"),
        Binding("question_mark", "help", "Help", key_display="?", tooltip="Help"),
        Binding("q", "quit", "Quit", tooltip="Quit (asks first when there are unsaved edits)"),
    ]

    def __init__(
        self,
        grid: Grid,
        path: Path | None = None,
        algorithm: str = DEFAULT_ALGORITHM,
        semantics: Semantics = DEFAULT_SEMANTICS,
        max_steps: int = MAX_STEPS,
        unsaved_name: str = "untitled",
        theme: str | None = None,
        config: Config | None = None,
        optimal_cost: float | None = None,
        exercise: int | None = None,
        compare: str | None = None,
        file_access: FileAccess | None = None,
    ) -> None:
        """``theme`` is for this run only (``--theme``); without it, the one the config file
        remembers.  ``config`` defaults to the user's file (:func:`~tui_search.tui.config.
        config_path`).  ``optimal_cost`` is a benchmark's lowest cost for this map, start and
        goal (a MovingAI ``.scen`` row: 8 moves, no corner cutting), shown beside a path's cost
        while the map, its ends and those rules stay as they are.  ``exercise`` opens the
        tutorial's exercise 1 or 2 as a live challenge (``x`` cycles them).  ``compare`` opens
        compare mode with those searches (``bfs,dfs``: :func:`~tui_search.engine.exercises.
        parse_compare`'s form).  ``file_access`` is where saving and opening may go
        (:class:`~tui_search.tui.file_access.FileAccess`: anywhere by default; the served
        app's is narrower)."""
        super().__init__()
        self.file_access = file_access or FileAccess()
        compare = normal_spec(compare) if compare else None
        self.compare = compare  # None: one search; else the searches side by side
        self.compare_pick = compare or DEFAULT_COMPARE  # what c compares
        self._panes: list[RunPane] = []  # compare mode's panes, in the contenders' order
        self.contenders: list[Contender] = []
        self.runs: list[Run] = []  # every search shown: one, or one a pane
        self.fold_trees = False  # compare mode: the trees folded away by the user
        self.exercise = exercise
        self._benchmark = None if optimal_cost is None else (
            bytes(grid.blocked), grid.start, grid.goal, optimal_cost)
        self.config = Config.load() if config is None else config
        self._config_noted = False  # a config problem is said once a run
        for own in textual_themes():
            self.register_theme(own)
        chosen = self.get_theme(theme or self.config.theme or DEFAULT_THEME)
        assert chosen is not None, "the command line and the config offer only the app's themes"
        if chosen.dark == self.current_theme.dark:
            # What Textual set up for its default (the ANSI palette, -dark-mode) holds: set the
            # name and the stylesheet's variables without the watcher, whose restyle of a
            # stylesheet not read yet would cost the first frame ~10 ms.  (A light theme takes
            # the watcher: it changes those.)
            self.set_reactive(App.theme, chosen.name)
            self.stylesheet.set_variables(self.get_css_variables())
        else:
            self.theme = chosen.name
        for name in list(self.available_themes):  # only the app's: their map colours are set
            if name not in THEMES:
                self.unregister_theme(name)
        self._remember_theme = True  # from now on a theme chosen in the app is saved
        self.grid = grid
        self.max_steps = max_steps
        self.map_path = Path(path) if path is not None else None
        self.unsaved_name = unsaved_name  # the title of a map with no file (the built-in one)
        self.algorithm = algorithm
        self.semantics = semantics
        self.dirty = False
        self.cursor_cell: Cell = grid.start or (0, 0)
        self.speed_index = playback.DEFAULT_SPEED
        self.playing = False
        self.seeking = False
        self._moves: Iterator[float] | None = None  # the pieces of a seek's move, once recorded
        self._seek_to = 0  # the step they move to
        self._seek_queue: list[tuple[Run, int | None]] = []  # runs to move: to 0, None the end
        self._seek_from: list[tuple[int, bool]] = []  # where the runs were when it started
        self._seek_noted = False  # the note says how far the seek is
        self._play_after = False  # play once the seek is there (space at the last step)
        self.note = ""
        self.search_run: Run | None = None
        self._stroke: bool | None = None  # what a mouse drag paints: True wall, False free
        self._bindings_key: tuple = ()
        self._mounted_ok = False  # True once mounted: widgets exist to show the run
        self._new_run()

    # -- layout -----------------------------------------------------------------------------
    def compose(self) -> ComposeResult:
        # The screen's mode class before its widgets are styled: set after, it would restyle
        # every widget once more.
        self.screen_stack[0].set_class(self.compare is not None, "-compare")
        self.view = view = GridView(self.grid, id="grid")
        self.frontier_panel = FrontierPanel(id="frontier")
        self.tree_panel = SearchTreePanel(id="tree")
        self.stats = Stats(id="stats")
        self.readout = CellReadout(id="readout")
        # One level: the key bar and the status lines split off the bottom, the side column
        # the right; the legend docks under the map, which is centred in what is left.
        # (Containers for the same layout cost every key a few more hops and every repaint
        # a few more widgets to composite.)
        yield KeyBar(KEY_IMPORTANCE, id="keys")
        yield self.stats
        self.compare_table = CompareTable(id="compare-table")
        yield self.compare_table
        with Vertical(id="side"):
            yield ChallengePanel(id="challenge")
            yield self.frontier_panel
            yield self.tree_panel
            yield Static(NEEDS_ENDPOINTS, id="side-note")
        yield self.readout
        yield Legend(view, id="legend")
        self._panes = self._new_panes()
        self.compare_box = GridBox(*self._panes, id="compare")
        yield self.compare_box
        yield view
        yield Static(id="too-small")

    def _new_panes(self) -> list[RunPane]:
        """A pane for each search compared (none in single mode)."""
        return [RunPane(self.grid, c.label) for c in self.contenders] if self.compare else []

    @property
    def panes(self) -> list[RunPane]:
        """Compare mode's panes (a pane a contender; mounted a moment after a change)."""
        return self._panes

    @property
    def views(self) -> list[GridView]:
        """The map views on screen: one a pane in compare mode, else the one."""
        return [pane.view for pane in self.panes] or [self.view]

    def on_mount(self) -> None:
        if self.config.problem:
            self._config_note(self.config.problem)
        self._timer = self.set_interval(1.0, self._tick, pause=True)
        self._set_speed(self.speed_index)
        self._check_size(self.size.width, self.size.height)
        self._arrange_panes(self.size.width, self.size.height)
        for view in self.views:
            view.set_cursor(self.cursor_cell)
        if self.compare:
            self.views[0].focus()
        self._mounted_ok = True
        self._check_exercise()
        self._show()

    def on_resize(self, event: events.Resize) -> None:
        self._check_size(event.size.width, event.size.height)
        self._arrange_panes(event.size.width, event.size.height)

    def _arrange_panes(self, width: int, height: int) -> None:
        """Compare mode's panes side by side while each is wide enough, else in fewer
        columns; their trees folded away when the panes are short (or when asked)."""
        n = len(self.contenders) if self.compare else 0
        if not n:
            return
        if self.exercise is not None:  # the challenge panel beside the panes (app.tcss)
            width -= min(56, max(38, width * 2 // 5))
        # What the bottom takes: the table (a line a search, head, two more, its border),
        # the status lines, the readout, the key bar and the legend.
        room = height - (n + 5) - 2 - 1 - 1 - 2
        columns, rows = pane_grid(n, width, room)
        box = self.compare_box
        box.styles.grid_size_columns = columns
        box.styles.grid_size_rows = rows
        box.set_class(self.fold_trees or room // rows < PANE_TREE_HEIGHT, "-no-trees")

    def _check_size(self, width: int, height: int) -> None:
        small = width < MIN_WIDTH or height < MIN_HEIGHT
        if small != self.too_small:
            self.screen_stack[0].set_class(small, "-too-small")
            self.refresh_bindings()  # behind the message only q acts
        self.screen_stack[0].query_one("#too-small", Static).update(
            f"Terminal too small: need at least {MIN_WIDTH}×{MIN_HEIGHT}, have {width}×{height}"
        )

    @property
    def too_small(self) -> bool:
        """True while the terminal is too small and the app shows only a message."""
        return bool(self.screen_stack) and self.screen_stack[0].has_class("-too-small")

    @property
    def map_name(self) -> str:
        """The map as its title names it: its file's name, else ``unsaved_name``."""
        return self.map_path.name if self.map_path else self.unsaved_name

    # -- themes ---------------------------------------------------------------------------
    def get_css_variables(self) -> dict[str, str]:
        """Textual's variables for the theme, and the map's own ones it does not set."""
        variables = super().get_css_variables()
        for name, value in map_defaults(variables).items():
            variables.setdefault(name, value)
        self.theme_variables = variables
        return variables

    def set_theme(self, name: str) -> None:
        """Switch to theme ``name`` (the palette's theme commands)."""
        self.theme = name

    def action_next_theme(self) -> None:
        names = list(THEMES)
        self.theme = names[(names.index(self.theme) + 1) % len(names)]

    def watch_theme(self, name: str) -> None:
        """A theme chosen in the app (key, palette, Textual's theme picker) is remembered."""
        if getattr(self, "_remember_theme", False):
            problem = self.config.save_theme(name)
            if problem:
                self._config_note(problem)

    def _config_note(self, text: str) -> None:
        """Say what is wrong with the config file, once a run (it never stops the app)."""
        if not self._config_noted:
            self._config_noted = True
            self.notify(text, title="Config file", severity="warning", timeout=10)

    # -- the run and what shows it ----------------------------------------------------------
    def _new_run(self, note: str = "") -> None:
        """A fresh run at step 0 on the map as it is now (or none without start and goal)."""
        self._stop()
        self.note = note
        grid = self.grid
        if self.compare:
            self.contenders, why = self._compare_contenders(self.compare)
            self.note = self.note or why
        if grid.start is None or grid.goal is None:
            self.runs = []
            self.note = note or NEEDS_ENDPOINTS
        else:
            searches = ([(c.algorithm, c.semantics) for c in self.contenders] if self.compare
                        else [(self.algorithm, self.semantics)])
            self.runs = [Run(grid, algorithm, semantics, self.max_steps)
                         for algorithm, semantics in searches]
            for run in self.runs:
                run.known_lowest = self._benchmark_cost()
        self.search_run = self.runs[0] if self.runs else None
        if self.search_run is not None and self.quiz and not self.note:
            self.note = self._quiz_question()
        if self._mounted_ok:
            self._check_exercise()
            self._show()

    def action_exercise(self) -> None:
        """Cycle the challenge: exercise 1, exercise 2, none."""
        self.action_show_exercise({None: 1, 1: 2, 2: 0}[self.exercise])

    def action_show_exercise(self, exercise: int) -> None:
        """Show exercise 1 or 2 as a live challenge on the map (0: none)."""
        self.exercise = exercise or None
        self._check_exercise()
        self._arrange_panes(self.size.width, self.size.height)

    def _check_exercise(self) -> None:
        """The challenge panel's verdict on the map as it is now: two whole searches, at once
        on a map of at most ``LIVE_CELLS`` cells, else in a thread once the edits pause."""
        screen = self.screen_stack[0]
        screen.set_class(self.exercise is not None, "-challenge")
        if self.exercise is None:
            return
        panel = screen.query_one(ChallengePanel)
        grid = self.grid
        if grid.start is None or grid.goal is None:
            panel.show(self.exercise, None, "Place a start (s) and a goal (g) to check it.")
        elif grid.width * grid.height > LIVE_CELLS:
            panel.show(self.exercise, None, f"Checking on this map ({group_digits(grid.width)}"
                       f" × {group_digits(grid.height)})…")
            exercise, copy = self.exercise, grid.copy()
            self.run_worker(lambda: self._check_big(exercise, copy), thread=True,
                            exclusive=True, group="exercise")
        else:
            panel.show(self.exercise, check(self.exercise, grid, tutorial_grid(),
                                            self.max_steps))

    def _check_big(self, exercise: int, grid: Grid) -> None:
        """(In a thread.)  Check ``exercise`` on ``grid``, a copy of the map as it was, once
        no edit has come for a moment (each edit starts a new check and cancels this one), and
        show the verdict if the map and the exercise are still the same."""
        sleep(EXERCISE_PAUSE)
        if get_current_worker().is_cancelled:
            return
        verdict = check(exercise, grid, tutorial_grid(), self.max_steps)
        self.call_from_thread(self._show_big_verdict, exercise, grid, verdict)

    def _show_big_verdict(self, exercise: int, grid: Grid, verdict: Verdict) -> None:
        now = self.grid
        if exercise == self.exercise and (grid.start, grid.goal) == (now.start, now.goal) \
                and grid.blocked == now.blocked:
            self.screen_stack[0].query_one(ChallengePanel).show(exercise, verdict)

    def _benchmark_cost(self) -> float | None:
        """The benchmark's lowest cost, if it applies to the map and the rules as they are."""
        if self._benchmark is None:
            return None
        blocked, start, goal, cost = self._benchmark
        grid, sem = self.grid, self.semantics
        same_map = (grid.start, grid.goal) == (start, goal) and bytes(grid.blocked) == blocked
        rules = sem.corners == "never" and len(sem.order) == 8
        return cost if same_map and rules else None

    def _compare_contenders(self, spec: str) -> tuple[list[Contender], str]:
        """The searches of ``spec`` under the settings in force, and a note when a setting
        does not apply to one of them (the visit rule: that one visits on generate)."""
        contenders = parse_compare(spec, self.semantics, fit=True)
        fitted = [c.label for c in contenders if c.semantics.visit != self.semantics.visit]
        note = (f"Visit on expand does not apply to {', '.join(fitted)}: visit on generate "
                "there" if fitted else "")
        return contenders, note

    def _show(self, changed: list[Cell] | None = None, follow: bool = True,
              per_run: list[list[Cell] | None] | None = None) -> None:
        """Push the runs at their positions to every widget; ``changed`` limits the map
        repaint (``per_run``: a list of changed cells for each run)."""
        run = self.search_run
        self.screen_stack[0].set_class(run is None, "-no-run")
        title = f"{self.map_name} {'· modified' if self.dirty else ''}".strip()
        if self.compare:
            runs = self.runs
            for i, pane in enumerate(self.panes):
                if not pane.is_mounted:
                    continue  # shown whole once mounted (_panes_mounted)
                r = runs[i] if runs else None
                pane.show(r, self.contenders[i].algorithm,
                          per_run[i] if per_run is not None else changed, follow=follow,
                          hide_order=self.quiz and i == 0,
                          done=r is not None and r.at_end)
                if pane.view.border_title != title:
                    pane.view.border_title = title
            self.compare_table.show([c.label for c in self.contenders], runs)
        else:
            show_run(self.view, self.frontier_panel, self.tree_panel, run,
                     per_run[0] if per_run is not None else changed, follow, self.quiz)
            if self.view.border_title != title:  # setting it repaints the whole view
                self.view.border_title = title
        self._show_pick()
        self._show_status()
        self.show_readout()

    def _refresh_keys(self) -> None:
        """Refresh the key bar when what greys out or hides its keys changed."""
        runs = self.runs
        key = (not runs, all(r.k == 0 for r in runs), all(r.at_end for r in runs),
               self.speed_index, self.playing, self.seeking, self.compare)
        if key != self._bindings_key:
            self._bindings_key = key
            self.refresh_bindings()

    def _show_status(self) -> None:
        """The status lines (counts, the note, the speed) and the key bar: all a seek's
        progress changes."""
        speed = playback.speed_text(playback.SPEEDS[self.speed_index])
        playing = f"▶ playing {speed}" if self.playing else f"speed {speed}"
        if self.compare:
            self.stats.show_compare([c.label for c in self.contenders], playing=playing,
                                    note=self.note, sentence=LOCKSTEP)
        else:
            self.stats.show(self.search_run, self.algorithm, playing=playing, note=self.note)
        self._refresh_keys()  # esc appears

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """Grey out (None) the keys that cannot act now, hide (False) those that do not apply
        (Play while playing, Pause while not, esc but while computing the end), and behind
        the "too small" message let only q act."""
        runs = self.runs
        if self.too_small:
            return action in ("quit", "help_quit")
        if action == "play":
            return False if self.playing else (None if not runs else True)
        if action == "pause":
            return self.playing
        if action == "stop_seek":
            return self.seeking
        if action in ("next", "last"):
            return None if not runs or (all(r.at_end for r in runs) and not self.playing) \
                else True
        if action in ("prev", "first"):
            return None if not runs or all(r.k == 0 for r in runs) else True
        if action == "reset":
            return None if not runs else True
        if action == "answer":
            return self.quiz and bool(runs)
        if action == "fold_trees":
            return self.compare is not None
        if action == "faster":
            return None if self.speed_index == len(playback.SPEEDS) - 1 else True
        if action == "slower":
            return None if self.speed_index == 0 else True
        return True

    # -- stepping: every run in lockstep ------------------------------------------------------
    def _moved(self, before: list[tuple[int, bool]]) -> None:
        """Show the runs after a move from ``before`` (each run's step and whether it was at
        its end): only the cells a one-step move changed."""
        self._show(per_run=[playback.step_changes(run, k, was_at_end)
                            for run, (k, was_at_end) in zip(self.runs, before)])

    def action_next(self) -> None:
        self._step(forward=True)

    def action_prev(self) -> None:
        self._step(forward=False)

    def _advance(self, forward: bool) -> list[tuple[int, bool]] | None:
        """One step of the lockstep: forwards, every run not at its end; backwards, the runs
        at the latest step (one that ended earlier stays on its last screen).  Where they
        were before, or None when none moved."""
        runs = self.runs
        if not runs:
            return None
        before = [(r.k, r.at_end) for r in runs]
        if forward:
            moved = [r.forward() for r in runs]
        else:
            latest = max(r.k for r in runs)
            moved = [r.k == latest and r.backward() for r in runs]
        return before if any(moved) else None

    def _step(self, forward: bool) -> None:
        self._stop()
        before = self._advance(forward)
        if before is not None:
            self._moved(before)

    def action_first(self) -> None:
        if self.runs:
            self._stop()
            self._seek([(run, 0) for run in self.runs])

    def action_reset(self) -> None:
        self._new_run()

    def action_last(self) -> None:
        """Go to the end: record each search, then move there, in slices of at most
        SLICE_SECONDS of work with the event loop answering keys in between (esc, or any key
        that moves the position, stops it where it is).  ``home`` from far moves the same way."""
        if not self.runs or all(r.at_end for r in self.runs):
            return
        self._stop()
        self._seek([(run, None) for run in self.runs])

    def _seek(self, targets: list[tuple[Run, int | None]], then_play: bool = False) -> None:
        """Move each run to its target (step 0, or None: its end), one run after another;
        then show them all (and play if asked)."""
        self.seeking = True
        self._seek_queue = targets
        self._seek_from = [(r.k, r.at_end) for r in self.runs]
        self._play_after = then_play
        self._moves = None
        self._seek_next()

    def _seek_next(self) -> None:
        """Start the next run's move; a run a few steps from its target moves at once."""
        queue = self._seek_queue
        while queue:
            run, target = queue[0]
            if target is None and run.at_end or target == 0 and run.k == 0:
                queue.pop(0)
            elif target == 0 and run.k <= run.REBUILD_AFTER:
                run.goto(0)
                queue.pop(0)
            else:
                if target == 0:
                    self._moves, self._seek_to = run.rebuild_pieces(0), 0
                self._seek_slice(run)
                return
        self._seek_done()

    def _seek_slice(self, run: Run) -> None:
        if not self.seeking or run not in self.runs or not self.is_running:
            return  # stopped, replaced, or the app is closing (its screens are gone)
        deadline = perf_counter() + playback.SLICE_SECONDS
        if self._moves is None:
            if not playback.record_for(run):
                recorded = group_digits(run.recorded)
                self._seek_note(run, f"Computing the search… {recorded} steps recorded")
                return
            if run.recorded - run.k <= run.REBUILD_AFTER:  # a few steps: at once
                run.goto(run.recorded)
                self._seek_arrived()
                return
            self._moves, self._seek_to = run.rebuild_pieces(run.recorded), run.recorded
        fraction = playback.rebuild_for(self._moves, max(0.0, deadline - perf_counter()))
        if fraction is not None:
            self._seek_note(run, f"Moving to step {group_digits(self._seek_to)}… {fraction:.0%}")
            return
        self._seek_arrived()

    def _seek_note(self, run: Run, text: str) -> None:
        """Say how far the seek is (and how to stop it), then carry on after a pause."""
        if self.compare:
            text = f"{run.algo.short}: {text[0].lower()}{text[1:]}"
        self.note = f"{text} — esc to stop"
        self._seek_noted = True
        self._show_status()  # only the note: the panes show where the runs were till the end
        self.set_timer(playback.SLICE_PAUSE, lambda: self._seek_slice(run))

    def _seek_arrived(self) -> None:
        """One run is where it was going: on to the next."""
        self._moves = None
        self._seek_queue.pop(0)
        self._seek_next()

    def _seek_done(self) -> None:
        """Every run is there: show them (or play, when asked)."""
        self.seeking = False
        if self._seek_noted:
            self._seek_noted = False
            self.note = ""
        if self._play_after:
            self._play_after = False
            self._play()
            return
        self._moved(self._seek_from)

    def action_stop_seek(self) -> None:
        """esc while computing the end: stop where the runs are (what was recorded is kept)."""
        if self.seeking:
            self._stop()
            self._show(changed=[])

    def action_play(self) -> None:
        """Play (at the last step: again from step 0); pause when playing."""
        runs = self.runs
        if self.playing:
            self.action_pause()
        elif runs:
            self._stop()
            if all(r.at_end for r in runs):
                self._seek([(run, 0) for run in runs], then_play=True)
            else:
                self._play()

    def _play(self) -> None:
        self.playing = True
        self._timer.resume()
        self._show()

    def action_pause(self) -> None:
        if self.playing:
            self._stop()
            self._show()

    def _stop(self) -> None:
        """Pause playback and abandon a seek (any key that moves the position does this)."""
        if self.seeking:
            self.seeking = False
            self._moves = None  # the runs are still whole where they were
            self._seek_queue = []
            self._play_after = False
            if self._seek_noted:
                self._seek_noted = False
                self.note = ""
        if self.playing:
            self.playing = False
            self._timer.pause()

    def _tick(self) -> None:
        runs = self.runs
        if not runs or not self.playing:
            return
        before = [(r.k, r.at_end) for r in runs]
        steps = playback.steps_per_tick(playback.SPEEDS[self.speed_index])
        playback.forward_for(runs, steps)
        if all(r.at_end for r in runs):
            self.playing = False
            self._timer.pause()
        self._moved(before)

    def _set_speed(self, index: int) -> None:
        self.speed_index = max(0, min(len(playback.SPEEDS) - 1, index))
        interval = playback.tick_interval(playback.SPEEDS[self.speed_index])
        self._timer.stop()
        self._timer = self.set_interval(interval, self._tick, pause=not self.playing)

    def action_faster(self) -> None:
        self._set_speed(self.speed_index + 1)
        self._show(changed=[])

    def action_slower(self) -> None:
        self._set_speed(self.speed_index - 1)
        self._show(changed=[])

    def action_algorithm(self, algorithm: str) -> None:
        """One search: run ``algorithm``.  Compare mode: add it to the searches compared, or
        take it out (two to four stay)."""
        if self.compare:
            parts = self.compare.split(",")  # normal_spec: no blanks
            keys = [p.partition(":")[0] for p in parts]
            name = get_algorithm(algorithm).short
            if algorithm in keys:
                if len(parts) == 2:
                    self.notify(f"Compare keeps two searches at least: {name} stays "
                                "(c for one search)", severity="warning", timeout=4)
                    return
                del parts[keys.index(algorithm)]
            elif len(parts) == 4:
                self.notify(f"Compare shows four searches at most: take one out to add {name}"
                            " (its key again)", severity="warning", timeout=4)
                return
            else:
                parts.append(algorithm)
            self._set_compare(",".join(parts))
            return
        self.algorithm = algorithm
        note = ""
        algo = get_algorithm(algorithm)
        if self.semantics.visit != "generate" and (algo.iterative or algo.weighted):
            # The visit rule does not apply to iterative deepening: back to the default.
            self.semantics = replace(self.semantics, visit="generate")
            note = f"Visit on expand does not apply to {algo.short}: back to visit on generate"
        self._new_run(note)

    def action_settings(self) -> None:
        from tui_search.tui.screens.settings import SettingsScreen  # only when asked

        self._stop()
        shown = ([get_algorithm(c.algorithm) for c in self.contenders] if self.compare
                 else [get_algorithm(self.algorithm)])
        self.push_screen(SettingsScreen(self.semantics, shown[0],
                                        self.compare or self.compare_pick, shown),
                         self._settings_chosen)

    def _settings_chosen(self, chosen: SettingsChoice | None) -> None:
        if chosen is None:
            return
        pick_changed = chosen.compare != (self.compare or self.compare_pick)
        self.compare_pick = chosen.compare
        if chosen.semantics == self.semantics and not (pick_changed and self.compare):
            return
        self.semantics = chosen.semantics
        if self.compare and pick_changed:
            self._set_compare(chosen.compare)
        else:
            self._new_run()

    # -- compare mode -------------------------------------------------------------------------
    def action_compare(self) -> None:
        """Compare mode on (the searches last picked) or off (one search again)."""
        self._set_compare(None if self.compare else self.compare_pick)

    def action_show_compare(self, spec: str) -> None:
        """Compare the searches of ``spec`` (the palette's comparisons)."""
        self._set_compare(spec)

    def _set_compare(self, spec: str | None) -> None:
        """Show the searches of ``spec`` side by side, a pane each (None: one search), and
        start them all at step 0 on the map as it is.  The state changes at once, so a key
        pressed next acts on the new runs; the new panes are mounted a moment later (until
        then what is shown skips them) and shown whole once they are."""
        self._stop()
        if spec is not None:
            try:
                spec = normal_spec(spec)
                contenders = self._compare_contenders(spec)[0]
            except ValueError as exc:  # a palette or settings spec the rules refuse
                self.notify(f"Cannot compare {spec}: {exc}", severity="error", timeout=5)
                return
            self.compare_pick = spec
        else:
            contenders = []
        old = self._panes
        state = (old[0].view if old else self.view).view_state()
        self.compare = spec
        self.contenders = contenders
        self._panes = self._new_panes()
        box = self.compare_box
        if old:
            box.remove_children()
        if self._panes:
            box.mount_all(self._panes)
        self.screen_stack[0].set_class(spec is not None, "-compare")
        if self.view.grid is not self.grid:  # the one view again, after a new map
            self.view.set_grid(self.grid)
        self._arrange_panes(self.size.width, self.size.height)
        for view in self.views:
            view.set_cursor(self.cursor_cell)
            view.set_view_state(state)  # zoom, labels, overview: as they were
        self._new_run()
        self.call_after_refresh(self._panes_mounted)

    def _panes_mounted(self) -> None:
        """The new panes are there: show every run in them, focus the first map."""
        if not all(pane.is_mounted for pane in self._panes):
            self.call_after_refresh(self._panes_mounted)
            return
        if self.screen is self.screen_stack[0]:
            self.views[0].focus()
        self._show()

    def action_fold_trees(self) -> None:
        """Compare mode: fold the panes' search trees away, or show them again."""
        self.fold_trees = not self.fold_trees
        self._arrange_panes(self.size.width, self.size.height)

    # -- the map ----------------------------------------------------------------------------
    def action_overview(self) -> None:
        on = not self.views[0].overview
        for view in self.views:
            view.set_overview(on)

    def action_zoom(self, steps: int) -> None:
        for view in self.views:
            view.zoom(steps)

    def action_labels(self) -> None:
        for view in self.views:
            mode = view.cycle_labels()
        self.notify(f"Cell labels: {mode}", timeout=2)

    def action_page(self, pages: int) -> None:
        """The cursor a screenful of cells up or down (at least one cell)."""
        view = self.views[0]
        rows = view.geometry.rows_in(view.scrollable_content_region.height)
        x, y = self.cursor_cell
        y = max(0, min(self.grid.height - 1, y + pages * max(1, rows - 1)))
        self._move_cursor((x, y))

    def action_jump(self, where: str) -> None:
        """The cursor to the start, the goal or the node being expanded (when there is one)."""
        run = self.search_run
        cell = {"start": self.grid.start, "goal": self.grid.goal,
                "current": run.current_node() if run is not None else None}[where]
        if cell is None:
            self.notify({"start": "No start on the map", "goal": "No goal on the map",
                         "current": "No node is being expanded (step 0)"}[where],
                        severity="warning", timeout=3)
            return
        self._move_cursor(cell)

    def show_readout(self) -> None:
        """What the run knows of the cell under the mouse, else of the cursor's."""
        hover = next((v.hover for v in self.views if v.hover is not None), None)
        cell, label = (hover, "Mouse") if hover is not None else (self.cursor_cell, "Cursor")
        if not self.grid.in_bounds(cell):
            cell, label = self.cursor_cell, "Cursor"
        if not self.compare:
            self.readout.show(label, describe(self.search_run, self.grid, cell))
            return
        self.readout.show(label, describe_each(self.runs, [c.label for c in self.contenders],
                                               self.grid, cell))

    def on_grid_view_cell_hovered(self, message: GridView.CellHovered) -> None:
        self.show_readout()

    def action_help(self) -> None:
        from tui_search.tui.screens.help import HelpScreen  # only when asked: start-up time

        self.push_screen(HelpScreen(self.view))
