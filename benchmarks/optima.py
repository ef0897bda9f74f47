#!/usr/bin/env python
"""Every row of every MovingAI ``.scen``: uniform-cost search and A* (octile, euclidean,
chebyshev, zero) under no corner cutting must find the row's optimal length (to 1e-4,
relative).  Prints a line per file and the count; exit 1 when any row misses.

    python benchmarks/optima.py                     # every row of every .scen in the maps folder
    python benchmarks/optima.py --every 50          # one row in 50 (a quick look)
    python benchmarks/optima.py --only arena,den312d --searches astar:octile
    python benchmarks/optima.py --log optima.jsonl  # resumable: rows already in the log are
                                                    # not run again (the whole check is ~5
                                                    # CPU-hours)
    python benchmarks/optima.py --log optima.jsonl --reverse  # beside it: from the other end

The maps folder is ``TUI_SEARCH_MAPS`` (default ``/work/shared/maps/movingai``; the test suite
checks a spread of rows on the copies in ``tests/data/movingai``).  The rows run on every CPU
(one process each), each search on the recorded loop the app uses.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != HERE]
sys.path.insert(0, str(HERE.parent))

from benchmarks.maps import MAPS
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.scenarios import read_scenarios
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics

SEARCHES = ("ucs", "astar:octile", "astar:euclidean", "astar:chebyshev", "astar:zero")


def scen_files(folder: Path, only: list[str] | None) -> list[tuple[Path, Path]]:
    """(map, scen) pairs: each .scen with the map its rows name, in the same folder."""
    pairs = []
    for scen in sorted(folder.glob("*.scen")):
        rows = read_scenarios(scen)
        if not rows:
            continue
        map_path = folder / Path(rows[0].map_name).name
        if only and not any(name in scen.name for name in only):
            continue
        pairs.append((map_path, scen))
    return pairs


def check_rows(map_path: str, scen_path: str, indices: list[int], searches: tuple[str, ...]
               ) -> list[tuple[int, str, float, float | None]]:
    """The misses among ``indices``: (row, search, optimal, found cost or None)."""
    base = load_map(Path(map_path))
    rows = read_scenarios(scen_path)
    misses = []
    for i in indices:
        scen = rows[i]
        grid = base.copy()
        grid.start, grid.goal = scen.start, scen.goal
        for search in searches:
            key, _, heuristic = search.partition(":")
            sem = Semantics(corners="never", heuristic=heuristic or "octile")
            cost = Run(grid, key, sem).outcome().cost
            if cost is None or not math.isclose(cost, scen.optimal_length, rel_tol=1e-4):
                misses.append((i, search, scen.optimal_length, cost))
    return misses


#: Rows a worker checks before it reports: a killed run loses at most this many a worker.
BATCH = 20


def read_log(path: Path | None, searches: tuple[str, ...]) -> dict[str, dict[int, list]]:
    """What an earlier run with ``--log`` checked, by .scen name: row -> its misses.  Lines
    for other searches, and a line cut short by a kill, are ignored."""
    done: dict[str, dict[int, list]] = {}
    if path is None or not path.exists():
        return done
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            entry = json.loads(line)
        except ValueError:
            continue
        if tuple(entry.get("searches", ())) != searches:
            continue
        rows = done.setdefault(entry["scen"], {})
        for row in entry["rows"]:
            rows[row] = [tuple(m) for m in entry["misses"] if m[0] == row]
    return done


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--maps", type=Path, default=MAPS, help=f"the folder (default {MAPS})")
    ap.add_argument("--every", type=int, default=1, help="check one row in N (default: all)")
    ap.add_argument("--only", help="comma-separated parts of .scen names")
    ap.add_argument("--searches", default=",".join(SEARCHES),
                    help=f"comma-separated (default {','.join(SEARCHES)})")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--reverse", action="store_true",
                    help="check each file's rows from its last (a second run sharing the log "
                    "meets the first in the middle)")
    ap.add_argument("--log", type=Path, help="append each batch of rows checked to this file "
                    "(JSON lines), and skip the rows it already holds")
    args = ap.parse_args(argv)
    searches = tuple(s.strip() for s in args.searches.split(",") if s.strip())
    pairs = scen_files(args.maps, args.only.split(",") if args.only else None)
    if not pairs:
        print(f"no .scen files in {args.maps}", file=sys.stderr)
        return 2
    done = read_log(args.log, searches)
    log = args.log.open("a", encoding="utf-8") if args.log else None
    if log is not None and args.log.stat().st_size and not args.log.read_bytes().endswith(b"\n"):
        log.write("\n")  # a line cut by a kill ends here, not glued to the next
    t0 = time.perf_counter()
    total = missed = 0
    with ProcessPoolExecutor(max_workers=args.jobs) as pool:
        for map_path, scen in pairs:
            n = len(read_scenarios(scen))
            picked = list(range(0, n, max(1, args.every)))
            earlier = done.get(scen.name, {})
            todo = [i for i in picked if i not in earlier]
            if args.reverse:
                todo.reverse()
            t = time.perf_counter()
            batches = [todo[i:i + BATCH] for i in range(0, len(todo), BATCH)]
            futures = {pool.submit(check_rows, str(map_path), str(scen), b, searches): b
                       for b in batches}
            misses = [m for i in picked if i in earlier for m in earlier[i]]
            for future in as_completed(futures):
                found = future.result()
                misses += found
                if log is not None:
                    log.write(json.dumps({"scen": scen.name, "searches": list(searches),
                                          "rows": futures[future], "misses": found}) + "\n")
                    log.flush()
            checked = len(picked) * len(searches)
            total += checked
            missed += len(misses)
            resumed = f", {len(picked) - len(todo):,} rows from the log" if earlier else ""
            print(f"{scen.name}: {len(picked):,} of {n:,} rows x {len(searches)} searches: "
                  f"{checked - len(misses):,} optimal, {len(misses)} missed "
                  f"({time.perf_counter() - t:.0f} s{resumed})", flush=True)
            for row, search, want, got in sorted(misses)[:10]:
                print(f"  row {row} {search}: optimal {want}, found {got}")
    if log is not None:
        log.close()
    print(f"{total - missed:,} of {total:,} searches met the optimal length "
          f"({time.perf_counter() - t0:.0f} s)")
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
