"""The run as the app draws it, a screen a step: the app itself, run headless (Textual's
``run_test``) at a fixed size, stepped with the action its ``n`` key calls, each step's screen
read back from the app's own screenshot (:mod:`~tui_search.export.cells`).

Nothing here depends on the terminal or the clock: the size is fixed, the theme is
``--theme``'s (else the default), the remembered config is not read, notifications are off,
and each screen is taken once two screenshots in a row agree (the app has laid out and
painted the step), so the same run gives the same frames.
"""

from __future__ import annotations

import asyncio
from typing import TYPE_CHECKING, NamedTuple

from tui_search.engine.util.numbers import group_digits
from tui_search.export.cells import Screen, crop, read_screenshot
from tui_search.export.kinds import MAX_FRAMES
from tui_search.tui.app import SearchApp
from tui_search.tui.config import Config
from tui_search.tui.view.themes import DEFAULT_THEME

if TYPE_CHECKING:
    from textual.pilot import Pilot

    from tui_search.export.job import Job

#: The app's size for the full view: the README's pictures' width.
FULL_SIZE = (100, 30)
#: The map view's sizes, tried in turn until the whole map shows (then the app's overview).
MAP_SIZES = ((100, 30), (140, 45), (200, 60))
#: Screenshots compared before a step's screen is taken anyway (each after a pause).
SETTLE_TRIES = 20


class ExportRefused(ValueError):
    """What the run or its map cannot be exported as (one line, naming the size)."""


class Film(NamedTuple):
    """The frames of a run: ``frames[k]`` the screen after step ``k``, each ``width`` x
    ``height`` cells; ``title`` says what runs on which map ("BFS on tutorial.txt")."""

    frames: list[Screen]
    width: int
    height: int
    title: str


def film(job: Job) -> Film:
    """The run ``job`` asks for, a frame a step (an :class:`ExportRefused` when it is too big
    to export)."""
    return asyncio.run(_film(job))


def new_app(job: Job) -> SearchApp:
    """The app as the command line would open it on ``job``'s run, in ``job``'s theme,
    remembering nothing."""
    return SearchApp(job.grid, path=job.path, algorithm=job.algorithm, semantics=job.semantics,
                     max_steps=job.max_steps, unsaved_name=job.unsaved_name,
                     theme=job.theme or DEFAULT_THEME, config=Config.in_memory(),
                     compare=job.compare)


def _steps(app: SearchApp) -> int:
    """The lockstep's steps: the longest run's (each recorded whole), refused past
    :data:`MAX_FRAMES` frames."""
    runs = app.session.runs
    for run in runs:
        run.advance()
    steps = max((run.total or 0) for run in runs)
    if steps + 1 > MAX_FRAMES:
        raise ExportRefused(f"the run takes {group_digits(steps)} steps: an export holds at "
                            f"most {group_digits(MAX_FRAMES)} frames, one a step (a smaller "
                            f"map, or --max-steps)")
    return steps


async def _film(job: Job) -> Film:
    app = new_app(job)
    steps = _steps(app)
    sizes = MAP_SIZES if job.view == "map" else (FULL_SIZE,)
    async with app.run_test(size=sizes[0]) as pilot:
        size = await _fitted(pilot, sizes, job)
        frames = [await _shot(pilot, size, job.view)]
        session = app.session
        while not session.at_end() and len(frames) <= steps:
            app.main.action_next()  # what n does
            frames.append(await _shot(pilot, size, job.view))
    height, width = len(frames[0]), len(frames[0][0])
    *others, last = app.session.labels
    names = f"{', '.join(others)} and {last}" if others else last
    return Film(frames, width, height, f"{names} on {app.session.map_name}")


async def _fitted(pilot: Pilot[int], sizes: tuple[tuple[int, int], ...], job: Job
                  ) -> tuple[int, int]:
    """The first of ``sizes`` at which the whole map shows (the map view: else the largest,
    in the overview); the full view of a map that does not fit is refused."""
    app = pilot.app
    assert isinstance(app, SearchApp)
    for size in sizes:
        if size != sizes[0]:
            await pilot.resize_terminal(*size)
        await _settled(pilot)
        if all(view.whole for view in app.main.views):
            return size
    grid = job.grid
    if job.view != "map":
        raise ExportRefused(
            f"the map is {grid.width}x{grid.height}: at {FULL_SIZE[0]}x{FULL_SIZE[1]} it does "
            "not show whole beside the frontier and the tree (--export-view map: the map "
            "alone)")
    app.main.action_overview()  # z: the whole map, a character a block of cells
    return sizes[-1]


async def _settled(pilot: Pilot[int]) -> str:
    """The screenshot once two in a row agree: the app has handled the step, laid out and
    painted it."""
    app = pilot.app
    await pilot.pause()
    svg = app.export_screenshot()
    for _ in range(SETTLE_TRIES):
        await pilot.pause()
        again = app.export_screenshot()
        if again == svg:
            break
        svg = again
    return svg


async def _shot(pilot: Pilot[int], size: tuple[int, int], view: str) -> Screen:
    """The screen now (the map view: the part that holds the maps)."""
    screen = read_screenshot(await _settled(pilot), *size)
    if view != "map":
        return screen
    app = pilot.app
    assert isinstance(app, SearchApp)
    regions = [v.region for v in app.main.views]
    left, top = min(r.x for r in regions), min(r.y for r in regions)
    right, bottom = max(r.right for r in regions), max(r.bottom for r in regions)
    return crop(screen, left, top, right - left, bottom - top)
