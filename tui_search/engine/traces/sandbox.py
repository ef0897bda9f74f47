"""A student's ``search.py`` run in a separate, fenced process (``--check-search-py``).

:func:`run_student` makes a fresh working folder, copies the student's file into it with a
course-like ``util.py`` (:mod:`~tui_search.engine.traces.course_util`) and a ``game.py``
(``Directions``), writes the problem, and runs
:mod:`~tui_search.engine.traces.sandbox_child` as ``python -I`` with stdin closed, a fresh
session, a small environment, and a time limit after which the whole process group is killed.
Where ``unshare`` can make a user namespace (Linux), the child also runs in its own network
namespace (no network at all) and its own process namespace (every process it starts dies
with it).  The child sets its own memory, CPU and file limits and, on Linux with Landlock,
refuses writes outside the working folder (:func:`isolation` says what fenced a run).
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from tui_search.engine.util.frozen import Frozen

__all__ = ["DEFAULT_MEMORY_MB", "DEFAULT_SECONDS", "StudentRun", "isolation", "run_student",
           "unfenced"]

DEFAULT_SECONDS = 10.0
DEFAULT_MEMORY_MB = 512
#: The student's file is read at most this big (a search.py is a few KB).
MAX_STUDENT_BYTES = 1024 * 1024
_HERE = Path(__file__).resolve().parent
_UNSHARE = ("unshare", "--user", "--map-root-user", "--net", "--pid", "--fork", "--kill-child")
_GAME = ('"""Directions, as a student\'s search.py may import them (tui-search\'s sandbox)."""'
         "\n\n\nclass Directions:\n    NORTH = 'North'\n    SOUTH = 'South'\n"
         "    EAST = 'East'\n    WEST = 'West'\n    STOP = 'Stop'\n")
_namespaces: bool | None = None


def namespaces_work() -> bool:
    """Whether ``unshare`` makes a user, network and process namespace here (once asked)."""
    global _namespaces
    if _namespaces is None:
        _namespaces = False
        if sys.platform == "linux" and shutil.which("unshare"):
            try:
                done = subprocess.run([*_UNSHARE, "true"], stdin=subprocess.DEVNULL,
                                      capture_output=True, timeout=10, check=False)
                _namespaces = done.returncode == 0
            except (OSError, subprocess.SubprocessError):
                _namespaces = False
    return _namespaces


def isolation(landlock: int) -> str:
    """What fenced the student's process in, in words (``landlock``: its ABI, 0 none)."""
    parts = ["time, memory, CPU and file-size limits", "stdin closed"]
    if namespaces_work():
        parts.append("no network (its own network namespace)")
        parts.append("its processes killed with it (a process namespace)")
    elif landlock >= 4:
        parts.append("no TCP (Landlock)")
    parts.append("writes only in its working folder (Landlock)" if landlock
                 else "writes NOT fenced (no Landlock here)")
    return "; ".join(parts)


def unfenced(landlock: int) -> str | None:
    """One line when neither Landlock nor a network namespace fenced the run in (None when
    either did)."""
    if landlock or namespaces_work():
        return None
    return ("neither Landlock nor a network namespace was available here: the student's code "
            "ran with the network and could write wherever you can (see docs/14-cs188.md)")


class StudentRun(Frozen):
    """What the student's function did: ``status`` ``ok`` (it returned ``actions``) or
    ``error`` (``message``, at ``line`` and ``col`` of the student's file, 0 unknown;
    ``about`` what failed: ``function`` the function, ``file`` the file (it does not
    compile), ``missing`` the file has no such function); the states it asked the successors
    of, in order (as the problem gave them: JSON values); the Landlock ABI the child fenced
    itself with (0 none)."""

    __slots__ = _FIELDS = ("status", "message", "line", "expanded", "actions", "landlock",
                           "col", "about")

    status: str
    message: str
    line: int
    expanded: list[object]
    actions: list[str] | None
    landlock: int
    col: int
    about: str

    def __init__(self, status: str, message: str, line: int, expanded: list[object],
                 actions: list[str] | None, landlock: int, col: int = 0,
                 about: str = "function") -> None:
        self._assign(status=status, message=message, line=line, expanded=expanded,
                     actions=actions, landlock=landlock, col=col, about=about)


def run_student(student_text: str, problem: dict[str, object], seconds: float = DEFAULT_SECONDS,
                memory_mb: int = DEFAULT_MEMORY_MB) -> StudentRun:
    """Run ``problem['function']`` of the student's file (its text) on ``problem`` in the
    fenced child; its answer, or a one-line reason it gave none."""
    if os.name != "posix":
        return StudentRun("error", "a student's search.py is run only on Linux and macOS "
                          "(no process limits here)", 0, [], None, 0)
    work = tempfile.mkdtemp(prefix="tui-search-student-")
    try:
        Path(work, "search.py").write_text(student_text, encoding="utf-8")
        shutil.copyfile(_HERE / "course_util.py", Path(work, "util.py"))
        Path(work, "game.py").write_text(_GAME, encoding="utf-8")
        Path(work, "problem.json").write_text(json.dumps(problem), encoding="utf-8")
        return _run_child(work, seconds, memory_mb)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _run_child(work: str, seconds: float, memory_mb: int) -> StudentRun:
    command = [sys.executable, "-I", str(_HERE / "sandbox_child.py"), work, f"{seconds:g}",
               str(memory_mb)]
    if namespaces_work():
        command = [*_UNSHARE, "--", *command]
    env = {"PATH": os.defpath, "LANG": "C.UTF-8", "PYTHONHASHSEED": "0"}
    began = time.monotonic()
    with open(Path(work, "stray.txt"), "wb") as stray:  # what is printed before the redirect
        child = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=stray,
                                 stderr=stray, cwd=work, env=env, start_new_session=True,
                                 close_fds=True)
        try:
            child.wait(timeout=seconds + 5)  # the child's own alarm comes first
            killed = False
        except subprocess.TimeoutExpired:
            killed = True
        finally:
            try:
                os.killpg(child.pid, signal.SIGKILL)  # and whatever it started
            except (ProcessLookupError, PermissionError):
                pass
            child.wait()
    answer = Path(work, "result.json")
    silent = not answer.exists() or answer.stat().st_size == 0
    if killed or (silent and time.monotonic() - began >= seconds):  # killed at its CPU limit
        return StudentRun("error", f"still running after {seconds:g} s (an endless loop that "
                          "ignores the time limit?)", 0, [], None, 0)
    return _result(work, child.returncode, memory_mb)


def _result(work: str, code: int, memory_mb: int) -> StudentRun:
    """The child's ``result.json``, or why there is none."""
    try:
        with open(Path(work, "result.json"), encoding="utf-8") as handle:
            data = json.loads(handle.read(64 * 1024 * 1024 + 1))
    except (OSError, ValueError):
        data = None
    if not isinstance(data, dict) or data.get("status") not in ("ok", "error"):
        if code == -signal.SIGXCPU or code == 128 + signal.SIGXCPU:
            why = "used up its CPU time"
        elif code < 0 or code > 128:
            number = -code if code < 0 else code - 128
            why = f"was killed by signal {number} ({_signal_name(number)})"
            if number == signal.SIGKILL:
                why += f": perhaps more than {memory_mb} MB"
        else:
            why = f"ended the process (exit code {code}) before returning"
        return StudentRun("error", why, 0, [], None, 0)
    expanded = data.get("expanded")
    actions = data.get("actions")
    line, landlock, col = data.get("line"), data.get("landlock"), data.get("col")
    about = data.get("about")
    return StudentRun(
        "ok" if data["status"] == "ok" else "error", str(data.get("message", ""))[:300],
        line if isinstance(line, int) and line >= 0 else 0,
        expanded if isinstance(expanded, list) else [],
        [str(a) for a in actions] if isinstance(actions, list) else None,
        landlock if isinstance(landlock, int) else 0,
        col if isinstance(col, int) and col >= 0 else 0,
        about if about in ("file", "missing") else "function")


def _signal_name(number: int) -> str:
    try:
        return signal.Signals(number).name
    except ValueError:
        return "unknown"
