"""What the app shows, without Textual: the map and its file, the searches shown (a pane each),
their runs in lockstep, the cursor, playback, the quiz and the exercise.

The screen turns keys into calls here and shows the result; nothing here draws.  Every search
shown is a pane: one search is a session with one contender, and comparing is more of them.
A new :class:`~tui_search.engine.run.recorded.Run` for every pane is made whenever the map is
edited, a search or a setting changes or ``r`` is pressed, so no search state outlives its map.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import MAX_STEPS, Run
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics
from tui_search.engine.search.compare import Contender
from tui_search.engine.search.registry import DEFAULT_ALGORITHM
from tui_search.engine.search.state import State
from tui_search.tui.model import playback, searches
from tui_search.tui.model.boards import has_endpoints, holds, semantics_for, start_of
from tui_search.tui.model.map_edits import BRUSHES, NO_BRUSH, MapEdits
from tui_search.tui.model.playback import Before
from tui_search.tui.model.quiz import Quiz, toggled, verdict
from tui_search.tui.model.replay_jumps import LOCKSTEP, LOCKSTEP_SHORT, REPLAY_ENDED, ReplayJumps
from tui_search.tui.model.searches import DEFAULT_COMPARE, normal_spec, searches_of, with_key

if TYPE_CHECKING:
    # Imported where used: exercises are read and graded only once one is shown, so the first
    # frame does without their modules (benchmarks/README.md, "startup").
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.course.grading import Verdict
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.maps.scenarios import Optimum
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.traces.replay import Replay
    from tui_search.tui.model.by_hand import ByHand
    from tui_search.tui.model.class_records import Recorder
    from tui_search.tui.model.graph_edits import GraphEdits
    from tui_search.tui.model.lesson_play import LessonPlay
    from tui_search.tui.model.seek import Seek

NEEDS_ENDPOINTS = "Place a start (s) and a goal (g) to search"


class Session:
    """The state behind the screen.  ``compare`` (``bfs,dfs``, as ``--compare`` spells it)
    opens with those searches side by side; else one pane runs ``algorithm``.

    ``optimal_cost`` is a benchmark's lowest cost for this map, start and goal (a MovingAI
    ``.scen`` row: 8 moves, no corner cutting), shown beside a path's cost while the map (its
    obstacles and terrain costs), its ends and those rules stay as they are.  ``exercise`` is an
    exercise (or the tutorial's number 1 or 2) shown as a live challenge.

    Its parts: ``edits``, the map and its edits (:class:`~tui_search.tui.model.map_edits.MapEdits`:
    the history, the terrain brush); ``jumps``, the replay shown and the jump to where it
    parts from its search (:class:`~tui_search.tui.model.replay_jumps.ReplayJumps`).  What a
    search's key does to the searches shown is :mod:`~tui_search.tui.model.searches`'s; a lockstep
    step, :mod:`~tui_search.tui.model.playback`'s.
    """

    def __init__(
        self,
        board: Grid | Graph,
        path: Path | None = None,
        algorithm: str = DEFAULT_ALGORITHM,
        semantics: Semantics = DEFAULT_SEMANTICS,
        max_steps: int = MAX_STEPS,
        unsaved_name: str = "untitled",
        optimal_cost: float | None = None,
        exercise: Exercise | int | None = None,
        compare: str | None = None,
        replay: Replay | None = None,
    ) -> None:
        self.edits: MapEdits | GraphEdits = self._edits_of(board)
        self.map_path = Path(path) if path is not None else None
        self.unsaved_name = unsaved_name  # the title of a map with no file
        if not isinstance(board, Grid) and unsaved_name == "untitled":
            self.unsaved_name = board.name  # a graph built in (Romania) or made in code
        self.max_steps = max_steps
        self.semantics = semantics_for(board, semantics)  # a graph's orders and estimates
        self.algorithm = algorithm  # what c shows alone
        self.comparison = DEFAULT_COMPARE  # what c compares
        self.spec = algorithm  # the searches shown, a pane each
        if compare:
            self._remember(normal_spec(compare))
        self.contenders: list[Contender] = []
        self.runs: list[Run | BiRun] = []
        #: The cursor: a cell of a grid, a node (its name) of a graph.
        self.cursor: State = start_of(board)
        self.speed_index = playback.DEFAULT_SPEED
        self.playing = False
        self.seek: Seek | None = None
        self.note = ""
        self.quiz = Quiz()
        self.jumps = ReplayJumps(replay, lambda: self.runs, self.goto)
        self.exercise: Exercise | None = None
        self.show_exercise(exercise)  # its rules are the panes'
        #: What x cycles through: the exercise given at start (a file), the tutorial's two.
        self._exercises = [e for e in (self.exercise,) if e is not None and e.number is None]
        self.fold_trees = False  # the panes' trees folded away by the user
        self.show_code = False  # the Code panel in the trees' place (the pseudocode, lit)
        self.lesson: LessonPlay | None = None  # --lesson: the lesson shown beside the panes
        self.by_hand: ByHand | None = None  # by hand: the student makes the pane's steps
        self.records: Recorder | None = None  # --records: where what the student did goes
        self._fitted = ""  # the note on a setting fitted to a search, once said
        self._optimum: Optimum | None = None  # while it holds: engine/scenarios.py
        if optimal_cost is not None and isinstance(board, Grid):  # a --scen row: imported
            from tui_search.engine.maps.scenarios import Optimum

            self._optimum = Optimum(board, optimal_cost)
        # what the file's reader had to say (a layout's several dots), said at the start
        self.new_runs(board.source.note if isinstance(board, Grid) and board.source else "")

    # -- what is shown -------------------------------------------------------------------
    @property
    def run(self) -> Run | BiRun | None:
        """The first pane's run (the quiz asks about it); None without start and goal."""
        return self.runs[0] if self.runs else None

    @property
    def board(self) -> Grid | Graph:
        """What is searched: the grid or the graph shown (its edits: ``edits``)."""
        return self.edits.board

    @property
    def grid(self) -> Grid:
        """The grid shown (a grid's features only: a graph has none, :attr:`board`)."""
        board = self.edits.board
        assert isinstance(board, Grid), "a graph is shown: session.board"
        return board

    @property
    def graph(self) -> Graph | None:
        """The graph shown (None: a grid)."""
        board = self.edits.board
        return None if isinstance(board, Grid) else board

    def _edits_of(self, board: Grid | Graph, brush: float | None = None
                  ) -> MapEdits | GraphEdits:
        if isinstance(board, Grid):
            return MapEdits(board, self._map_edited, brush=brush)
        from tui_search.tui.model.graph_edits import GraphEdits  # a graph's only

        return GraphEdits(board, self._map_edited)

    @property
    def labels(self) -> list[str]:
        """The panes' names, in order."""
        replay = self.jumps.replay
        if replay is not None:
            return replay.labels
        return [c.label for c in self.contenders]

    @property
    def map_name(self) -> str:
        """The map as its title names it: its file's name, else ``unsaved_name``."""
        return self.map_path.name if self.map_path else self.unsaved_name

    @property
    def dirty(self) -> bool:
        """True when the map differs from its file (edits not saved, nor undone)."""
        return self.edits.history.modified

    @property
    def title(self) -> str:
        return f"{self.map_name} {'· modified' if self.dirty else ''}".strip()

    @property
    def seeking(self) -> bool:
        return self.seek is not None

    @property
    def speed(self) -> int:
        return playback.SPEEDS[self.speed_index]

    def at_start(self) -> bool:
        return all(r.k == 0 for r in self.runs)

    def at_end(self) -> bool:
        return all(r.at_end for r in self.runs)

    @property
    def names(self) -> list[str]:
        """The panes' names where one line speaks of every pane (the readout, a seek's
        progress): names tell runs apart, so a run alone goes unnamed."""
        labels = self.labels
        return labels if len(labels) > 1 else [""] * len(labels)  # rule over N: naming

    def new_runs(self, note: str = "") -> None:
        """A fresh run a pane at step 0 on the map as it is now (none without start and
        goal)."""
        self.stop()
        self.contenders, why = searches_of(self.spec, self.semantics)
        self.note = note or (why if why != self._fitted else "")  # said once, not at each edit
        self._fitted = why
        board = self.board
        if not has_endpoints(board):
            self.runs = []
            self.note = note or NEEDS_ENDPOINTS
        else:
            replay = self.jumps.replay
            if replay is not None and not replay.fits(board):
                self.jumps.end()
                replay, self.note = None, note or REPLAY_ENDED
            try:
                self.runs = ([*replay.runs(board, self.max_steps)] if replay is not None
                             else [searches.run_of(board, c.algorithm, c.semantics, self.max_steps)
                                   for c in self.contenders])
            except ValueError as refused:  # a search the app cannot show on this map
                self.runs, self.note = [], note or str(refused)
            optimum = self._optimum  # a benchmark's, for a grid's map
            if optimum is not None and isinstance(board, Grid):
                known = optimum.on(board, self.semantics.corners, len(self.semantics.order))
                for run in self.runs:
                    run.known_lowest = known
        if self.runs and self.quiz.on and not self.note:
            self.note = self.quiz.question(self.runs[0])

    # -- the searches shown --------------------------------------------------------------
    def choose_algorithm(self, key: str) -> str | None:
        """One pane: run ``key`` there.  Several: add it, or take it out (two stay, four at
        most: :func:`~tui_search.tui.model.searches.with_key`).  None, or a warning why nothing
        changed."""
        spec, refused = with_key(self.spec, key)
        return refused if refused is not None else self.show_searches(spec)

    def show_searches(self, spec: str) -> str | None:
        """Show the searches of ``spec`` (``bfs,dfs``; one key: one pane) from step 0.  None,
        or the one-line reason the spec is refused (nothing changes then)."""
        spec = normal_spec(spec)
        try:
            searches_of(spec, self.semantics)
        except ValueError as exc:
            return f"Cannot compare {spec}: {exc}"
        self.jumps.end()  # other searches: the replay is over
        self._remember(spec)
        self.new_runs()
        return None

    def _remember(self, spec: str) -> None:
        """Show ``spec`` and remember it for c: c goes between the last search shown alone
        and the last ones side by side (the settings' pick)."""
        self.spec = spec
        searches = spec.split(",")
        if len(searches) == 1:  # rule over N: c's two memories, told apart by what they name
            self.algorithm = spec
        else:
            self.comparison = spec

    def toggle_compare(self) -> str | None:
        """c: the searches remembered that are not shown (one search, or those compared)."""
        return self.show_searches(
            next(spec for spec in (self.comparison, self.algorithm) if spec != self.spec))

    def choose_settings(self, semantics: Semantics, compare: str) -> None:
        """The settings screen's choice: the rules, and what ``c`` compares (shown at once
        where the old pick is shown)."""
        spec = compare if self.spec == self.comparison else self.spec
        self.comparison = compare
        if (semantics, spec) == (self.semantics, self.spec):
            return
        self.jumps.end()  # other rules: the replay is over
        self.semantics = semantics_for(self.board, semantics)
        if spec != self.spec:
            self.show_searches(spec)
        else:
            self.new_runs()

    # -- the map (its edits: ``edits``) ---------------------------------------------------
    def _map_edited(self, cursor: State | None) -> None:
        """The map was edited (or an edit undone: the cursor on ``cursor``): from step 0."""
        if cursor is not None:
            self.cursor = cursor
        self.new_runs()

    def move_cursor(self, cell: State) -> bool:
        if not holds(self.board, cell):
            return False
        self.cursor = cell
        return True

    def use_map(self, grid: Grid | Graph, path: Path | None,
                untitled: str | None = None) -> None:
        """Show ``grid`` (or a graph, read from ``path``) instead, from step 0; ``untitled``:
        the title of a map with no file (a generated map's recipe)."""
        if untitled is not None:
            self.unsaved_name = untitled
        self.edits = self._edits_of(grid, brush=self.edits.brush)
        self.semantics = semantics_for(grid, self.semantics)
        self.map_path = Path(path) if path is not None else None
        self.cursor = start_of(grid)
        self.jumps.end()
        self.new_runs()

    def show_replay(self, replay: Replay, grid: Grid, name: str) -> None:
        """Show ``replay`` (a run by hand's) beside its search, on ``grid`` (titled ``name``)
        when the map shown is another."""
        if not replay.fits(self.grid):
            self.use_map(grid.copy(), None, untitled=name)
        self.semantics = replay.semantics
        self._remember(replay.algorithm)
        self.jumps = ReplayJumps(replay, lambda: self.runs, self.goto)
        self.new_runs()

    def saved(self, path: Path) -> None:
        self.map_path = Path(path)
        self.edits.history.saved()

    # -- moving in lockstep --------------------------------------------------------------
    def where(self) -> Before:
        return playback.where(self.runs)

    def advance(self, forward: bool) -> Before | None:
        """One step of the lockstep (:func:`~tui_search.tui.model.playback.advance`)."""
        return playback.advance(self.runs, forward)

    def goto(self, k: int | None) -> None:
        """Every run at step ``k`` (None: its end), from where it is."""
        self.stop()
        for run in self.runs:
            run.goto(self.max_steps if k is None else k)

    def step(self, forward: bool) -> Before | None:
        self.stop()
        return self.advance(forward)

    def tick(self) -> Before | None:
        """A playback tick: a few steps at high speeds; playback stops at the end."""
        if not self.runs or not self.playing:
            return None
        before = self.where()
        playback.forward_for(self.runs, playback.steps_per_tick(self.speed))
        if self.at_end():
            self.playing = False
        return before

    def start_seek(self, to_end: bool, then_play: bool = False) -> None:
        """Move every run to its end (or step 0) in slices: :meth:`Seek.work`."""
        from tui_search.tui.model.seek import Seek  # once a key asks: the first frame has none

        self.stop()
        targets = [(run, None if to_end else 0) for run in self.runs]
        self.seek = Seek(targets, self.names, self.where(), then_play)

    def seek_done(self) -> Before:
        """The seek has arrived: where the runs were when it started (play if asked)."""
        seek = self.seek
        assert seek is not None
        self.seek = None
        if seek.noted:
            self.note = ""
        if seek.then_play:
            self.playing = True
        return seek.before

    def stop(self) -> None:
        """Pause playback and abandon a seek (any key that moves the position does this)."""
        if self.seek is not None:
            if self.seek.noted:
                self.note = ""
            self.seek = None  # the runs are still whole where they were
        self.playing = False

    def play(self) -> bool:
        """Play (at the last step: True, seek to step 0 first)."""
        self.stop()
        if self.at_end():
            self.start_seek(to_end=False, then_play=True)
            return True
        self.playing = True
        return False

    def set_speed(self, index: int) -> None:
        self.speed_index = max(0, min(len(playback.SPEEDS) - 1, index))

    # -- the quiz --------------------------------------------------------------------------
    def toggle_quiz(self) -> None:
        self.quiz, self.note = toggled(self.quiz, self.run)

    def answer(self) -> Before | None:
        """Take the step and mark the guess, the cell under the cursor (None: no step)."""
        run = self.run
        if not self.quiz.on or run is None:
            return None
        if run.at_end:
            self.note = self.quiz.over()
            return None
        self.stop()
        guess = self.cursor
        before = self.advance(forward=True)  # every pane steps
        if before is None:
            return None
        node = searches.current_node(run)
        if node is not None and run.k != before[0][0]:
            self.quiz, self.note = verdict(self.quiz, run, node, guess)
            if self.records is not None:
                self.records.quiz(run, node, guess, self.quiz)
        return before

    # -- the exercise ----------------------------------------------------------------------
    def show_exercise(self, exercise: Exercise | int | None) -> str:
        """Show ``exercise`` (1 or 2: the tutorial's) as the live challenge; None: none.  The
        panes take its rules, as its searches run under them: when that changed them, a note
        saying so (the caller runs the searches anew), else ""."""
        if isinstance(exercise, int):
            from tui_search.engine.course.exercise_file import built_in_exercise

            exercise = built_in_exercise(exercise)
        self.exercise = exercise
        if exercise is None or exercise.semantics == self.semantics:
            return ""
        self.jumps.end()  # other rules: a replay is over
        self.semantics = exercise.semantics
        rules = exercise.rules or "the tutorial's"
        return f"The searches run under {exercise.title}'s rules: {rules}"

    def cycle_exercise(self) -> str:
        """The next challenge: the exercise file given at start, exercise 1, 2, none (a note
        when the panes took its rules, as :meth:`show_exercise`)."""
        from tui_search.engine.course.exercise_file import built_in_exercise

        cycle: list[Exercise | None] = [*self._exercises, built_in_exercise(1),
                                        built_in_exercise(2), None]
        return self.show_exercise(cycle[(cycle.index(self.exercise) + 1) % len(cycle)])

    def own_exercise(self, exercise: Exercise) -> None:
        """A student's own exercise (``seed = "student"``, now they are named): shown in
        place of the one given at start, its map too."""
        self._exercises = [exercise if e is not None and e.path == exercise.path else e
                           for e in self._exercises]
        self.show_exercise(exercise)
        recipe = exercise.recipe
        self.use_map(exercise.grid.copy(), None, recipe.title if recipe is not None else None)

    def verdict(self) -> Verdict:
        """The exercise's verdict on the map as it is (its searches, whole)."""
        from tui_search.engine.course.grading import grade

        assert self.exercise is not None
        return grade(self.exercise, self.board, self.max_steps)


__all__ = ["BRUSHES", "DEFAULT_COMPARE", "LOCKSTEP", "LOCKSTEP_SHORT", "NEEDS_ENDPOINTS",
           "NO_BRUSH", "Before", "Session", "normal_spec"]
