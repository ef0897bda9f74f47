"""The issue's hostile files on the command line: each a one-line error and exit 2, never a
traceback (``RecursionError`` once) nor the app opened.  The readers themselves are held by
tests/engine/test_untrusted_files.py."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_cli_trace import TUTORIAL, run_cli
from tui_search.cli import main as cli


@pytest.fixture
def opened(monkeypatch) -> list:
    """The apps the command line would have run (none is)."""
    apps: list = []
    monkeypatch.setattr(cli, "run_app", lambda options: apps.append(options) or 0)
    return apps


DEEP_TRACE = '{"node": ' + "[" * 200_000 + "]" * 200_000 + "}\n"
EXERCISE = ('title = "t"\ntext = "t"\ngenerate = "maze 9x9 1"\nsearches = ["bfs"]\n'
            'solved = "bfs.found"\nhint = ')
DEEP_HINT = EXERCISE + "[" * 100_000 + "]" * 100_000 + "\n"  # the issue's
DEEPISH_HINT = EXERCISE + "[" * 20_000 + "]" * 20_000 + "\n"  # within the size limit


@pytest.mark.parametrize("argv, file, text, expected", [
    (["--headless", "-a", "bfs", "--check-trace", "T"], "T", DEEP_TRACE,
     "T:1:109: nested more than 100 deep"),
    (["--replay", "T"], "T", DEEP_TRACE, "T:1:109: nested more than 100 deep"),
    (["--exercise", "E.toml"], "E.toml", DEEP_HINT,
     "E.toml: file is 195.5 KB; an exercise file may be at most 64 KB"),
    (["--exercise", "E.toml"], "E.toml", DEEPISH_HINT, "E.toml:6:108: nested more than 100 deep"),
    (["--exercise", "E.toml", "--headless"], "E.toml", DEEPISH_HINT,
     "E.toml:6:108: nested more than 100 deep"),
    (["--lesson", "L.md"], "L.md", "## One\n" + "x" * 5000 + "\n",
     "L.md:1:1: the section has 5,008 characters; a section may have at most 4,000"),
    (["--headless", "-a", "bfs", "--check-trace", "T"], "T", '{"node": [1, 1]}\n\xff\n',
     "T:2:1: not UTF-8 (byte 0xc3): a trace is UTF-8 text"),
])
def test_a_hostile_file_is_one_line_and_exit_2(capsys, tmp_path: Path, monkeypatch, opened,
                                               argv, file, text, expected) -> None:
    monkeypatch.chdir(tmp_path)
    data = text.encode("utf-8")
    (tmp_path / file).write_bytes(data.replace(b"\xc3\xbf", b"\xc3") if "\xff" in text else data)
    code, out, err = run_cli(capsys, TUTORIAL, *argv)
    assert (code, out, err) == (2, "", f"tui-search: {expected}\n")
    assert not opened
