"""Timing a real process to its first full frame in a pseudo-terminal (POSIX only)."""

from __future__ import annotations

import os
import select
import subprocess
import time
from pathlib import Path

from benchmarks.apps import TERMINAL


def first_frame(argv: list[str], timeout: float = 60.0) -> float:
    """Seconds from starting ``argv`` in a pseudo-terminal of TERMINAL size to the moment its
    first full frame has been written: Textual writes a full frame line by line, each after a
    cursor move, so the move to the last row marks the frame's end.  The process is killed
    after (it is ours; by its pid)."""
    return first_frame_times(argv, timeout)[0]


def first_frame_times(argv: list[str], timeout: float = 60.0,
                      env: dict[str, str] | None = None) -> tuple[float, float]:
    """``first_frame``'s seconds, and the CPU seconds (user + system) the process had used when
    it was killed just after that frame: on a shared machine with more runnable processes than
    CPUs the wall clock also counts the waits for a CPU, the CPU time does not.  ``env``: more
    environment variables for the process."""
    import fcntl
    import struct
    import termios

    cols, rows = TERMINAL
    master, slave = os.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", rows, cols, 0, 0))
    extra, env = env or {}, {k: v for k, v in os.environ.items() if not k.startswith("TEXTUAL")}
    env.update(extra)
    env.update(TERM="xterm-256color", COLORTERM="truecolor", COLUMNS=str(cols), LINES=str(rows))
    marker = f"\x1b[{rows};1H".encode()
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv, stdin=slave, stdout=slave, stderr=slave, env=env,
                            start_new_session=True, close_fds=True)
    os.close(slave)
    buf = b""
    try:
        while True:
            left = timeout - (time.perf_counter() - t0)
            if left <= 0:
                raise TimeoutError(f"no frame from {argv} in {timeout} s")
            ready, _, _ = select.select([master], [], [], left)
            if not ready:
                continue
            try:
                chunk = os.read(master, 65536)
            except OSError:  # the child closed the terminal: it died
                chunk = b""
            if not chunk:
                last = buf.decode("utf-8", "replace").strip().splitlines()[-1:] or ["no output"]
                raise RuntimeError(f"{Path(argv[-1]).name}: exited before a frame: {last[0]}")
            buf += chunk
            if marker in buf:
                wall = time.perf_counter() - t0
                break
    finally:
        proc.kill()
        try:  # drain so the child is not blocked writing while it dies
            while select.select([master], [], [], 0.05)[0] and os.read(master, 65536):
                pass
        except OSError:
            pass
        _, _, usage = os.wait4(proc.pid, 0)
        proc.returncode = -9  # reaped here: Popen must not wait for it again
        os.close(master)
    return wall, usage.ru_utime + usage.ru_stime
