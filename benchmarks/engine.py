"""Section "engine": recording a whole search (``Run(grid, algo).advance()``) against the bare
BFS, the peers, and its memory per expansion."""

from __future__ import annotations

import gc
import sys
import tracemalloc
from collections.abc import Callable

from benchmarks.baselines import bare_bfs, bare_dfs, bare_path_len
from benchmarks.harness import fmt_time, interleaved, med, paired, series, timed
from benchmarks.maps import big_maps
from benchmarks.peers import networkx_bfs, pathfinding_bfs, scipy_bfs
from benchmarks.table import Row, add
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics


def recorded(grid: Grid, algorithm: str, semantics: Semantics = DEFAULT_SEMANTICS) -> Run:
    run = Run(grid, algorithm, semantics)
    run.advance()
    return run


def traced(fn: Callable[[], object]) -> tuple[int, int]:
    """(peak, retained) bytes allocated while ``fn`` runs, ``retained`` with its result alive
    once the interpreter's free lists are emptied.  (A heapq search leaves CPython's free list
    of 2,000 spare tuples full -- 144 KB of four-tuples -- which tracemalloc counts as
    allocated and any next tuple reuses: the interpreter's, not the result's.  The full
    collection empties the free lists; the peak is read before it.)"""
    gc.collect()
    tracemalloc.start()
    try:
        keep = fn()
        peak = tracemalloc.get_traced_memory()[1]
        gc.collect()
        retained = tracemalloc.get_traced_memory()[0]
    finally:
        tracemalloc.stop()
    del keep
    return peak, retained


def bench_memory(name: str, grid: Grid, algorithm: str, run: Run, section: str = "engine",
                 bare: Callable[[Grid], object] | None = None) -> None:
    """Bytes per expansion three ways: the record's arrays (``rec.nbytes``); what the recorded
    Run keeps; and its peak while recording.  The last two are tracemalloc figures minus the
    same for a Run on the same map with the goal on the start (no expansions), which holds
    everything map-sized: the grid copy, the padded walls, the closed set, the per-cell
    counters.  (The peak difference can come out below the record: both peaks include
    construction temporaries that the longer run has freed by its own peak.)

    The target is the recorded run's memory: the record and what the Run keeps.  The peak
    also holds the search's own frontier, which is the algorithm's and not the record's: a
    search that pushes five entries for each it expands peaks above 64 B an expansion however
    it records, so ``bare`` (the same search as a bare loop, measured the same way) gives the
    peak's floor beside it."""
    steps = run.recorded
    rec_b = recording_of(run).rec.nbytes() / steps
    trivial = grid.copy()
    trivial.goal = trivial.start
    sem = run.semantics
    map_peak, map_kept = traced(lambda: recorded(trivial, algorithm, sem))
    peak, kept = traced(lambda: recorded(grid, algorithm, sem))
    kept_b, peak_b = (kept - map_kept) / steps, (peak - map_peak) / steps
    floor = ""
    if bare is not None:
        bare_peak = traced(lambda: bare(grid))[0] - traced(lambda: bare(trivial))[0]
        floor = f"; bare loop's peak {bare_peak / steps:.1f} B"
    add(Row(section, f"{name} {run.algo.short} memory per expansion (rec.nbytes | kept | "
            "peak, above the map)", f"{rec_b:.1f} | {kept_b:.1f} | {peak_b:.1f} B",
            f"map-only Run {map_peak / 1e6:.1f} MB{floor}", None, "≤ 64 B (rec, kept)",
            max(rec_b, kept_b) <= 64))


def bench_engine(quick: bool) -> None:
    print("engine ...", file=sys.stderr, flush=True)
    maps = big_maps("engine")
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
                    f"({runs[a].recorded:,} expansions)", fmt_time(t[f"run {a}"]),
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
