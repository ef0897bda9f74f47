"""Section "instructions": the first frame counted in instructions (callgrind), against the
trivial app's.  Unlike the timed "startup" rows, which move by ±0.2 on a shared machine with no
change at all, a count is the same from run to run (within ~0.01 %) whatever the load: the
figure to trust for the start-up targets.

Each program runs once under ``valgrind --tool=callgrind`` in a pseudo-terminal of TERMINAL
size, to its first frame (:mod:`benchmarks.frame_exit` ends it there), with
``PYTHONHASHSEED=0`` (the hash seed changes the order of sets, and so the count, by ~0.5 %).
Without valgrind the rows say so.  Each takes 15-30 s.
"""

from __future__ import annotations

import compileall
import os
import re
import select
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import tui_search
from benchmarks.apps import TERMINAL
from benchmarks.maps import MAPS, MAZE, TUTORIAL, maze_cli_args
from benchmarks.table import Row, add

FRAME_EXIT = Path(__file__).resolve().with_name("frame_exit.py")
#: The cases: the arguments of tui-search, and the target against the trivial app.
CASES = {
    "tutorial": ([str(TUTORIAL)], 1.4),
    "compare": ([str(TUTORIAL), "--compare", "bfs,dfs"], 1.6),
}


def run_in_pty(argv: list[str], env: dict[str, str], timeout: float = 600.0) -> int:
    """Run ``argv`` in a pseudo-terminal of TERMINAL size to its end (its output read and
    dropped); its exit status."""
    import fcntl
    import struct
    import termios

    cols, rows = TERMINAL
    master, slave = os.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", rows, cols, 0, 0))
    proc = subprocess.Popen(argv, stdin=slave, stdout=slave, stderr=slave, env=env,
                            start_new_session=True, close_fds=True)
    os.close(slave)
    try:
        while select.select([master], [], [], timeout)[0]:
            try:
                if not os.read(master, 65536):
                    break
            except OSError:  # the child closed the terminal
                break
        else:
            proc.kill()
        return proc.wait()
    finally:
        os.close(master)


def instructions(program: list[str]) -> int | str:
    """Instructions ``frame_exit.py program`` runs to its first frame, or why not counted."""
    cols, rows = TERMINAL
    env = {k: v for k, v in os.environ.items() if not k.startswith("TEXTUAL")}
    env.update(TERM="xterm-256color", COLORTERM="truecolor", COLUMNS=str(cols),
               LINES=str(rows), PYTHONHASHSEED="0")
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "callgrind.log"
        status = run_in_pty(["valgrind", "--tool=callgrind", f"--log-file={log}",
                             f"--callgrind-out-file={Path(tmp) / 'callgrind.out'}",
                             sys.executable, str(FRAME_EXIT), *program], env)
        text = log.read_text(encoding="utf-8", errors="replace") if log.exists() else ""
    found = re.search(r"I\s+refs:\s+([\d,]+)", text)
    if status != 0 or not found:
        return f"no count (exit {status})"
    return int(found.group(1).replace(",", ""))


def bench_instructions(quick: bool) -> None:
    print("instructions ...", file=sys.stderr, flush=True)
    if shutil.which("valgrind") is None:
        add(Row("instructions", "first frame, instructions (callgrind)", "skipped",
                "valgrind not found"))
        return
    # What a user's second start finds: the package's bytecode cached (as in "startup").
    compileall.compile_dir(Path(tui_search.__file__).parent, quiet=1)
    cases = dict(CASES)
    if not quick and (MAPS / MAZE).exists():
        cases["maze512"] = (maze_cli_args(), 2.0)
    base = instructions(["trivial"])
    add(Row("instructions", "trivial Textual app → first frame, instructions (callgrind)",
            f"{base:,}" if isinstance(base, int) else base, "", None, "report"))
    for key, (args, limit) in cases.items():
        count = instructions(["tui-search", *args])
        ratio = count / base if isinstance(count, int) and isinstance(base, int) else None
        add(Row("instructions", f"tui-search {key} → first frame, instructions vs the trivial "
                "app's", f"{count:,}" if isinstance(count, int) else count,
                f"trivial {base:,}" if isinstance(base, int) else "", ratio, f"≤ {limit}",
                None if ratio is None else ratio <= limit))
