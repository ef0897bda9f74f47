"""Section "big_map" (issue 21): the largest map a file may be (64 MB), read as the grading
loop over a folder reads it: ``tui-search FILE --headless --exercise 1`` in a process of its
own, its peak memory (``ru_maxrss``, from ``os.wait4``) against the file's size, and its CPU
time.

The two files are the issue's: 64 MB of ``.\\n`` rows (32 million one-cell rows) and of
``..\\n`` rows (21 million two-cell rows), neither with a start, so the answer is "no start
'S' in the map".  The baseline is the floor: a Python process that only reads the file and
decodes it, as any reader must.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

from benchmarks.table import Row, add

_READ_ONLY = "import sys; open(sys.argv[1], 'rb').read().decode('utf-8')"


def _peak(argv: list[str]) -> tuple[float, float]:
    """Peak resident memory (bytes) and CPU seconds (user + system) of the command."""
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(proc.pid, 0)
    proc.returncode = 0  # reaped by wait4
    return usage.ru_maxrss * 1024.0, usage.ru_utime + usage.ru_stime


def bench_big_map(quick: bool) -> None:
    print("big_map ...", file=sys.stderr, flush=True)
    app = [sys.executable, "-m", "tui_search"]
    with tempfile.TemporaryDirectory() as tmp:
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
