"""A class's records (``--records DIR``): what each student did, as JSON lines, one event a
line, in a file of their own in the teacher's folder -- written by the app (in a terminal, or
served: each visitor's app), read by the class report and the teacher's page.

A line: ``{"v": 1, "time": "2025-03-04T10:15:02Z", "student": "Ada", "event": "quiz", ...}``
(``visitor``: the served visitor's id).  The events (docs/13-by-hand-and-records.md):
``start``, ``exercise`` (a verdict, with the map), ``quiz`` (an answer), ``by_hand`` (a run
stepped by hand: its steps, mistakes by cause, time) and ``trace_check`` (the verdict and the
diagnosis).

**Writing** (:class:`Writer`): each event is one line written whole while the file is locked
(``flock``), then ``fsync`` -- not a bare ``O_APPEND`` write: the kernel promises a write of
at most ``PIPE_BUF`` bytes whole only to a pipe, and a line with its map may be longer.  A
writer killed in the middle of its line leaves it torn, without its newline: the next writer
ends it first, so it tears only itself.  The file's name is made from the student's name,
cleaned (:func:`file_stem`: no ``/``, ``..`` or control characters), and the visitor's id the
server made, so a visitor writes only their own file; it is opened ``O_NOFOLLOW``.

**Reading** (:func:`read_records`): a line that is not a JSON object (torn by a kill, or
edited) is skipped with a warning naming the file and the line.
"""

from __future__ import annotations

import fcntl
import json
import os
import re
import time
from pathlib import Path
from typing import Any, NamedTuple

from tui_search.engine.util.atomic import os_reason
from tui_search.engine.util.untrusted import BadInput, load_json

#: The records' format (each line's ``v``).
VERSION = 1
SUFFIX = ".jsonl"
#: The events a line may be.
EVENTS = ("start", "exercise", "quiz", "by_hand", "trace_check")
#: A name as the records keep it: at most this many characters.
MAX_NAME = 60
#: A file's name from it: at most this many characters before the visitor's id.
MAX_STEM = 40
#: A map of more characters than this is recorded by its size only.
MAX_MAP_CHARS = 64 * 1024
#: A line longer than this is refused when written, skipped when read.
MAX_LINE = 1024 * 1024
#: A records file bigger than this is read up to it (and said so).
MAX_FILE = 64 * 1024 * 1024
_NOT_IN_STEM = re.compile(r"[^\w-]+")


class RecordsError(Exception):
    """The records folder cannot be used: one line."""


def clean_name(name: str) -> str:
    """A student's name as the records keep it: control and other unprintable characters
    taken out, spaces run together, at most :data:`MAX_NAME` characters ("" if none is
    left)."""
    printable = "".join(ch if ch.isprintable() else " " for ch in name)
    return " ".join(printable.split())[:MAX_NAME].strip()


def file_stem(name: str) -> str:
    """The part of a records file's name that a student's name makes: letters, digits, ``-``
    and ``_`` kept, every run of anything else one ``-`` -- so no ``/``, no ``..``, no control
    character, no leading dot ("student" when nothing is left)."""
    stem = _NOT_IN_STEM.sub("-", clean_name(name)).strip("-_")[:MAX_STEM].strip("-_")
    return stem or "student"


def file_name(name: str, visitor: str | None = None) -> str:
    """The records file of a student (``ada.jsonl``), or of a served visitor
    (``ada.3fa9c1.jsonl``: two visitors who give the same name write two files)."""
    ident = _NOT_IN_STEM.sub("", visitor or "")[:16]
    return f"{file_stem(name)}{'.' + ident if ident else ''}{SUFFIX}"


def open_folder(folder: str | Path) -> Path:
    """``--records DIR``: the folder, made if it is not there (its parent must be); a
    RecordsError saying why it cannot be used."""
    path = Path(folder)
    try:
        if not path.is_dir() and not path.exists():
            path.mkdir()
        if not path.is_dir():
            raise RecordsError(f"--records {folder}: not a folder")
        if not os.access(path, os.W_OK | os.X_OK):
            raise RecordsError(f"--records {folder}: cannot write in it")
    except OSError as err:
        raise RecordsError(f"--records {folder}: {os_reason(err)}") from None
    return path.resolve()


def now_text() -> str:
    """The time a line says, UTC to the second."""
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())


class Writer:
    """A student's records file in ``folder``, appended to an event a line; only that file
    (its name is :func:`file_name`'s, never a path from outside).  A write that fails says
    why (:meth:`write`'s one line) and never raises."""

    def __init__(self, folder: str | Path, student: str, visitor: str | None = None) -> None:
        self.folder = Path(folder)
        self.student = clean_name(student) or "student"
        self.visitor = visitor
        self.path = self.folder / file_name(student, visitor)
        assert self.path.parent == self.folder  # a name with no separator
        self.problem = ""  # the last write's problem ("" none)

    def write(self, event: str, **fields: Any) -> str | None:
        """Append the event; None, or why it was not written (one line)."""
        record: dict[str, Any] = {"v": VERSION, "time": now_text(), "student": self.student}
        if self.visitor:
            record["visitor"] = self.visitor
        record["event"] = event
        record.update(fields)
        data = (json.dumps(record, ensure_ascii=False, separators=(",", ":")) + "\n").encode()
        if len(data) > MAX_LINE:
            return self._failed(f"a {event} record of {len(data):,} bytes is too long")
        try:
            append_line(self.path, data)
        except OSError as err:
            return self._failed(f"cannot write {self.path}: {os_reason(err)}")
        self.problem = ""
        return None

    def _failed(self, why: str) -> str:
        self.problem = f"Records: {why}"
        return self.problem


def append_line(path: Path, data: bytes) -> None:
    """Append ``data`` (one line, ending in a newline) to ``path`` whole: under an exclusive
    lock, after a newline that ends a torn last line, then flushed to the disk."""
    flags = os.O_RDWR | os.O_APPEND | os.O_CREAT | os.O_CLOEXEC | getattr(os, "O_NOFOLLOW", 0)
    fd = os.open(path, flags, 0o644)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        size = os.fstat(fd).st_size
        if size and os.pread(fd, 1, size - 1) != b"\n":
            data = b"\n" + data  # a writer killed mid-line: end its line, keep ours whole
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
        os.fsync(fd)
    finally:
        os.close(fd)  # (and the lock with it)


class Event(NamedTuple):
    """A line read: its file's name, its line number and what it says."""

    file: str
    line: int
    data: dict[str, Any]

    @property
    def student(self) -> str:
        name = self.data.get("student")
        return clean_name(name) if isinstance(name, str) and clean_name(name) else (
            Path(self.file).name.split(".")[0])

    @property
    def kind(self) -> str:
        kind = self.data.get("event")
        return kind if isinstance(kind, str) else ""


def read_records(folder: str | Path) -> tuple[list[Event], list[str]]:
    """Every event of the records files (``*.jsonl``) in ``folder``, file by file in the
    order of their names, line by line; and a warning for each line skipped ("records/ada.
    jsonl:7: a torn or malformed line, skipped") or file that could not be read.  A folder
    that cannot be read is a RecordsError."""
    root = Path(folder)
    try:
        names = sorted(p for p in root.iterdir() if p.name.endswith(SUFFIX))
    except OSError as err:
        raise RecordsError(f"{folder}: {os_reason(err)}") from None
    events: list[Event] = []
    warnings: list[str] = []
    for path in names:
        shown = str(path)
        try:
            with open(path, "rb") as file:
                data = file.read(MAX_FILE + 1)
        except OSError as err:
            warnings.append(f"{shown}: cannot read it: {os_reason(err)}")
            continue
        if len(data) > MAX_FILE:
            warnings.append(f"{shown}: over {MAX_FILE // 2**20} MB: read up to there")
            data = data[:MAX_FILE]
        for number, raw in enumerate(data.split(b"\n"), 1):
            if not raw.strip():
                continue
            event = _line(raw)
            if event is None:
                warnings.append(f"{shown}:{number}: a torn or malformed line, skipped")
            else:
                events.append(Event(path.name, number, event))
    return events, warnings


def _line(raw: bytes) -> dict[str, Any] | None:
    """A line's event, or None when it is not one (not UTF-8, not a JSON object, too long)."""
    if len(raw) > MAX_LINE:
        return None
    try:
        value = load_json(raw.decode("utf-8"), 8 * len(raw) + 4096)
    except (UnicodeDecodeError, BadInput):
        return None
    return value if isinstance(value, dict) else None


def map_field(text: str, width: int, height: int) -> dict[str, Any]:
    """A map as an event carries it: its text, or its size alone when it is too big."""
    if len(text) > MAX_MAP_CHARS:
        return {"map": None, "map_size": [width, height]}
    return {"map": text, "map_size": [width, height]}


__all__ = ["EVENTS", "MAX_NAME", "VERSION", "Event", "RecordsError", "Writer", "append_line",
           "clean_name", "file_name", "file_stem", "map_field", "open_folder", "read_records"]
