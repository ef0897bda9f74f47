"""Section "weighted" (issue 38): weighted A* with w = 2 on maze512 and the MovingAI sets --
its path's cost over the row's optimum (the ``.scen``'s optimal length, corners never, as the
optima check, ``benchmarks/optima.py``, takes it) must stay at most 2, measured in one run.

A spread of rows of every ``.scen`` of the maps folder (the optima check runs every row, about
five CPU-hours: too long for a benchmark run), evenly spaced from the first to the last, so the
longest paths of each file are among them: ``ROWS`` a file (``QUICK_ROWS`` with ``--quick``).
Each row runs A* (w = 1), weighted A* (w = 2, re-opening a cell reached cheaper, the app's
default) and weighted A* with a closed set (``--reopen no``, as published weighted A* keeps
one: the bound holds too) recorded to the end on the core in use (``Run(...).outcome()``; the
closed set on the reference-recording loop); the rows report, a file each, the largest ratio
and the mean, A*'s own misses of the optimum (none expected: the optima check), and, over all
the rows, what the weight costs or saves: nodes expanded and CPU time over A*'s.  Re-opening
is the catch: W·h overestimates, so weighted A* reaches expanded cells more cheaply and
expands them again -- on the room maps many times over.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Iterator
from pathlib import Path

from benchmarks.core import NEVER
from benchmarks.maps import MAPS
from benchmarks.table import Row, add
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.scenarios import Scenario
from tui_search.engine.run.recorded import Run

#: Rows a ``.scen`` file (evenly spaced, its last included), and with ``--quick``.
ROWS, QUICK_ROWS = 24, 6
#: The weight measured, and the bound it promises.
WEIGHT = 2.0


def _spread(n: int, count: int) -> list[int]:
    """``count`` row indices of ``n``, evenly spaced from the first to the last."""
    if n <= count:
        return list(range(n))
    return sorted({round(i * (n - 1) / (count - 1)) for i in range(count)})


def _scen_maps() -> Iterator[tuple[Path, list[Scenario], Grid]]:
    """Each ``.scen`` of the maps folder with its rows and its map (those with no rows or no
    map left out)."""
    from tui_search.engine.maps.load import load_map
    from tui_search.engine.maps.scenarios import read_scenarios

    for scen_path in sorted(MAPS.glob("*.scen")):
        rows = read_scenarios(scen_path)
        if not rows:
            continue
        map_path = scen_path.parent / rows[0].map_name.rsplit("/", 1)[-1]
        if map_path.exists():
            yield scen_path, rows, load_map(map_path)


def bench_weighted(quick: bool) -> None:
    print("weighted ...", file=sys.stderr, flush=True)
    scens = sorted(MAPS.glob("*.scen"))
    if not scens:
        add(Row("weighted", "weighted A* w=2 / the optimum", "skipped", f"no .scen in {MAPS}"))
        return
    heavy = NEVER.replace(weight=WEIGHT)
    closed = heavy.replace(reopen=False)  # a closed set: published weighted A*'s
    runs = {"w=1": NEVER, "w=2": heavy, "w=2 closed": closed}
    expanded = dict.fromkeys(runs, 0)
    cpu = dict.fromkeys(runs, 0.0)
    worst_all, rows_all = 1.0, 0
    for scen_path, rows, base in _scen_maps():
        ratios: list[float] = []
        closed_ratios: list[float] = []
        misses = 0
        for i in _spread(len(rows), QUICK_ROWS if quick else ROWS):
            scen = rows[i]
            if scen.optimal_length <= 0:
                continue
            grid = base.copy()
            grid.start, grid.goal = scen.start, scen.goal
            outcomes = {}
            for name, sem in runs.items():
                t0 = time.process_time()
                outcome = Run(grid, "astar", sem).outcome()
                cpu[name] += time.process_time() - t0
                expanded[name] += outcome.expanded
                outcomes[name] = outcome
            plain = outcomes["w=1"]
            if plain.cost is None or not math.isclose(plain.cost, scen.optimal_length,
                                                      rel_tol=1e-4):
                misses += 1
            ratios.append((outcomes["w=2"].cost or math.inf) / scen.optimal_length)
            closed_ratios.append((outcomes["w=2 closed"].cost or math.inf)
                                 / scen.optimal_length)
        if not ratios:
            continue
        worst = max(ratios + closed_ratios)
        worst_all, rows_all = max(worst_all, worst), rows_all + len(ratios)
        add(Row("weighted", f"{scen_path.name}: w=2 cost / optimum, {len(ratios)} rows",
                f"max {max(ratios):.4f}, mean {sum(ratios) / len(ratios):.4f}; closed set "
                f"max {max(closed_ratios):.4f}",
                f"A* w=1 missed the optimum on {misses}", worst, f"≤ {WEIGHT:g}",
                worst <= WEIGHT * (1 + 1e-9) and misses == 0))
    add(Row("weighted", f"every file: w=2 cost / optimum, {rows_all} rows",
            f"max {worst_all:.4f}", "", worst_all, f"≤ {WEIGHT:g}",
            worst_all <= WEIGHT * (1 + 1e-9)))
    for name in ("w=2", "w=2 closed"):  # over A* (w=1), the same rows
        if expanded["w=1"]:
            add(Row("weighted", f"nodes expanded, {name} / w=1", f"{expanded[name]:,}",
                    f"{expanded['w=1']:,}", expanded[name] / expanded["w=1"]))
        if cpu["w=1"] > 0:
            add(Row("weighted", f"CPU time recorded to the end, {name} / w=1",
                    f"{cpu[name]:.2f} s", f"{cpu['w=1']:.2f} s", cpu[name] / cpu["w=1"]))


def every_row(step: int = 1) -> bool:
    """Weighted A* (w = 2, re-opening: the app's default) on every row of every ``.scen``
    (``step``: one row in ``step``), its cost over the row's optimum: the issue's check "on
    every scenario of the optima check".  Only w = 2 runs (the ``.scen`` gives the optimum;
    the optima check holds A* to it), recorded on the core in use.  Prints a line a file and
    the total; True when every ratio is at most 2."""
    heavy = NEVER.replace(weight=WEIGHT)
    worst_all, rows_all, cpu_all = 1.0, 0, 0.0
    for scen_path, rows, base in _scen_maps():
        worst, count, t0 = 1.0, 0, time.process_time()
        for scen in rows[::step]:
            if scen.optimal_length <= 0:
                continue
            grid = base.copy()
            grid.start, grid.goal = scen.start, scen.goal
            cost = Run(grid, "astar", heavy).outcome().cost
            worst, count = max(worst, (cost or math.inf) / scen.optimal_length), count + 1
        cpu = time.process_time() - t0
        worst_all, rows_all, cpu_all = max(worst_all, worst), rows_all + count, cpu_all + cpu
        print(f"{scen_path.name}: {count} rows, w=2 cost / optimum max {worst:.4f} "
              f"({cpu:.1f} s CPU)", flush=True)
    ok = worst_all <= WEIGHT * (1 + 1e-9)
    print(f"every file: {rows_all} rows, max {worst_all:.4f} (bound {WEIGHT:g}): "
          f"{'within' if ok else 'OVER'}; {cpu_all:.0f} s CPU")
    return ok


if __name__ == "__main__":  # python -m benchmarks.weighted [--every N]
    args = sys.argv[1:]
    sys.exit(0 if every_row(int(args[1]) if args[:1] == ["--every"] else 1) else 1)
