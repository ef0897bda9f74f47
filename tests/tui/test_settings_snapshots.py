"""Pictures of the search settings and of the choices they make visible."""

from __future__ import annotations

from tests.tui.test_app import tutorial_app

SIZE = (100, 32)


def test_settings_screen(snap_compare) -> None:
    """The settings over the tutorial: moves N,NW,W,SW,S,SE,E,NE in a text field, corners
    'always' picked, visit 'when pushed', goal test 'when pushed', tree search unticked, each
    with its line of explanation; Apply, Defaults, Cancel."""
    assert snap_compare(tutorial_app(), press=["comma"], terminal_size=SIZE)


def test_tree_search_greys_out_the_visit_rule(snap_compare) -> None:
    """Tree search ticked: the visit rule is greyed out and says it does not apply."""

    async def tick(pilot) -> None:
        await pilot.press("comma")
        await pilot.click("#tree_search")
        await pilot.pause()

    assert snap_compare(tutorial_app(), run_before=tick, terminal_size=SIZE)
