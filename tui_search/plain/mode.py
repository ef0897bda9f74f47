"""Plain mode: the app as lines of text, for a screen reader, a braille display or SSH.  It
reads a command a line (:mod:`~tui_search.plain.commands`) and says what changed in plain
sentences (:mod:`~tui_search.plain.telling`, :mod:`~tui_search.plain.describe`), on the same
Textual-free session the app shows (:class:`~tui_search.tui.model.session.Session`): the same
searches, choices, edits, exercises and quiz.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from tui_search.engine.maps.grid import Cell
from tui_search.engine.maps.load import parse_cell
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.registry import ALGORITHMS, get_algorithm
from tui_search.engine.search.state import as_cell
from tui_search.plain import describe, telling, two_way
from tui_search.plain.commands import APP_ONLY, find, help_lines
from tui_search.plain.editing import EditCommands
from tui_search.plain.settings import apply_setting, settings_lines
from tui_search.tui.model.searches import current_node
from tui_search.tui.model.session import Session
from tui_search.tui.view.narration import cell_text, status_parts
from tui_search.tui.view.two_way.words import two_way_parts

_BY_KEY = {a.app_key: a.key for a in ALGORITHMS.values()}


class PlainMode:
    """A session driven by typed lines; ``write`` takes each line said."""

    def __init__(self, session: Session, write: Callable[[str], None]) -> None:
        self.session = session
        self.write = write
        #: The edits of the map and its files: a part, with its own commands.
        self.edits = EditCommands(self)

    def say(self, *lines: str) -> None:
        for line in lines:
            if line:
                self.write(line)

    # -- the loop -------------------------------------------------------------------------
    def start(self) -> None:
        s = self.session
        g = s.grid
        self.say(f"tui-search, plain mode: {self._searches()} on {s.map_name}, a map "
                 f"{g.width} wide and {g.height} high. The cursor is on "
                 f"{cell_text(s.cursor)}. Type a command and press enter: n for the next "
                 "step, help for every command, q to quit.")
        self.report()

    def handle(self, line: str) -> bool:
        """Do what ``line`` says; False once the mode should end."""
        word, _, rest = line.strip().partition(" ")
        rest = rest.strip()
        if not word:
            return True
        command = find(word)
        self.edits.asked_before(command.action if command is not None else "")
        if command is None:
            said = APP_ONLY.get(word) or APP_ONLY.get(word.lower())
            self.say(said or f"Unknown command {word!r}: help lists them.")
            return True
        owner = self if hasattr(self, f"do_{command.action}") else self.edits
        result: bool | None = getattr(owner, f"do_{command.action}")(rest, word)
        return result is not False

    # -- what is said after a change --------------------------------------------------------
    def _searches(self) -> str:
        labels = self.session.labels
        return " and ".join(labels) if labels else "no search"

    def report(self, moved: list[bool] | None = None) -> None:
        """Each search's step (``moved``: which moved; one that did not says it is done)."""
        s = self.session
        if not s.runs:
            self.say(s.note or "Place a start (s) and a goal (g) to search.")
            return
        several = len(s.runs) > 1
        for i, run in enumerate(s.runs):
            name = s.labels[i] if several else ""
            if moved is not None and not moved[i]:
                self.say(f"{name} is done at step {run.k}." if name else
                         f"At step {run.k}.")
                continue
            self.say(*two_way.report(run, name, hide_order=s.quiz.on))
        if s.note and not s.quiz.on:
            self.say(s.note)

    def _new_searches(self, warning: str | None = None) -> None:
        self.say(warning or "", f"Now {self._searches()} on {self.session.map_name}, from "
                 "step 0.")
        self.report()

    # -- stepping ---------------------------------------------------------------------------
    def _count(self, rest: str) -> int | None:
        if not rest:
            return 1
        if rest.isdigit() and int(rest) > 0:
            return int(rest)
        self.say(f"{rest!r} is not a number of steps.")
        return None

    def _step(self, forward: bool, rest: str) -> None:
        count = self._count(rest)
        s = self.session
        if count is None:
            return
        if not s.runs:
            self.report()
            return
        for _ in range(count):
            before = s.step(forward)
            if before is None:
                self.say("Already at the last step: home or p goes back." if forward else
                         "Already at step 0.")
                return
            self.report([k != run.k for (k, _end), run in zip(before, s.runs, strict=True)])

    def do_next(self, rest: str, word: str) -> None:
        self._step(True, rest)

    def do_prev(self, rest: str, word: str) -> None:
        self._step(False, rest)

    def do_play(self, rest: str, word: str) -> None:
        while self.session.runs and not self.session.at_end():
            self._step(True, "")

    def do_first(self, rest: str, word: str) -> None:
        self.session.goto(0)
        self.report()

    def do_last(self, rest: str, word: str) -> None:
        self.session.goto(None)
        self.report()

    def do_reset(self, rest: str, word: str) -> None:
        self.session.new_runs()
        self._new_searches()

    def do_status(self, rest: str, word: str) -> None:
        s = self.session
        for i, run in enumerate(s.runs):
            name = f"{s.labels[i]}: " if len(s.runs) > 1 else ""
            if not isinstance(run, Run):  # a bidirectional search: both halves' counts
                counts = ", ".join(f"{label} {value}" for label, value in two_way_parts(run))
                self.say(f"{name}{counts}.", two_way.two_way_step(run))
                continue
            counts = ", ".join(f"{label} {value}" for label, value in status_parts(run))
            self.say(f"{name}{counts}.", telling.step_sentence(run))
        if not s.runs:
            self.report()

    def do_frontier(self, rest: str, word: str) -> None:
        for run in self.session.runs:
            self.say(telling.frontier_sentence(run, self.session.quiz.on) if isinstance(run, Run)
                     else two_way.two_way_frontiers(run, self.session.quiz.on))

    def do_tree(self, rest: str, word: str) -> None:
        for run in self.session.runs:
            self.say(*(telling.tree_lines(run) if isinstance(run, Run)
                       else two_way.two_way_trees(run)))

    def do_code(self, rest: str, word: str) -> None:
        from tui_search.tui.view.code_trace import code_of, line_notes, lit_lines

        for run in self.session.runs:
            code = code_of(run)
            if not isinstance(run, Run):
                from tui_search.tui.view.two_way.code_lines import two_way_lines

                lit = two_way_lines(run)[0]
                notes: list[str] = []
            else:
                lit = lit_lines(run) if run.k else frozenset()
                notes = line_notes(run)
            self.say(f"{code.title}, the lines the step ran marked:")
            for i, line in enumerate(code.lines, start=1):
                self.say(f"Line {i}{', ran' if i in lit else ''}: {'  ' * line.indent}"
                         f"{line.text}")
            self.say(*(note + "." for note in notes))

    # -- the searches, the quiz, the exercise, the settings -----------------------------------
    def do_algorithm(self, rest: str, word: str) -> None:
        key = _BY_KEY.get(word, word.lower())
        self._new_searches(self.session.choose_algorithm(get_algorithm(key).key))

    def do_compare(self, rest: str, word: str) -> None:
        s = self.session
        self._new_searches(s.show_searches(rest.lower()) if rest else s.toggle_compare())

    def do_quiz(self, rest: str, word: str) -> None:
        s = self.session
        s.toggle_quiz()
        if not s.quiz.on:
            self.say("Quiz off.")
            return
        run = s.run
        if run is None:
            self.say("Quiz: place a start and a goal first.")
            return
        self.say(f"Quiz on: which node comes off the {run.algo.frontier.noun} next? Type "
                 "answer X,Y (answer alone: the cursor's cell). i ends the quiz.")
        self.do_frontier("", "")

    def do_answer(self, rest: str, word: str) -> None:
        s = self.session
        if not s.quiz.on:
            self.say("The quiz is off: i starts it.")
            return
        if rest:
            cell = self._cell(rest)
            if cell is None:
                return
            s.move_cursor(cell)
        run = s.run
        if run is None or run.at_end:
            self.say(f"Quiz over: the search is done. Score {s.quiz.score}.")
            return
        guess, asked = s.cursor, s.quiz.asked
        s.answer()
        node = current_node(run)
        if s.quiz.asked > asked and node is not None:
            verdict = "Right" if node == guess else f"Not quite: you said {cell_text(guess)}"
            self.say(f"{verdict}: {cell_text(node)} came off next. Score {s.quiz.score}.")
        self.report()

    def do_exercise(self, rest: str, word: str) -> None:
        s = self.session
        if rest in ("1", "2"):
            s.show_exercise(int(rest))
        elif rest == "off":
            s.show_exercise(None)
        elif rest:
            self.say("exercise takes 1, 2 or off (x cycles them).")
            return
        else:
            s.cycle_exercise()
        self.exercise_said(always=True)

    def exercise_said(self, always: bool = False) -> None:
        s = self.session
        if s.exercise is None:
            if always:
                self.say("No exercise shown.")
            return
        verdict = s.verdict()
        status = {"solved": "Solved", "not solved": "Not solved yet",
                  "not graded": "Not graded"}[verdict.status]
        self.say(f"{s.exercise.title}: {s.exercise.text}", f"{status}: {verdict.said}.",
                 f"Hint: {verdict.hints}" if verdict.hints else "")

    def do_settings(self, rest: str, word: str) -> None:
        self.say(*settings_lines(self.session))

    def do_set(self, rest: str, word: str) -> None:
        name, _, value = rest.partition(" ")
        runs = self.session.runs
        self.say(apply_setting(self.session, name.lower(), value.strip()))
        if self.session.runs is not runs:
            self.report()

    # -- the map in words --------------------------------------------------------------------
    def do_describe(self, rest: str, word: str) -> None:
        what, _, arg = rest.partition(" ")
        if what.lower() in ("map", "row", "column", "col", "cell", "around"):
            self.handle(f"{what} {arg}")
        else:
            self.say("describe takes map, row Y, column X, cell X,Y or around.")

    def do_map(self, rest: str, word: str) -> None:
        self.say(*describe.describe_map(self.session))

    def _number(self, rest: str, what: str) -> int | None:
        if rest.isdigit():
            return int(rest)
        self.say(f"{what} takes a number, counted from 0.")
        return None

    def do_row(self, rest: str, word: str) -> None:
        y = self._number(rest, "row") if rest else as_cell(self.session.cursor)[1]
        if y is not None:
            self.say(describe.describe_row(self.session, y))

    def do_column(self, rest: str, word: str) -> None:
        x = self._number(rest, "column") if rest else as_cell(self.session.cursor)[0]
        if x is not None:
            self.say(describe.describe_column(self.session, x))

    def _cell(self, text: str) -> Cell | None:
        try:
            return parse_cell(text)
        except ValueError as exc:
            self.say(f"{exc}.")
            return None

    def do_cell(self, rest: str, word: str) -> None:
        cell = self._cell(rest) if rest else as_cell(self.session.cursor)
        if cell is not None:
            self.say(describe.describe_cell(self.session, cell))

    def do_around(self, rest: str, word: str) -> None:
        self.say(describe.describe_around(self.session))

    # -- the cursor ----------------------------------------------------------------------------
    def _move_to(self, cell: Cell | None) -> None:
        if cell is None:
            return
        if not self.session.move_cursor(cell):
            self.say(f"{cell_text(cell)} is off the map: the cursor stays on "
                     f"{cell_text(self.session.cursor)}.")
            return
        self.say(describe.describe_cell(self.session, cell))

    def _by(self, dx: int, dy: int) -> None:
        x, y = as_cell(self.session.cursor)
        self._move_to((x + dx, y + dy))

    def do_left(self, rest: str, word: str) -> None:
        self._by(-1, 0)

    def do_right(self, rest: str, word: str) -> None:
        self._by(1, 0)

    def do_up(self, rest: str, word: str) -> None:
        self._by(0, -1)

    def do_down(self, rest: str, word: str) -> None:
        self._by(0, 1)

    def do_go(self, rest: str, word: str) -> None:
        self._move_to(self._cell(rest))

    def _to(self, cell: Cell | None, missing: str) -> None:
        if cell is None:
            self.say(missing)
        else:
            self._move_to(cell)

    def do_to_start(self, rest: str, word: str) -> None:
        self._to(self.session.grid.start, "No start on the map.")

    def do_to_goal(self, rest: str, word: str) -> None:
        self._to(self.session.grid.goal, "No goal on the map.")

    def do_to_node(self, rest: str, word: str) -> None:
        run = self.session.run
        node = current_node(run) if run else None
        self._to(None if node is None else as_cell(node), "No node is being expanded (step 0).")

    # -- help and quit -------------------------------------------------------------------------
    def do_help(self, rest: str, word: str) -> None:
        self.say(*help_lines())

    def do_quit(self, rest: str, word: str) -> bool:
        return not self.edits.may_leave("quit", "leaves")


def run_plain(session: Session, lines: Iterable[str], write: Callable[[str], None]) -> int:
    """Plain mode on ``session``: each of ``lines`` a command, each line said to ``write``,
    until q or the end of the lines; exit code 0."""
    mode = PlainMode(session, write)
    mode.start()
    for line in lines:
        if not mode.handle(line):
            return 0
    if session.dirty:
        write("The input ended: the map's unsaved edits are not saved.")
    return 0
