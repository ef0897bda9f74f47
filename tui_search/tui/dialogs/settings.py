"""Search settings (``,``): every choice of :mod:`tui_search.engine.search.choices`, each with a
line on what it changes, and the searches compare mode compares.  Dismisses with a
:class:`SettingsChoice`, or None when cancelled; the app then starts a new run at step 0 on the
same map.

Apply, Defaults, CS188 (the course's choices, ``--preset cs188``: each still changeable after
it) and Cancel are docked under the choices, so they never scroll away; on a
short terminal the blank lines between the choices go first, then the explanations (a note
that a choice does not apply, or a problem, stays).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Button, Checkbox, Input, Label, RadioButton, RadioSet

from tui_search.engine.maps.grid import DEFAULT_ORDER, parse_order
from tui_search.engine.search.choices import (
    CORNER_RULES,
    EXPLAIN,
    GOAL_TESTS,
    GRAPH_ORDERS,
    RECURSIVE_FORMS,
    TIE_RULES,
    VISIT_RULES,
    Semantics,
    check_weight,
    weight_text,
)
from tui_search.engine.search.heuristics import CHEAPER_BY, HEURISTICS, INADMISSIBLE, admissible
from tui_search.engine.search.registry import ALGORITHMS, Algorithm
from tui_search.tui.dialogs.settings_choice import SettingsChoice
from tui_search.tui.widgets.pick_button import PickButton
from tui_search.tui.widgets.tick_box import TickBox

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph

#: A word on each value, shown beside its radio button.
VALUE_WORDS: dict[str, str] = {
    "always": "always",
    "one": "if one side is free",
    "never": "if both sides are free",
    "generate": "when pushed",
    "expand": "when taken off",
    "expand-again": "taken off, not checked",
    **{name: name for name in HEURISTICS},
    "file": "as the file lists its roads", "name": "by name", "table": "the file's h table",
    "stack": "a stack",
    "neighbours": "a line lists neighbours",
    "calls": "a line lists calls",
    "fifo": "old", "lifo": "new", "node": "cell", "low-h": "low h",
    "high-h": "high h", "low-g": "low g", "high-g": "high g",
}
#: What recursion's radio buttons stand for: a stack (no recursion), or a trace's form.
RECURSION = ("stack", *RECURSIVE_FORMS)


class SettingsScreen(ModalScreen["SettingsChoice | None"]):
    """The choices as radio buttons, a move order and a checkbox; Apply, Defaults, Cancel."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]
    AUTO_FOCUS = "#corners"
    #: By the terminal's height: all of it from 37 lines (the box is 36 high); below, no
    #: blank line between the choices (29 high); below 30, the explanations hidden too,
    #: save a choice's note (does not apply, inadmissible) or a problem.
    #: (Not ClassVar: textual's annotation makes mypy see an instance variable.)
    VERTICAL_BREAKPOINTS = [(0, "-tiny"), (30, "-short"), (37, "-tall")]  # noqa: RUF012

    DEFAULT_CSS = """
    SettingsScreen {
        align: center middle;
        & > VerticalScroll {
            width: 76;
            max-width: 98%;
            height: auto;
            max-height: 98%;
            border: round $primary;
            background: $surface;
            padding: 0 1;
        }
        & .choice { text-style: bold; margin-top: 1; }
        & .explain, & .hint { color: $text-muted; width: 100%; }
        &.-short .choice, &.-tiny .choice { margin-top: 0; }
        &.-tiny .minor, &.-tiny .extra, &.-short .extra { display: none; }
        &.-tiny .explain { display: none; }
        &.-tiny .explain.-note, &.-tiny .explain.problem { display: block; }
        & .problem { color: $text-error; width: 100%; }
        & RadioSet { layout: horizontal; height: 1; width: 100%; }
        & RadioSet > RadioButton { width: auto; margin-right: 3; }
        & #heuristic > RadioButton { margin-right: 1; }  /* five in a row */
        & #ties > RadioButton { margin-right: 0; }  /* seven */
        & #weight { width: 7; }  /* beside the ticks */
        & #weight-label { width: auto; margin-right: 1; }
        & #compare-picks, .ticks { height: 1; width: 100%; margin-top: 0; }
        & #compare-picks > Checkbox, .ticks > Checkbox { width: auto; margin-right: 2; }
        & Input { width: 100%; background: $boost; }
        & #settings-buttons { dock: bottom; height: auto; background: $surface; }
        & #settings-buttons > Horizontal { height: 1; margin-top: 1; }
        & Button { margin-right: 2; min-width: 10; }
    }
    """

    def __init__(self, semantics: Semantics, algorithm: Algorithm,
                 compare: str = "bfs,dfs", algorithms: list[Algorithm] | None = None,
                 graph: Graph | None = None) -> None:
        """``compare``: the searches compare mode compares, as ``--compare`` spells them;
        ``algorithms``: the searches the choices are for (compare mode's, else
        ``algorithm``): a choice is greyed out only when it applies to none of them.
        ``graph``: the choices are a graph's (no moves nor corners: the order of its roads,
        its estimates)."""
        super().__init__()
        self.graph = graph
        if graph is not None:
            from tui_search.engine.search.choices import graph_heuristics

            self.heuristics: tuple[str, ...] = tuple(graph_heuristics(graph))
        else:
            self.heuristics = tuple(HEURISTICS)
        self.semantics = semantics
        self.algorithm = algorithm
        self.algorithms = algorithms or [algorithm]
        self.comparison = compare

    # -- layout ------------------------------------------------------------------------------
    def compose(self) -> ComposeResult:
        sem = self.semantics
        with VerticalScroll() as box:
            box.border_title = "Search settings · " + " · ".join(
                a.short for a in self.algorithms)
            if self.graph is not None:  # a graph: its roads' order; no moves, no corners
                yield Label("Successors, in the order added", classes="choice")
                yield Label("a node's roads as the file lists them, or by the names they "
                            "reach", classes="explain")
                yield self._radios("order", GRAPH_ORDERS, sem.order[0])
            else:
                yield Label("Moves, in the order tried", classes="choice")
                yield Label(f"{EXPLAIN['order']} (all eight: {','.join(DEFAULT_ORDER)}; "
                            "4-connected: N,W,S,E)", classes="explain")
                yield Input(",".join(sem.order), id="order", compact=True)
                yield Label("", id="order-error", classes="problem")
                yield Label("Diagonal past corners", classes="choice")
                yield Label(EXPLAIN["corners"], classes="explain")
                yield self._radios("corners", CORNER_RULES, sem.corners)
            yield Label("A cell counts as visited", classes="choice")
            yield Label("", id="visit-explain", classes="explain")
            yield self._radios("visit", VISIT_RULES, sem.visit)
            yield Label("Goal test", classes="choice")
            yield Label(EXPLAIN["goal_test"], classes="explain")
            yield self._radios("goal_test", GOAL_TESTS, sem.goal_test_for(self.algorithm))
            yield Label("Graph or tree search, stack or recursion", classes="choice minor")
            with Horizontal(classes="ticks"):
                yield TickBox("tree search", sem.tree_search, id="tree_search", compact=True)
                yield TickBox("no path check", not sem.path_check, id="no_path_check",
                               compact=True)
                yield TickBox("mark the start", sem.mark_start, id="mark_start",
                               compact=True)
            yield self._radios("recursive", RECURSION, sem.recursive or "stack")
            yield Label(f"{EXPLAIN['tree_search']}; {EXPLAIN['recursive']}",
                        id="recursive-explain", classes="explain extra")
            yield Label("Heuristic; a priority queue's ties, re-opening, costs; A*'s weight",
                        classes="choice")
            yield Label("", id="heuristic-explain", classes="explain")
            yield self._radios("heuristic", self.heuristics, sem.heuristic)
            yield self._radios("ties", TIE_RULES, sem.ties)
            with Horizontal(classes="ticks"):
                yield TickBox("re-open a cell reached cheaper", sem.reopen, id="reopen",
                               compact=True)
                yield TickBox("exact costs", sem.cost_tolerance == 0, id="exact_costs",
                               compact=True)
                yield Label("weight W", id="weight-label")  # weighted A*'s
                yield Input(weight_text(sem.weight), id="weight", compact=True)
            yield Label(EXPLAIN["weight"], id="weight-explain", classes="explain extra")
            yield Label("Compare (c)", classes="choice")
            picked = {part.strip().partition(":")[0] for part in self.comparison.split(",")}
            with Horizontal(id="compare-picks"):
                for algo in ALGORITHMS.values():
                    yield TickBox(algo.short, algo.key in picked, id=f"compare-{algo.key}",
                                   compact=True)
            yield Label("two to four searches side by side, in lockstep on the same map",
                        id="compare-explain", classes="explain")
            with Vertical(id="settings-buttons"):  # docked: never scrolled away
                with Horizontal():
                    yield Button("Apply", id="apply", variant="primary", compact=True)
                    yield Button("Defaults", id="defaults", compact=True)
                    yield Button("CS188", id="preset-cs188", compact=True,
                                 tooltip="the course's choices: --preset cs188")
                    yield Button("Cancel", id="cancel", compact=True)
                yield Label("tab / shift+tab move · arrows and enter pick · escape cancels",
                            classes="hint")

    @staticmethod
    def _radios(name: str, values: tuple[str, ...], chosen: str) -> RadioSet:
        return RadioSet(
            *(PickButton(VALUE_WORDS[v], v == chosen, id=f"{name}-{v}") for v in values),
            id=name.replace("_", "-"),
            compact=True,
        )

    def on_mount(self) -> None:
        if self.graph is not None:  # no corners to focus first: the order of the roads
            self.query_one("#order", RadioSet).focus()
        self._sync_visit()
        self._sync_heuristic()
        self._sync_published()

    # -- reading the controls ---------------------------------------------------------------
    def _choice(self, set_id: str) -> str:
        button = self.query_one(f"#{set_id}", RadioSet).pressed_button
        assert button is not None and button.id is not None
        return button.id.split("-", 1)[1]

    def picked(self) -> str | None:
        """The searches ticked for compare mode (``bfs,dfs``; a heuristic given on the
        command line kept), or None when fewer than two or more than four are."""
        kept = {part.strip().partition(":")[0]: part.strip()
                for part in self.comparison.split(",") if part.strip()}
        ticked = [key for key in ALGORITHMS
                  if self.query_one(f"#compare-{key}", Checkbox).value]
        explain = self.query_one("#compare-explain", Label)
        if set(ticked) == set(kept):  # unchanged: as compared (order, A* twice, heuristics)
            explain.set_class(False, "problem")
            return ",".join(part.strip() for part in self.comparison.split(",") if part.strip())
        # in the order they were compared, then the newly ticked in the registry's
        keys = [key for key in kept if key in ticked] + [k for k in ticked if k not in kept]
        if not 2 <= len(keys) <= 4:
            explain.set_class(True, "problem")
            explain.update(f"Compare: tick two to four searches ({len(keys)} ticked)")
            explain.scroll_visible()  # on a short terminal it may be below the choices shown
            return None
        explain.set_class(False, "problem")
        explain.update("two to four searches side by side, in lockstep on the same map")
        return ",".join(kept.get(key, key) for key in keys)

    def chosen(self) -> Semantics | None:
        """The settings as the controls show them (None, with the reason shown, when the move
        order does not parse)."""
        if self.graph is not None:
            order: tuple[str, ...] = (self._choice("order"),)
            corners = self.semantics.corners  # not a graph's: kept as it was
        else:
            error = self.query_one("#order-error", Label)
            try:
                order = parse_order(self.query_one("#order", Input).value)
            except ValueError as exc:
                error.update(f"Moves: {exc}")
                return None
            error.update("")
            corners = self._choice("corners")
        tree = self.query_one("#tree_search", Checkbox).value
        algo = self.algorithm
        recursive = self._choice("recursive")
        recursive = "" if recursive == "stack" or not self._recursion_applies() else recursive
        visit = ("generate" if tree or recursive or not self._visit_applies()
                 else self._choice("visit"))
        goal_test = self._choice("goal-test")
        mark = self.query_one("#mark_start", Checkbox).value or bool(
            tree or recursive or visit != "generate")
        exact = self.query_one("#exact_costs", Checkbox).value
        weight = self._weight() if any(a.priority == "g+h" for a in self.algorithms) else 1.0
        if weight is None:
            return None
        return Semantics(order=order, corners=corners, visit=visit,
                         goal_test=None if goal_test == algo.goal_test else goal_test,
                         tree_search=tree, heuristic=self._choice("heuristic"),
                         ties=self._choice("ties"), cost_tolerance=0.0 if exact else CHEAPER_BY,
                         reopen=self.query_one("#reopen", Checkbox).value,
                         recursive=recursive,
                         path_check=not (tree and self.query_one("#no_path_check",
                                                                 Checkbox).value),
                         mark_start=mark, weight=weight,
                         # not on the screen: kept as the command line gave it
                         flip_even=self.semantics.flip_even and self.graph is None)

    def _sync_visit(self) -> None:
        """The visit rule does not apply to tree search nor to iterative deepening: say so
        and grey it out."""
        tree = self.query_one("#tree_search", Checkbox).value
        radios = self.query_one("#visit", RadioSet)
        if not self._visit_applies() and self.algorithm.iterative and (
                not self.algorithm.contours):
            why = f"does not apply to {self.algorithm.short}: it re-opens cells reached shallower"
        elif not self._visit_applies():
            names = " or ".join(a.short for a in self.algorithms)
            why = f"does not apply to {names}: it re-opens cells reached with a lower g"
        elif tree:
            why = "does not apply to tree search: it has no visited set"
        elif self._choice("recursive") != "stack" and self._recursion_applies():
            why = "does not apply to a recursion: it visits a cell when it enters it"
        else:
            why = ""
        radios.disabled = bool(why)
        explain = self.query_one("#visit-explain", Label)
        explain.update(why or EXPLAIN["visit"])
        explain.set_class(bool(why), "-note")

    def _recursion_applies(self) -> bool:
        """Recursion applies to DFS and iterative deepening (in compare mode: to one)."""
        return any(a.key in ("dfs", "iddfs") for a in self.algorithms)

    def _sync_published(self) -> None:
        """The choices of published code: grey out those that apply to none of the searches
        (a priority queue's; recursion; the path check without tree search; the start's
        mark where nothing is marked on a push), and say which."""
        tree = self.query_one("#tree_search", Checkbox).value
        recursive = self._choice("recursive") != "stack" and self._recursion_applies()
        queue = any(a.queued for a in self.algorithms)
        visit = self._choice("visit") if self._visit_applies() else "generate"
        self.query_one("#no_path_check", Checkbox).disabled = not tree
        self.query_one("#mark_start", Checkbox).disabled = bool(
            tree or recursive or (visit != "generate" and not queue))
        self.query_one("#recursive", RadioSet).disabled = not self._recursion_applies()
        for name in ("#ties", "#reopen", "#exact_costs"):
            self.query_one(name).disabled = not queue
        astar = any(a.priority == "g+h" for a in self.algorithms)
        self.query_one("#weight", Input).disabled = not astar
        if not astar:
            self.query_one("#weight-explain", Label).update(
                "W, weighted A*'s weight (f = g + W·h), applies to A* only")

    def _weight(self) -> float | None:
        """The weight typed (None, with the reason shown, when it is no number 1 or
        more)."""
        explain = self.query_one("#weight-explain", Label)
        try:
            weight = check_weight(self.query_one("#weight", Input).value.strip())
        except ValueError as exc:
            explain.update(f"Weight: {exc}")
            explain.set_class(True, "problem")
            return None
        explain.update(EXPLAIN["weight"])
        explain.set_class(False, "problem")
        return weight

    def _visit_applies(self) -> bool:
        """The visit rule applies to BFS and DFS (in compare mode: to one of the searches)."""
        return any(not (a.iterative or a.weighted) for a in self.algorithms)

    def _sync_heuristic(self) -> None:
        """The heuristic applies to greedy and A* only; an inadmissible one is named."""
        radios = self.query_one("#heuristic", RadioSet)
        radios.disabled = not any(a.informed for a in self.algorithms)
        names = " or ".join(a.short for a in self.algorithms)
        if not any(a.weighted for a in self.algorithms):
            text = f"does not apply to {names}: no estimate, no priority queue"
        elif radios.disabled:
            text = f"the heuristic does not apply to {names}: it uses no estimate"
        elif self.graph is not None:  # a graph's table or straight line: said when checked
            text = EXPLAIN["heuristic"]
        else:
            name = self._choice("heuristic")
            order = self.query_one("#order", Input).value
            try:
                moves = parse_order(order)
            except ValueError:
                moves = DEFAULT_ORDER
            text = INADMISSIBLE if not admissible(name, moves) else EXPLAIN["heuristic"]
        explain = self.query_one("#heuristic-explain", Label)
        explain.update(text)
        explain.set_class(text != EXPLAIN["heuristic"], "-note")

    # -- events ------------------------------------------------------------------------------
    def on_radio_set_changed(self, event: RadioSet.Changed) -> None:
        self._sync_heuristic()
        self._sync_visit()
        self._sync_published()

    def on_checkbox_changed(self, event: Checkbox.Changed) -> None:
        self._sync_visit()
        self._sync_published()
        self.picked()  # shows or clears the problem as boxes are ticked

    def on_input_changed(self, event: Input.Changed) -> None:
        self.chosen()  # shows or clears the error as the order is typed
        self._sync_heuristic()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        self._apply()

    def on_button_pressed(self, event: Button.Pressed) -> None:
        if event.button.id == "apply":
            self._apply()
        elif event.button.id == "preset-cs188":
            from tui_search.engine.course.presets import preset_semantics
            from tui_search.tui.model.boards import semantics_for

            cs188 = preset_semantics("cs188", self.algorithm)  # a graph: its roads, its h
            self._show(cs188 if self.graph is None else semantics_for(self.graph, cs188))
        elif event.button.id == "defaults":
            if self.graph is not None:
                from tui_search.tui.model.boards import semantics_for

                self._show(semantics_for(self.graph, Semantics()))
            else:
                self._show(Semantics())
        else:
            self.dismiss(None)

    def _apply(self) -> None:
        semantics, compare = self.chosen(), self.picked()
        if semantics is not None and compare is not None:
            self.dismiss(SettingsChoice(semantics, compare))

    def _show(self, sem: Semantics) -> None:
        if self.graph is not None:
            self.query_one(f"#order-{sem.order[0]}", RadioButton).value = True
        else:
            self.query_one("#order", Input).value = ",".join(sem.order)
            self.query_one(f"#corners-{sem.corners}", RadioButton).value = True
        for name, value in (("visit", sem.visit),
                            ("goal_test", sem.goal_test_for(self.algorithm)),
                            ("heuristic", sem.heuristic), ("ties", sem.ties),
                            ("recursive", sem.recursive or "stack")):
            self.query_one(f"#{name}-{value}", RadioButton).value = True
        self.query_one("#weight", Input).value = weight_text(sem.weight)
        for name, on in (("tree_search", sem.tree_search), ("no_path_check", not sem.path_check),
                         ("mark_start", sem.mark_start), ("reopen", sem.reopen),
                         ("exact_costs", sem.cost_tolerance == 0)):
            self.query_one(f"#{name}", Checkbox).value = on
        self._sync_visit()
        self._sync_heuristic()
        self._sync_published()

    def action_cancel(self) -> None:
        self.dismiss(None)


__all__ = ["SettingsScreen"]
