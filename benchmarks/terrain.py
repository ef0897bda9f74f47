"""Section "terrain" (issue 22): searches that weigh costs on a map with terrain against the
same searches on the same map with every cell costing 1.

UCS and A* on maze512 (its ``.scen`` row 3, corners never), recorded to the end (``Run(...)``
and ``advance()``, set-up included) on the core in use, once with seeded random costs 1-9 on
every free cell and once without costs, beside the same pair run by the C floor
(``benchmarks/floor.c``, which weighs costs as the compiled core does), all four interleaved in
CPU time: a target below the floor's ratio says so; the run's set-up alone (``Run(...)``, which
the floor makes before its time), on the map as it is (its padded walls and costs shared by
every run of it: ``Grid.derived``) and right after an edit (padded again, its costs copied);
and the record's bytes an expansion, which terrain does not
change (a cost is read from the map, never stored per event).
"""

from __future__ import annotations

import random
import sys
from array import array
from functools import partial

from benchmarks.core import MAZE_ROW, NEVER, floor_search, maze_row, recorded
from benchmarks.harness import CPU, fmt_time, interleaved, paired, series
from benchmarks.maps import MAPS, MAZE
from benchmarks.table import Row, add
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.loops import compiled


def with_random_costs(grid: Grid, seed: int = 22) -> Grid:
    """A copy of ``grid`` whose free cells cost 1 to 9, at random (seeded)."""
    rng = random.Random(seed)
    costed = grid.copy()
    costed.costs = array("d", (float(rng.randint(1, 9)) for _ in range(len(grid.blocked))))
    return costed


def _edited_run(grid: Grid, cell: tuple[int, int], key: str) -> Run:
    """A run right after an edit (a cost painted again): nothing worked out is shared."""
    grid.set_cost(cell, grid.cost(cell))
    return Run(grid, key, NEVER)


def bench_terrain(quick: bool) -> None:
    print("terrain ...", file=sys.stderr, flush=True)
    plain = maze_row()
    if plain is None:
        add(Row("terrain", MAZE, "skipped", f"not found in {MAPS}"))
        return
    costed = with_random_costs(plain)
    core = compiled.core_name()
    repeats = 3 if quick else 7
    for key in ("ucs", "astar"):
        steps = {name: recorded(g, key, NEVER).recorded
                 for name, g in (("plain", plain), ("costed", costed))}
        floors = {name: floor_search(g, key, NEVER) for name, g in (("plain", plain),
                                                                    ("costed", costed))}
        edited = costed.copy()
        cell = next((x, y) for y in range(edited.height) for x in range(edited.width)
                    if edited.is_free((x, y)))
        t = interleaved({"plain": lambda k=key: recorded(plain, k, NEVER),
                         "costed": lambda k=key: recorded(costed, k, NEVER),
                         "floor plain": floors["plain"], "floor costed": floors["costed"],
                         "set-up plain": partial(Run, plain, key, NEVER),
                         "set-up costed": partial(Run, costed, key, NEVER),
                         "set-up edited": partial(_edited_run, edited, cell, key)},
                        repeats, CPU)
        for what, xs in t.items():
            series(f"terrain maze512 {key} {what}", xs)
        # The floor first: what terrain costs the least loop that weighs it (the same searches,
        # the same steps), so a ratio over the target that the floor shares is no fault of
        # the engine's.
        floor = paired(t["floor costed"], t["floor plain"])
        add(Row("terrain", f"maze512 row {MAZE_ROW}, corners never, {key.upper()} C floor with "
                f"costs 1-9 vs all 1 (the floor of the row below); a step "
                f"{floor * steps['plain'] / steps['costed']:.2f}x",
                fmt_time(t["floor costed"]), f"all 1 {fmt_time(t['floor plain'])}", floor,
                "report"))
        # The floor's set-up is made before its time; a run's is in it: the grid copied (its
        # costs and padded arrays shared while the map is not edited) and the first chunk.
        # After an edit the costs are copied and padded again (2 MB each on maze512).
        add(Row("terrain", f"maze512 {key.upper()} set-up (Run(): the grid copied, the first "
                f"4,096 steps recorded), costs 1-9 vs all 1", fmt_time(t["set-up costed"]),
                f"all 1 {fmt_time(t['set-up plain'])}",
                paired(t["set-up costed"], t["set-up plain"]), "report"))
        add(Row("terrain", f"maze512 {key.upper()} set-up right after an edit (its costs "
                f"copied and padded again), costs 1-9 vs all 1", fmt_time(t["set-up edited"]),
                f"all 1 {fmt_time(t['set-up plain'])}",
                paired(t["set-up edited"], t["set-up plain"]), "report"))
        r = paired(t["costed"], t["plain"])
        per_step = r * steps["plain"] / steps["costed"]  # the searches differ in length
        add(Row("terrain", f"maze512 row {MAZE_ROW}, corners never, {key.upper()} with costs "
                f"1-9 ({steps['costed']:,} steps) vs all 1 ({steps['plain']:,}), {core}; "
                f"a step {per_step:.2f}x",
                fmt_time(t["costed"]), f"all 1 {fmt_time(t['plain'])}", r, "≤ 1.2", r <= 1.2,
                floor=floor))
        recs = {name: recording_of(recorded(g, key, NEVER)).rec
                for name, g in (("plain", plain), ("costed", costed))}
        size = {name: rec.nbytes() / rec.steps for name, rec in recs.items()}
        add(Row("terrain", f"maze512 {key.upper()} record, bytes an expansion, costs 1-9",
                f"{size['costed']:.2f} B", f"all 1 {size['plain']:.2f} B",
                size["costed"] / size["plain"], "≤ 1", size["costed"] <= size["plain"] * 1.0001))
