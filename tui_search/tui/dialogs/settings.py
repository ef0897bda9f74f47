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
    STOP_RULES,
    TIE_RULES,
    TURN_RULES,
    VISIT_RULES,
    Semantics,
    check_weight,
    weight_text,
)
from tui_search.engine.search.heuristics import CHEAPER_BY, HEURISTICS
from tui_search.engine.search.registry import Algorithm
from tui_search.tui.dialogs.settings_choice import SettingsChoice
from tui_search.tui.dialogs.settings_controls import (
    RECURSION,
    compare_picks,
    picked,
    picked_comparison,
    radios,
)
from tui_search.tui.dialogs.settings_greying import (
    recursion_applies,
    sync_heuristic,
    sync_published,
    sync_two_way,
    sync_visit,
    visit_applies,
    weight_applies,
)
from tui_search.tui.widgets.tick_box import TickBox

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph

class SettingsScreen(ModalScreen["SettingsChoice | None"]):
    """The choices as radio buttons, a move order and a checkbox; Apply, Defaults, Cancel."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]
    #: The first choice has the focus (on_mount), the box not scrolled to centre it.
    AUTO_FOCUS = None
    #: By the terminal's height: all of it from 46 lines (the box is 45 high); below, no
    #: blank line between the choices and fewer explanations (31 high); below 32, the
    #: explanations hidden too, save a choice's note (does not apply, inadmissible) or a
    #: problem.
    #: (Not ClassVar: textual's annotation makes mypy see an instance variable.)
    VERTICAL_BREAKPOINTS = [(0, "-tiny"), (32, "-short"), (46, "-tall")]  # noqa: RUF012

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
        &.-short .extra.problem { display: block; }
        &.-tiny .explain { display: none; }
        &.-tiny .explain.-note, &.-tiny .explain.problem { display: block; }
        & .problem { color: $text-error; width: 100%; }
        & RadioSet { layout: horizontal; height: 1; width: 100%; }
        & RadioSet > RadioButton { width: auto; margin-right: 3; }
        & #heuristic > RadioButton { margin-right: 1; }  /* five in a row */
        & #ties > RadioButton { margin-right: 0; }  /* seven */
        & #weight { width: 7; }  /* beside the ticks */
        & #weight-label { width: auto; margin-right: 1; }
        & .picks, .ticks { height: 1; width: 100%; margin-top: 0; }
        & .picks > Checkbox, .ticks > Checkbox { width: auto; margin-right: 2; }
        & .row-label { width: auto; margin-right: 1; }
        & .row-label:disabled { color: $text-disabled; }
        & #stop, #turn { width: auto; margin-right: 2; }
        & #stop > RadioButton, #turn > RadioButton { margin-right: 1; }
        & #order-error { display: none; }  /* a line only when there is a problem */
        & #order-error.-shown { display: block; }
        & Input { width: 100%; background: $boost; }
        & #settings-buttons { dock: bottom; height: auto; background: $surface; }
        & #settings-buttons > Horizontal { height: 1; margin-top: 1; }
        &.-tiny #settings-buttons > Horizontal { margin-top: 0; }
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
                yield radios("order", GRAPH_ORDERS, sem.order[0])
            else:
                yield Label("Moves, in the order tried", classes="choice")
                yield Label(f"{EXPLAIN['order']} (all eight: {','.join(DEFAULT_ORDER)}; "
                            "4-connected: N,W,S,E)", classes="explain")
                yield Input(",".join(sem.order), id="order", compact=True)
                yield Label("", id="order-error", classes="problem")
                yield Label("Diagonal past corners", classes="choice")
                yield Label(EXPLAIN["corners"], classes="explain")
                yield radios("corners", CORNER_RULES, sem.corners)
            yield Label("A cell counts as visited", classes="choice")
            yield Label("", id="visit-explain", classes="explain")
            yield radios("visit", VISIT_RULES, sem.visit)
            yield Label("Goal test", classes="choice")
            yield Label(EXPLAIN["goal_test"], id="goal-explain", classes="explain")
            yield radios("goal_test", GOAL_TESTS, sem.goal_test_for(self.algorithm))
            yield Label("Graph or tree search, stack or recursion", classes="choice minor")
            with Horizontal(classes="ticks"):
                yield TickBox("tree search", sem.tree_search, id="tree_search", compact=True)
                yield TickBox("no path check", not sem.path_check, id="no_path_check",
                               compact=True)
                yield TickBox("mark the start", sem.mark_start, id="mark_start",
                               compact=True)
            yield radios("recursive", RECURSION, sem.recursive or "stack")
            yield Label(f"{EXPLAIN['tree_search']}; {EXPLAIN['recursive']}",
                        id="recursive-explain", classes="explain extra")
            yield Label("Heuristic; a priority queue's ties, re-opening, costs; A*'s weight",
                        classes="choice")
            yield Label("", id="heuristic-explain", classes="explain")
            yield radios("heuristic", self.heuristics, sem.heuristic)
            yield radios("ties", TIE_RULES, sem.ties)
            with Horizontal(classes="ticks"):
                yield TickBox("re-open a cell reached cheaper", sem.reopen, id="reopen",
                               compact=True)
                yield TickBox("exact costs", sem.cost_tolerance == 0, id="exact_costs",
                               compact=True)
                yield Label("weight W", id="weight-label")  # weighted A*'s
                yield Input(weight_text(sem.weight), id="weight", compact=True)
            yield Label(EXPLAIN["weight"], id="weight-explain", classes="explain extra")
            yield Label("Bidirectional search: when it stops, whose step is next",
                        classes="choice extra")  # the row says stop and turn
            yield Label("", id="two-way-explain", classes="explain extra")
            with Horizontal(classes="ticks"):
                yield Label("stop", classes="row-label")
                yield radios("stop", STOP_RULES, sem.stop)
                yield Label("turn", classes="row-label")
                yield radios("turn", TURN_RULES, sem.turn)
            yield from compare_picks(self.comparison)
            with Vertical(id="settings-buttons"):  # docked: never scrolled away
                with Horizontal():
                    yield Button("Apply", id="apply", variant="primary", compact=True)
                    yield Button("Defaults", id="defaults", compact=True)
                    yield Button("CS188", id="preset-cs188", compact=True,
                                 tooltip="the course's choices: --preset cs188")
                    yield Button("Cancel", id="cancel", compact=True)
                yield Label("tab / shift+tab move · arrows and enter pick · escape cancels",
                            classes="hint")

    def on_mount(self) -> None:
        # a graph has no corners to focus first: the order of its roads.  Not scrolled to
        # the middle of the box, as a focus is: its first lines stay in view
        first = self.query_one("#order" if self.graph is not None else "#corners", RadioSet)
        self.set_focus(first, scroll_visible=False)
        self._sync()

    # -- reading the controls ---------------------------------------------------------------
    def picked(self) -> str | None:
        """The searches ticked for compare mode (``bfs,dfs``; a heuristic or a rule given on
        the command line kept), or None when fewer than two or more than four are."""
        return picked_comparison(self, self.comparison)

    def chosen(self) -> Semantics | None:
        """The settings as the controls show them (None, with the reason shown, when the move
        order does not parse)."""
        if self.graph is not None:
            order: tuple[str, ...] = (picked(self, "order"),)
            corners = self.semantics.corners  # not a graph's: kept as it was
        else:
            error = self.query_one("#order-error", Label)
            try:
                order = parse_order(self.query_one("#order", Input).value)
            except ValueError as exc:
                error.update(f"Moves: {exc}")
                error.add_class("-shown")
                return None
            error.update("")
            error.remove_class("-shown")
            corners = picked(self, "corners")
        tree = self.query_one("#tree_search", Checkbox).value
        algo = self.algorithm
        recursive = picked(self, "recursive")
        if recursive == "stack" or not recursion_applies(self.algorithms):
            recursive = ""
        visit = ("generate" if tree or recursive or not visit_applies(self.algorithms)
                 else picked(self, "visit"))
        goal_test = picked(self, "goal-test")
        mark = self.query_one("#mark_start", Checkbox).value or bool(
            tree or recursive or visit != "generate")
        exact = self.query_one("#exact_costs", Checkbox).value
        weight = self._weight() if weight_applies(self.algorithms) else 1.0
        if weight is None:
            return None
        return Semantics(order=order, corners=corners, visit=visit,
                         goal_test=None if goal_test == algo.goal_test else goal_test,
                         tree_search=tree, heuristic=picked(self, "heuristic"),
                         ties=picked(self, "ties"), cost_tolerance=0.0 if exact else CHEAPER_BY,
                         reopen=self.query_one("#reopen", Checkbox).value,
                         recursive=recursive,
                         path_check=not (tree and self.query_one("#no_path_check",
                                                                 Checkbox).value),
                         mark_start=mark, weight=weight, stop=picked(self, "stop"),
                         turn=picked(self, "turn"),
                         # not on the screen: kept as the command line gave it
                         flip_even=self.semantics.flip_even and self.graph is None)

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

    def _sync(self) -> None:
        """Grey out the choices that apply to none of the searches, and say why."""
        sync_heuristic(self, self.algorithms, self.graph is not None)
        sync_visit(self, self.algorithms)
        sync_published(self, self.algorithms)
        sync_two_way(self, self.algorithms)

    # -- events ------------------------------------------------------------------------------
    def on_radio_set_changed(self, event: RadioSet.Changed) -> None:
        self._sync()

    def on_checkbox_changed(self, event: Checkbox.Changed) -> None:
        self._sync()
        self.picked()  # shows or clears the problem as boxes are ticked

    def on_input_changed(self, event: Input.Changed) -> None:
        self.chosen()  # shows or clears the error as the order is typed
        sync_heuristic(self, self.algorithms, self.graph is not None)

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
                            ("recursive", sem.recursive or "stack"), ("stop", sem.stop),
                            ("turn", sem.turn)):
            self.query_one(f"#{name}-{value}", RadioButton).value = True
        self.query_one("#weight", Input).value = weight_text(sem.weight)
        for name, on in (("tree_search", sem.tree_search), ("no_path_check", not sem.path_check),
                         ("mark_start", sem.mark_start), ("reopen", sem.reopen),
                         ("exact_costs", sem.cost_tolerance == 0)):
            self.query_one(f"#{name}", Checkbox).value = on
        self._sync()

    def action_cancel(self) -> None:
        self.dismiss(None)


__all__ = ["SettingsScreen"]
