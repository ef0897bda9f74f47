"""The child's side of ``--check-search-py``: run as a script (``python -I sandbox_child.py
WORK SECONDS MEGABYTES``) in a fresh working folder, it fences itself in, imports the
student's ``search.py`` beside a course-like ``util`` module, runs one search function on the
problem the parent wrote (``problem.json``) and writes what happened to ``result.json``.

It imports nothing of tui_search (the parent's package is not the child's business), only
the standard library.  Before the student's code runs: a memory limit (``RLIMIT_AS``), a CPU
limit, a largest file (``RLIMIT_FSIZE``), no new processes where the OS counts them
(``RLIMIT_NPROC``; root is not counted) and ``os.fork`` and its kin refused, and on Linux with
Landlock writes refused outside the working folder and TCP refused (see
:func:`landlock_writes_only_in`).  The parent adds a network namespace and a process namespace
where ``unshare`` works, and kills the whole process group at the time limit.

The student's code can undo what this process does to itself; what it cannot undo is what
the kernel enforces (the limits, Landlock, the namespaces) and the parent's kill.  The result
is checked by the parent, which trusts only the states it can check against its own problem;
code set on cheating can still forge them (it shares this Python and the working folder).
"""

import ctypes
import json
import os
import resource
import signal
import sys
import traceback
from collections.abc import Callable
from types import FrameType, TracebackType
from typing import Any, TextIO

#: The student's printed output kept at most (the rest is refused: a flood of output).
OUTPUT_CAP = 64 * 1024
#: A file the child writes may be at most this big (the result of a long search included).
FILE_CAP = 64 * 1024 * 1024
MOVES = (("North", 0, 1), ("South", 0, -1), ("East", 1, 0), ("West", -1, 0))


class OutOfTime(BaseException):
    """The time limit, raised where the student's code is running."""


class OutputFlood(BaseException):
    """More printed than :data:`OUTPUT_CAP`."""


class CappedOutput:
    """``sys.stdout`` and ``sys.stderr``: a file in the working folder, refusing more than
    :data:`OUTPUT_CAP` characters in all."""

    def __init__(self, handle: TextIO) -> None:
        self.handle = handle
        self.written = 0

    def write(self, text: str) -> int:
        self.written += len(text)
        if self.written > OUTPUT_CAP:
            raise OutputFlood()
        return self.handle.write(text)

    def flush(self) -> None:
        self.handle.flush()

    def isatty(self) -> bool:
        return False


def landlock_writes_only_in(folder: str) -> int:
    """Refuse, for this process and its children, every write outside ``folder`` and every
    TCP bind and connect (Linux's Landlock, kernel 5.13+; TCP from its ABI 4).  The Landlock
    ABI in force, or 0 when the kernel offers none."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        abi = int(libc.syscall(444, None, 0, 1))  # landlock_create_ruleset(NULL, 0, VERSION)
    except (OSError, AttributeError):
        return 0
    if abi < 1:
        return 0
    write = (1 << 1) | sum(1 << bit for bit in range(4, 13))  # write, remove, make *
    if abi >= 2:
        write |= 1 << 13  # refer (rename and link across folders)
    if abi >= 3:
        write |= 1 << 14  # truncate
    net = (1 << 0) | (1 << 1) if abi >= 4 else 0  # bind and connect TCP
    attr = (ctypes.c_uint64 * 2)(write, net) if net else (ctypes.c_uint64 * 1)(write)
    ruleset: int = libc.syscall(444, ctypes.byref(attr), ctypes.sizeof(attr), 0)
    if ruleset < 0:
        return 0
    fd = os.open(folder, os.O_PATH | os.O_DIRECTORY)
    beneath = (ctypes.c_char * 12)()  # struct landlock_path_beneath_attr, packed
    ctypes.memmove(beneath, ctypes.byref(ctypes.c_uint64(write)), 8)
    ctypes.memmove(ctypes.byref(beneath, 8), ctypes.byref(ctypes.c_int32(fd)), 4)
    added = libc.syscall(445, ruleset, 1, ctypes.byref(beneath), 0)
    os.close(fd)
    if added < 0 or libc.prctl(38, 1, 0, 0, 0) != 0:  # PR_SET_NO_NEW_PRIVS
        return 0
    if libc.syscall(446, ruleset, 0) != 0:  # landlock_restrict_self
        return 0
    os.close(ruleset)
    return abi


def refuse_processes() -> None:
    """No new process: refused by the OS where it counts them, and in Python's own calls."""
    try:
        resource.setrlimit(resource.RLIMIT_NPROC, (0, 0))
    except (ValueError, OSError, AttributeError):
        pass

    def refused(*args: object, **kwargs: object) -> Any:
        raise PermissionError("starting a process is not allowed here")

    for name in ("fork", "forkpty", "vfork", "system", "posix_spawn", "posix_spawnp",
                 "execv", "execve", "execvp", "execvpe", "execl", "execle", "execlp",
                 "spawnv", "spawnve", "popen"):
        if hasattr(os, name):
            setattr(os, name, refused)


class Problem:
    """The search problem in the course's conventions: ``getStartState``, ``isGoalState``,
    ``getSuccessors`` (each call an expansion, passed to ``record``), ``getCostOfActions``.

    The record is ``main``'s, not a list on the problem, so that a student's code does not
    change it by chance; code set on it can still reach it (it runs in this same Python)."""

    def __init__(self, spec: dict[str, Any], record: Callable[[Any], None]) -> None:
        self.spec = spec
        self.__record = record
        self.__calls = 0
        self.limit = spec["max_expansions"]
        if spec["kind"] == "grid":
            rows = spec["walls"]
            self.height = len(rows)
            self.walls = {(x, self.height - 1 - y) for y, row in enumerate(rows)
                          for x, c in enumerate(row) if c == "%"}
            self.width = len(rows[0])
            self.start = tuple(spec["start"])
            self.goals = {tuple(g) for g in spec["goals"]}
            self.column_cost = spec["column_cost"]
        else:
            self.start = spec["start"]
            self.goals = set(spec["goals"])
            self.roads = spec["roads"]

    def getStartState(self) -> Any:
        return self.start

    def isGoalState(self, state: Any) -> bool:
        return state in self.goals

    def _free(self, x: int, y: int) -> bool:
        return 0 <= x < self.width and 0 <= y < self.height and (x, y) not in self.walls

    def getSuccessors(self, state: Any) -> list[tuple[Any, str, float]]:
        if self.__calls >= self.limit:
            raise RuntimeError(f"more than {self.limit:,} calls of getSuccessors")
        if self.spec["kind"] == "grid":
            if not (isinstance(state, tuple) and len(state) == 2
                    and all(isinstance(v, int) for v in state) and self._free(*state)):
                raise ValueError(f"getSuccessors({state!r}): not a free cell (x, y)")
            self.__record(list(state))
            self.__calls += 1
            out = []
            for action, dx, dy in MOVES:
                x, y = state[0] + dx, state[1] + dy
                if self._free(x, y):
                    out.append(((x, y), action, self.column_cost ** x))
            return out
        if not isinstance(state, str) or state not in self.roads:
            raise ValueError(f"getSuccessors({state!r}): no such state")
        self.__record(state)
        self.__calls += 1
        return [(b, action, cost) for action, b, cost in self.roads[state]]

    def getCostOfActions(self, actions: list[str]) -> float:
        return float(len(actions))


def heuristic_of(spec: dict[str, Any]) -> Callable[..., float]:
    """The A* heuristic the parent named, as the course's ``heuristic(state, problem)``."""
    name = spec.get("heuristic")
    goal = spec["goals"][0] if spec["goals"] else None
    if isinstance(name, dict):
        table = name
        return lambda state, problem=None: table.get(state, 0.0)
    if name == "manhattan" and goal is not None:
        return lambda s, problem=None: abs(s[0] - goal[0]) + abs(s[1] - goal[1])
    if name == "euclidean" and goal is not None:
        return lambda s, problem=None: ((s[0] - goal[0]) ** 2 + (s[1] - goal[1]) ** 2) ** 0.5
    return lambda state, problem=None: 0


def where_in(student: str, tb: TracebackType | None) -> int:
    """The line of the student's file nearest the error (0: none of its lines)."""
    line = 0
    for frame in traceback.extract_tb(tb):
        if os.path.abspath(frame.filename) == student:
            line = frame.lineno or 0
    return line


def main() -> None:
    work, seconds, megabytes = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
    os.chdir(work)
    with open("problem.json", encoding="utf-8") as handle:
        spec = json.load(handle)
    result: dict[str, Any] = {"status": "error", "message": "", "line": 0, "col": 0,
                              "about": "function", "expanded": [], "actions": None,
                              "landlock": 0}
    try:
        resource.setrlimit(resource.RLIMIT_AS, (megabytes * 1024 * 1024,) * 2)
    except (ValueError, OSError):
        pass  # (macOS does not enforce it)
    cpu = int(seconds) + 2
    resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
    resource.setrlimit(resource.RLIMIT_FSIZE, (FILE_CAP, FILE_CAP))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    output = open("output.txt", "w", encoding="utf-8", errors="replace")  # noqa: SIM115
    result_file = open("result.json", "w", encoding="utf-8")  # noqa: SIM115
    result["landlock"] = landlock_writes_only_in(work) if sys.platform == "linux" else 0
    refuse_processes()
    sys.stdout = sys.stderr = CappedOutput(output)
    sys.dont_write_bytecode = True
    sys.path.insert(0, work)
    student = os.path.abspath("search.py")
    expanded: list[Any] = []
    problem = Problem(spec, expanded.append)
    name = spec["function"]

    def out_of_time(signum: int, frame: FrameType | None) -> None:
        raise OutOfTime()

    signal.signal(signal.SIGALRM, out_of_time)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        import importlib

        search = importlib.import_module("search")  # the student's file

        function = getattr(search, name, None)
        if not callable(function):
            result["about"] = "missing"
        else:
            result["line"] = function.__code__.co_firstlineno if hasattr(
                function, "__code__") else 0
            if name == "aStarSearch":
                actions = function(problem, heuristic_of(spec))
            else:
                actions = function(problem)
            signal.setitimer(signal.ITIMER_REAL, 0)
            if actions is None and not spec.get("path_exists", True):
                result["status"] = "ok"  # the course's "no path" where there is none
            elif not isinstance(actions, (list, tuple)):
                result["message"] = (f"returned {type(actions).__name__}, not a list "
                                     "of actions")
            elif not all(isinstance(a, str) for a in actions):
                wrong = next(a for a in actions if not isinstance(a, str))
                result["message"] = ("returned a list holding "
                                     f"{type(wrong).__name__} {str(wrong)[:40]!r}, not only "
                                     "actions (strings)")
            else:
                result["status"], result["actions"] = "ok", [a[:100] for a in actions[:10**6]]
    except OutOfTime as exc:
        result["message"] = f"still running after {seconds:g} s (an endless loop?)"
        result["line"] = where_in(student, exc.__traceback__)
    except OutputFlood as exc:
        result["message"] = f"printed more than {OUTPUT_CAP // 1024} KB"
        result["line"] = where_in(student, exc.__traceback__)
    except MemoryError as exc:
        result["message"] = f"used more than the memory limit ({megabytes} MB)"
        result["line"] = where_in(student, exc.__traceback__)
    except SystemExit as exc:
        result["message"] = f"called exit ({exc.code!r}) instead of returning"
        result["line"] = where_in(student, exc.__traceback__)
    except RecursionError as exc:
        result["message"] = "recursed too deep (RecursionError)"
        result["line"] = where_in(student, exc.__traceback__)
    except BaseException as exc:  # the student's error, whatever it is
        signal.setitimer(signal.ITIMER_REAL, 0)
        if isinstance(exc, SyntaxError) and exc.filename is not None and os.path.abspath(
                exc.filename) == student:  # its file does not compile: its line and column
            result["about"] = "file"
            result["message"] = f"{type(exc).__name__}: {exc.msg}"
            result["line"], result["col"] = exc.lineno or 0, exc.offset or 0
        else:
            text = str(exc).splitlines()[0][:120] if str(exc) else ""
            result["message"] = f"raised {type(exc).__name__}" + (f": {text}" if text else "")
            result["line"] = where_in(student, exc.__traceback__)
    signal.setitimer(signal.ITIMER_REAL, 0)
    result["expanded"] = expanded
    json.dump(result, result_file)
    result_file.close()
    output.close()
    os._exit(0)  # no atexit, no finaliser of the student's


if __name__ == "__main__":
    main()
