"""Section "startup": the console script to its first frame (against the trivial app, by
path) and ``--headless`` (against ``python -c pass``, and importing neither textual nor rich)."""

from __future__ import annotations

import compileall
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import tui_search
from benchmarks.apps import TERMINAL, search_app_class
from benchmarks.harness import fmt_time, interleaved, paired, series
from benchmarks.maps import MAPS, MAZE, TUTORIAL, maze_cli_args
from benchmarks.pty_probe import first_frame, first_frame_times
from benchmarks.table import Row, add

#: The trivial Textual app, run by path as a user runs a script.
TRIVIAL_APP = Path(__file__).resolve().with_name("trivial_app.py")


def wall_of(argv: list[str]) -> float:
    t = time.perf_counter()
    subprocess.run(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - t


def cli_argv() -> list[str]:
    script = Path(sys.executable).parent / "tui-search"
    return [str(script)] if script.exists() else [sys.executable, "-m", "tui_search"]


def screen_widgets(argv: list[str]) -> int:
    """How many widgets the app's first screen has for the command line ``argv`` (hidden ones
    included: they are composed and styled too), counted under ``run_test`` at TERMINAL size:
    the widget count of the trivial app that is that screen's floor."""
    import asyncio

    from tui_search.cli.main import build_app
    from tui_search.cli.parse import parse_options

    app = build_app(parse_options(argv))

    async def count() -> int:
        async with app.run_test(size=TERMINAL) as pilot:
            await pilot.pause()
            return len(list(app.screen.walk_children()))

    return asyncio.run(count())


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
    cpu: dict[str, list[float]] = {}  # each start's CPU seconds, beside its wall time

    def probe(key: str, argv: list[str], env: dict[str, str] | None = None
              ) -> Callable[[], float]:
        def start() -> float:
            wall, used = first_frame_times(argv, env=env)
            cpu.setdefault(key, []).append(used)
            return wall
        return start

    fns = {"trivial": probe("trivial", [py, str(TRIVIAL_APP)])}
    widgets: dict[str, int] = {}
    if app_cls is not None:
        # the floors: the trivial app with as many bordered line-API widgets as the screen
        widgets = {"tutorial": screen_widgets([str(TUTORIAL)]),
                   "compare": screen_widgets([str(TUTORIAL), "--compare", "bfs,dfs"])}
        for key, n in widgets.items():
            fns[f"floor-{key}"] = probe(f"floor-{key}", [py, str(TRIVIAL_APP), str(n)])
        fns["tutorial"] = probe("tutorial", cli + [str(TUTORIAL)])
        # issue 26: the first frame is the same whichever search core runs
        fns["tutorial-python"] = probe("tutorial-python", cli + [str(TUTORIAL)],
                                       {"TUI_SEARCH_CORE": "python"})
        fns["compare"] = probe("compare", cli + [str(TUTORIAL), "--compare", "bfs,dfs"])
        if (MAPS / MAZE).exists():
            fns["maze"] = probe("maze", cli + maze_cli_args())
    first_frame([py, str(TRIVIAL_APP)])  # warm the file cache and the .pyc files
    t = interleaved(fns, reps)
    cpu = {key: xs[1:] for key, xs in cpu.items()}  # interleaved's first, untimed call dropped
    for key, xs in t.items():
        series(f"first frame {key}", xs)
        series(f"first frame {key} (CPU)", cpu[key])
    base = t["trivial"]
    add(Row("startup", "trivial Textual app: process start → first frame (pty)", fmt_time(base),
            "", None, "report"))
    if app_cls is None:
        add(Row("startup", "tui-search first frame", "skipped", why))
        return

    def against_trivial(key: str, what: str, limit: float) -> None:
        """The row of ``key``'s first frame against the trivial app's, and its CPU row; the
        rows of its floor (``floor-key``), and whether ``limit`` is below that floor."""
        n = widgets[key]
        floor = {label: paired(times[f"floor-{key}"], times["trivial"])
                 for times, label in ((t, "wall"), (cpu, "CPU"))}
        cpu_label = "… its CPU time to the first frame vs the trivial app's"
        for times, label, kind in ((t, what, "wall"), (cpu, cpu_label, "CPU")):
            r = paired(times[key], times["trivial"])
            add(Row("startup", label, fmt_time(times[key]), f"trivial {fmt_time(times['trivial'])}",
                    r, f"≤ {limit}", r <= limit, floor=floor[kind]))
        for times, kind in ((t, "wall"), (cpu, "CPU")):
            add(Row("startup", f"… its floor, {kind}: the trivial app with {n} bordered widgets "
                    f"(the screen's count) → first frame", fmt_time(times[f"floor-{key}"]),
                    f"trivial {fmt_time(times['trivial'])}", floor[kind], "report"))
        add(Row("startup", f"… is its target ≤ {limit} below the floor (CPU)?",
                "yes" if floor["CPU"] > limit else "no", f"floor {floor['CPU']:.2f}",
                floor["CPU"] / limit, "report"))

    against_trivial("tutorial", "tui-search maps/tutorial.txt → first frame vs trivial app", 1.4)
    for times, what in ((t, ""), (cpu, ", CPU time")):
        r = paired(times["tutorial"], times["tutorial-python"])
        add(Row("startup", f"tui-search maps/tutorial.txt → first frame{what}: compiled core vs "
                "Python core", fmt_time(times["tutorial"]),
                f"Python core {fmt_time(times['tutorial-python'])}", r, "report"))
    r = paired(t["compare"], t["tutorial"])
    add(Row("startup", "tui-search --compare bfs,dfs vs tui-search (one search) → first frame",
            fmt_time(t["compare"]), f"one search {fmt_time(t['tutorial'])}", r, "report"))
    against_trivial("compare", "tui-search maps/tutorial.txt --compare bfs,dfs → first frame "
                    "vs trivial", 1.6)
    if "maze" in t:
        r = paired(t["maze"], base)
        add(Row("startup", "tui-search maze512 (+.scen) → first frame vs trivial app",
                fmt_time(t["maze"]), f"trivial {fmt_time(base)}", r, "≤ 2", r <= 2))
