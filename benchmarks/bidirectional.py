"""Section "bidirectional" (issue 38): bidirectional BFS against BFS on the open 1024² map
(start and goal at opposite corners, eight moves), in one run -- nodes expanded and CPU time.

Both run on the reference loop, streamed as ``--headless`` runs them (the bidirectional
searches have no faster loop: the app does not record them), so the CPU times compare the
same Python loop one way and both ways; BFS recorded on the core in use (``Run``) is printed
beside them as what the app's own BFS costs.  Bidirectional BFS runs under both stopping
rules: ``first-meeting`` stops at the first cell both searches reach, ``proven`` once the
two queues' front depths sum to the best meeting's moves.  The target: bidirectional BFS
expands fewer nodes than BFS (``proven`` included).  ``--quick``: 512².

    python benchmarks/bidirectional.py [--quick]
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from pathlib import Path

if __name__ == "__main__":  # run as a script: the checkout first, as bench.py does
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.maps import open_grid
from benchmarks.table import Row, add
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.reference import stream
from tui_search.engine.search.registry import get_algorithm

#: The map's side, and with ``--quick``.
SIDE, QUICK_SIDE = 1024, 512


def _timed(run: Callable[[], Outcome]) -> tuple[Outcome, float]:
    t0 = time.process_time()
    outcome = run()
    return outcome, time.process_time() - t0


def bench_bidirectional(quick: bool) -> None:
    print("bidirectional ...", file=sys.stderr, flush=True)
    side = QUICK_SIDE if quick else SIDE
    grid = open_grid(side)
    limit = side * side * 2
    sem = Semantics()
    bfs, bfs_cpu = _timed(lambda: stream(grid, get_algorithm("bfs"), sem, limit))
    runs = {stop: _timed(lambda stop=stop: stream(grid, get_algorithm("bibfs"),
                                                  sem.replace(stop=stop), limit))
            for stop in ("first-meeting", "proven")}
    recorded, recorded_cpu = _timed(lambda: Run(grid, "bfs", sem, limit).outcome())
    where = f"open {side}², corner to corner"
    add(Row("bidirectional", f"BFS on {where}: reference loop",
            f"{bfs.expanded:,} expanded, {bfs_cpu:.2f} s CPU, {bfs.length} moves"))
    add(Row("bidirectional", f"BFS on {where}: recorded, the core in use",
            f"{recorded.expanded:,} expanded, {recorded_cpu:.2f} s CPU"))
    for stop, (out, cpu) in runs.items():
        add(Row("bidirectional", f"bidirectional BFS ({stop}) / BFS: nodes expanded",
                f"{out.expanded:,} ({out.length} moves)", f"{bfs.expanded:,}",
                out.expanded / bfs.expanded, "< 1", out.expanded < bfs.expanded
                and out.length == bfs.length))
        add(Row("bidirectional", f"bidirectional BFS ({stop}) / BFS: CPU time, reference loop",
                f"{cpu:.2f} s", f"{bfs_cpu:.2f} s", cpu / bfs_cpu))


if __name__ == "__main__":
    from benchmarks.table import ROWS, print_table

    bench_bidirectional("--quick" in sys.argv[1:])
    print_table(ROWS)
