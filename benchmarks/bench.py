#!/usr/bin/env python
"""tui-search against its targets (GitHub issues 4, 9 and 10), as ratios measured in one process.

    python benchmarks/bench.py            # the full run (a few minutes)
    python benchmarks/bench.py --quick    # a few minutes: fewer repeats, no networkx
    python benchmarks/bench.py --only engine,step

Every figure is compared with a baseline measured in the same run (a bare Python BFS, the
``pathfinding`` package, a trivial Textual app, ``python -c pass``), because absolute times on a
shared machine mean little.  Each figure is the median of several repeats, interleaved with its
baseline's; the "±" after a time is the spread of the repeats, (max - min) / median.

The peers (``pip install -e .[bench]``: pathfinding, networkx, scipy) are optional: a missing one
gives a "not installed" row.  See benchmarks/README.md for what each row means.

This file is the entry point only: each section lives in its own module of this package
(core.py, fallback.py, engine.py, choices.py, informed.py, jump.py, step.py, startup.py,
instructions.py, class_load.py, terrain.py, big_map.py, diagnose.py, graphs.py,
weighted.py, bidirectional.py), on the shared
table.py,
harness.py and
maps.py.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
# Run as a script, this folder is sys.path[0]: drop it so that its modules are imported only
# as ``benchmarks.*`` (a module named step or engine must not shadow another package's), and
# put the checkout first so it runs without installing.
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != HERE]
sys.path.insert(0, str(ROOT))

from benchmarks.bidirectional import bench_bidirectional
from benchmarks.big_map import bench_big_map
from benchmarks.choices import bench_choices
from benchmarks.class_load import bench_class_load
from benchmarks.compare import bench_compare
from benchmarks.core import bench_core
from benchmarks.diagnose import bench_diagnose
from benchmarks.engine import bench_engine
from benchmarks.fallback import bench_fallback
from benchmarks.graphs import bench_graph
from benchmarks.harness import NOISE, med
from benchmarks.informed import bench_informed
from benchmarks.instructions import bench_instructions
from benchmarks.jump import bench_jump
from benchmarks.startup import bench_startup
from benchmarks.step import bench_step
from benchmarks.table import ROWS, Row, add, print_table
from benchmarks.terrain import bench_terrain
from benchmarks.weighted import bench_weighted

#: The sections, in the order they run and print.
SECTIONS = {"core": bench_core, "fallback": bench_fallback, "engine": bench_engine,
            "choices": bench_choices, "informed": bench_informed, "jump": bench_jump,
            "step": bench_step, "compare": bench_compare, "startup": bench_startup,
            "instructions": bench_instructions, "class_load": bench_class_load,
            "terrain": bench_terrain, "big_map": bench_big_map, "diagnose": bench_diagnose,
            "graph": bench_graph, "weighted": bench_weighted,
            "bidirectional": bench_bidirectional}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="fewer repeats, networkx skipped")
    ap.add_argument("--only", default=",".join(SECTIONS),
                    help=f"comma-separated sections (default: {','.join(SECTIONS)})")
    args = ap.parse_args(argv)
    chosen = [s.strip() for s in args.only.split(",") if s.strip()]
    bad = [s for s in chosen if s not in SECTIONS]
    if bad:
        ap.error(f"unknown section {bad[0]!r}")
    t0 = time.perf_counter()
    for name, bench in SECTIONS.items():
        if name in chosen:
            try:
                bench(args.quick)
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
