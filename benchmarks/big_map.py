"""Section "big_map" (issues 21 and 42): the largest files the readers take, each read in a
process of its own, its peak memory (``ru_maxrss``, from ``os.wait4``) against the file's size,
and its CPU time.

- The grading loop's: ``tui-search FILE --headless --exercise 1`` on 64 MB of ``.\\n`` rows (32
  million one-cell rows) and of ``..\\n`` rows (21 million two-cell rows), neither with a
  start, so the answer is "no start 'S' in the map".  The baseline is the floor: a Python
  process that only reads the file and decodes it, as any reader must.
- A search's: ``--headless --max-steps 1`` on 64 MB of one-cell rows from ``S`` to ``G`` (once
  9.6 GB, a slice object a row), beside a square map of the same size.
- The app's: ``tui-search FILE`` refuses both by size (over ``APP_MAX_CELLS``, in one line,
  within ten times the file); the app built on them anyway, to its first frame (its run's
  counters are per cell: the one-cell rows may cost more than the square only by their
  border cells).
- Every other reader of big files on its heaviest file at its cap: a trace of short lines, a
  map whose every row is read on its own (a comment between rows), a MovingAI map of
  one-cell rows, a scenario file of blank lines.  (The readers of small files, exercise
  files, lessons and terrain tables, are measured by tests/engine/test_untrusted_files.py:
  at 64 KB a process's resident size is too coarse to tell.)
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

from benchmarks.table import Row, add

_READ_ONLY = "import sys; open(sys.argv[1], 'rb').read().decode('utf-8')"
#: The app run to its first frame on the map named, and ended.
_APP_FRAME = """
import asyncio, sys
from pathlib import Path
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
async def main():
    app = SearchApp(load_map(sys.argv[1]), path=Path(sys.argv[1]))
    async with app.run_test(size=(100, 32)) as pilot:
        await pilot.pause()
asyncio.run(main())
"""
#: A reader, given its module, function and how it is called on the file ``p``.
_READ_WITH = """
import sys
from tui_search.engine.maps.read import MapError
p = sys.argv[1]
{imports}
try:
    {call}
except MapError as err:
    print(err)
"""
MB = 1024 * 1024
#: Each reader: its name, what it imports, how it reads ``p``, its cap and its heaviest file
#: of ``n`` bytes.
READERS: list[tuple[str, str, str, int, Callable[[int], str]]] = [
    ("trace of short lines", "from tui_search.engine.traces.read import load_trace\n"
     "from tui_search.engine.maps.load import load_map",
     "load_trace(p, load_map('maps/exercise2-dfs-longer.txt'))", 64 * MB,
     lambda n: '{"node":[1,1]}\n' * (n // 15)),
    ("text map, a comment between rows", "from tui_search.engine.maps.load import load_map",
     "load_map(p)", 64 * MB, lambda n: "S\n" + ".\n; c\n" * (n // 6 - 1) + "G\n"),
    ("MovingAI map of one-cell rows", "from tui_search.engine.maps.load import load_map",
     "load_map(p)", 64 * MB,
     lambda n: f"type octile\nheight {n // 2 - 20}\nwidth 1\nmap\n" + ".\n" * (n // 2 - 20)),
    ("scenario file of blank lines", "from tui_search.engine.maps.scenarios import "
     "load_scenario", "load_scenario(p, 0)", 16 * MB, lambda n: "version 1\n" + "\n" * (n - 20)),
]


#: Runs ``-m MODULE ARGS`` or ``-c CODE ARGS`` as Python would, and at its exit writes its
#: own peak resident size (``VmHWM``, in KB) to the file ``$PEAK_FILE``.  A child's
#: ``ru_maxrss`` is no use here: a child started by ``vfork`` takes on the parent's peak
#: (this process's, which wrote 64 MB strings), so every command would seem to need as much.
_MEASURED = """
import atexit, os, runpy, sys
def said():
    with open("/proc/self/status") as status, open(os.environ["PEAK_FILE"], "w") as out:
        out.write(next(line.split()[1] for line in status if line.startswith("VmHWM:")))
atexit.register(said)
how, what, *sys.argv[1:] = sys.argv[1:]
if how == "-m":
    sys.argv[0] = what
    runpy.run_module(what, run_name="__main__", alter_sys=True)
else:
    sys.argv[0] = "-c"
    exec(compile(what, "<string>", "exec"), {"__name__": "__main__"})
"""


def _peak(argv: list[str]) -> tuple[float, float]:
    """Peak resident memory (bytes) and CPU seconds (user + system) of the command
    ``[python, "-m" or "-c", ...]``."""
    with tempfile.NamedTemporaryFile("r") as said:
        proc = subprocess.Popen([argv[0], "-c", _MEASURED, *argv[1:]],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                env={**os.environ, "PEAK_FILE": said.name})
        _, _, usage = os.wait4(proc.pid, 0)
        proc.returncode = 0  # reaped by wait4
        peak = said.read().strip()
    if not peak.isdigit():
        raise RuntimeError(f"{argv[1:3]} did not run to its end")
    return int(peak) * 1024.0, usage.ru_utime + usage.ru_stime


def _grading(tmp: str) -> None:
    app = [sys.executable, "-m", "tui_search"]
    for row, count in ((".\n", 32_000_000), ("..\n", 21_000_000)):
        path = Path(tmp, "big.txt")
        path.write_text(row * count)
        size = path.stat().st_size
        peak, cpu = _peak([*app, str(path), "--headless", "--exercise", "1"])
        floor, floor_cpu = _peak([sys.executable, "-c", _READ_ONLY, str(path)])
        ratio = peak / size
        add(Row("big_map", f"{size / 1e6:.0f} MB of {row!r} rows, --headless --exercise 1: "
                f"peak memory / file size ({cpu:.1f} s CPU; reading alone {floor_cpu:.1f} s)",
                f"{peak / 1e6:.0f} MB", f"read+decode {floor / 1e6:.0f} MB", ratio,
                "≤ 10", ratio <= 10, floor=floor / size))
        path.unlink()


def _one_column_and_square(tmp: str, quick: bool) -> None:
    """The one-cell rows from S to G and a square map as big: searched (one step), and in the
    app (its first frame)."""
    rows = 8_000_000 if quick else 32_000_000
    side = int((2 * rows) ** 0.5)
    column, square = Path(tmp, "column.txt"), Path(tmp, "square.txt")
    column.write_text("S\n" + ".\n" * (rows - 2) + "G\n")
    lines = ["." * side] * side
    lines[0], lines[-1] = "S" + "." * (side - 1), "." * (side - 1) + "G"
    square.write_text("\n".join(lines) + "\n")
    searched = [sys.executable, "-m", "tui_search", "--headless", "--max-steps", "1"]
    ratios = {}
    for path, what in ((column, "one-cell rows from S to G"), (square, "a square map")):
        size = path.stat().st_size
        peak, cpu = _peak([*searched, str(path)])
        ratio = peak / size
        add(Row("big_map", f"{size / 1e6:.0f} MB, {what}, --headless --max-steps 1: peak memory "
                f"/ file size ({cpu:.1f} s CPU)", f"{peak / 1e6:.0f} MB", "the file", ratio,
                "≤ 10", ratio <= 10))
        peak, cpu = _peak([sys.executable, "-m", "tui_search", str(path)])
        ratio = peak / size  # refused by size (over APP_MAX_CELLS): read, then one line
        add(Row("big_map", f"{size / 1e6:.0f} MB, {what}, `tui-search FILE` (the app refuses "
                f"it by size): peak memory / file size ({cpu:.1f} s CPU)",
                f"{peak / 1e6:.0f} MB", "the file", ratio, "≤ 10", ratio <= 10))
        peak, cpu = _peak([sys.executable, "-c", _APP_FRAME, str(path)])
        ratios[what] = peak / size
        add(Row("big_map", f"{size / 1e6:.0f} MB, {what}, the app's first frame: peak memory / "
                f"file size ({cpu:.1f} s CPU)", f"{peak / 1e6:.0f} MB", "the file",
                peak / size, "report", None))
    ratio = ratios["one-cell rows from S to G"] / ratios["a square map"]
    add(Row("big_map", "the app on one-cell rows against a square map as big: memory / file "
            "size, one over the other (the border cells a row: 1.5 at most)",
            f"{ratio:.2f}", "the square map", ratio, "≤ 1.5", ratio <= 1.5))
    column.unlink()
    square.unlink()


def _readers(tmp: str, quick: bool) -> None:
    for name, imports, call, cap, heaviest in READERS:
        path = Path(tmp, "heavy")
        path.write_text(heaviest((cap // 4 if quick else cap) - 1000))
        size = path.stat().st_size
        script = _READ_WITH.format(imports=imports, call=call)
        peak, cpu = _peak([sys.executable, "-c", script, str(path)])
        base, _ = _peak([sys.executable, "-c", script, os.devnull])
        ratio = (peak - base) / size
        add(Row("big_map", f"{name}, {size / MB:.2f} MiB (its limit {cap / MB:.2f} MiB): memory "
                f"beyond the reader's own (peak less an empty file's) / file size ({cpu:.1f} s "
                "CPU)",
                f"{(peak - base) / 1e6:.1f} MB", "the file", ratio, "≤ 10", ratio <= 10))
        path.unlink()


def bench_big_map(quick: bool) -> None:
    print("big_map ...", file=sys.stderr, flush=True)
    root = Path(__file__).resolve().parents[1]
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.getcwd()
        os.chdir(root)  # (the trace's map is the repository's)
        try:
            _grading(tmp)
            _one_column_and_square(tmp, quick)
            _readers(tmp, quick)
        finally:
            os.chdir(cwd)
