"""The ``bidirectional`` lesson: each section shows what its text says (through the runs'
named queries), every number its text gives is the search's, and a student plays it through
in the app: steps to the meeting, reads why the first-meeting pane stopped, pages to the end."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from tests.tui.test_app import sync, wait_until
from tests.tui.test_lesson import Seen, glyphs_in, lesson_app, walk
from tui_search.engine.course.lesson import find_lesson, read_lesson
from tui_search.engine.run.bidirectional import BiRun
from tui_search.engine.search.state import State
from tui_search.tui.widgets.run_pane import RunPane

TRAP = "pathfinding-js-28.txt"
SQRT2 = math.sqrt(2)
FIRST, PROVEN = "BiA* (first-meeting)", "BiA*"


def two_way(seen: Seen) -> list[BiRun]:
    """The section's bidirectional runs, in their panes' order."""
    return [r for r in seen.runs if isinstance(r, BiRun)]


def reached_at(run: BiRun, k: int) -> tuple[str, list[State]]:
    """Which half took step ``k`` and the cells it pushed (the run is left where it was)."""
    was = run.k
    run.goto(k)
    half = run.halves[run.direction(k) != "forward"]
    cells = [half.nodes.cell(g) for g in half.now.added_now()]
    run.goto(was)
    return run.direction(k), cells


def ends(run: BiRun) -> tuple[State | None, float, int, int]:
    """A finished run's meeting, cost (two places), moves and nodes expanded."""
    assert run.at_end and run.found
    out = run.outcome()
    return run.meeting(), round(out.cost, 2), len(run.moves() or []), out.expanded


def g_both(run: BiRun, cell: State) -> tuple[float, float]:
    """``cell``'s g forward and backward at the run's end (on both frontiers)."""
    gs = []
    for half in run.halves:
        (g,) = [e for e in half.now.frontier() if half.nodes.cell(e) == cell]
        gs.append(half.nodes.cost(g))
    return gs[0], gs[1]


def root_form(a: int, b: int) -> str:
    """``a + b·√2`` as the lesson writes it: ``(3 + 2·√2)``, ``(7 + √2)``."""
    return f"({a} + {f'{b}·' if b > 1 else ''}√2)"


CLAIMS: list[Callable[[Seen], bool]] = [
    # 1. the trap's map, both rules side by side, step 0
    lambda s: s.map == TRAP and s.labels == [FIRST, PROVEN]
    and [r.k for r in two_way(s)] == [0, 0]
    and [r.semantics.stop for r in two_way(s)] == ["first-meeting", "proven"],
    # 2. step 16: not met; the backward half reached (8,3) at 14, (7,3) at 16; step 17 is
    # the forward half's, expanding (7,2)
    lambda s: all(r.k == 16 and r.meeting() is None for r in two_way(s))
    and reached_at(two_way(s)[0], 14) == ("backward", [(8, 3), (8, 4), (8, 5)])
    and reached_at(two_way(s)[0], 16) == ("backward", [(7, 3), (7, 4), (7, 5)])
    and two_way(s)[0].next_direction() == "forward",
    # 3. the ends: (7,3) at 14.24 in 13 moves, (8,3) at 13.66 in 12, both at step 17
    lambda s: [ends(r) for r in two_way(s)] == [((7, 3), 14.24, 13, 17), ((8, 3), 13.66, 12, 17)],
    # 4. proven against A*: the same cost, 17 expansions to 33
    lambda s: s.labels == [PROVEN, "A*"] and ends(two_way(s)[0]) == ((8, 3), 13.66, 12, 17)
    and (round(s.runs[1].path_cost(), 2), s.runs[1].now.expanded) == (13.66, 33),
    # 5. bidirectional BFS: both through (8,0) in 12 moves, 72 and 82 expanded
    lambda s: s.labels == ["BiBFS (first-meeting)", "BiBFS"]
    and [(r.meeting(), len(r.moves() or []), r.outcome().expanded) for r in two_way(s)]
    == [((8, 0), 12, 72), ((8, 0), 12, 82)],
]


def test_every_section_of_the_bidirectional_lesson_shows_what_it_says() -> None:
    seen = walk("bidirectional")
    assert len(seen) == len(CLAIMS)
    failed = [i + 1 for i, (claim, s) in enumerate(zip(CLAIMS, seen, strict=True))
              if not claim(s)]
    assert failed == []


def test_the_bidirectional_lesson_s_numbers_are_the_searches() -> None:
    """Section 2: the step 17 expands (7,2), pushing S (7,3) before SE (8,3); section 3:
    each meeting's g forward + g backward; section 4: the forward frontier's smallest f is
    μ when the proven search stops."""
    texts = [" ".join(s.text.split())
             for s in read_lesson(find_lesson("bidirectional"), "bidirectional").sections]
    seen = walk("bidirectional")
    first = two_way(seen[1])[0]
    first.goto(17)
    assert first.current_node() == (7, 2)
    assert reached_at(first, 17) == ("forward", [(7, 3)])  # and stops: S before SE
    proven = two_way(seen[2])[1]
    assert reached_at(proven, 17) == ("forward", [(7, 3), (8, 3), (8, 2), (8, 1)])
    assert "S, (7,3), comes before SE, (8,3)" in texts[1]
    assert "cost **14.24**, 13 moves" in texts[1] and "**13.66**, 12 moves" in texts[1]
    for (x, y), (a, b), (c, d) in (((7, 3), (3, 2), (7, 1)), ((8, 3), (2, 3), (6, 1))):
        # g forward is a + b·√2, g backward c + d·√2, as the text writes them
        assert g_both(proven, (x, y)) == pytest.approx((a + b * SQRT2, c + d * SQRT2))
        total = f"{a + c + (b + d) * SQRT2:.2f}"
        assert f"({x},{y}): {root_form(a, b)} + {root_form(c, d)} = **{total}**" in texts[2]
    ahead = two_way(seen[3])[0].halves[0]
    smallest = min(ahead.nodes.costs(g)[2] for g in ahead.now.frontier())  # type: ignore[index]
    assert round(smallest, 2) == round(two_way(seen[3])[0].mu(), 2) == 13.66
    assert "the forward frontier's smallest f is 13.66 = μ" in texts[3]
    assert "in 33 expansions to 17" in texts[3]
    assert "through (8,0)" in texts[4] and "82 expansions to 72" in texts[4]


@sync
async def test_a_student_steps_to_the_meeting_and_pages_through_the_lesson() -> None:
    """At section 2, `n` takes both panes to step 17: the first-meeting pane says why it
    stopped and that 14.24 is not the cheapest (13.66), the proven one its front-to-end
    proof; each map marks its best meeting (✦) once, the proven one a cell both reached (◐).
    Then pgdn to the last section, and no further."""
    app = lesson_app("bidirectional")
    async with app.run_test(size=(120, 40)) as pilot:
        panel = app.main.query_one(".lesson")
        await wait_until(pilot, lambda: "Lesson bidirectional 1/5" in str(panel.border_title))
        assert app.session.labels == [FIRST, PROVEN] and app.session.note == ""
        await pilot.press("pagedown")
        await wait_until(pilot, lambda: "2/5" in str(panel.border_title)
                         and [r.k for r in app.session.runs] == [16, 16])
        await pilot.press("n")
        await wait_until(pilot, lambda: all(r.at_end for r in app.session.runs))
        first, proven = app.main.panes

        def said(pane: RunPane) -> str:
            return " ".join(pane.stats.narration_text.split())

        await wait_until(pilot, lambda: "lowest 13.66" in said(first)
                         and "front-to-end" in said(proven))
        assert ("both searches reached (7,3): with first-meeting this is the path, cost "
                "14.24; it is not the cheapest (lowest 13.66)") in said(first)
        assert "the best meeting, (8,3), cost μ = 13.66, is proven the cheapest" in said(proven)
        await wait_until(pilot, lambda: all(glyphs_in(app, p.view.region).count("✦") == 1
                                            for p in app.main.panes))
        assert "◐" in glyphs_in(app, proven.view.region)
        for section in (3, 4, 5):
            await pilot.press("pagedown")
            await wait_until(pilot, lambda section=section: f"{section}/5"
                             in str(panel.border_title))
        await wait_until(pilot, lambda: app.session.labels == ["BiBFS (first-meeting)", "BiBFS"]
                         and all(r.at_end for r in app.session.runs))
        await pilot.press("pagedown")
        await pilot.press("pageup")
        await wait_until(pilot, lambda: "4/5" in str(panel.border_title))
        assert app.session.labels == [PROVEN, "A*"]
