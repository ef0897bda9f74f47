"""Teaching text wraps instead of being cut, at every terminal size: read off the screen as
painted, no status line, narration, readout, frontier line or comparison table ends in "…" or
shows a piece of a word (a number cut short), and what the lesson is about -- the tutorial's
bound, the quiz's score, a priority queue's f, g and h, iterative deepening's next depth
limit, an exercise's verdict -- is on the screen whole; the file prompts' labels wrap too, and
no panel's border title or legend is cut with "…" (a shorter wording shows instead)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from textual.pilot import Pilot
from textual.widget import Widget
from textual.widgets import Input, Label, Static

from tests.textual_internals import repainted
from tests.tui.test_app import TUTORIAL, sync, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.open_map import OpenMapScreen
from tui_search.tui.dialogs.save_as import SaveAsScreen
from tui_search.tui.view.pieces import Line, Parts, Piece, lay_out, text_of, wrap
from tui_search.tui.widgets.cell_readout import CellReadout
from tui_search.tui.widgets.challenge import ChallengePanel
from tui_search.tui.widgets.code_panel import CodePanel
from tui_search.tui.widgets.compare_table import CompareTable
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.line_panel import LinePanel
from tui_search.tui.widgets.stats import Stats
from tui_search.tui.widgets.wrapped_lines import PartsLines

SIZES = [(80, 24), (100, 30), (120, 40), (160, 48), (200, 60)]


def _bound(app: SearchApp) -> list[str]:
    """BFS at the end of the tutorial: the bound, with its value, in the status lines."""
    assert app.session.run.at_end
    return ["at most 7⁸ = 5,764,801"]


def _quiz(app: SearchApp) -> list[str]:
    return [app.session.note]  # the question, score first, whole


def _figures(app: SearchApp) -> list[str]:
    """A*: the entry expanded next, with its f, g and h, in the frontier panel."""
    run = app.session.run
    (g,) = run.now.frontier(0, 1)
    x, y = run.nodes.cell(g)
    cost, h, f = run.nodes.costs(g)
    return [f"({x},{y}) {run.nodes.move(g)}", f"f {f:.2f}", f"g {cost:.2f}", f"h {h:.2f}"]


def _next_limit(app: SearchApp) -> list[str]:
    """Iterative deepening between two iterations: the next depth limit."""
    run = app.session.run
    assert run.now.frontier_len() == 0
    return [f"next: depth limit {run.steps.depth_limit() + 1}"]


def _queue_figures(app: SearchApp) -> list[str]:
    """Every priority queue shown: the cell expanded next, with its f, g and h (pressed
    close in a narrow panel: "f6.41"), and every search's counts."""
    texts = _counts(app)
    for panel in app.main.query(FrontierPanel):
        run = panel.run
        if run and panel.display and panel.region.area and run.algo.weighted and (
                run.now.frontier_len()):
            (g,) = run.now.frontier(0, 1)
            x, y = run.nodes.cell(g)
            cost, h, f = run.nodes.costs(g)
            texts += [f"({x},{y})", f"f {f:.2f}", f"g {cost:.2f}", f"h {h:.2f}"]
    return texts


def _nothing(app: SearchApp) -> list[str]:
    return []


def _counts(app: SearchApp) -> list[str]:
    """Every search's step and nodes expanded, in its pane's status lines (what the lessons
    count: they wrap onto another row, never go)."""
    from tui_search.tui.view.narration import status_parts

    return [f"{label} {value}" for run in app.session.runs
            for label, value in status_parts(run) if label in ("step", "expanded")]


def _verdict(app: SearchApp) -> list[str]:
    """An exercise: its words, and the verdict with BFS's and DFS's figures."""
    verdict = app.main.query_one(ChallengePanel).verdict
    assert verdict is not None and app.session.exercise is not None
    return [app.session.exercise.text, verdict.reason]


def _terrain_note(app: SearchApp) -> list[str]:
    """UCS on the mud: the narration's words for what a cell's cost adds to g."""
    narration = app.main.query_one(Stats).narration_text
    assert "costs 9: g" in narration
    return [narration.rpartition("; ")[2]]


MUD = TUTORIAL.parent / "terrain-mud.txt"
#: A map no pane can show whole at any of SIZES in a comparison: the panes' maps scroll.
BIG = Path(__file__).parents[1] / "data" / "open-60x40.txt"

#: Each case: how the app opens (``path``: a map other than the tutorial's), the keys, and
#: the texts that must be on the screen whole.
CASES: dict[str, tuple[dict[str, object], list[str], Callable[[SearchApp], list[str]]]] = {
    "bfs at the end": ({"algorithm": "bfs"}, ["end"], _bound),
    "dfs mid-run": ({"algorithm": "dfs"}, ["n"] * 4, _nothing),
    "iddfs between iterations": ({"algorithm": "iddfs"}, ["n"] * 3, _next_limit),
    "iddfs mid-run": ({"algorithm": "iddfs"}, ["n"] * 9, _nothing),
    "astar's priority queue": ({"algorithm": "astar"}, ["n"] * 5, _figures),
    "the quiz": ({"algorithm": "bfs"}, ["i"], _quiz),
    "compare at the end": ({"compare": "bfs,dfs"}, ["end"], _counts),
    "compare 3 mid-run": ({"compare": "bfs,dfs,astar"}, ["n"] * 5, _counts),
    "compare 3 at the end": ({"compare": "bfs,dfs,astar"}, ["end"], _counts),
    "compare 4 mid-run": ({"compare": "bfs,dfs,astar,iddfs"}, ["n"] * 5, _counts),
    "compare 4 at the end": ({"compare": "bfs,dfs,astar,iddfs"}, ["end"], _counts),
    "compare 3 with A* and IDDFS, n n n": ({"compare": "bfs,astar,iddfs"}, ["n"] * 3,
                                           _queue_figures),
    "compare 3 with A* mid-run": ({"compare": "bfs,dfs,astar"}, ["n"] * 3, _queue_figures),
    "compare 4 with A* and IDDFS, n n n": ({"compare": "bfs,dfs,iddfs,astar"}, ["n"] * 3,
                                           _queue_figures),
    "compare 4 with UCS and IDDFS, n n n": ({"compare": "iddfs,ucs,dfs,astar"}, ["n"] * 3,
                                            _queue_figures),
    "the quiz comparing 2": ({"compare": "bfs,dfs"}, ["i"], _quiz),
    "the quiz comparing 4": ({"compare": "bfs,dfs,astar,iddfs"}, ["i"], _quiz),
    "exercise 1": ({"algorithm": "bfs"}, ["x"], _verdict),
    "exercise 1 solved": ({"exercise": 1}, ["j"] * 4 + ["g"], _verdict),
    "exercise 2 beside a comparison": ({"exercise": 2, "compare": "bfs,dfs"}, ["end"],
                                       _verdict),
    "the code panel": ({"algorithm": "bfs"}, ["n"] * 4 + ["v"], _nothing),
    "the code panels comparing": ({"compare": "bfs,astar"}, ["end", "v"], _nothing),
    "terrain: ucs says what the mud adds": ({"path": MUD, "algorithm": "ucs"}, ["n"] * 5,
                                            _terrain_note),
    "terrain: compare says each path's cost": ({"path": MUD, "compare": "bfs,ucs"}, ["end"],
                                               _nothing),
    "compare on a map that does not fit": ({"path": BIG, "compare": "bfs,dfs"}, [], _nothing),
    "compare with A* on a map that does not fit": ({"path": BIG, "compare": "bfs,astar"},
                                                   ["n"] * 4, _queue_figures),
}


def _words(texts: list[str]) -> set[str]:
    return {word for text in texts for word in text.split()}


def _whole_texts(widget: Widget) -> list[str]:
    """What ``widget`` has to say, unwrapped: every word it may show."""
    if isinstance(widget, Stats):
        return [widget.status_text, widget.narration_text, widget.short_text]
    if isinstance(widget, CellReadout):
        return [f"{widget.label} {widget.text}"]
    if isinstance(widget, CompareTable):
        return widget.text_lines
    if isinstance(widget, ChallengePanel):
        return [widget.text]
    assert isinstance(widget, FrontierPanel | CodePanel)
    return widget.lines()


def _cropped(panel: LinePanel, rows: list[str]) -> list[str]:
    """The rows of ``panel`` as shown (``rows``) that are not its whole lines: its lines
    wrap to its width, so none is scrolled sideways or cut at the edge, even between two
    words (which the words seen cannot tell)."""
    top = round(panel.scroll_y)
    shown = (panel.line_text(top + y) for y in range(len(rows)))
    return [f"{type(panel).__name__} shows {row.strip()!r} of {line!r}"
            for row, line in zip(rows, shown, strict=True) if row.rstrip() != line]


def problems(app: SearchApp, screen: list[str], lesson: list[str]) -> list[str]:
    """What is cut on ``screen`` (its lines as text), and what of ``lesson`` is not on it."""
    found = []
    seen = []
    kinds = (Stats, CellReadout, CompareTable, FrontierPanel, ChallengePanel, CodePanel)
    for widget in app.main.query("*"):
        if not isinstance(widget, kinds) or not widget.display or not widget.region.area:
            continue
        region = widget.scrollable_content_region
        rows = [screen[y][region.x:region.right] for y in range(region.y, region.bottom)]
        text = " ".join(" ".join(rows).split())
        seen.append(text)
        name = type(widget).__name__
        whole = _whole_texts(widget)
        if text.count("…") > sum(line.count("…") for line in whole):  # not its own (a run
            found.append(f"{name} ends in '…': {text!r}")  # going: "… step 5")
        cut = _words(rows) - _words(whole)
        if cut:
            found.append(f"{name} shows cut words {sorted(cut)}: {text!r}")
        if isinstance(widget, LinePanel):  # a word cut off whole at the panel's edge, too
            found += _cropped(widget, rows)
        if isinstance(widget, PartsLines) and len(widget.rows(region.width)) > region.height:
            found.append(f"{name} has rows under its region (words cut off whole): {text!r}")
        if isinstance(widget, FrontierPanel) and widget.run and widget.run.now.frontier_len() \
                and not any("(" in row for row in rows[1:]):
            found.append(f"{name} shows no entry of its frontier: {text!r}")
    for whole in lesson:
        if not any(whole in text or whole.replace(" ", "", 1) in text for text in seen):
            found.append(f"{whole!r} not on the screen whole")
    return [f"{app.size}: {problem}" for problem in found]


@pytest.mark.parametrize("case", CASES)
@sync
async def test_teaching_text_wraps_and_is_on_the_screen_whole(case: str) -> None:
    options, keys, lesson_of = CASES[case]
    options = dict(options)
    path = options.pop("path", TUTORIAL)
    assert isinstance(path, Path)
    app = SearchApp(load_map(path), path=path, **options)  # type: ignore[arg-type]
    async with app.run_test(size=SIZES[0]) as pilot:
        await pilot.press(*keys)
        await wait_until(pilot, lambda: not app.session.seeking)
        lesson = lesson_of(app)
        await at_every_size(pilot, lambda screen: problems(app, screen, lesson), case)


async def at_every_size(pilot: Pilot, check: Callable[[list[str]], list[str]],
                        what: str) -> None:
    """Resize the terminal to each of SIZES and assert that ``check`` finds nothing wrong on
    the screen as painted (its lines as text) once the panes are fitted."""
    app = pilot.app
    for size in SIZES:
        await pilot.resize_terminal(*size)
        found: list[str] = ["not drawn yet"]
        for _ in range(300):  # the panes are fitted after the resize: wait for it (a busy
            # machine may take seconds)
            screen = ["".join(text for text, _ in line) for line in await repainted(pilot)]
            found = check(screen)
            if not found and app.size == size:
                break
            await pilot.pause(0.05)
        assert not found, (what, found)


@sync
async def test_a_pane_s_status_lines_are_not_under_its_lists_column() -> None:
    """Panes wide and short keep their lists in a column beside the map: the column spans
    the pane's height, the status lines the rest of its width."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    async with app.run_test(size=(160, 30)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: all(pane.has_class("-beside")
                                            for pane in app.main.panes))
        for pane in app.main.panes:  # the lists' box paints nothing (app.tcss): its parts
            for part in (pane.frontier, pane.tree_panel):
                assert part.region.area and not pane.stats.region.overlaps(part.region)


def prompt_problems(app: SearchApp, screen: list[str]) -> list[str]:
    """What of the file prompt's label, hint and error is not on ``screen`` whole (each in
    its place, wrapped, every word shown), and any border cut with "…"."""
    prompt = app.screen
    assert isinstance(prompt, SaveAsScreen | OpenMapScreen)
    found = cut_borders(app, screen)
    for widget, whole, folds in ((prompt.query(Label).first(), prompt.LABEL_TEXT, False),
                                 (prompt.query_one(".hint", Label), prompt.HINT_TEXT, False),
                                 (prompt.query_one("#error", Static), prompt.error, True)):
        if not whole:
            continue
        region = widget.content_region
        rows = [screen[y][region.x:region.right] for y in range(region.y, region.bottom)]
        shown = " ".join(" ".join(rows).split())
        joiner = "" if folds else " "  # a name typed, wider than the box, folds
        if joiner.join(shown.split()) != joiner.join(whole.split()):
            found.append(f"{app.size}: {whole!r} shown as {shown!r}")
    return found


@pytest.mark.parametrize("error", [False, True])
@pytest.mark.parametrize(("key", "prompt"), [("w", SaveAsScreen), ("ctrl+o", OpenMapScreen)])
@sync
async def test_the_save_as_and_open_prompts_wrap_their_labels(
        key: str, prompt: type, error: bool, tmp_path: Path) -> None:
    """A label longer than the prompt's box wraps onto more lines, every word shown, and so do
    the hint and an error (a folder named), at every size."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL)
    async with app.run_test(size=SIZES[0]) as pilot:
        await pilot.press(key)
        await wait_until(pilot, lambda: isinstance(app.screen, prompt))
        if error:
            app.screen.query_one("#filename", Input).value = str(tmp_path)
            await pilot.press("enter")
            await wait_until(pilot, lambda: bool(app.screen.error))
        await at_every_size(pilot, lambda screen: prompt_problems(app, screen), prompt.__name__)


def _rows(rows: list[Parts]) -> list[str]:
    return [text_of(row) for row in rows]


def test_a_line_wraps_between_its_pieces_and_drops_the_separator_at_a_break() -> None:
    sep = (" │ ", "")
    line = Line([Piece([("BFS", "")]), Piece([("step 4/18", "")], 1, sep),
                 Piece([("generated 5,764,801", "")], 1, sep)])
    assert _rows(wrap(line, 40)) == ["BFS │ step 4/18 │ generated 5,764,801"]
    assert _rows(wrap(line, 20)) == ["BFS │ step 4/18", "generated 5,764,801"]
    assert _rows(wrap(line, 12)) == ["BFS", "step 4/18", "generated", "5,764,801"]


def test_prose_flows_word_by_word_and_no_row_starts_with_a_separator() -> None:
    line = Line([Piece([("Goal (5,2) found", "")]),
                 Piece([("at most 7⁸ = 5,764,801", "")], 0, (" · ", ""))], prose=True)
    assert _rows(wrap(line, 18)) == ["Goal (5,2) found ·", "at most 7⁸ =", "5,764,801"]
    assert _rows(wrap(line, 16)) == ["Goal (5,2) found", "at most 7⁸ =", "5,764,801"]


def test_when_the_rows_run_out_the_highest_rank_goes_first_and_rank_0_never() -> None:
    sep = (" │ ", "")
    status = Line([Piece([("A*", "")]), Piece([("step 5/16", "")], 1, sep),
                   Piece([("queue 5 (peak 5)", "")], 5, sep, [("queue 5", "")]),
                   Piece([("speed 5/s", "")], 6, sep)])
    narration = Line([Piece([("Expanded (0,2) f = 7.00 (g 2.00 + h 5.00)", "")])], prose=True)
    assert _rows(lay_out([status, narration], 30, 3)) == [
        "A* │ step 5/16 │ queue 5", "Expanded (0,2) f = 7.00 (g", "2.00 + h 5.00)"]
    assert len(lay_out([status, narration], 12, 2)) > 2  # rank 0 takes the rows it needs


def test_a_short_form_goes_at_its_own_rank_after_the_pieces_above_it() -> None:
    """The queue's size, once its peak went, stays while a count of lesser note can go, and
    goes in its turn (it stayed for good, and the step went before it)."""
    sep = (" │ ", "")
    queue = Piece([("queue 5 (peak 5)", "")], 6, sep, [("queue 5", "")], 2)
    status = Line([Piece([("BFS", "")]), Piece([("step 5/22", "")], 0, sep), queue,
                   Piece([("generated 9", "")], 3, sep)])
    assert _rows(lay_out([status], 30, 1)) == ["BFS │ step 5/22 │ queue 5"]
    assert _rows(lay_out([status], 20, 1)) == ["BFS │ step 5/22"]
    assert _rows(lay_out([status], 20, 2)) == ["BFS │ step 5/22", "queue 5"]


@pytest.mark.parametrize("options", [{}, {"compare": "bfs,dfs"}, {"compare": "bfs,astar"}])
@pytest.mark.parametrize("size", [(80, 24), (100, 30)])
@sync
async def test_the_panels_bottom_legends_are_shortened_not_cut(
        options: dict[str, str], size: tuple[int, int]) -> None:
    """A narrow frontier or tree panel shows a shorter wording of its bottom legend (or none)
    rather than the border's "…", stepping and in the quiz."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, **options)  # type: ignore[arg-type]
    async with app.run_test(size=size) as pilot:
        for keys in (["n"] * 3, ["i"]):
            await pilot.press(*keys)
            await pilot.pause()
            screen = ["".join(text for text, _ in line) for line in await repainted(pilot)]
            for panel in app.main.query(".pane-frontier, .pane-tree"):
                if panel.display and panel.region.area:
                    region = panel.region
                    bottom = screen[region.bottom - 1][region.x:region.right]
                    assert "…" not in bottom, (size, options, bottom)
                    assert panel.border_subtitle in bottom


#: Each mode of the app: how it opens and the keys that bring it on.
MODES: dict[str, tuple[dict[str, object], list[str]]] = {
    "single": ({"algorithm": "iddfs"}, ["n"] * 3),
    "compare 2": ({"compare": "bfs,dfs"}, ["n"] * 3),
    "compare 3": ({"compare": "bfs,dfs,astar"}, ["n"] * 3),
    "compare 4": ({"compare": "bfs,dfs,astar,iddfs"}, ["n"] * 3),
    "exercise": ({"compare": "bfs,dfs"}, ["x"]),
    "quiz": ({"algorithm": "astar"}, ["i"]),
    "quiz comparing 2": ({"compare": "bfs,dfs"}, ["i"]),
    "quiz comparing 4": ({"compare": "bfs,dfs,astar,iddfs"}, ["i"]),
    "code panel": ({"algorithm": "iddfs"}, ["n"] * 3 + ["v"]),
    "code panels comparing 2": ({"compare": "bfs,dfs"}, ["n"] * 3 + ["v"]),
    "code panels comparing 4": ({"compare": "bfs,dfs,astar,iddfs"}, ["n"] * 3 + ["v"]),
}


def cut_borders(app: SearchApp, screen: list[str]) -> list[str]:
    """The border rows on ``screen`` (its lines as text) that Textual cut a title or a legend
    of with "…"."""
    found = []
    for widget in app.screen.query("*"):
        if not widget.display or not widget.region.area:
            continue
        region = widget.region
        for y, edge in ((region.y, widget.styles.border_top),
                        (region.bottom - 1, widget.styles.border_bottom)):
            row = screen[y][region.x:region.right]
            if edge[0] not in ("", "none", "hidden") and "…" in row:
                found.append(f"{app.size}: {type(widget).__name__}: {row!r}")
    return found


@pytest.mark.parametrize("mode", MODES)
@sync
async def test_no_panel_border_is_cut(mode: str) -> None:
    """Every panel's border title and legend is shown whole, in a shorter wording where the
    longest does not fit, at every size, in every mode."""
    options, keys = MODES[mode]
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, **options)  # type: ignore[arg-type]
    async with app.run_test(size=SIZES[0]) as pilot:
        await pilot.press(*keys)
        await wait_until(pilot, lambda: not app.session.seeking)
        await at_every_size(pilot, lambda screen: cut_borders(app, screen), mode)
