"""Pictures of the search settings and of the choices they make visible."""

from __future__ import annotations

from tests.tui.test_app import click_shown, tutorial_app

SIZE = (100, 32)


def test_settings_screen(snap_compare) -> None:
    """The settings over the tutorial: moves N,NW,W,SW,S,SE,E,NE in a text field, corners
    'always' picked, visit 'when pushed' (or taken off, or taken off and not checked), goal
    test 'when pushed', tree search unticked (no path check greyed out), the start marked, a
    stack (recursion greyed out for BFS), the heuristic and the priority queue's ties ('old'),
    re-opening (ticked) and exact costs greyed out with their note; each with its line of
    explanation; Apply, Defaults, Cancel."""
    assert snap_compare(tutorial_app(), press=["comma"], terminal_size=SIZE)


def test_tree_search_greys_out_the_visit_rule(snap_compare) -> None:
    """Tree search ticked: the visit rule is greyed out and says it does not apply."""

    async def tick(pilot) -> None:
        await pilot.press("comma")
        # On a loaded machine the click can come before the screen has settled and miss
        # the box (seen: the picture taken with it unticked), or the screen can handle the
        # box's Changed message after one pause: wait for the layout, click until ticked,
        # then wait for the visit rule to be greyed out.
        box = pilot.app.screen.query_one("#tree_search")
        explain = pilot.app.screen.query_one("#visit-explain")
        for _ in range(100):
            before = box.region
            await pilot.pause()
            if box.region == before and box.region.height:
                break
        for _ in range(5):
            if box.value:
                break
            await click_shown(pilot, "#tree_search")
            for _ in range(20):
                await pilot.pause()
                if box.value:
                    break
        for _ in range(100):
            if "does not apply" in str(explain.content):
                break
            await pilot.pause()
        await pilot.pause()

    assert snap_compare(tutorial_app(), run_before=tick, terminal_size=SIZE)


def test_a_discarded_step(snap_compare) -> None:
    """BFS with visit on expand at its first discarded step: the queue's first line marks
    under its count the entry thrown away (✗ … discarded, struck through), the tree marks it
    '◀ discarded'; the status line counts 'discarded 1' and says 'visit on expand'; the narration
    says the cell was taken off again and discarded."""
    from tests.tui.test_app import TUTORIAL
    from tui_search.engine.maps.load import load_map
    from tui_search.engine.run.recorded import Run, recording_of
    from tui_search.engine.search.choices import Semantics
    from tui_search.tui.app import SearchApp

    sem = Semantics(visit="expand")
    probe = Run(load_map(TUTORIAL), "bfs", sem)
    probe.advance()
    k = recording_of(probe).discarded_steps()[0]
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, semantics=sem)
    assert snap_compare(app, press=["n"] * k, terminal_size=SIZE)


def test_settings_ticked_and_empty_in_the_light_theme(snap_compare) -> None:
    """The settings on a projector's light theme: a ticked box holds ✓ and a picked radio
    button ●, an unticked or unpicked one is an empty box (BFS and DFS ticked for c, IDDFS to
    A* empty; tree search empty)."""
    from tests.tui.test_snapshots_themes import themed_app

    assert snap_compare(themed_app("light"), press=["comma"], terminal_size=SIZE)


def test_settings_ticked_and_empty_in_the_colour_blind_theme(snap_compare) -> None:
    """As in the light theme: ✓ and ● in the boxes ticked or picked, the others empty."""
    from tests.tui.test_snapshots_themes import themed_app

    assert snap_compare(themed_app("colour-blind"), press=["comma"], terminal_size=SIZE)
