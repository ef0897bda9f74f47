"""File names as typed: :func:`describe_name` shows any name on one line, every character
visible; :func:`name_problem` says in one line why a name cannot be a file's (strictly, in
the served save folder, control and bidi characters too)."""

from __future__ import annotations

import os

from hypothesis import given
from hypothesis import strategies as st

from tui_search.engine.util.filenames import describe_name, name_problem


def test_describe_name_escapes_control_and_bidi_characters() -> None:
    assert describe_name("map.txt") == "map.txt"
    assert describe_name("[/]é 地図.txt") == "[/]é 地図.txt"
    assert describe_name("\x1b[31mred\x07.txt") == "\\x1b[31mred\\x07.txt"
    assert describe_name("evil\u202etxt.exe") == "evil\\u202etxt.exe"
    assert describe_name("a\nb\rc\u2028d") == "a\\nb\\rc\\u2028d"
    assert describe_name("bad\udc80") == "bad\\udc80"


@given(st.text())
def test_any_name_is_described_on_one_printable_line(name: str) -> None:
    shown = describe_name(name)
    assert shown.isprintable()
    assert describe_name(shown) == shown


def test_names_no_file_can_have() -> None:
    assert name_problem("") == name_problem("   ") == "type a file name"
    assert "NUL" in (name_problem("a\x00b.txt") or "")
    assert "too long" in (name_problem("a" * 300 + ".txt") or "")
    assert "too long" in (name_problem(("d" * 200 + os.sep) * 30 + "m.txt") or "")
    assert name_problem("d" * 200 + os.sep + "m" * 200 + ".txt") is None  # each part fits
    assert name_problem("é" * 127 + ".txt") is not None  # 254 bytes + 4
    assert name_problem("\ud800.txt") is not None  # not encodable


def test_control_and_bidi_characters_are_refused_only_strictly() -> None:
    for name in ("\x1b[31m.txt", "evil\u202etxt.map", "tab\there.txt", "a\u2066b.txt"):
        assert name_problem(name) is None
        problem = name_problem(name, strict=True)
        assert problem is not None and "control, bidi or invisible" in problem
        assert problem.isprintable()
    assert name_problem("[bold]plain é.txt", strict=True) is None


@given(st.text(), st.booleans())
def test_name_problem_never_raises_and_is_one_line(name: str, strict: bool) -> None:
    problem = name_problem(name, strict=strict)
    assert problem is None or (problem and problem.isprintable())
