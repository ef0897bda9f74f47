"""Section "fallback" (issue 26): the Python search core against the engine before the
compiled core, and against the compiled core.

A machine without a C compiler runs the Python loops (``TUI_SEARCH_CORE=python``); they must
stay within 1.5x of the engine as it was before the compiled core (git ``7b34bba``, the
package extracted from this repository's history into a temporary folder: no history, no
row).  Each engine runs the core section's recorded runs and the re-run after an edit in a
process of its own (CPU seconds, measured inside it), the engines in turn, a repeat at a
time.  The compiled core's figures come from the same kind of process.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
from io import BytesIO
from pathlib import Path

from benchmarks.harness import fmt_time, med, paired, series
from benchmarks.maps import ROOT
from benchmarks.table import Row, add

#: The last commit before the compiled core: "today's engine" of issue 26.
BEFORE_CORE = "7b34bba"

#: The cases, by name: (map, algorithm).  The open 4096² BFS row is left out (a minute a run
#: in Python).
CASES = [("maze512 row 3, corners never", "bfs"), ("maze512 row 3, corners never", "dfs"),
         ("maze512 row 3, corners never", "astar"), ("maze512 row 3, corners never", "ucs"),
         ("open 1024²", "bfs"), ("open 1024²", "dfs"), ("open 1024²", "astar"),
         ("open 1024²", "ucs"), ("open 1024²", "edit")]

#: What a probe process runs: each case once, its CPU seconds printed as JSON, after the same
#: search on a small map (untimed: the first call's imports and caches).  ``edit`` is the
#: re-run after an edit (a wall toggled, BFS recorded and moved to its end).
PROBE = r"""
import json, sys, time
sys.path[:0] = [sys.argv[1], sys.argv[2]]
from benchmarks.baselines import walled_in
from benchmarks.maps import MAPS, MAZE, MAZE_SCEN, open_grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run
from tui_search.engine.maps.scenarios import load_scenario
from tui_search.engine.search.choices import Semantics

def grid_of(name):
    if name == "open 1024²":
        return open_grid(), Semantics()
    scen = load_scenario(MAPS / MAZE_SCEN, 3)
    return load_map(MAPS / MAZE, start=scen.start, goal=scen.goal), Semantics(corners="never")

def rerun(grid, sem):
    run = Run(grid, "bfs", sem)
    run.advance()
    run.goto(run.total)

out = {}
for name, key in json.loads(sys.argv[3]):
    grid, sem = grid_of(name)
    if key == "edit":
        rerun(open_grid(64), sem)
        grid.set_blocked((512, 512), True)
        t = time.process_time()
        rerun(grid, sem)
    else:
        g = walled_in(grid) if key == "dfs" else grid
        Run(open_grid(64), key, sem).advance()
        t = time.process_time()
        Run(g, key, sem).advance()
    out[f"{name} {key}"] = time.process_time() - t
print(json.dumps(out))
"""


def old_engine() -> Path | None:
    """The package as it was at BEFORE_CORE, extracted into a temporary folder (None: no
    git history here)."""
    try:
        tar = subprocess.run(["git", "-C", str(ROOT), "archive", BEFORE_CORE, "tui_search"],
                             capture_output=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    folder = Path(tempfile.mkdtemp(prefix="tui-search-before-core-"))
    with tarfile.open(fileobj=BytesIO(tar)) as archive:
        safe = {"filter": "data"} if hasattr(tarfile, "data_filter") else {}
        archive.extractall(folder, **safe)  # type: ignore[arg-type]
    return folder


def probe(engine: Path, core: str | None, cases: list[tuple[str, str]]) -> dict[str, float]:
    """Each case's CPU seconds in a new process on ``engine`` (a folder holding tui_search)
    with ``TUI_SEARCH_CORE`` set to ``core`` (unset: None)."""
    env = {k: v for k, v in os.environ.items() if k != "TUI_SEARCH_CORE"}
    if core is not None:
        env["TUI_SEARCH_CORE"] = core
    done = subprocess.run([sys.executable, "-c", PROBE, str(engine), str(ROOT), json.dumps(cases)],
                          capture_output=True, text=True, env=env, check=True)
    result: dict[str, float] = json.loads(done.stdout)
    return result


def bench_fallback(quick: bool) -> None:
    print("fallback ...", file=sys.stderr, flush=True)
    from benchmarks.maps import MAPS, MAZE

    cases = [c for c in CASES if (MAPS / MAZE).exists() or not c[0].startswith("maze")]
    before = old_engine()
    engines = {"python": (ROOT, "python"), "compiled": (ROOT, None)}
    if before is None:
        add(Row("fallback", f"the engine before the compiled core ({BEFORE_CORE})", "skipped",
                "no git history here"))
    else:
        engines["before"] = (before, None)
    times: dict[str, dict[str, list[float]]] = {name: {} for name in engines}
    for _ in range(2 if quick else 3):
        for name, (engine, core) in engines.items():
            for case, seconds in probe(engine, core, cases).items():
                times[name].setdefault(case, []).append(seconds)
    if before is not None:
        shutil.rmtree(before, ignore_errors=True)
    for case in times["python"]:
        python, compiled = times["python"][case], times["compiled"][case]
        series(f"fallback {case} python", python)
        label = case.replace(" edit", " re-run after an edit (BFS to its end)")
        if before is not None:
            old = series(f"fallback {case} before", times["before"][case])
            r = paired(python, old)
            add(Row("fallback", f"{label}: Python core vs the engine before the compiled core",
                    fmt_time(python), f"before {fmt_time(old)}", r, "≤ 1.5", r <= 1.5))
        add(Row("fallback", f"{label}: Python core vs compiled core", fmt_time(python),
                f"compiled {fmt_time(compiled)}", med(python) / med(compiled), "report"))
    _reference_alone(times, "before" if before is not None else "python")


def _reference_alone(times: dict[str, dict[str, list[float]]], base: str) -> None:
    """Is the reference loop alone a good enough fallback (issue 26: then the Python fast loops
    retire)?  It runs each maze512 case to its end in this process, iterating its steps and
    keeping no record (less than a fallback would have to do), against ``base``'s recorded
    runs: the engine before the compiled core, within 1.5x of which a fallback must stay."""
    from benchmarks.baselines import walled_in
    from benchmarks.core import maze_row
    from tui_search.engine.search.choices import Semantics
    from tui_search.engine.search.reference import ReferenceSearch
    from tui_search.engine.search.registry import get_algorithm

    grid = maze_row()
    if grid is None:
        return
    sem = Semantics(corners="never")
    for key in ("bfs", "dfs", "astar", "ucs"):
        case = f"maze512 row 3, corners never {key}"
        if case not in times[base]:
            continue
        g = walled_in(grid) if key == "dfs" else grid
        t = time.process_time()
        steps = sum(1 for _ in ReferenceSearch(g, get_algorithm(key), sem))
        ref = time.process_time() - t
        r = ref / med(times[base][case])
        against = "the engine before the compiled core" if base == "before" else "the Python core"
        add(Row("fallback", f"maze512 {key.upper()} ({steps:,} steps): the reference loop alone, "
                f"no record, vs {against}",
                fmt_time(ref), f"{base} {fmt_time(times[base][case])}", r,
                "report: ≤ 1.5 retires the fast loops"))
