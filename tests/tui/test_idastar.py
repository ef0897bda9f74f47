"""IDA* in the app (``-a idastar``, key 7): the status line's f-limit and the next, the
tree panel's contour (its f-limit in the title, each node cut off marked with its f), the
narration of a cut-off and of a new iteration, the Code panel's lines, the quiz's question;
and a snapshot at its second contour (80x24)."""

from __future__ import annotations

from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tests.tui.test_app import stats, sync, tutorial_app, wait_until
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.tui.model.quiz import Quiz
from tui_search.tui.view.code_trace import code_of, lit_kinds
from tui_search.tui.view.narration import narrate, status_parts
from tui_search.tui.view.tree_listing import TreeModel
from tui_search.tui.widgets.search_tree import SearchTreePanel

SIZE = (80, 24)
#: On the tutorial's map IDA*'s iterations begin at these steps, with these f-limits.
FIRSTS = [1, 3, 12, 22, 36, 53, 71, 90]
LIMITS = ["5.83", "6.41", "7.00", "7.24", "7.83", "8.07", "8.41", "8.66"]


def run_at(k: int, **choices: object) -> Run:
    run = Run(grid_from_rows(TUTORIAL_ROWS), "idastar", Semantics(**choices))  # type: ignore[arg-type]
    run.goto(k)
    return run


def test_each_iteration_begins_at_the_start_with_its_f_limit() -> None:
    run = run_at(0)
    assert [run.steps.first_of_iteration(i) for i in range(len(FIRSTS))] == FIRSTS
    for first, limit in zip(FIRSTS, LIMITS, strict=True):
        run.goto(first)
        assert dict(status_parts(run))["f-limit"] == limit
        assert run.nodes.cell(run.steps.expanded_event(first)) == (0, 0)
    run.goto(FIRSTS[1])
    assert narrate(run).startswith("f-limit 6.41 (the smallest f cut off before), a new "
                                   "iteration from START. ")
    assert "limit_init" not in lit_kinds(run) and "next_limit" in lit_kinds(run)
    run.goto(0)
    assert narrate(run) == ("START (0,0) is on the stack (f-limit 5.83, the start's f). "
                            "Press n to expand it.")
    assert {"limit_init", "deepen", "next_init", "init"} <= lit_kinds(run)


def test_a_node_over_the_limit_is_cut_off_and_sets_the_next_limit() -> None:
    run = run_at(8)  # (3,3), f 7.24, over the second iteration's limit 6.41
    parts = dict(status_parts(run))
    assert (parts["f-limit"], parts["next"], parts["f"]) == ("6.41", "7.24",
                                                             "7.24 (g 4.83 + h 2.41)")
    assert "discarded" not in parts  # IDA* discards nothing
    assert run.steps.is_cut_off() and not run.now.added_now()
    assert narrate(run) == ("Took (3,3) f = 7.24 (g 4.83 + h 2.41) off the stack: over the "
                            "f-limit 6.41, cut off (the next limit at most 7.24)")
    code = code_of(run)
    kinds = lit_kinds(run)
    assert "cutoff" in kinds and "goal_node" not in kinds and "for" not in kinds
    assert "next ← min(next, node.f)" in code.lines[code.number("cutoff") - 1].text
    run.goto(4)  # within the limit: expanded, and nothing over it met yet
    assert dict(status_parts(run))["next"] == "∞" and not run.steps.is_cut_off()


def test_an_empty_stack_between_iterations_names_the_next_f_limit() -> None:
    from tui_search.tui.view.frontier_text import describe_empty

    run = run_at(FIRSTS[1] - 1)  # the first iteration's last step: its stack empty
    assert run.now.frontier_len() == 0
    assert describe_empty(run) == "empty — iteration over; next: f-limit 6.41"


def test_the_tree_shows_the_iterations_contour() -> None:
    model = TreeModel()
    run = run_at(10)
    model.update(run)
    assert model.f_limit is not None and round(model.f_limit, 2) == 6.41
    lines = [model.line_text(i) for i in range(1, model.line_count())]
    cut = [line for line in lines if "✂ f" in line]
    assert any("(3,3)" in line and "✂ f 7.24" in line for line in cut)
    assert not any("(0,2)" in line and "✂" in line for line in lines)  # f 6.41: within


def test_the_quiz_asks_for_the_top_of_the_stack() -> None:
    question = Quiz(on=True).question(run_at(3))
    assert "off the stack next" in question and "lowest" not in question


@sync
async def test_key_7_runs_idastar_and_the_tree_and_status_say_its_limits() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("7")
        await wait_until(pilot, lambda: app.session.run.algorithm == "idastar")
        for _ in range(8):
            await pilot.press("n")
        await wait_until(pilot, lambda: app.session.run.k == 8)
        await wait_until(pilot, lambda: "f-limit 6.41" in stats(app)[0])
        assert "next 7.24" in stats(app)[0] and "cut off" in stats(app)[1]
        panel = app.query_one(SearchTreePanel)
        await wait_until(pilot, lambda: "f-limit 6.41" in str(panel.border_title))
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        await wait_until(pilot, lambda: "cost 8.66 (the lowest)" in stats(app)[1])
        assert "f-limit 8.66" in stats(app)[0]


@sync
async def test_key_7_adds_idastar_to_compare_mode_beside_astar() -> None:
    from tests.helpers import MAPS
    from tui_search.engine.maps.load import load_map
    from tui_search.tui.app import SearchApp

    app = SearchApp(load_map(MAPS / "tutorial.txt"), compare="astar,iddfs")
    async with app.run_test(size=(120, 36)) as pilot:
        await pilot.press("7")
        await wait_until(pilot, lambda: [r.algorithm for r in app.session.runs]
                         == ["astar", "iddfs", "idastar"])
        await pilot.press("end")
        await wait_until(pilot, lambda: all(r.at_end for r in app.session.runs))
        astar, _, ida = (r.path_cost() for r in app.session.runs)
        assert astar is not None and ida == astar  # A*'s cost, 97 steps against 16


def test_idastar_at_its_second_contour(snap_compare) -> None:
    """IDA* on the tutorial's map at step 8, in its second iteration (f-limit 6.41): the
    stack panel 'Stack (f = g + h ≤ limit)' with (1,3) next; the tree titled 'Search tree ·
    f-limit 6.41', its contour, (3,3) being cut off ('◀ cut', at the panel's edge); the
    status line 'f-limit 6.41 | next 7.24' and the narration '... over the f-limit 6.41, cut
    off (the next limit at most 7.24)'; the key bar as for every search (IDA*'s key 7 is in
    the help)."""
    assert snap_compare(tutorial_app("idastar"), press=["n"] * 8, terminal_size=SIZE)
