"""Saving never loses someone's work: a file changed on disk, a read-only file, hard links and
a map that would not load again are refused (the file untouched); a symlink stays a link; the
owner, group and mode are kept; a killed save's temporary files go at the next save."""

from __future__ import annotations

import os
import pwd
import signal
import stat
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.map_helpers import TUTORIAL, MAI_2x3, error_of, grids, write
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import MOVINGAI
from tui_search.engine.maps.write import (
    ChangedOnDisk,
    HardLinked,
    ReadOnlyFile,
    WouldNotLoad,
    save_map,
)
from tui_search.engine.util import atomic

IS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0


def raised(func, *args, **kwargs) -> MapError:  # type: ignore[no-untyped-def]
    with pytest.raises(MapError) as info:
        func(*args, **kwargs)
    return info.value


def snapshot(path: Path) -> tuple[bytes, int, int, int, int]:
    st_ = path.stat()
    return path.read_bytes(), st_.st_mode, st_.st_uid, st_.st_gid, st_.st_ino


# -- changed on disk -----------------------------------------------------------------------


def test_a_file_changed_on_disk_is_not_saved_over(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", "; mine\n" + TUTORIAL)
    grid = load_map(path)
    grid.set_blocked((0, 1), True)
    theirs = "; theirs\n" + TUTORIAL.replace("S#...#", "S#.#.#")  # the same size
    path.write_text(theirs)
    error = raised(save_map, grid, path)
    assert isinstance(error, ChangedOnDisk)
    assert str(error) == (f"{path}: cannot save: the file changed on disk since it was opened "
                          "or saved")
    assert path.read_text() == theirs and os.listdir(tmp_path) == ["m.txt"]
    # Overwrite when told to; the next save compares with what was written.
    grid.source = save_map(grid, path, overwrite=True)
    assert load_map(path) == grid
    grid.set_blocked((0, 2), True)
    grid.source = save_map(grid, path)
    assert load_map(path) == grid


def test_reloading_then_saving_works(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", TUTORIAL)
    grid = load_map(path)
    path.write_text("; a comment\n" + TUTORIAL)
    assert isinstance(raised(save_map, grid, path), ChangedOnDisk)
    grid = load_map(path)  # reload: the other program's comment is in the source
    grid.set_blocked((0, 1), True)
    save_map(grid, path)
    assert path.read_text().startswith("; a comment\n") and load_map(path) == grid


def test_touched_deleted_or_saved_elsewhere_is_no_change(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", TUTORIAL)
    grid = load_map(path)
    os.utime(path, ns=(1, 1))  # touched: same bytes
    grid.source = save_map(grid, path)
    path.unlink()  # deleted: nothing of anyone's to lose
    grid.source = save_map(grid, path)
    assert path.read_text() == TUTORIAL
    other = write(tmp_path, "other.txt", "old\n")  # save-as: not the file that was read
    grid.source = save_map(grid, other)
    assert other.read_text() == TUTORIAL
    assert grid.source.stamp == load_map(other).source.stamp  # type: ignore[union-attr]


def test_a_stamp_is_the_file_as_read_or_written(tmp_path: Path) -> None:
    path = write(tmp_path, "m.map", MAI_2x3)
    stamp = load_map(path).source.stamp  # type: ignore[union-attr]
    assert stamp is not None
    assert (stamp.path, stamp.size, stamp.mtime_ns) == (
        os.path.realpath(path), len(MAI_2x3), path.stat().st_mtime_ns)
    written = save_map(load_map(path), path, MOVINGAI).stamp
    assert written is not None and written.same_bytes(stamp)
    assert written.mtime_ns == path.stat().st_mtime_ns


# -- read-only -----------------------------------------------------------------------------


def test_a_read_only_file_is_refused_even_to_root(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", TUTORIAL)
    path.chmod(0o444)
    before = snapshot(path)
    grid = load_map(path)
    grid.set_blocked((0, 1), True)
    for options in ({}, {"overwrite": True}, {"in_place": True}):
        error = raised(save_map, grid, path, **options)
        assert isinstance(error, ReadOnlyFile)
        assert str(error) == f"{path}: cannot save: the file is read-only"
    assert snapshot(path) == before and os.listdir(tmp_path) == ["m.txt"]


def save_as_user(uid: int, gid: int, path: Path) -> str:
    """In a child process as ``uid``/``gid`` (no other groups): load ``path``, edit, save;
    what it raised (``Name message``), or ``""``.  A fork, so nothing is imported from
    folders the user may not read."""
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child
        answer = "crashed"
        try:
            os.close(read_end)
            os.setgroups([])
            os.setgid(gid)
            os.setuid(uid)
            grid = load_map(path)
            grid.set_blocked((0, 1), True)
            try:
                save_map(grid, path)
                answer = ""
            except MapError as err:
                answer = f"{type(err).__name__} {err}"
        finally:
            os.write(write_end, answer.encode())
            os._exit(0)
    os.close(write_end)
    with os.fdopen(read_end, "rb") as pipe:
        answer = pipe.read().decode()
    os.waitpid(pid, 0)
    return answer


@pytest.mark.skipif(not IS_ROOT, reason="needs root to act as another user")
def test_a_read_only_file_is_refused_to_a_user(tmp_path: Path) -> None:
    """As ``nobody``, in a folder ``nobody`` may write, a 0444 file of its own."""
    try:
        nobody = pwd.getpwnam("nobody")
    except KeyError:
        pytest.skip("no user 'nobody' on this machine")
    folder = Path(tempfile.mkdtemp(prefix="tui-search-ro-"))
    try:
        os.chown(folder, nobody.pw_uid, nobody.pw_gid)
        path = write(folder, "m.txt", TUTORIAL)
        os.chown(path, nobody.pw_uid, nobody.pw_gid)
        path.chmod(0o444)
        before = snapshot(path)
        answer = save_as_user(nobody.pw_uid, nobody.pw_gid, path)
        assert answer == f"ReadOnlyFile {path}: cannot save: the file is read-only"
        assert snapshot(path) == before and os.listdir(folder) == ["m.txt"]
        path.chmod(0o644)  # writable: the same child saves, and the file stays nobody's
        assert save_as_user(nobody.pw_uid, nobody.pw_gid, path) == ""
        after = path.stat()
        assert (after.st_uid, after.st_gid) == (nobody.pw_uid, nobody.pw_gid)
        assert load_map(path).is_blocked((0, 1))
    finally:
        for name in os.listdir(folder):
            os.unlink(folder / name)
        folder.rmdir()


# -- symlinks, owner, group, mode ------------------------------------------------------------


def test_a_symlink_stays_a_link_and_its_target_is_written_beside_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "real").mkdir()
    (tmp_path / "links").mkdir()
    target = write(tmp_path / "real", "m.txt", TUTORIAL)
    link = tmp_path / "links" / "m.txt"
    link.symlink_to(os.path.relpath(target, link.parent))
    grid = load_map(link)
    grid.set_blocked((0, 1), True)
    renames: list[tuple[str, str]] = []
    real_replace = os.replace

    def spy(src: str, dst: str) -> None:
        renames.append((src, dst))
        real_replace(src, dst)

    monkeypatch.setattr(atomic.os, "replace", spy)
    grid.source = save_map(grid, link)
    assert [(os.path.dirname(s), d) for s, d in renames] == [(str(tmp_path / "real"), str(target))]
    assert link.is_symlink() and load_map(target) == grid
    assert os.listdir(tmp_path / "links") == ["m.txt"]
    assert os.listdir(tmp_path / "real") == ["m.txt"]
    grid.set_blocked((0, 2), True)
    save_map(grid, link)  # the stamp names the target: the second save is no "change on disk"
    assert load_map(target) == grid


def test_mode_owner_and_group_are_kept(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", TUTORIAL)
    path.chmod(0o640)
    if IS_ROOT:
        os.chown(path, 65534, 65534)
    before = path.stat()
    grid = load_map(path)
    grid.set_blocked((0, 1), True)
    save_map(grid, path)
    after = path.stat()
    assert after.st_ino != before.st_ino  # replaced (atomically), not written in place
    assert (stat.S_IMODE(after.st_mode), after.st_uid, after.st_gid) == (
        0o640, before.st_uid, before.st_gid)


def test_an_owner_the_process_may_not_set_is_let_go(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """As a user saving another's file in its own folder: the save still succeeds."""
    path = write(tmp_path, "m.txt", TUTORIAL)
    calls: list[tuple[int, int]] = []

    def refuse(fd: int, uid: int, gid: int) -> None:
        calls.append((uid, gid))
        raise PermissionError(1, "Operation not permitted")

    real_fstat = os.fstat

    def other_owner(fd: int) -> os.stat_result:
        s = real_fstat(fd)
        return os.stat_result((s.st_mode, s.st_ino, s.st_dev, s.st_nlink, s.st_uid + 1,
                               s.st_gid + 1, s.st_size, s.st_atime, s.st_mtime, s.st_ctime))

    monkeypatch.setattr(atomic.os, "fchown", refuse)
    monkeypatch.setattr(atomic.os, "fstat", other_owner)
    save_map(load_map(path), path)
    owner = path.stat()
    assert calls == [(owner.st_uid, owner.st_gid), (-1, owner.st_gid)]


# -- hard links ----------------------------------------------------------------------------


def test_hard_links_are_written_in_place_only_when_asked(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", TUTORIAL)
    other = tmp_path / "also.txt"
    os.link(path, other)
    before = snapshot(path)
    grid = load_map(path)
    grid.set_blocked((0, 1), True)
    error = raised(save_map, grid, path)
    assert isinstance(error, HardLinked)
    assert str(error) == (f"{path}: cannot save: the file has 2 hard links, which replacing it "
                          "would split")
    assert snapshot(path) == before and sorted(os.listdir(tmp_path)) == ["also.txt", "m.txt"]
    grid.source = save_map(grid, path, in_place=True)
    assert path.stat().st_ino == before[4] and path.stat().st_nlink == 2
    assert load_map(other) == grid and load_map(path).source.stamp == grid.source.stamp  # type: ignore[union-attr]
    grid.set_blocked((0, 1), False)
    save_map(grid, path, in_place=True)  # shorter or not, the file is exactly what was written
    assert other.read_text() == TUTORIAL


# -- never write a file that would not load ----------------------------------------------------


@pytest.mark.parametrize(("start", "goal", "reason"), [
    ((0, 0), (0, 0), "no start 'S' in the map"),
    (None, (1, 0), "no start 'S' in the map"),
    ((0, 0), None, "no goal 'G' in the map"),
])
def test_a_map_that_would_not_load_is_not_written(
    tmp_path: Path, start: tuple[int, int] | None, goal: tuple[int, int] | None, reason: str
) -> None:
    path = write(tmp_path, "m.txt", TUTORIAL)
    grid = load_map(path)
    grid.start, grid.goal = start, goal
    error = raised(save_map, grid, path)
    assert isinstance(error, WouldNotLoad)
    assert str(error) == f"{path}: cannot save: the file would not open again: {reason}"
    assert path.read_text() == TUTORIAL
    new = tmp_path / "new.txt"
    assert isinstance(raised(save_map, grid, new), WouldNotLoad) and not new.exists()
    # MovingAI files have no start or goal: the same grid saves as one.
    save_map(grid, tmp_path / "m.map", MOVINGAI)
    assert load_map(tmp_path / "m.map").blocked == grid.blocked


def test_a_file_over_the_size_a_map_may_be_is_not_written(tmp_path: Path, monkeypatch) -> None:
    from tui_search.engine.maps import read as mapread
    from tui_search.engine.maps import write as mapwrite

    path = write(tmp_path, "m.txt", TUTORIAL)
    grid = load_map(path)
    limit = len(TUTORIAL.encode()) + 8  # the text fits; the .map's header does not
    monkeypatch.setattr(mapwrite, "MAX_MAP_BYTES", limit)
    monkeypatch.setattr(mapread, "MAX_MAP_BYTES", limit)
    target = tmp_path / "m.map"
    error = raised(save_map, grid, target, MOVINGAI)
    assert isinstance(error, WouldNotLoad) and not target.exists()
    assert "cannot save: the file would not open again: file is" in str(error)
    save_map(grid, path, overwrite=True)  # the text map itself still saves
    assert path.read_text() == TUTORIAL


cells = st.one_of(st.none(), st.tuples(st.integers(0, 11), st.integers(0, 11)))


@settings(max_examples=60, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(grids(), cells, cells)
def test_every_saved_map_loads_again(tmp_path: Path, grid: Grid, start: object,
                                     goal: object) -> None:
    grid.start, grid.goal = start, goal  # type: ignore[assignment]
    path = tmp_path / "g.txt"
    path.write_text("old\n")
    try:
        save_map(grid, path, overwrite=True)
    except WouldNotLoad:
        assert path.read_text() == "old\n"
    else:
        load_map(path)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no named pipes on this system")
def test_saving_onto_a_fifo_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "pipe.txt"
    os.mkfifo(path)
    grid = load_map(write(tmp_path, "m.txt", TUTORIAL))
    assert error_of(save_map, grid, path) == f"{path}: cannot save: not a regular file"
    assert stat.S_ISFIFO(path.stat().st_mode)


# -- stale temporary files ---------------------------------------------------------------------


def test_stale_temporary_files_of_this_map_are_removed_at_its_next_save(tmp_path: Path) -> None:
    path = write(tmp_path, "m.txt", TUTORIAL)
    old = time.time() - atomic.STALE_TEMP_SECONDS - 5
    stale = [".m.txt.0123abcd.tmp", ".m.txt.ffffffff.tmp"]
    kept = [
        ".m.txt.0123abcd.tmp.keep", ".m.txt.0123ABCD.tmp", ".m.txt.0123abc.tmp", ".m.txt.swp",
        ".m.txt.tmp", "m.txt.0123abcd.tmp", ".other.txt.0123abcd.tmp", ".m.txt.x0123abcd.tmp",
    ]
    for name in stale + kept:
        write(tmp_path, name, "x")
        os.utime(tmp_path / name, (old, old))
    write(tmp_path, ".m.txt.89abcdef.tmp", "being written")  # fresh: another save's, live
    (tmp_path / ".m.txt.00000000.tmp").mkdir()  # not a regular file
    os.utime(tmp_path / ".m.txt.00000000.tmp", (old, old))
    (tmp_path / ".m.txt.11111111.tmp").symlink_to(path)
    os.utime(tmp_path / ".m.txt.11111111.tmp", (old, old), follow_symlinks=False)
    save_map(load_map(path), path)
    left = set(os.listdir(tmp_path))
    assert not left & set(stale)
    assert left == {"m.txt", *kept, ".m.txt.89abcdef.tmp", ".m.txt.00000000.tmp",
                    ".m.txt.11111111.tmp"}
    assert path.read_text() == TUTORIAL


KILLED_SAVER = """
import sys
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.write import save_map
grid = load_map(sys.argv[1])
while True:
    save_map(grid, sys.argv[1], overwrite=True)
"""


def test_a_save_killed_midway_leaves_the_old_file_and_its_temporary_file_goes_later(
        tmp_path: Path) -> None:
    text = "S" + "." * 1999 + "\n" + ("." * 2000 + "\n") * 1998 + "." * 1999 + "G\n"
    path = write(tmp_path, "big.txt", text)
    saver = subprocess.Popen([sys.executable, "-c", KILLED_SAVER, str(path)])
    temps: list[str] = []
    deadline = time.monotonic() + 60
    try:
        while not temps and time.monotonic() < deadline and saver.poll() is None:
            temps = [n for n in os.listdir(tmp_path) if n.endswith(".tmp")]
            time.sleep(0.002)  # polling for the temporary file of a save under way
    finally:
        saver.send_signal(signal.SIGKILL)
        saver.wait()
    assert temps, "no save was seen under way"
    assert path.read_text() == text  # the old file (or the same bytes, renamed in): whole
    left = [n for n in os.listdir(tmp_path) if n.endswith(".tmp")]
    old = time.time() - atomic.STALE_TEMP_SECONDS - 5
    for name in left:
        os.utime(tmp_path / name, (old, old))
    save_map(load_map(path), path)
    assert [n for n in os.listdir(tmp_path) if n.endswith(".tmp")] == []
