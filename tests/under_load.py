"""The test suite on a busy machine: ``python -m tests.under_load [--busy N] [pytest args]``.

Starts N CPU-bound processes (two unless ``--busy`` says otherwise, which must come first):
plain Python loops that stop on their own after an hour or when this runner is gone, and are
killed when the tests end.  Beside them it runs the project's test command, ``python -m pytest``
with the arguments given, then prints the wall time and the result.  Its exit code is
pytest's.  A test that sleeps a fixed time, or asserts before the state it checks has arrived,
fails here when it passes on an idle machine.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time

BUSY = 2
LIMIT = 3600.0  # seconds: a busy loop left behind (the runner killed) ends by itself

# Spins until LIMIT seconds have passed or its parent (this runner) is gone.
LOOP = f"""
import os, time
parent, end, n = os.getppid(), time.monotonic() + {LIMIT}, 0
while True:
    n += 1
    if n % 1_000_000 == 0 and (time.monotonic() > end or os.getppid() != parent):
        break
"""


def busy_processes(count: int) -> list[subprocess.Popen[bytes]]:
    return [subprocess.Popen([sys.executable, "-c", LOOP]) for _ in range(count)]


def stop(processes: list[subprocess.Popen[bytes]]) -> None:
    for process in processes:
        process.kill()
    for process in processes:
        process.wait()


def split_arguments(argv: list[str]) -> tuple[int, list[str]]:
    """(how many busy processes, pytest's arguments)."""
    if argv[:1] == ["--busy"] and len(argv) >= 2:
        return int(argv[1]), argv[2:]
    if argv[:1] and argv[0].startswith("--busy="):
        return int(argv[0].split("=", 1)[1]), argv[1:]
    return BUSY, argv


def main(argv: list[str]) -> int:
    count, pytest_args = split_arguments(argv)
    command = [sys.executable, "-m", "pytest", *pytest_args]
    busy = busy_processes(count)
    start = time.monotonic()
    try:
        code = subprocess.call(command)
    finally:
        elapsed = time.monotonic() - start
        stop(busy)
    verdict = "passed" if code == 0 else f"failed (pytest exit code {code})"
    print(f"under load ({count} busy processes on {os.cpu_count()} cores): "
          f"{verdict} in {elapsed:.0f} s", flush=True)
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
