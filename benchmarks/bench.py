#!/usr/bin/env python
"""tui-search against its targets (GitHub issue 4), as ratios measured in one process.

    python benchmarks/bench.py            # the full run (a few minutes)
    python benchmarks/bench.py --quick    # about a minute: fewer repeats, no networkx
    python benchmarks/bench.py --only engine,step

Every figure is compared with a baseline measured in the same run (a bare Python BFS, the
``pathfinding`` package, a trivial Textual app, ``python -c pass``), because absolute times on a
shared machine mean little.  Each figure is the median of several repeats, interleaved with its
baseline's; the "±" after a time is the spread of the repeats, (max - min) / median.

The peers (``pip install -e .[bench]``: pathfinding, networkx, scipy) are optional: a missing one
gives a "not installed" row.  See benchmarks/README.md for what each row means.
"""

from __future__ import annotations

import argparse
import asyncio
import compileall
import gc
import os
import select
import statistics
import subprocess
import sys
import tempfile
import time
import tracemalloc
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))  # run from a checkout without installing

import tui_search
from tui_search.engine.grid import DEFAULT_ORDER, DELTAS, Grid
from tui_search.engine.run import Run

#: Where the MovingAI maps are (not shipped in the package); override with TUI_SEARCH_MAPS.
MAPS = Path(os.environ.get("TUI_SEARCH_MAPS", "/work/shared/maps/movingai"))
TUTORIAL = ROOT / "maps" / "tutorial.txt"
MAZE, MAZE_SCEN = "maze512-1-0.map", "maze512-1-0.map.scen"
OPEN_SIZE = 1024
TERMINAL = (160, 50)  # columns, rows of the headless and pty runs

SECTIONS = ("engine", "jump", "step", "startup")


# -- the table ---------------------------------------------------------------------------------
@dataclass
class Row:
    section: str
    what: str
    measured: str
    baseline: str = ""
    ratio: float | None = None
    target: str = ""
    ok: bool | None = None  # None: reported only (no target), or not measured

    @property
    def verdict(self) -> str:
        if self.target == "baseline":
            return "-"
        if self.ok is None:
            return "n/a" if self.measured in ("not installed", "skipped") else "report"
        return "pass" if self.ok else "FAIL"


ROWS: list[Row] = []


def add(row: Row) -> Row:
    ROWS.append(row)
    print(f"  [{row.section}] {row.what}: {row.measured} | {row.baseline} | "
          f"{fmt_ratio(row.ratio)} {row.target} {row.verdict}", file=sys.stderr, flush=True)
    return row


def fmt_ratio(r: float | None) -> str:
    if r is None:
        return "-"
    return f"{r:.3f}" if r < 0.1 else f"{r:.2f}"


def print_table(rows: list[Row]) -> None:
    head = ("section", "what", "measured", "baseline", "ratio", "target", "result")
    cells = [head] + [
        (r.section, r.what, r.measured, r.baseline, fmt_ratio(r.ratio), r.target, r.verdict)
        for r in rows
    ]
    widths = [max(len(c[i]) for c in cells) for i in range(len(head))]
    line = "  ".join("-" * w for w in widths)
    print(line)
    for i, c in enumerate(cells):
        print("  ".join(s.ljust(w) for s, w in zip(c, widths)).rstrip())
        if i == 0:
            print(line)
    print(line)
    passed = sum(r.ok is True for r in rows)
    failed = [r for r in rows if r.ok is False]
    print(f"{passed} pass, {len(failed)} fail, {sum(r.ok is None for r in rows)} reported only")
    for r in failed:
        print(f"  FAIL: [{r.section}] {r.what} ({fmt_ratio(r.ratio)}, target {r.target})")


# -- timing helpers ----------------------------------------------------------------------------
def timed(fn: Callable[[], object]) -> tuple[float, object]:
    gc.collect()
    t = time.perf_counter()
    result = fn()
    return time.perf_counter() - t, result


#: A timed sample lasts at least this long: a shorter call is repeated inside the sample.
MIN_SAMPLE = 0.05


def interleaved(fns: dict[str, Callable[[], object]], repeats: int) -> dict[str, list[float]]:
    """Seconds per call of each function, ``repeats`` samples each, round-robin, so a slow
    patch of the machine hits every contender alike.  A call shorter than MIN_SAMPLE is
    repeated within its sample (the number fixed by a first, untimed-for-results call)."""
    number = {}
    for name, fn in fns.items():
        dt, result = timed(fn)
        del result
        number[name] = max(1, min(200, round(MIN_SAMPLE / max(dt, 1e-6))))
    out: dict[str, list[float]] = {name: [] for name in fns}
    for _ in range(repeats):
        for name, fn in fns.items():
            n = number[name]
            if n == 1:
                dt, result = timed(fn)
                del result
            else:
                gc.collect()
                t = time.perf_counter()
                for _ in range(n):
                    fn()
                dt = (time.perf_counter() - t) / n
            out[name].append(dt)
    return out


def med(xs: list[float]) -> float:
    return statistics.median(xs)


def paired(xs: list[float], base: list[float]) -> float:
    """The median of the per-repeat ratios: each repeat's pair ran back to back (interleaved),
    so a slow patch of the shared machine mostly cancels out."""
    return med([x / b for x, b in zip(xs, base)])


def spread(xs: list[float]) -> float:
    """(max - min) / median: how noisy the repeats were."""
    return (max(xs) - min(xs)) / med(xs) if len(xs) > 1 and med(xs) > 0 else 0.0


def fmt_time(xs: list[float] | float) -> str:
    if isinstance(xs, float):
        xs = [xs]
    m = med(xs)
    text = f"{m * 1e3:.3g} ms" if m < 1 else f"{m:.3g} s"
    if len(xs) > 1:
        text += f" ±{spread(xs) * 100:.0f}%"
    return text


NOISE: list[tuple[str, float]] = []  # (what, spread) of every timed series, for the summary


def series(name: str, xs: list[float]) -> list[float]:
    if len(xs) > 1:
        NOISE.append((name, spread(xs)))
    return xs


# -- maps --------------------------------------------------------------------------------------
def open_grid(n: int = OPEN_SIZE) -> Grid:
    return Grid(n, n, start=(0, 0), goal=(n - 1, n - 1))


def maze_grid() -> Grid | None:
    """maze512-1-0 with the start and goal of the last (longest) row of its .scen."""
    m, s = MAPS / MAZE, MAPS / MAZE_SCEN
    if not m.exists() or not s.exists():
        return None
    rows = [ln for ln in s.read_text().splitlines()[1:] if ln.strip()]
    last = len(rows) - 1
    try:
        from tui_search.engine.mapfile import load_map, load_scenario

        scen = load_scenario(s, last)
        return load_map(m, start=scen.start, goal=scen.goal)
    except ImportError:  # the parser is not there: read the two formats here
        f = rows[last].split("\t")
        lines = m.read_text().splitlines()
        h, w = int(lines[1].split()[1]), int(lines[2].split()[1])
        body = "".join(lines[4 : 4 + h])
        blocked = bytearray(0 if ch in ".GS" else 1 for ch in body)
        return Grid(w, h, blocked, (int(f[4]), int(f[5])), (int(f[6]), int(f[7])))


def maze_cli_args() -> list[str]:
    rows = [ln for ln in (MAPS / MAZE_SCEN).read_text().splitlines()[1:] if ln.strip()]
    return [str(MAPS / MAZE), "--scen", str(MAPS / MAZE_SCEN), "--scen-row", str(len(rows) - 1)]


# -- 1. the engine -----------------------------------------------------------------------------
def pad(grid: Grid) -> tuple[bytearray, int, int, int, tuple[int, ...]]:
    """The engine's technique, written out: walls with a one-cell wall border, flat indices,
    the eight neighbour offsets in the default order."""
    w, h = grid.width, grid.height
    stride = w + 2
    walls = bytearray(b"\x01") * (stride * (h + 2))
    for y in range(h):
        row = (y + 1) * stride + 1
        walls[row : row + w] = grid.blocked[y * w : (y + 1) * w]
    start = (grid.start[1] + 1) * stride + grid.start[0] + 1
    goal = (grid.goal[1] + 1) * stride + grid.goal[0] + 1
    offs = tuple(DELTAS[d][1] * stride + DELTAS[d][0] for d in DEFAULT_ORDER)
    return walls, stride, start, goal, offs


def bare_search(grid: Grid, lifo: bool = False) -> list[int]:
    """The fastest plain-Python BFS we could write: a deque, a closed bytearray (the padded
    walls themselves), a parent list; no recording.  Same semantics as the engine (mark and
    goal-test on generation, neighbours in the default order), so the same path.  With
    ``lifo`` the deque is a stack: the engine's DFS, same path again."""
    closed, _, start, goal, offs = pad(grid)
    parent = [-1] * len(closed)
    if start == goal:
        return parent
    q = deque([start])
    closed[start] = 1
    pop, push = (q.pop if lifo else q.popleft), q.append
    while q:
        n = pop()
        for off in offs:
            m = n + off
            if closed[m]:
                continue
            closed[m] = 1
            parent[m] = n
            if m == goal:
                return parent
            push(m)
    return parent


def bare_bfs(grid: Grid) -> list[int]:
    return bare_search(grid)


def bare_dfs(grid: Grid) -> list[int]:
    return bare_search(grid, lifo=True)


def bare_path_len(grid: Grid, parent: list[int]) -> int:
    _, _, start, goal, _ = pad(grid)
    n, moves = goal, 0
    while n != start:
        n = parent[n]
        if n < 0:
            return -1
        moves += 1
    return moves


def recorded(grid: Grid, algorithm: str) -> Run:
    run = Run(grid, algorithm)
    run.advance()
    return run


def traced(fn: Callable[[], object]) -> tuple[int, int]:
    """(peak, retained) bytes allocated while ``fn`` runs, ``retained`` with its result alive."""
    gc.collect()
    tracemalloc.start()
    try:
        keep = fn()
        retained, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    del keep
    return peak, retained


def bench_memory(name: str, grid: Grid, algorithm: str, run: Run) -> None:
    """Bytes per expansion three ways: the record's arrays (``rec.nbytes``); what the recorded
    Run keeps; and its peak while recording.  The last two are tracemalloc figures minus the
    same for a Run on the same map with the goal on the start (no expansions), which holds
    everything map-sized: the grid copy, the padded walls, the closed set, the per-cell
    counters.  (The peak difference can come out below the record: both peaks include
    construction temporaries that the longer run has freed by its own peak.)"""
    steps = run.rec.steps
    rec_b = run.rec.nbytes() / steps
    trivial = grid.copy()
    trivial.goal = trivial.start
    map_peak, map_kept = traced(lambda: recorded(trivial, algorithm))
    peak, kept = traced(lambda: recorded(grid, algorithm))
    kept_b, peak_b = (kept - map_kept) / steps, (peak - map_peak) / steps
    add(Row("engine", f"{name} {algorithm.upper()} memory per expansion (rec.nbytes | kept | "
            "peak, above the map)", f"{rec_b:.1f} | {kept_b:.1f} | {peak_b:.1f} B",
            f"map-only Run {map_peak / 1e6:.1f} MB", None, "≤ 64 B",
            max(rec_b, kept_b, peak_b) <= 64))


def pathfinding_bfs(grid: Grid) -> Callable[[], object] | None:
    try:
        from pathfinding.core.diagonal_movement import DiagonalMovement
        from pathfinding.core.grid import Grid as PFGrid
        from pathfinding.finder.breadth_first import BreadthFirstFinder
    except ImportError:
        return None
    w = grid.width
    matrix = [[0 if grid.blocked[y * w + x] else 1 for x in range(w)] for y in range(grid.height)]

    def solve():  # grid construction included: pathfinding keeps search state on its nodes
        pf = PFGrid(matrix=matrix)
        finder = BreadthFirstFinder(diagonal_movement=DiagonalMovement.always)
        path, _ = finder.find_path(pf.node(*grid.start), pf.node(*grid.goal), pf)
        return len(path) - 1

    return solve


def edges(grid: Grid):
    """Directed edges between free padded cells, one array per neighbour offset (numpy)."""
    import numpy as np

    walls, _, _, _, offs = pad(grid)
    free = np.frombuffer(bytes(walls), dtype=np.uint8) == 0
    n = len(walls)
    src, dst = [], []
    idx = np.flatnonzero(free).astype(np.int32)
    for off in offs:
        ok = free[idx + off]  # the border keeps idx + off in range
        src.append(idx[ok])
        dst.append(idx[ok] + off)
    return n, np.concatenate(src), np.concatenate(dst)


def scipy_bfs(grid: Grid) -> Callable[[], object] | None:
    try:
        import numpy as np
        from scipy.sparse import csr_matrix
        from scipy.sparse.csgraph import breadth_first_order
    except ImportError:
        return None
    _, _, start, goal, _ = pad(grid)

    def solve():
        n, src, dst = edges(grid)
        graph = csr_matrix((np.ones(len(src), dtype=np.int8), (src, dst)), shape=(n, n))
        t = time.perf_counter()
        _, pred = breadth_first_order(graph, start, directed=True, return_predecessors=True)
        solve.bfs_only.append(time.perf_counter() - t)
        moves, v = 0, goal
        while v != start:
            v = pred[v]
            moves += 1
        return moves

    solve.bfs_only = []
    return solve


def networkx_bfs(grid: Grid) -> Callable[[], object] | None:
    try:
        import networkx as nx
    except ImportError:
        return None
    walls, _, start, goal, offs = pad(grid)
    half = [o for o in offs if o > 0]  # undirected: each edge once

    def solve():
        g = nx.Graph()
        g.add_edges_from(
            (p, p + o) for p in range(len(walls)) if not walls[p] for o in half if not walls[p + o]
        )
        return len(nx.shortest_path(g, start, goal)) - 1

    return solve


def bench_engine(quick: bool) -> None:
    print("engine ...", file=sys.stderr, flush=True)
    maps = [(f"open {OPEN_SIZE}²", open_grid())]
    maze = maze_grid()
    if maze is None:
        add(Row("engine", f"{MAZE}", "skipped", f"not found in {MAPS}"))
    else:
        maps.append(("maze512", maze))
    repeats = 3 if quick else 7
    for name, grid in maps:
        runs = {a: recorded(grid, a) for a in ("bfs", "dfs")}  # warm-up, and the answers
        for a, bare in (("bfs", bare_bfs), ("dfs", bare_dfs)):
            got, want = len(runs[a].path()) - 1, bare_path_len(grid, bare(grid))
            if got != want:
                print(f"WARNING: {name} {a}: engine path {got} moves, bare {want}", file=sys.stderr)
        t = interleaved({
            "bare bfs": lambda g=grid: bare_bfs(g),
            "run bfs": lambda g=grid: recorded(g, "bfs"),
            "bare dfs": lambda g=grid: bare_dfs(g),
            "run dfs": lambda g=grid: recorded(g, "dfs"),
        }, repeats)
        for key, xs in t.items():
            series(f"{name} {key}", xs)
        # The target: both recorded runs against a bare BFS of the same map.
        for a in ("bfs", "dfs"):
            r = paired(t[f"run {a}"], t["bare bfs"])
            add(Row("engine", f"{name} {a.upper()} recorded run vs bare BFS "
                    f"({runs[a].rec.steps:,} expansions)", fmt_time(t[f"run {a}"]),
                    f"bare BFS {fmt_time(t['bare bfs'])}", r, "≤ 1.30", r <= 1.30))
        # Stricter, for us: the DFS recording against a bare DFS (same loop, list as a stack).
        r = paired(t["run dfs"], t["bare dfs"])
        add(Row("engine", f"{name} DFS recorded run vs bare DFS (stricter)", fmt_time(t["run dfs"]),
                f"bare DFS {fmt_time(t['bare dfs'])}", r, "report (≤ 1.30)"))

        ours = t["run bfs"]
        pf = pathfinding_bfs(grid)
        if pf is None:
            add(Row("engine", f"{name} pathfinding BFS", "not installed"))
        else:
            pf_t = series(f"{name} pathfinding", [timed(pf)[0] for _ in range(1 if quick else 3)])
            r = med(ours) / med(pf_t)  # not interleaved: pathfinding runs take seconds
            add(Row("engine", f"{name} BFS recorded run vs pathfinding 1.0.23 BFS (+grid)",
                    fmt_time(ours), f"pathfinding {fmt_time(pf_t)}", r, "≤ 0.125 (8× less)",
                    r <= 0.125))
        sp = scipy_bfs(grid)
        if sp is None:
            add(Row("engine", f"{name} scipy breadth_first_order", "not installed"))
        else:
            sp()  # warm-up: scipy's first call pays for lazy imports and fresh pages
            sp.bfs_only.clear()
            sp_t = series(f"{name} scipy", [timed(sp)[0] for _ in range(3 if quick else 5)])
            add(Row("engine", f"{name} BFS recorded run vs scipy csgraph BFS (+graph build; "
                    f"BFS alone {fmt_time(med(sp.bfs_only))})", fmt_time(ours),
                    f"scipy {fmt_time(sp_t)}", med(ours) / med(sp_t), "report"))
        if name.startswith("maze"):
            nxs = networkx_bfs(grid)
            if quick:
                add(Row("engine", f"{name} networkx shortest_path (+graph build)", "skipped",
                        "--quick"))
            elif nxs is None:
                add(Row("engine", f"{name} networkx shortest_path", "not installed"))
            else:
                nx_t = series(f"{name} networkx", [timed(nxs)[0] for _ in range(3)])
                add(Row("engine", f"{name} BFS recorded run vs networkx 3.6.1 shortest_path "
                        f"(+graph build)", fmt_time(ours), f"networkx {fmt_time(nx_t)}",
                        med(ours) / med(nx_t), "report"))
        for a in ("bfs", "dfs"):
            bench_memory(name, grid, a, runs[a])
        del runs
        gc.collect()


# -- Textual helpers ---------------------------------------------------------------------------
TRIVIAL_APP = '''
"""The baseline: the least a Textual app can do -- one line-API widget whose line 5 changes
when n or p is pressed."""
from rich.segment import Segment
from textual.app import App
from textual.geometry import Region
from textual.strip import Strip
from textual.widget import Widget


class Lines(Widget, can_focus=True):
    count = 0

    def render_line(self, y):
        text = f"line {y}" + (f": pressed {self.count} times" if y == 5 else "")
        return Strip([Segment(text.ljust(self.size.width))], self.size.width)


class TrivialApp(App):
    BINDINGS = [("n", "bump(1)", "Next"), ("p", "bump(-1)", "Prev"), ("m", "all", "All"),
                ("f", "first", "First lines")]
    FIRST = 1  # lines that f redraws

    def compose(self):
        yield Lines()

    def action_bump(self, d):
        lines = self.query_one(Lines)
        lines.count += d
        lines.refresh(Region(0, 5, lines.size.width, 1))

    def action_first(self):  # the same change, and the first FIRST lines repainted
        lines = self.query_one(Lines)
        lines.count += 1
        lines.refresh(Region(0, 0, lines.size.width, self.FIRST))

    def action_all(self):  # the same change, but the whole widget is repainted
        lines = self.query_one(Lines)
        lines.count += 1
        lines.refresh()


if __name__ == "__main__":
    TrivialApp().run()
'''


def trivial_app_class():
    namespace: dict = {"__name__": "trivial_app"}
    exec(compile(TRIVIAL_APP, "<trivial app>", "exec"), namespace)  # noqa: S102 -- our text
    return namespace["TrivialApp"]


def search_app_class():
    """SearchApp, or None with the reason (the app may not be written yet)."""
    try:
        from tui_search.tui.app import SearchApp
    except Exception as exc:  # noqa: BLE001 -- any failure means "no app to measure"
        return None, f"app not available ({type(exc).__name__}: {exc})"
    return SearchApp, ""


def app_run(app) -> Run | None:
    """The app's current Run (``App.run`` is Textual's method, so the app calls it
    ``search_run``)."""
    run = getattr(app, "search_run", None)
    if run is None:
        run = getattr(app, "run_", None)
    return run


async def settle(pilot) -> None:
    """Let every queued message be handled (twice: a handler may post more), then repaint
    now -- what ``pilot.pause()`` does, without its idle-detection sleeps (>= 20 ms each),
    which would swamp a millisecond step."""
    await pilot._wait_for_screen()
    await pilot._wait_for_screen()
    pilot.app.screen._on_timer_update()


async def fast_press(pilot, key: str) -> None:
    from textual import events

    pilot.app.post_message(events.Key(key, key if len(key) == 1 else None))
    await settle(pilot)


# -- 2. jump to the end ------------------------------------------------------------------------
async def _jump_once(app_cls, grid: Grid) -> tuple[float, int]:
    app = app_cls(grid.copy(), algorithm="bfs")
    async with app.run_test(size=TERMINAL) as pilot:
        await pilot.pause()
        gc.collect()
        t0 = time.perf_counter()
        await fast_press(pilot, "end")
        # Poll without forcing repaints (pilot.pause() would repaint every poll, which the
        # app's own screen-update timer does not): the app paints as it would in a terminal.
        while True:
            run = app_run(app)
            if run is not None and run.at_end:
                break
            await asyncio.sleep(0.01)
            if time.perf_counter() - t0 > 120:
                raise TimeoutError("end did not reach the end in 120 s")
        await settle(pilot)  # the final screen, painted
        return time.perf_counter() - t0, app_run(app).k


def bench_jump(quick: bool) -> None:
    print("jump ...", file=sys.stderr, flush=True)
    app_cls, why = search_app_class()
    if app_cls is None:
        add(Row("jump", "end on maze512 / 1024²", "skipped", why))
        return
    cases = []
    maze = maze_grid()
    if maze is not None:
        cases.append(("maze512", maze, 0.5))
    cases.append((f"open {OPEN_SIZE}²", open_grid(), 2.0))
    for name, grid, limit in cases:
        times, k = [], 0
        for _ in range(2 if quick else 3):
            dt, k = asyncio.run(_jump_once(app_cls, grid))
            times.append(dt)
        series(f"jump {name}", times)
        add(Row("jump", f"{name} BFS: press end → final screen ({k:,} steps)", fmt_time(times),
                f"limit {limit} s", med(times) / limit, f"≤ {limit} s", med(times) <= limit))


# -- 3. one step, and playback -----------------------------------------------------------------
class DrawnLines:
    """Counts the lines Textual draws afresh (each one a widget's line with its border and
    padding: ``StylesCache.render_line``; a line left unchanged comes from its cache), while
    in a ``with`` block."""

    def __enter__(self) -> DrawnLines:
        from textual._styles_cache import StylesCache

        self.count, self._cls = 0, StylesCache
        self._original = original = StylesCache.render_line

        def counted(*args, **kwargs):
            self.count += 1
            return original(*args, **kwargs)

        StylesCache.render_line = counted  # type: ignore[method-assign]
        return self

    def __exit__(self, *exc) -> None:
        self._cls.render_line = self._original  # type: ignore[method-assign]


async def _presses(app, keys: list[str], warmup: int = 20
                   ) -> tuple[list[float], float, float, float]:
    """Pressing ``keys`` in turn: the wall time of each press (key to repainted screen), the
    CPU seconds per press, the CPU seconds of the same waiting and repainting with no key
    (the Pilot's own cost, which grows with the number of widgets), and the lines drawn per
    press (counted in a second, untimed pass over the same keys: the keys go forwards and
    back, so it replays the same steps)."""
    async with app.run_test(size=TERMINAL) as pilot:
        await pilot.pause()
        for i in range(warmup):
            await fast_press(pilot, keys[i % len(keys)])
        walls = []
        gc.collect()
        cpu = time.process_time()
        for key in keys:
            t = time.perf_counter()
            await fast_press(pilot, key)
            walls.append(time.perf_counter() - t)
        cpu = (time.process_time() - cpu) / len(keys)
        idle = time.process_time()
        for _ in keys:
            await settle(pilot)
        idle = (time.process_time() - idle) / len(keys)
        with DrawnLines() as drawn:
            for key in keys:
                await fast_press(pilot, key)
        return walls, cpu, idle, drawn.count / len(keys)


def step_keys(n: int) -> list[str]:
    """n presses: forwards n/2 steps, then back again (so every press moves)."""
    return ["n"] * (n // 2) + ["p"] * (n // 2)


async def _playback(app_cls, grid: Grid, seconds: float) -> tuple[float, int]:
    from tui_search.tui import playback

    app = app_cls(grid.copy(), algorithm="bfs")
    async with app.run_test(size=TERMINAL) as pilot:
        await pilot.pause()
        for _ in range(len(playback.SPEEDS)):
            await fast_press(pilot, "plus")
        run = app_run(app)
        run.advance()  # record first: measure playing, not recording
        k0 = run.k
        t0 = time.perf_counter()
        await fast_press(pilot, "space")
        while time.perf_counter() - t0 < seconds and not run.at_end:
            await asyncio.sleep(0.05)
        dt = time.perf_counter() - t0
        k = run.k
        await fast_press(pilot, "space")
        return (k - k0) / dt, playback.SPEEDS[app.speed_index]


def bench_step(quick: bool) -> None:
    print("step ...", file=sys.stderr, flush=True)
    app_cls, why = search_app_class()
    trivial = trivial_app_class()
    n = 100 if quick else 200
    reps = 3 if quick else 5
    names = ("trivial", "trivial-full", "trivial-same", "tutorial", "maze")
    results: dict[str, list[tuple[list[float], float, float, float]]] = {k: [] for k in names}
    tutorial = maze = None
    if app_cls is not None:
        from tui_search.engine.mapfile import load_map

        tutorial = load_map(TUTORIAL)
        maze = maze_grid()
    # The trivial app redrawing as many lines as a maze512 step draws: Textual's cost of
    # drawing that many lines in one plain widget (counted first, in an untimed run of the
    # same presses).
    same = trivial_app_class()
    if maze is not None:
        same.FIRST = max(1, round(asyncio.run(_presses(app_cls(maze.copy()), step_keys(n)))[3]))
    for _ in range(reps):  # interleave the apps
        results["trivial"].append(asyncio.run(_presses(trivial(), step_keys(n))))
        results["trivial-full"].append(asyncio.run(_presses(trivial(), ["m"] * n)))
        results["trivial-same"].append(asyncio.run(_presses(same(), ["f"] * n)))
        if app_cls is not None:
            # the tutorial run has 22 steps: go 8 forwards and back again, over and over
            results["tutorial"].append(asyncio.run(_presses(
                app_cls(tutorial.copy()), step_keys(16) * (n // 16))))
            if maze is not None:
                results["maze"].append(asyncio.run(_presses(app_cls(maze.copy()), step_keys(n))))

    def per_press(name: str) -> tuple[list[float], list[float], list[float]]:
        """Per repeat: median wall time per press, net CPU per press (minus the Pilot's own
        waiting), gross CPU per press."""
        wall = series(f"step {name} wall", [med(w) for w, _, _, _ in results[name]])
        net = series(f"step {name} cpu", [c - i for _, c, i, _ in results[name]])
        gross = [c for _, c, _, _ in results[name]]
        return wall, net, gross

    def drawn(name: str) -> float:
        """Lines drawn afresh per press (the same in every repeat)."""
        return med([lines for _, _, _, lines in results[name]])

    def cpu_text(net: list[float], gross: list[float]) -> str:
        return f"{fmt_time(net)} (gross {fmt_time(med(gross))})"

    tw, tc, tg = per_press("trivial")
    add(Row("step", "trivial Textual app: key → 1 line redrawn (CPU per press, net of Pilot)",
            cpu_text(tc, tg), f"wall {fmt_time(tw)}", None, "baseline"))
    _, fc, fg = per_press("trivial-full")
    _, sc, sg = per_press("trivial-same")
    add(Row("step", f"trivial Textual app: key → whole {TERMINAL[1]}-line screen redrawn",
            cpu_text(fc, fg), f"1 line {fmt_time(tc)}", paired(fc, tc), "report"))
    if app_cls is None:
        add(Row("step", "n/p on maze512 and the tutorial map", "skipped", why))
        return
    uw, uc, ug = per_press("tutorial")
    add(Row("step", "n/p on tutorial 6×6 vs trivial app (CPU per press, net of Pilot)",
            cpu_text(uc, ug), f"trivial {fmt_time(tc)}", paired(uc, tc), "report"))
    if maze is not None:
        mw, mc, mg = per_press("maze")
        r = paired(mc, tc)
        add(Row("step", "n/p on maze512 vs trivial app (CPU per press, net of Pilot)",
                cpu_text(mc, mg), f"trivial {fmt_time(tc)}", r, "≤ 3", r <= 3))
        r = paired(mc, uc)
        add(Row("step", "n/p on maze512 vs tutorial 6×6 (CPU per press, net of Pilot)",
                cpu_text(mc, mg), f"tutorial {fmt_time(uc)}", r, "≤ 1.5", r <= 1.5))
        add(Row("step", "n/p on maze512 vs trivial app (median wall per press)", fmt_time(mw),
                f"trivial {fmt_time(tw)}", paired(mw, tw), "report (≤ 3)"))
        add(Row("step", "n/p on maze512 vs tutorial 6×6 (median wall per press)", fmt_time(mw),
                f"tutorial {fmt_time(uw)}", paired(mw, uw), "report (≤ 1.5)"))
        lines = {name: drawn(name) for name in names}
        add(Row("step", f"trivial Textual app: key → {same.FIRST} lines redrawn (as many as a "
                "maze512 step draws)", cpu_text(sc, sg), f"1 line {fmt_time(tc)}",
                paired(sc, tc), "report"))
        r = paired(mc, sc)
        add(Row("step", f"n/p on maze512 vs trivial app redrawing the same {same.FIRST} lines",
                cpu_text(mc, mg), f"trivial {fmt_time(sc)}", r, "report"))
        add(Row("step", "lines drawn afresh per press: trivial 1-line / whole screen / as many as "
                "maze512 / tutorial / maze512", " / ".join(f"{lines[k]:.1f}" for k in names), "",
                None, "report"))
        per_line = [(m / lines["maze"]) / (u / lines["tutorial"]) for m, u in zip(mc, uc)]
        add(Row("step", "n/p on maze512 vs tutorial 6×6, CPU per line drawn",
                f"{med(mc) / lines['maze'] * 1e6:.0f} µs/line",
                f"tutorial {med(uc) / lines['tutorial'] * 1e6:.0f} µs/line", med(per_line),
                "report (≤ 1.5)"))
        per_line = [(m / lines["maze"]) / (f / lines["trivial-full"]) for m, f in zip(mc, fc)]
        add(Row("step", "n/p on maze512: CPU per line drawn vs the trivial app's whole-screen "
                "redraw", f"{med(mc) / lines['maze'] * 1e6:.0f} µs/line",
                f"{med(fc) / lines['trivial-full'] * 1e6:.0f} µs/line", med(per_line),
                "report"))
    grid = open_grid()
    rate, speed = asyncio.run(_playback(app_cls, grid, 1.5 if quick else 3.0))
    add(Row("step", f"playback (space) at the top speed ({speed:,}/s) on open {OPEN_SIZE}², "
            "steps/s", f"{rate:,.0f} steps/s", "", None, "report"))


# -- 4. start-up -------------------------------------------------------------------------------
def first_frame(argv: list[str], timeout: float = 60.0) -> float:
    """Seconds from starting ``argv`` in a pseudo-terminal of TERMINAL size to the moment its
    first full frame has been written: Textual writes a full frame line by line, each after a
    cursor move, so the move to the last row marks the frame's end.  The process is killed
    after (it is ours; by its pid)."""
    import fcntl
    import struct
    import termios

    cols, rows = TERMINAL
    master, slave = os.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", rows, cols, 0, 0))
    env = {k: v for k, v in os.environ.items() if not k.startswith("TEXTUAL")}
    env.update(TERM="xterm-256color", COLORTERM="truecolor", COLUMNS=str(cols), LINES=str(rows))
    marker = f"\x1b[{rows};1H".encode()
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv, stdin=slave, stdout=slave, stderr=slave, env=env,
                            start_new_session=True, close_fds=True)
    os.close(slave)
    buf = b""
    try:
        while True:
            left = timeout - (time.perf_counter() - t0)
            if left <= 0:
                raise TimeoutError(f"no frame from {argv} in {timeout} s")
            ready, _, _ = select.select([master], [], [], left)
            if not ready:
                continue
            try:
                chunk = os.read(master, 65536)
            except OSError:  # the child closed the terminal: it died
                chunk = b""
            if not chunk:
                last = buf.decode("utf-8", "replace").strip().splitlines()[-1:] or ["no output"]
                raise RuntimeError(f"{Path(argv[-1]).name}: exited before a frame: {last[0]}")
            buf += chunk
            if marker in buf:
                return time.perf_counter() - t0
    finally:
        proc.kill()
        try:  # drain so the child is not blocked writing while it dies
            while select.select([master], [], [], 0.05)[0] and os.read(master, 65536):
                pass
        except OSError:
            pass
        proc.wait()
        os.close(master)


def wall_of(argv: list[str]) -> float:
    t = time.perf_counter()
    subprocess.run(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - t


def cli_argv() -> list[str]:
    script = Path(sys.executable).parent / "tui-search"
    return [str(script)] if script.exists() else [sys.executable, "-m", "tui_search"]


def bench_startup(quick: bool) -> None:
    print("startup ...", file=sys.stderr, flush=True)
    reps = 5 if quick else 11
    py = sys.executable
    cli = cli_argv()
    # What a user's second start finds: the package's bytecode cached. (An editable install
    # writes no .pyc until the first import, and with PYTHONDONTWRITEBYTECODE set -- as on
    # the machines this was written on -- never: every start would compile ~20 ms of source.)
    compileall.compile_dir(Path(tui_search.__file__).parent, quiet=1)
    # the headless CLI: must not import Textual; compared with python -c pass
    imp = subprocess.run([py, "-X", "importtime", "-m", "tui_search", str(TUTORIAL),
                          "--headless"], capture_output=True, text=True, check=False)
    heavy = sorted({ln.split("|")[-1].strip().split(".")[0] for ln in imp.stderr.splitlines()
                    if ln.split("|")[-1].strip().split(".")[0] in ("textual", "rich")})
    t = interleaved({"pass": lambda: wall_of([py, "-c", "pass"]),
                     "headless": lambda: wall_of(cli + [str(TUTORIAL), "--headless"])}, reps)
    series("python -c pass", t["pass"])
    series("headless", t["headless"])
    add(Row("startup", "tui-search tutorial.txt --headless imports textual/rich",
            ", ".join(heavy) or "neither", "", None, "neither", not heavy))
    add(Row("startup", "tui-search tutorial.txt --headless (whole process) vs python -c pass",
            fmt_time(t["headless"]), f"pass {fmt_time(t['pass'])}",
            paired(t["headless"], t["pass"]), "report"))

    app_cls, why = search_app_class()
    with tempfile.TemporaryDirectory() as tmp:
        trivial = Path(tmp) / "trivial_app.py"
        trivial.write_text(TRIVIAL_APP)
        fns = {"trivial": lambda: first_frame([py, str(trivial)])}
        if app_cls is not None:
            fns["tutorial"] = lambda: first_frame(cli + [str(TUTORIAL)])
            if (MAPS / MAZE).exists():
                fns["maze"] = lambda: first_frame(cli + maze_cli_args())
        first_frame([py, str(trivial)])  # warm the file cache and the .pyc files
        t = interleaved(fns, reps)
    for key, xs in t.items():
        series(f"first frame {key}", xs)
    base = t["trivial"]
    add(Row("startup", "trivial Textual app: process start → first frame (pty)", fmt_time(base),
            "", None, "report"))
    if app_cls is None:
        add(Row("startup", "tui-search first frame", "skipped", why))
        return
    r = paired(t["tutorial"], base)
    add(Row("startup", "tui-search maps/tutorial.txt → first frame vs trivial app",
            fmt_time(t["tutorial"]), f"trivial {fmt_time(base)}", r, "≤ 1.3", r <= 1.3))
    if "maze" in t:
        r = paired(t["maze"], base)
        add(Row("startup", "tui-search maze512 (+.scen) → first frame vs trivial app",
                fmt_time(t["maze"]), f"trivial {fmt_time(base)}", r, "≤ 2", r <= 2))


# -- main --------------------------------------------------------------------------------------
def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="about a minute: fewer repeats")
    ap.add_argument("--only", default=",".join(SECTIONS),
                    help=f"comma-separated sections (default: {','.join(SECTIONS)})")
    args = ap.parse_args(argv)
    chosen = [s.strip() for s in args.only.split(",") if s.strip()]
    bad = [s for s in chosen if s not in SECTIONS]
    if bad:
        ap.error(f"unknown section {bad[0]!r}")
    t0 = time.perf_counter()
    for name in SECTIONS:
        if name in chosen:
            try:
                globals()[f"bench_{name}"](args.quick)
            except Exception as exc:  # noqa: BLE001 -- the app is young: report, go on
                import traceback

                traceback.print_exc()
                add(Row(name, "section failed", f"{type(exc).__name__}: {exc}"[:100]))
    print()
    print(f"tui-search benchmarks ({'quick' if args.quick else 'full'}; Python "
          f"{sys.version.split()[0]}; {os.cpu_count()} CPUs; load average "
          f"{', '.join(f'{x:.2f}' for x in os.getloadavg())})")
    print_table(ROWS)
    if NOISE:
        worst = max(NOISE, key=lambda x: x[1])
        print(f"noise: median spread of the timed series {med([s for _, s in NOISE]) * 100:.0f}%, "
              f"worst {worst[1] * 100:.0f}% ({worst[0]}); spread = (max - min) / median")
    print(f"took {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
