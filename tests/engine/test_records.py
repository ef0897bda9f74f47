"""A class's records: a file a student (a served visitor's own), an event a line written whole
however many write at once, and a line torn by a kill skipped on reading with a warning that
names the file and the line."""

from __future__ import annotations

import json
import multiprocessing
import os
import signal
from pathlib import Path

import pytest

from tui_search.engine.course.records import (
    EVENTS,
    Writer,
    clean_name,
    file_name,
    file_stem,
    open_folder,
    read_records,
)

WRITERS, EACH = 30, 40


@pytest.mark.parametrize(("name", "stem"), [
    ("Ada Lovelace", "Ada-Lovelace"),
    ("../../etc/passwd", "etc-passwd"),
    ("..", "student"),
    ("bob/../alice", "bob-alice"),
    ("\x1b[31mred\x07", "31mred"),
    ("  ", "student"),
    ("Zoë O'Brien", "Zoë-O-Brien"),
    ("a" * 200, "a" * 40),
])
def test_a_file_name_is_made_from_the_name_cleaned(name: str, stem: str) -> None:
    assert file_stem(name) == stem
    made = file_name(name, "3fa9c1")
    assert made == f"{stem}.3fa9c1.jsonl"
    assert "/" not in made and ".." not in made and made.isprintable()


def test_a_name_is_kept_without_control_characters() -> None:
    assert clean_name("  Ada\tLove\x1b[0mlace\n") == "Ada Love [0mlace"
    assert clean_name("\x00\x01") == ""


def test_a_visitor_writes_only_their_own_file(tmp_path: Path) -> None:
    """Two visitors who give the same name write two files; a name that looks like a path
    stays in the folder; a link planted where a visitor's file goes is not followed."""
    a, b = Writer(tmp_path, "alice", "aaaaaa"), Writer(tmp_path, "alice", "bbbbbb")
    assert a.path != b.path and a.path.parent == b.path.parent == tmp_path
    sneaky = Writer(tmp_path, "../alice.aaaaaa", "cccccc")
    assert sneaky.path.parent == tmp_path and sneaky.path not in (a.path, b.path)
    for writer in (a, b, sneaky):
        assert writer.write("start", map_name="t") is None
    assert len(a.path.read_text().splitlines()) == 1
    victim = tmp_path / "elsewhere.txt"
    victim.write_text("not yours\n")
    planted = Writer(tmp_path, "mallory", "dddddd")
    planted.path.symlink_to(victim)
    problem = planted.write("quiz", right=True)
    assert problem is not None and problem.startswith("Records: cannot write")
    assert victim.read_text() == "not yours\n"


def _write_many(folder: str, name: str, visitor: str | None, n: int) -> None:
    writer = Writer(folder, name, visitor)
    for i in range(n):
        assert writer.write("quiz", right=i % 2 == 0, step=i, pad="x" * (i * 97 % 5000)) is None


@pytest.mark.parametrize("shared", [True, False], ids=["one file", "a file each"])
def test_thirty_writers_at_once_lose_no_line(tmp_path: Path, shared: bool) -> None:
    """30 processes write 40 lines each (some over PIPE_BUF), at once: every line is there,
    whole, each file's lines in its writer's order."""
    context = multiprocessing.get_context("fork")
    procs = [context.Process(target=_write_many,
                             args=(str(tmp_path), "class" if shared else f"s{i}",
                                   None if shared else f"{i:06x}", EACH))
             for i in range(WRITERS)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(60)
        assert p.exitcode == 0
    events, warnings = read_records(tmp_path)
    assert warnings == []
    assert len(events) == WRITERS * EACH
    files = {e.file for e in events}
    assert len(files) == (1 if shared else WRITERS)
    if not shared:
        for file in files:
            assert [e.data["step"] for e in events if e.file == file] == list(range(EACH))


def _torn(path: str) -> None:
    """A writer killed in the middle of its line: half a line, no newline."""
    fd = os.open(path, os.O_WRONLY | os.O_APPEND | os.O_CREAT)
    os.write(fd, b'{"v":1,"student":"ada","event":"qu')
    os.kill(os.getpid(), signal.SIGKILL)


def test_a_line_torn_by_a_kill_is_skipped_with_its_file_and_line(tmp_path: Path) -> None:
    writer = Writer(tmp_path, "ada")
    assert writer.write("start", map_name="tutorial") is None
    child = multiprocessing.get_context("fork").Process(target=_torn, args=(str(writer.path),))
    child.start()
    child.join(30)
    assert child.exitcode == -signal.SIGKILL
    assert writer.write("quiz", right=True) is None  # after the torn one: its own line
    events, warnings = read_records(tmp_path)
    assert [e.kind for e in events] == ["start", "quiz"]
    assert [e.line for e in events] == [1, 3]
    assert warnings == [f"{writer.path}:2: a torn or malformed line, skipped"]


def test_what_is_not_an_event_is_skipped_and_said(tmp_path: Path) -> None:
    (tmp_path / "x.jsonl").write_bytes(b'[1, 2]\n{"event": "quiz"}\n\xff\xfe\n\n{"a": 1')
    (tmp_path / "notes.txt").write_text("not a records file\n")
    events, warnings = read_records(tmp_path)
    assert [(e.line, e.kind) for e in events] == [(2, "quiz")]
    assert [w.rsplit(":", 2)[1] for w in warnings] == ["1", "3", "5"]
    assert events[0].student == "x"  # no name in the line: the file's


def test_each_line_says_its_version_time_student_and_event(tmp_path: Path) -> None:
    Writer(tmp_path, "Ben", "0a0b0c").write("by_hand", algorithm="bfs", by_cause={"newest": 1})
    (line,) = (tmp_path / "Ben.0a0b0c.jsonl").read_text().splitlines()
    data = json.loads(line)
    assert list(data)[:5] == ["v", "time", "student", "visitor", "event"]
    assert (data["v"], data["student"], data["visitor"], data["event"]) == (
        1, "Ben", "0a0b0c", "by_hand")
    assert "by_hand" in EVENTS


def test_the_records_folder_is_made_or_refused_in_one_line(tmp_path: Path) -> None:
    assert open_folder(tmp_path / "new") == (tmp_path / "new").resolve()
    (tmp_path / "file").write_text("")
    with pytest.raises(Exception, match=r"file: not a folder$"):
        open_folder(tmp_path / "file")
    with pytest.raises(Exception, match=r"deeper: no such file|deeper: No such file"):
        open_folder(tmp_path / "missing" / "deeper")
