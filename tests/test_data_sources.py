"""The real MovingAI files the tests read live in the repository, each with its source named.

A test that reads a file outside the repository is skipped in every fresh clone and in CI, so
the copies must be here; and a copy is only worth having if it is the unmodified benchmark file,
so SOURCES.md names each one with the git blob of the original.
"""

from __future__ import annotations

import hashlib
import re

from tests.helpers import MOVINGAI, ROOT


def git_blob(data: bytes) -> str:
    """What ``git hash-object`` prints for a file holding ``data``."""
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def sources_rows() -> dict[str, str]:
    """File name -> blob prefix, from the table in SOURCES.md."""
    text = (MOVINGAI / "SOURCES.md").read_text()
    return {
        m.group(1): m.group(2)
        for m in re.finditer(r"^\| `([^`]+)` \|.*\| ([0-9a-f]{8}) \|$", text, re.MULTILINE)
    }


def test_the_movingai_folder_is_inside_the_repository() -> None:
    assert MOVINGAI.resolve().is_relative_to(ROOT) and MOVINGAI.is_dir()


def test_every_copied_file_has_its_source_and_is_byte_identical() -> None:
    files = {p.name for p in MOVINGAI.iterdir() if p.name != "SOURCES.md"}
    rows = sources_rows()
    assert set(rows) == files
    for name, blob in rows.items():
        assert git_blob((MOVINGAI / name).read_bytes()).startswith(blob), name


#: The one big copy: the overview's snapshot draws the whole of a real 512x512 maze.
BIG_COPIES = {"maze512-1-0.map"}


def test_the_copies_stay_small() -> None:
    """Whole benchmark files are copied only when small, but for the maze the overview's
    snapshot draws; the other 512x512 ones stay outside."""
    assert sum(p.stat().st_size for p in MOVINGAI.iterdir() if p.name not in BIG_COPIES) < 100_000
    assert all((MOVINGAI / name).stat().st_size < 300_000 for name in BIG_COPIES)
