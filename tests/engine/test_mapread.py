"""Reading input files: MapError, exact reasons a file cannot be read (missing, a folder,
permissions, too big, binary), and reads capped without big allocations."""

from __future__ import annotations

import os
import pickle
import threading
import tracemalloc
from pathlib import Path

import pytest

from tests.engine.map_helpers import TUTORIAL, error_of, write
from tests.helpers import MAPS
from tui_search.engine.maps import read as mapread
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MAX_MAP_BYTES, MapError
from tui_search.engine.maps.text import parse_text_map

# -- MapError ------------------------------------------------------------------------------


def test_map_error_str_and_attributes() -> None:
    err = MapError("a.txt", "bad", 3, 7)
    assert (err.path, err.message, err.line, err.col) == ("a.txt", "bad", 3, 7)
    assert str(err) == "a.txt:3:7: bad"
    assert str(MapError("a.txt", "bad", 3)) == "a.txt:3: bad"
    assert str(MapError("a.txt", "bad")) == "a.txt: bad"


def test_map_error_pickles() -> None:
    """Errors may cross a process boundary (workers); they must survive pickling."""
    err = pickle.loads(pickle.dumps(MapError("a.txt", "bad", 3, 7)))
    assert str(err) == "a.txt:3:7: bad" and err.col == 7


# -- reading a file ------------------------------------------------------------------------


def test_load_map_reads_a_file(tmp_path: Path) -> None:
    path = write(tmp_path, "t.txt", TUTORIAL)
    assert load_map(path) == parse_text_map(TUTORIAL)
    assert load_map(str(path)) == parse_text_map(TUTORIAL)


def test_load_map_errors_name_the_file(tmp_path: Path) -> None:
    path = write(tmp_path, "t.txt", "S.\n.q\n")
    assert error_of(load_map, path) == f"{path}:2:2: unknown cell character 'q'"


def test_load_map_missing_file(tmp_path: Path) -> None:
    path = tmp_path / "nope.txt"
    assert error_of(load_map, path) == f"{path}: no such file"
    inside_a_file = write(tmp_path, "t.txt", TUTORIAL) / "x"
    assert error_of(load_map, inside_a_file) == f"{inside_a_file}: no such file"


def test_load_map_directory(tmp_path: Path) -> None:
    assert error_of(load_map, tmp_path) == f"{tmp_path}: is a directory, not a map file"


def test_load_map_permission_denied(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Simulated, because root (CI containers) can read a chmod 000 file."""
    path = write(tmp_path, "t.txt", TUTORIAL)

    def denied(*args: object, **kwargs: object) -> None:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(mapread, "open", denied, raising=False)
    assert error_of(load_map, path) == f"{path}: permission denied"


def test_load_map_permission_denied_by_stat(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A folder on the way that may not be searched: ``os.stat`` itself is refused (simulated:
    root, as in CI, may search any folder)."""
    path = write(tmp_path, "t.txt", TUTORIAL)

    def denied(*args: object, **kwargs: object) -> None:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(mapread.os, "stat", denied)
    assert error_of(load_map, path) == f"{path}: permission denied"


def test_load_map_too_big_is_refused_before_reading(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "huge.map"
    with open(path, "wb") as handle:  # sparse: no disk used
        handle.truncate(MAX_MAP_BYTES + 1)

    def no_reading(*args: object, **kwargs: object) -> None:
        raise AssertionError("the file was opened")

    monkeypatch.setattr(mapread, "open", no_reading, raising=False)
    assert error_of(load_map, path) == f"{path}: file is 64.1 MB; a map may be at most 64 MB"
    with open(path, "r+b") as handle:
        handle.truncate(200 * 1024 * 1024)
    assert error_of(load_map, path) == f"{path}: file is 200.0 MB; a map may be at most 64 MB"


def test_load_map_just_under_the_limit_is_read(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(mapread, "MAX_MAP_BYTES", len(TUTORIAL))
    assert load_map(write(tmp_path, "t.txt", TUTORIAL)).width == 6
    path = write(tmp_path, "u.txt", TUTORIAL + "\n")
    assert "a map may be at most" in error_of(load_map, path)


def test_loading_a_small_map_allocates_little() -> None:
    """A read capped at 64 MB must not ask for 64 MB: ``read(n)`` allocates ``n`` bytes first,
    which made loading the six-line tutorial map peak at 67 MB."""
    load_map(MAPS / "tutorial.txt")  # once first, so one-off caches do not count
    tracemalloc.start()
    try:
        grid = load_map(MAPS / "tutorial.txt")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert (grid.width, grid.height) == (6, 6)
    assert peak < 256 * 1024


def stat_says_empty(monkeypatch: pytest.MonkeyPatch) -> None:
    """``os.fstat`` says 0 bytes: the file grew after it was looked at."""
    real_fstat = os.fstat

    def fstat(fd: int) -> os.stat_result:
        st = real_fstat(fd)
        return os.stat_result((st.st_mode, st.st_ino, st.st_dev, st.st_nlink, st.st_uid,
                               st.st_gid, 0, st.st_atime, st.st_mtime, st.st_ctime))

    monkeypatch.setattr(mapread.os, "fstat", fstat)


def test_a_map_longer_than_stat_said_is_read_in_chunks_up_to_the_cap(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A file growing while it is read holds more than ``os.fstat`` said: the rest is read in
    bounded chunks, and never more than the cap plus one byte."""
    monkeypatch.setattr(mapread, "_READ_CHUNK", 5)
    path = write(tmp_path, "grew.txt", TUTORIAL)
    stat_says_empty(monkeypatch)
    assert load_map(path) == parse_text_map(TUTORIAL)
    monkeypatch.setattr(mapread, "MAX_MAP_BYTES", 1024 * 1024)
    reads: list[int] = []
    real_open = open

    def spying_open(*args: object, **kwargs: object):  # type: ignore[no-untyped-def]
        handle = real_open(*args, **kwargs)  # type: ignore[call-overload]
        read = handle.read
        handle.read = lambda n=-1: reads.append(n) or read(n)  # type: ignore[method-assign]
        return handle

    monkeypatch.setattr(mapread, "open", spying_open, raising=False)
    monkeypatch.setattr(mapread, "_READ_CHUNK", 64 * 1024)
    path = write(tmp_path, "big.txt", b"." * (3 * 1024 * 1024))
    monkeypatch.setattr(mapread, "_check_kind", lambda *args: None)  # past the os.stat
    assert error_of(load_map, path) == f"{path}: file is 1.1 MB; a map may be at most 1 MB"
    assert max(reads) <= 64 * 1024 and sum(reads) == 1024 * 1024 + 1


def within_seconds(seconds: float, func, *args: object) -> object:  # type: ignore[no-untyped-def]
    """``func(*args)``'s result or exception, failing the test if it takes longer (a hang)."""
    outcome: list[object] = []

    def call() -> None:
        try:
            outcome.append(func(*args))
        except Exception as exc:  # noqa: BLE001 - handed back to the test
            outcome.append(exc)

    thread = threading.Thread(target=call, daemon=True)
    thread.start()
    thread.join(seconds)
    assert outcome, f"{func.__name__} hung"
    return outcome[0]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no named pipes on this system")
def test_a_fifo_is_refused_at_once(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A named pipe with no writer would block ``open`` (and ``read``) forever."""
    path = tmp_path / "pipe.txt"
    os.mkfifo(path)
    error = within_seconds(5, load_map, path)
    assert isinstance(error, MapError) and str(error) == f"{path}: not a regular file"
    # Swapped in between the os.stat and the open: the open does not block, fstat refuses it.
    real_stat = os.stat
    regular = real_stat(write(tmp_path, "m.txt", TUTORIAL))
    monkeypatch.setattr(mapread.os, "stat", lambda p, *a, **k: regular if p == str(path)
                        else real_stat(p, *a, **k))
    error = within_seconds(5, load_map, path)
    assert isinstance(error, MapError) and str(error) == f"{path}: not a regular file"


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero on this system")
def test_a_device_is_refused(tmp_path: Path) -> None:
    link = tmp_path / "zero.txt"
    link.symlink_to("/dev/zero")
    for path in (Path("/dev/zero"), link):
        error = within_seconds(5, load_map, path)
        assert isinstance(error, MapError) and str(error) == f"{path}: not a regular file"


@pytest.mark.parametrize("content, where, what", [
    (b"S.\n.G\x00\n", "2:3", "binary file (a NUL byte), not a map"),
    (b"\x89PNG\r\n\x1a\n", "1:1", "not UTF-8 (byte 0x89): a map is UTF-8 text"),
    ("S.\n.G\n".encode("utf-16"), "1:4", "binary file (a NUL byte), not a map"),
    (b"S.\n\xff\xfe\n", "2:1", "not UTF-8 (byte 0xff): a map is UTF-8 text"),
    ("Sé\n.\xffG\n".encode("utf-8").replace(b"\xc3\xbf", b"\xbf"), "2:2",
     "not UTF-8 (byte 0xbf): a map is UTF-8 text"),
])
def test_load_map_binary(tmp_path: Path, content: bytes, where: str, what: str) -> None:
    """A NUL or a byte that is not UTF-8 is named at its line and column (in characters)."""
    path = write(tmp_path, "b.map", content)
    assert error_of(load_map, path) == f"{path}:{where}: {what}"


@pytest.mark.parametrize("row", [".", "..........", "T" * 80])
def test_loading_a_map_of_many_short_rows_peaks_near_its_size(tmp_path: Path, row: str) -> None:
    """A map of millions of one-cell rows once peaked at about 90 times its size (a Python
    object per row, twice): now about 10 (the text, the lines, a compact grid)."""
    rows = 500_000 // (len(row) + 1)
    if row == ".":
        text = "S\n" + f"{row}\n" * rows + "G\n"
    else:
        text = f"type octile\nheight {rows}\nwidth {len(row)}\nmap\n" + f"{row}\n" * rows
    path = write(tmp_path, "many.txt", text)
    load_map(path)  # once first, so one-off caches do not count
    tracemalloc.start()
    try:
        grid = load_map(path)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert grid.height >= rows
    assert peak < 12 * len(text)


def test_a_map_over_the_limit_is_refused_in_one_line_naming_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(mapread, "MAX_MAP_BYTES", 1024 * 1024)
    path = write(tmp_path, "dots.txt", "S\n" + ".\n" * (600 * 1024) + "G\n")
    assert error_of(load_map, path) == f"{path}: file is 1.2 MB; a map may be at most 1 MB"
