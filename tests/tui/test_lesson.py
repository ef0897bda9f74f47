"""Lessons in the app: every section of the built-in lessons puts the session in the state its
text describes (checked through the runs' named queries), the teacher's lesson applies every
key, and ``pgdn`` / ``pgup`` move between sections while every other key acts on the app."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

from textual.geometry import Region

from tests.engine.test_lesson import LESSONS, TEACHER
from tests.tui.test_app import TUTORIAL, sync, wait_until
from tui_search.engine.course.exercise_file import built_in_exercise
from tui_search.engine.course.lesson import find_lesson, read_lesson
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run
from tui_search.tui.app import SearchApp
from tui_search.tui.model.lesson_play import LessonPlay
from tui_search.tui.model.session import Session


def walk(name: str) -> list[Session]:
    """The session as each section of the lesson leaves it, read forwards."""
    session = Session(load_map(TUTORIAL), TUTORIAL)
    play = LessonPlay(read_lesson(find_lesson(name), name))
    play.open(session)
    seen = []
    while True:
        seen.append(snapshot(session))
        if not play.move(session, 1):
            return seen


class Seen:
    """What a section shows: the map's name, the panes' runs and the session's switches."""

    def __init__(self, session: Session) -> None:
        self.map = session.map_name
        self.labels = session.labels
        self.runs = list(session.runs)
        self.code = session.show_code
        self.exercise = session.exercise.number if session.exercise else None
        self.semantics = session.semantics


def snapshot(session: Session) -> Seen:
    return Seen(session)


def cells(run: Run, events: list[int]) -> list[tuple[int, int]]:
    return [run.nodes.cell(g) for g in events]


def moves_added(run: Run) -> list[str]:
    return [run.nodes.move(g) for g in run.now.added_now()]


def ended(run: Run) -> tuple[int, int]:
    """A finished run's expanded nodes and its path's moves."""
    assert run.at_end and run.found
    return run.now.expanded, len(run.moves() or [])


def one(seen: Seen) -> Run:
    assert len(seen.runs) == 1
    return seen.runs[0]


TUTORIAL_CLAIMS: list[Callable[[Seen], bool]] = [
    # 1. the robot and its eight moves: step 0, only S open from the start
    lambda s: one(s).k == 0 and s.map == "tutorial.txt" and s.labels == ["BFS"]
    and len(s.semantics.order) == 8 and not one(s).grid.is_blocked((0, 1))
    and one(s).grid.is_blocked((1, 0)) and one(s).grid.is_blocked((1, 1)),
    # 2. BFS at step 4: the SE node expanded, E and NE just added, the queue as the text says
    lambda s: one(s).k == 4 and one(s).now.current_node() == (1, 2)
    and moves_added(one(s)) == ["E", "NE"]
    and cells(one(s), one(s).now.frontier()) == [(0, 3), (1, 3), (2, 2), (2, 1)],
    # 3. the path traced back
    lambda s: one(s).moves() == ["S", "SE", "NE", "NE", "E", "SE", "S"],
    # 4. complete and optimal: the status line's path and bound at the end
    lambda s: ended(one(s)) == (22, 7) and s.labels == ["BFS"],
    # 5. DFS at step 3: SE expanded, SW, S, E, NE pushed, NE on top
    lambda s: s.labels == ["DFS"] and one(s).k == 3 and one(s).now.current_node() == (1, 2)
    and moves_added(one(s)) == ["SW", "S", "E", "NE"]
    and cells(one(s), one(s).now.frontier())[0] == (2, 1),
    # 6. DFS not optimal: 8 moves to BFS's 5
    lambda s: s.map == "dfs-longer.txt" and s.labels == ["BFS", "DFS"]
    and [ended(r)[1] for r in s.runs] == [5, 8],
    # 7. iterative deepening: 85 steps, 7 moves, the tutorial's map again
    lambda s: s.map == "tutorial.txt" and s.labels == ["IDDFS"] and ended(one(s)) == (85, 7),
    # 8. side by side: the same 7-move path, DFS 7 nodes to BFS's 22
    lambda s: s.labels == ["BFS", "DFS"] and [ended(r) for r in s.runs] == [(22, 7), (7, 7)]
    and s.exercise is None,
    # 9. the exercises, live, from step 0
    lambda s: s.exercise == 1 and s.labels == ["BFS", "DFS"] and all(r.k == 0 for r in s.runs),
    # 10. A*: 16 nodes to BFS's 22, a shortest path
    lambda s: s.exercise is None and s.labels == ["BFS", "A*"]
    and [ended(r) for r in s.runs] == [(22, 7), (16, 7)],
]


def test_every_section_of_the_tutorial_lesson_shows_what_it_says() -> None:
    seen = walk("tutorial")
    assert len(seen) == len(TUTORIAL_CLAIMS)
    failed = [i + 1 for i, (claim, s) in enumerate(zip(TUTORIAL_CLAIMS, seen, strict=True))
              if not claim(s)]
    assert failed == []
    assert not any(s.code for s in seen)


def test_the_tutorial_lesson_s_words_are_true_of_the_map() -> None:
    """Section 1 names the obstacles by the legend (their colour is the theme's); section 2's
    step 4 skips N and SE as obstacles and four visited cells; section 8's DFS expands START
    and the path's cells before the goal, never the goal."""
    from tui_search.tui.view.code_trace import skipped

    texts = [section.text for section in read_lesson(find_lesson("tutorial"), "tutorial").sections]
    assert "dark" not in texts[0] and "(see the legend)" in texts[0]
    seen = walk("tutorial")
    skips = {(skip.move, skip.kind) for skip in skipped(one(seen[1]))}
    assert skips == {("N", "blocked"), ("SE", "blocked"), ("S", "reached"),
                     ("SW", "reached"), ("W", "reached"), ("NW", "reached")}
    assert "N and SE are obstacles and the other four are already visited" in \
        " ".join(texts[1].split())
    dfs = seen[7].runs[1]
    expanded = {dfs.nodes.cell(dfs.steps.expanded_event(k)) for k in range(1, dfs.k + 1)}
    path = dfs.path() or []
    assert len(path) == 8 and expanded == set(path[:-1])
    assert "START and the six cells of its path before the goal" in " ".join(texts[7].split())


def narration_lines(run: Run) -> str:
    from tui_search.tui.view.narration import narrate

    return narrate(run, True)


CHOICES_CLAIMS: list[Callable[[Seen], bool]] = [
    # 1. four moves: no path on the tutorial's map
    lambda s: s.labels == ["DFS"] and s.semantics.order == ("N", "W", "S", "E")
    and one(s).k == 4 and one(s).goto(10_000) is None and not one(s).found,
    # 2. corners never: step 2 skips (1,2) past a blocked corner; no path
    lambda s: s.semantics.corners == "never" and one(s).k == 2
    and "(1,2) is past a blocked corner" in narration_lines(one(s))
    and one(s).goto(10_000) is None and not one(s).found,
    # 3. visit on expand: BFS's step 7 is discarded
    lambda s: s.labels == ["BFS"] and s.semantics.visit == "expand" and one(s).k == 7
    and one(s).steps.is_discarded(7),
    # 4. goal test on expand: 24 steps, the same 7-move path
    lambda s: s.semantics.goal_test == "expand" and ended(one(s)) == (24, 7),
    # 5. tree search: 557 steps for the same path
    lambda s: s.semantics.tree_search and ended(one(s)) == (557, 7),
]


def test_every_section_of_the_choices_lesson_has_the_code_panel_and_its_choice() -> None:
    seen = walk("choices")
    assert len(seen) == len(CHOICES_CLAIMS) and all(s.code for s in seen)
    failed = [i + 1 for i, (claim, s) in enumerate(zip(CHOICES_CLAIMS, seen, strict=True))
              if not claim(s)]
    assert failed == []


def test_the_teacher_s_lesson_sets_every_key_and_a_section_without_a_block_keeps_the_app(
) -> None:
    session = Session(load_map(TUTORIAL), TUTORIAL)
    play = LessonPlay(read_lesson(TEACHER))
    play.open(session)
    run = session.runs[0]
    assert session.map_path == (LESSONS / "discard.txt").resolve() and session.show_code
    assert (session.labels, run.k, session.semantics.visit) == (["DFS"], 4, "expand")
    assert run.steps.is_discarded(4)
    play.move(session, 1)
    assert session.labels == ["A* (manhattan)"] and session.runs[0].at_end and not session.show_code
    assert (session.semantics.heuristic, session.runs[0].goal_test) == ("manhattan", "generate")
    session.step(forward=False)  # the student steps back: a section without a block keeps it
    k = session.runs[0].k
    play.move(session, 1)
    assert session.runs[0].k == k and play.where == "teacher 3/6"
    play.move(session, 1)
    assert session.semantics.order == ("N", "W", "S", "E") and session.semantics.tree_search
    assert (session.semantics.corners, session.labels, session.runs[0].k) == ("never", ["BFS"], 2)
    play.move(session, 1)
    assert session.labels == ["BFS", "DFS"] and session.exercise is built_in_exercise(2)
    # exercise 2's rules (the tutorial's: corners always), as its searches run under them
    assert session.semantics.corners == "always" and all(r.at_end for r in session.runs)
    play.move(session, 1)
    assert (session.labels, session.exercise, session.runs[0].k) == (["UCS"], None, 1)
    assert not play.move(session, 1) and play.where == "teacher 6/6"
    for _ in range(5):
        assert play.move(session, -1)
    assert not play.move(session, -1)
    assert session.labels == ["DFS"] and session.runs[0].k == 4  # the first section again


def lesson_app(name: str) -> SearchApp:
    return SearchApp(load_map(TUTORIAL), path=TUTORIAL,
                     lesson=read_lesson(find_lesson(name), name))


@sync
async def test_pgdn_and_pgup_move_between_sections_and_other_keys_act_on_the_app() -> None:
    app = lesson_app("tutorial")
    async with app.run_test(size=(120, 40)) as pilot:
        panel = app.main.query_one(".lesson")
        await wait_until(pilot, lambda: "Lesson tutorial 1/10" in str(panel.border_title))
        assert app.session.runs[0].k == 0
        await pilot.press("pagedown")
        await wait_until(pilot, lambda: "2/10" in str(panel.border_title))
        assert app.session.runs[0].k == 4
        await pilot.press("n")  # still the app's: a step
        await wait_until(pilot, lambda: app.session.runs[0].k == 5)
        await pilot.press("pageup", "pageup")  # the second is at the first section: nothing
        await wait_until(pilot, lambda: "1/10" in str(panel.border_title))
        assert app.session.runs[0].k == 0 and app.session.cursor == (0, 0)
        for _ in range(7):
            await pilot.press("pagedown")
        await wait_until(pilot, lambda: len(app.main.panes) == 2)
        assert "8/10" in str(panel.border_title)


def test_start_up_without_a_lesson_does_not_load_the_markdown_widget() -> None:
    """Nor the lesson's own modules: start-up without ``--lesson`` imports what it did."""
    code = ("import asyncio, sys\n"
            "from tests.tui.test_app import tutorial_app\n"
            "async def main():\n"
            "    app = tutorial_app()\n"
            "    async with app.run_test(size=(100, 32)) as pilot:\n"
            "        await pilot.pause()\n"
            "asyncio.run(main())\n"
            "print([m for m in sys.modules if 'markdown' in m.lower() or 'lesson' in m])\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]"


@sync
async def test_the_command_line_opens_a_lesson_file_beside_the_panes() -> None:
    from tui_search.cli.main import build_app
    from tui_search.cli.parse import parse_options

    options = parse_options(["--lesson", str(TEACHER)])
    assert options.lesson_read is not None
    app = build_app(options)
    async with app.run_test(size=(120, 40)) as pilot:
        panel = app.main.query_one(".lesson")
        await wait_until(pilot, lambda: "teacher 1/6" in str(panel.border_title))
        assert app.session.map_name == "discard.txt" and app.session.labels == ["DFS"]
        await wait_until(pilot, lambda: app.main.panes[0].code_panel.display)
        assert panel.outer_size.width == 48  # two fifths of 120


def glyphs_in(app: SearchApp, region: Region) -> str:
    """The text the terminal shows inside ``region``."""
    from tests.textual_internals import composited

    rows = composited(app)[region.y:region.bottom]
    return "\n".join("".join(text for text, _ in row)[region.x:region.right] for row in rows)


@sync
async def test_at_80x24_sections_6_and_8_name_what_is_on_screen() -> None:
    """Without the comparison table (no room at 80x24), the paths drawn (◆ between S and G)
    and the expanded cells (●) say what sections 6 and 8 claim."""
    app = lesson_app("tutorial")
    async with app.run_test(size=(80, 24)) as pilot:
        panel = app.main.query_one(".lesson")
        seen = {}
        for section in (6, 8):
            while f"{section}/10" not in str(panel.border_title):
                await pilot.press("pagedown")
                await pilot.pause()
            await wait_until(pilot, lambda: all(r.at_end for r in app.session.runs))
            await pilot.pause()
            assert not app.main.table.display  # the table: no room
            seen[section] = [glyphs_in(app, p.view.region) for p in app.main.panes]
        bfs, dfs = seen[6]  # 5 moves against 8: 4 and 7 cells between S and G
        assert (bfs.count("◆"), dfs.count("◆")) == (4, 7)
        bfs, dfs = seen[8]  # both 7 moves; DFS expanded only its path, BFS 22 cells
        assert (bfs.count("◆"), dfs.count("◆")) == (6, 6)
        assert dfs.count("●") == 0 and bfs.count("●") == 22 - 7


@sync
async def test_at_80x24_shift_keys_scroll_the_lesson_and_move_between_sections() -> None:
    """The lesson never takes the focus, and its text is longer than the panel at 80x24:
    shift+down scrolls its last line into view, shift+up back; shift+right and shift+left
    move between sections as pgdn and pgup do (a keyboard without them)."""
    app = lesson_app("tutorial")
    async with app.run_test(size=(80, 24)) as pilot:
        panel = app.main.query_one(".lesson")
        await wait_until(pilot, lambda: "1/10" in str(panel.border_title)
                         and panel.max_scroll_y > 0)
        assert "⇧↑↓ scroll" in str(panel.border_subtitle)
        for _ in range(panel.max_scroll_y):
            await pilot.press("shift+down")
            if panel.scroll_y >= panel.max_scroll_y:
                break
        await wait_until(pilot, lambda: panel.scroll_y == panel.max_scroll_y)
        assert app.session.cursor == (0, 0)  # the keys were the lesson's, not the cursor's
        await pilot.press("shift+up")
        await wait_until(pilot, lambda: panel.scroll_y < panel.max_scroll_y)
        await pilot.press("shift+right")
        await wait_until(pilot, lambda: "2/10" in str(panel.border_title))
        assert app.session.runs[0].k == 4
        await pilot.press("shift+left")
        await wait_until(pilot, lambda: "1/10" in str(panel.border_title))


@sync
async def test_at_80x24_section_6_s_narrow_panes_say_each_path_s_moves() -> None:
    """Issue 20: a number the lesson is about never goes.  Section 6 compares the paths'
    moves (5 against 8) in panes about 23 columns wide: the panes' own lines give way to
    their frontiers there (issue 42), and the line under the panes says each path's moves
    with each search's counts."""
    app = lesson_app("tutorial")
    async with app.run_test(size=(80, 24)) as pilot:
        panel = app.main.query_one(".lesson")
        while "6/10" not in str(panel.border_title):
            await pilot.press("pagedown")
            await pilot.pause()
        await wait_until(pilot, lambda: len(app.main.panes) == 2
                         and all(r.at_end for r in app.session.runs))

        def said() -> str:
            lines = [line for pane in app.main.panes if pane.stats.display
                     for line in pane.stats.shown_lines()] + app.main.stats.shown_lines()
            return " ".join(" ".join(lines).split())

        for label, moves in zip(app.session.labels, (5, 8), strict=True):
            await wait_until(pilot, lambda label=label, moves=moves: any(
                pane.label == label and pane.stats.display and pane.stats.region.area
                and f"path: {moves} moves, cost" in " ".join(pane.stats.shown_lines())
                for pane in app.main.panes) or f"{label} step" in said()
                and f"path {moves} moves" in said().split(f"{label} step")[1].split("│")[0])


def test_a_lesson_on_romania_moves_from_a_grid_to_a_graph_and_back(tmp_path: Path) -> None:
    """``map: romania`` (or a .graph file) in a lesson's block: the section shows the graph
    under a graph's rules (``order: name``, ``heuristic: table``); a later ``map:`` of a grid
    brings the grid's rules back."""
    from tui_search.engine.course.lesson import parse_lesson

    text = ("# Romania\n\n## A* on the road map\n\n```lesson\nmap: romania\nalgorithm: astar\n"
            "heuristic: table\nstep: end\n```\n\n## By name\n\n```lesson\norder: name\n"
            "algorithm: dfs\nstep: end\n```\n\n## Back to the grid\n\n```lesson\n"
            f"map: {TUTORIAL}\nalgorithm: bfs\nstep: 4\n```\n")
    session = Session(load_map(TUTORIAL), TUTORIAL)
    play = LessonPlay(parse_lesson(text, tmp_path / "romania.md"))
    play.open(session)
    run = session.runs[0]
    assert session.graph is not None and session.semantics.heuristic == "table"
    assert run.path() == ["Arad", "Sibiu", "Rimnicu", "Pitesti", "Bucharest"]
    play.move(session, 1)
    assert session.semantics.order == ("name",) and session.labels == ["DFS"]
    assert session.runs[0].found
    play.move(session, 1)
    assert session.graph is None and session.semantics.order[0] == "N"
    assert session.runs[0].k == 4
