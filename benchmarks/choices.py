"""Section "choices": the search choices of issue 9 against the bare BFS of the same map.

* a full DFS traversal (the goal walled in, so every reachable cell is expanded) under the
  default choices: ≤ 1.3x the bare BFS of the same walled-in map, beside its floor, a bare DFS
  of the same traversal;
* each non-default combination (visit on expand, goal test on expand, corners never, a
  4-move order), for BFS (the map as it is) and DFS (walled in, a full traversal: a DFS that
  finds its goal early, as on the open map, would time almost nothing): ≤ 3x the bare BFS,
  with "visit on expand" beside its floor, a bare search that closes a cell when popped (it
  pushes a cell once per neighbour that reaches it first, so it does several times the work);
* tree search stops at its step limit with ``gave_up`` (exponential: no time target).

The two DFS rows have a second, *recorded* floor: the same bare DFS plus the least record of
its steps, the same arrays as the engine's (``bare_dfs_recorded``,
``bare_dfs_visit_on_expand_recorded``).  A target below its floor cannot be met by any
recording loop: the row says so, and its verdict reads "FAIL, target below the floor".  Times are
CPU seconds of this process (``harness.CPU``): the searches are single-threaded and CPU-bound, and
on a shared machine the wall clock also counts the waits for a CPU.
"""

from __future__ import annotations

import sys
from collections.abc import Callable

from benchmarks.baselines import (
    bare_bfs,
    bare_dfs,
    bare_dfs_recorded,
    bare_dfs_visit_on_expand_recorded,
    bare_path_len,
    bare_search_visit_on_expand,
    walled_in,
)
from benchmarks.harness import CPU, fmt_time, interleaved, paired, series, timed
from benchmarks.maps import big_maps
from benchmarks.table import Row, add
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics

#: The non-default combinations timed, by the name their rows print.
COMBINATIONS: dict[str, Semantics] = {
    "visit on expand": Semantics(visit="expand"),
    "goal test on expand": Semantics(goal_test="expand"),
    "corners never": Semantics(corners="never"),
    "moves N,W,S,E": Semantics(order=("N", "W", "S", "E")),
}
#: The tree-search check's step limit (BFS; DFS a hundredth of it).
TREE_LIMIT = 100_000


def recorded(grid: Grid, algorithm: str, semantics: Semantics = DEFAULT_SEMANTICS,
             max_steps: int | None = None) -> Run:
    run = Run(grid, algorithm, semantics) if max_steps is None else Run(
        grid, algorithm, semantics, max_steps)
    run.advance()
    return run


def contenders(grid: Grid, walled: Grid) -> dict[str, Callable[[], object]]:
    """Everything this section times on one map, to be interleaved: the baselines, the
    floors, the full DFS traversal and each combination (BFS on the map, DFS walled in)."""
    fns: dict[str, Callable[[], object]] = {
        "bare bfs": lambda: bare_bfs(grid),
        "bare bfs walled": lambda: bare_bfs(walled),
        "bare dfs walled": lambda: bare_dfs(walled),
        "bare bfs visit on expand": lambda: bare_search_visit_on_expand(grid),
        "bare dfs visit on expand walled": lambda: bare_search_visit_on_expand(walled, True),
        "bare dfs recorded walled": lambda: bare_dfs_recorded(walled),
        "bare dfs visit on expand recorded walled":
            lambda: bare_dfs_visit_on_expand_recorded(walled),
        "run dfs walled": lambda: recorded(walled, "dfs"),
    }
    for name, sem in COMBINATIONS.items():
        fns[f"run bfs {name}"] = lambda s=sem: recorded(grid, "bfs", s)
        fns[f"run dfs {name} walled"] = lambda s=sem: recorded(walled, "dfs", s)
    return fns


def check_answers(name: str, grid: Grid, walled: Grid) -> None:
    """The bare floors search what the engine does: the same path lengths (none, walled in),
    and the recorded floors record the same arrays."""
    pairs = [(grid, "bfs", Semantics(visit="expand"), bare_search_visit_on_expand(grid)),
             (walled, "dfs", Semantics(), bare_dfs(walled))]
    for g, algorithm, sem, parent in pairs:
        path = recorded(g, algorithm, sem).path()
        got, want = len(path) - 1 if path else -1, bare_path_len(g, parent)
        if got != want:
            print(f"WARNING: {name} {algorithm} {sem.differences()}: engine path {got} moves, "
                  f"bare {want}", file=sys.stderr)
    for floor, sem in ((bare_dfs_recorded, Semantics()),
                       (bare_dfs_visit_on_expand_recorded, Semantics(visit="expand"))):
        rec, bare = recording_of(recorded(walled, "dfs", sem)).rec, floor(walled)
        if (bare.gen_node, bare.step_end, bare.step_exp, bare.discarded) != (
                rec.gen_node, rec.step_end, rec.step_exp, rec.discarded):
            print(f"WARNING: {name} {floor.__name__}: not the engine's record", file=sys.stderr)


def floor_note(floor: float, limit: float) -> str:
    return f"; target below the floor ({floor:.2f})" if floor > limit else ""


#: What the recorded floors are, in their rows (README.md: "Floors").
RECORDED_FLOOR = "plus the least record of its steps, the engine's arrays"


def bench_map(name: str, grid: Grid, repeats: int) -> None:
    walled = walled_in(grid)
    check_answers(name, grid, walled)
    steps = recorded(walled, "dfs").recorded
    t = interleaved(contenders(grid, walled), repeats, CPU)
    for key, xs in t.items():
        series(f"{name} {key}", xs)
    base, base_w = t["bare bfs"], t["bare bfs walled"]

    # (b) the full DFS traversal, and its floors: a bare DFS of the same traversal, and the
    # same DFS recording what the engine records
    floor = paired(t["bare dfs walled"], base_w)
    add(Row("choices", f"{name} bare DFS, full traversal (goal walled in; the floor of the "
            "next rows, no record) vs bare BFS of the same map", fmt_time(t["bare dfs walled"]),
            f"bare BFS {fmt_time(base_w)}", floor, "report"))
    rec_floor = paired(t["bare dfs recorded walled"], base_w)
    add(Row("choices", f"{name} bare DFS {RECORDED_FLOOR}, full traversal (the recorded floor "
            "of the next row) vs bare BFS of the same map",
            fmt_time(t["bare dfs recorded walled"]), f"bare BFS {fmt_time(base_w)}", rec_floor,
            "report"))
    r = paired(t["run dfs walled"], base_w)
    add(Row("choices", f"{name} DFS recorded run, full traversal ({steps:,} expansions) vs bare "
            f"BFS of the same map (bare DFS {floor:.2f}, recorded floor {rec_floor:.2f}"
            f"{floor_note(rec_floor, 1.3)})",
            fmt_time(t["run dfs walled"]), f"bare BFS {fmt_time(base_w)}", r, "≤ 1.30",
            r <= 1.30, floor=rec_floor))

    # (c) every non-default combination, BFS on the map and DFS walled in
    floors = {"bfs": paired(t["bare bfs visit on expand"], base),
              "dfs": paired(t["bare dfs visit on expand walled"], base_w)}
    voe_floor = paired(t["bare dfs visit on expand recorded walled"], base_w)
    add(Row("choices", f"{name} bare BFS, visit on expand (the floor of that row) vs bare BFS",
            fmt_time(t["bare bfs visit on expand"]), f"bare BFS {fmt_time(base)}",
            floors["bfs"], "report"))
    add(Row("choices", f"{name} bare DFS, visit on expand, walled in (the floor of that row, no "
            "record) vs bare BFS of the same map", fmt_time(t["bare dfs visit on expand walled"]),
            f"bare BFS {fmt_time(base_w)}", floors["dfs"], "report"))
    add(Row("choices", f"{name} bare DFS, visit on expand, {RECORDED_FLOOR} and the discarded "
            "steps, walled in (the recorded floor of that row) vs bare BFS of the same map",
            fmt_time(t["bare dfs visit on expand recorded walled"]),
            f"bare BFS {fmt_time(base_w)}", voe_floor, "report"))
    for algorithm, suffix, b in (("bfs", "", base), ("dfs", " walled", base_w)):
        for combo in COMBINATIONS:
            xs = t[f"run {algorithm} {combo}{suffix}"]
            r = paired(xs, b)
            where = ", full traversal" if suffix else ""
            note, row_floor = "", None
            if combo == "visit on expand":
                row_floor = voe_floor if algorithm == "dfs" else floors[algorithm]
                recorded_part = f", recorded floor {voe_floor:.2f}" if algorithm == "dfs" else ""
                note = (f" (bare floor {floors[algorithm]:.2f}{recorded_part}"
                        f"{floor_note(row_floor, 3)})")
            add(Row("choices", f"{name} {algorithm.upper()} {combo}{where} vs bare BFS{note}",
                    fmt_time(xs), f"bare BFS {fmt_time(b)}", r, "≤ 3", r <= 3,
                    floor=row_floor))


def bench_tree(maps: list[tuple[str, Grid]]) -> None:
    """(d) Tree search is exponential: it must stop at the step limit, unfinished.  On the
    walled-in maps, so that no search ends by finding the goal first (on the tutorial map BFS
    finds it in 557 steps, DFS on the open map in 2,046).  DFS is far slower a step -- its path
    check walks a path as deep as the steps so far (open 1024²: 3.9 ms a step at 10,000
    steps) -- so a smaller limit."""
    for name, grid in ((name, walled_in(grid)) for name, grid in maps):
        for algorithm, limit in (("bfs", TREE_LIMIT), ("dfs", TREE_LIMIT // 100)):
            dt, run = timed(lambda a=algorithm, n=limit, g=grid: recorded(
                g, a, Semantics(tree_search=True), n), CPU)
            ok = run.gave_up and run.recorded == limit
            add(Row("choices", f"{name} walled in, {algorithm.upper()} tree search, max_steps "
                    f"{limit:,}: "
                    f"gave_up {run.gave_up}, {run.recorded:,} steps"
                    f"{', found' if run.found else ''}", fmt_time(dt),
                    f"{dt / run.recorded * 1e6:.0f} µs a step", None, "gave_up", ok))


def bench_choices(quick: bool) -> None:
    print("choices ...", file=sys.stderr, flush=True)
    maps = big_maps("choices")
    for name, grid in maps:
        bench_map(name, grid, 3 if quick else 5)
    bench_tree(maps)
