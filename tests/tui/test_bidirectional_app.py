"""Bidirectional search in the app (``-a biastar``, ``--stop``, ``--compare``): both halves on
one map (the backward half's kinds of cell, a cell both reached, the best meeting), a frontier
panel and a tree for each half, the narration of each step and of why the search stopped
(PathFinding.js #28's trap: 14.24 where the cheapest is 13.66), the Code panel's lines,
the quiz, compare mode side by side, a graph, plain mode; the map's new colours in every
theme; and snapshots of bidirectional A* midway in the dark and colour-blind themes."""

from __future__ import annotations

from tests.helpers import MAPS, TUTORIAL_ROWS, grid_from_rows
from tests.plain.test_plain import plain
from tests.textual_internals import notifications
from tests.tui.test_app import stats, sync, wait_until
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.load import load_board, load_map
from tui_search.engine.run.bidirectional import BiRun
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp
from tui_search.tui.view.cell_codes import (
    BACK_CURRENT,
    BACK_EXPANDED,
    BACK_FRONTIER,
    BOTH,
    CURRENT,
    EXPANDED,
    FRONTIER,
    MEETING,
    PATH,
)
from tui_search.tui.view.two_way.cells import combine, node_code, two_way_codes
from tui_search.tui.view.two_way.code_lines import two_way_kinds
from tui_search.tui.view.two_way.words import two_way_narration, two_way_parts
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.search_tree import SearchTreePanel

TRAP = MAPS / "pathfinding-js-28.txt"
SIZE = (80, 24)
BIG = (120, 36)


def trap_app(stop: str = "first-meeting", theme: str | None = None, **kwargs: object
             ) -> SearchApp:
    return SearchApp(load_map(TRAP), path=TRAP, algorithm="biastar",
                     semantics=Semantics(stop=stop), theme=theme, **kwargs)  # type: ignore[arg-type]


def trap_run(stop: str = "first-meeting") -> BiRun:
    return BiRun(load_map(TRAP), "biastar", Semantics(stop=stop))


# -- what the map draws, what the lines say (no app) ---------------------------------------
def test_a_cell_both_halves_reached_is_drawn_as_such() -> None:
    assert combine(FRONTIER, 0) == FRONTIER and combine(0, 2) == BACK_EXPANDED
    assert combine(0, 1) == BACK_FRONTIER and combine(0, 3) == BACK_CURRENT
    assert combine(EXPANDED, 1) == BOTH and combine(CURRENT, 2) == CURRENT
    assert combine(2, 3) == BACK_CURRENT


def test_the_map_draws_each_half_the_meeting_and_at_the_end_the_path() -> None:
    run = trap_run()
    grid = run.grid
    run.goto(9)  # the forward half took step 9: only its node is being expanded

    def codes() -> dict[tuple[int, int], int]:
        return {(x, y): code for y in range(grid.height)
                for x, code in enumerate(two_way_codes(run, y, 0, grid.width))}

    now = codes()
    assert run.direction(9) == "forward"
    assert now[(5, 2)] == CURRENT and BACK_CURRENT not in now.values()
    assert {BACK_FRONTIER, BACK_EXPANDED, FRONTIER, EXPANDED} <= set(now.values())
    run.goto(10**6)
    end = codes()
    assert end[(7, 3)] == MEETING  # the first meeting, marked on its path
    path = set(run.path() or [])
    assert all(end[cell] == PATH for cell in path if cell != (7, 3))
    assert run.at_end and round(run.path_cost(), 2) == 14.24


def test_the_narration_says_whose_step_and_why_it_stopped() -> None:
    run = trap_run()
    assert "they take a step each in turn, forward first" in two_way_narration(run)
    run.goto(2)
    assert two_way_narration(run).startswith("← Backward: expanded GOAL (15,4) f = 10.00")
    run.goto(10**6)
    said = two_way_narration(run)
    assert "(7,3) was reached by the backward search too: a path of cost 14.24" in said
    assert ("Stopped: both searches reached (7,3): with first-meeting this is the path, cost "
            "14.24; it is not the cheapest (lowest 13.66)") in said
    proven = trap_run("proven")
    proven.goto(10**6)
    assert "is proven the cheapest" in two_way_narration(proven)
    assert dict(two_way_parts(proven))["μ"] == "13.66 at (8,3)"


def test_the_code_panel_lights_the_meeting_and_the_rule_that_stopped() -> None:
    run = trap_run()
    run.goto(10**6)
    assert {"meet", "first", "push", "take"} <= two_way_kinds(run)
    proven = trap_run("proven")
    proven.goto(1)
    assert "proven" in two_way_kinds(proven) and "first" not in two_way_kinds(proven)


def test_a_graph_s_nodes_are_drawn_from_both_halves() -> None:
    romania = load_board("romania")
    assert isinstance(romania, Graph)
    run = BiRun(romania, "biucs", Semantics(order=("file",)))
    run.goto(10**6)
    assert run.found and node_code(run, run.meeting()) == MEETING
    assert node_code(run, romania.start) == PATH


# -- the app ---------------------------------------------------------------------------------
@sync
async def test_the_trap_in_the_app_both_frontiers_both_trees_and_why_it_stopped() -> None:
    app = trap_app()
    async with app.run_test(size=BIG) as pilot:
        await wait_until(pilot, lambda: len(app.query(FrontierPanel)) == 2)
        ahead, behind = app.query(FrontierPanel)
        assert str(ahead.border_title).startswith("→ Forward")
        await wait_until(pilot, lambda: str(behind.border_title).startswith("← Backward"))
        trees = app.query(SearchTreePanel)
        assert [str(t.border_title)[:1] for t in trees] == ["→", "←"]
        await pilot.press("n", "n")
        await wait_until(pilot, lambda: app.session.run is not None and app.session.run.k == 2)
        await wait_until(pilot, lambda: "← Backward: expanded GOAL (15,4)" in stats(app)[1])
        assert "expanded 2 (→ 1 ← 1)" in stats(app)[0]
        await pilot.press("end")
        await wait_until(pilot, lambda: "it is not the cheapest (lowest 13.66)" in stats(app)[1])
        assert "cost 14.24, met at (7,3)" in stats(app)[1]
        await pilot.press("p")  # a step back: the path goes, the search goes on
        await wait_until(pilot, lambda: "Stopped" not in stats(app)[1])


@sync
async def test_compare_shows_the_trap_beside_the_proven_rule() -> None:
    app = SearchApp(load_map(TRAP), path=TRAP, compare="biastar:first-meeting,biastar")
    async with app.run_test(size=BIG) as pilot:
        await wait_until(pilot, lambda: len(app.session.runs) == 2)
        assert all(isinstance(run, BiRun) for run in app.session.runs)
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.at_end())
        costs = [round(run.path_cost(), 2) for run in app.session.runs]
        assert costs == [14.24, 13.66]
        await wait_until(pilot, lambda: len(app.query(FrontierPanel)) == 4)


@sync
async def test_the_quiz_asks_whose_turn_it_is() -> None:
    app = SearchApp(grid_from_rows(TUTORIAL_ROWS), algorithm="bibfs")
    async with app.run_test(size=BIG) as pilot:
        await pilot.press("i")
        await wait_until(pilot, lambda: "the forward search's queue's front" in stats(app)[1])
        await pilot.press("n")
        await wait_until(pilot, lambda: app.session.run is not None and app.session.run.k == 1)
        await pilot.press("i", "i")
        await wait_until(pilot, lambda: "the backward search's queue's front" in stats(app)[1])


@sync
async def test_the_code_panel_shows_the_bidirectional_pseudocode() -> None:
    app = trap_app()
    async with app.run_test(size=BIG) as pilot:
        await pilot.press("v")
        from tui_search.tui.widgets.code_panel import CodePanel

        await wait_until(pilot, lambda: bool(app.query(CodePanel))
                         and app.query_one(CodePanel).code is not None)
        code = app.query_one(CodePanel).code
        assert code is not None and "Bidirectional" in code.title
        await pilot.press("end")
        await wait_until(pilot, lambda: app.query_one(CodePanel).focus_number
                         == code.number("first"))


@sync
async def test_a_graph_with_two_goals_says_why_in_one_line() -> None:
    romania = load_board("romania")
    assert isinstance(romania, Graph)
    romania.goals = (romania.goals[0], "Sibiu")
    app = SearchApp(romania, algorithm="bibfs")
    async with app.run_test(size=BIG) as pilot:
        await wait_until(pilot, lambda: "2 goals" in app.session.note)
        assert app.session.runs == []


def test_plain_mode_tells_both_halves() -> None:
    said = plain("n", "n", "last", path=TRAP, algorithm="biastar",
                 semantics=Semantics(stop="first-meeting"))
    text = "\n".join(said)
    assert "Step 1: → Forward: expanded START (5,4)" in text
    assert "Step 2: ← Backward: expanded GOAL (15,4)" in text
    assert "Backward: Priority queue" in text
    assert "through the meeting (7,3)" in text and "cost 14.24" in text


# -- snapshots -----------------------------------------------------------------------------------
def test_bidirectional_astar_midway(snap_compare) -> None:
    """Bidirectional A* (first meeting) on the trap map at step 9 of 17, 80x24, dark: the
    forward half (black frontier, blue expanded) round the start, the backward half (brown
    squares, orange expanded) from the goal; the two frontier panels, each titled by its
    half; the legend's arrows; the status line 'step 9/17 | expanded 9 (→ 5 ← 4)' and the
    narration of the forward step."""
    assert snap_compare(trap_app(), press=["n"] * 9, terminal_size=SIZE)


def test_bidirectional_astar_midway_colour_blind(snap_compare) -> None:
    """The same in the colour-blind theme: the backward half in browns and ambers against
    the forward's blues."""
    assert snap_compare(trap_app(theme="colour-blind"), press=["n"] * 9, terminal_size=SIZE)


# -- colours: the backward half's kinds stand apart in every theme and vision -----------------
#: Below the colour-blind theme's 30 between the one-way kinds: 13 kinds of cell share the
#: space two visions squeeze; the glyphs (squares against circles, ◐, ✦) tell them apart too.
TWO_WAY_DIFFERENCE = 20


async def two_way_least_difference(theme: str) -> tuple[float, str]:
    """The closest pair of a bidirectional kind and any kind of cell (a free cell and a
    replay's mark too), as drawn in ``theme``, in normal, protanopic or deuteranopic vision."""
    import itertools
    import math

    from tests.tui.test_themes import DEUTAN, NORMAL, PROTAN, seen
    from tui_search.tui.widgets.grid_view import GridView

    app = trap_app(theme=theme)
    new = ("back-frontier", "back-expanded", "back-current", "both", "meeting")
    async with app.run_test(size=BIG):
        view = app.query_one(GridView)
        fills = {"free": view.rich_style.bgcolor}
        for kind in ("wall", "start", "goal", "frontier", "expanded", "current", "path",
                     "marked", *new):
            style = view.get_component_rich_style(f"grid-view--{kind}")
            fills[kind] = style.color if kind == "wall" else style.bgcolor
    return min((math.dist(seen(a, v), seen(b, v)), f"{ka}/{kb} {name}")
               for name, v in (("normal", NORMAL), ("protan", PROTAN), ("deutan", DEUTAN))
               for (ka, a), (kb, b) in itertools.combinations(fills.items(), 2)
               if ka in new or kb in new)


@sync
async def test_the_backward_half_stands_apart_in_every_theme() -> None:
    from tui_search.tui.view.themes import THEMES

    for theme in THEMES:
        difference, pair = await two_way_least_difference(theme)
        assert difference >= TWO_WAY_DIFFERENCE, (theme, pair, difference)


@sync
async def test_by_hand_says_it_steps_a_one_way_search() -> None:
    app = trap_app()
    async with app.run_test(size=BIG) as pilot:
        await pilot.press("H")
        await wait_until(pilot, lambda: any("By hand steps a one-way search" in n.message
                                            for n in notifications(app)))
        assert len(app.screen_stack) == 1  # the main screen alone: no by-hand screen


def test_a_spec_s_own_stopping_rule_is_no_setting_that_does_not_apply() -> None:
    from tui_search.tui.model.searches import searches_of

    contenders, note = searches_of("biastar:first-meeting,biastar", Semantics())
    assert [c.semantics.stop for c in contenders] == ["first-meeting", "proven"]
    assert note == ""


def test_plain_mode_s_trees_name_the_goal_root_and_one_node_being_expanded() -> None:
    said = "\n".join(plain("n", "n", "tree", path=TRAP, algorithm="bibfs"))
    assert "Forward search tree, 6 nodes:\nSTART (5,4), expanded, 5 children" in said
    assert "Backward search tree, 5 nodes:\nGOAL (15,4), being expanded, 4 children" in said


TRAP_EXERCISE = """\
title = "The first meeting"
text = "Find a map where stopping at the first meeting costs more than the proven meeting."
map = "pathfinding-js-28.txt"
searches = ["biastar:first-meeting", "biastar"]
edits = ["obstacles"]
solved = "biastar_first_meeting.cost > biastar.cost"
"""


@sync
async def test_the_app_s_challenge_grades_bidirectional_searches() -> None:
    from tui_search.engine.course.exercise_file import parse_exercise

    exercise = parse_exercise(TRAP_EXERCISE, str(MAPS / "trap.toml"))
    app = SearchApp(exercise.board, exercise=exercise)
    async with app.run_test(size=BIG) as pilot:
        panel = app.main.challenge
        await wait_until(pilot, lambda: panel.is_mounted and "Solved" in panel.text)
        assert "BiA* (first-meeting)'s path costs 14.24, BiA*'s 13.66" in panel.text
