"""Lessons: a Markdown text whose sections move the app (``tui-search --lesson NAME|FILE.md``).

A lesson is split into sections at its ``## `` headings (what comes before the first one is
shown with the first).  A fenced block with the info string ``lesson`` at the head of a
section sets the app's state for that section, one ``key: value`` a line (:data:`KEYS`).  A
block changes only the keys it names: the others keep what the blocks before it set, from the
defaults (:class:`State`), so a section shows the same whether it is reached forwards or
backwards.  A section without a block leaves the app as the student has it.

Everything is checked when the lesson is read: a bad block is a
:class:`~tui_search.engine.maps.read.MapError` naming the lesson file, line and column.  No
Textual here: :mod:`tui_search.tui.model.lesson_play` applies a section to the session.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from tui_search.engine.maps.graph_file import BUILT_IN
from tui_search.engine.maps.grid import DEFAULT_ORDER, parse_order
from tui_search.engine.maps.load import load_board
from tui_search.engine.maps.read import MapError, read_text
from tui_search.engine.maps.source import Lines
from tui_search.engine.search.choices import (
    CORNER_RULES,
    GOAL_TESTS,
    GRAPH_ORDERS,
    TABLE,
    VISIT_RULES,
    Semantics,
)
from tui_search.engine.search.compare import parse_compare
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.registry import ALGORITHMS, DEFAULT_ALGORITHM, get_algorithm

if TYPE_CHECKING:  # read only when a lesson shows one (tomllib and the conditions)
    from tui_search.engine.course.exercise_file import Exercise

#: Bigger lessons are refused before reading (a long one is a few pages of text).
MAX_LESSON_BYTES = 64 * 1024
#: A lesson's sections, and a section's text (what the panel shows at once), are at most
#: this many: the panel's Markdown parser takes time and memory many times the text of some
#: texts (``[[[[``, tables of thousands of cells).
MAX_SECTIONS = 200
MAX_SECTION_CHARS = 4000
#: The built-in lessons: ``tui_search/lessons/NAME.md``.
LESSON_DIR = Path(__file__).resolve().parents[2] / "lessons"  # tui_search/lessons
ON_OFF = {"on": True, "off": False}
#: A block's keys, and what each takes (for the docs and the errors).
KEYS: dict[str, str] = {
    "map": "a map or graph file, relative to the lesson file, or romania",
    "algorithm": ", ".join(ALGORITHMS),
    "step": "a step number, or end",
    "compare": "two to four searches (bfs,dfs), or off",
    "order": "the moves in order (N,W,S,E); on a graph, file or name",
    "corners": ", ".join(CORNER_RULES),
    "visit": ", ".join(VISIT_RULES),
    "goal-test": ", ".join((*GOAL_TESTS, "default")),
    "tree-search": "on, off",
    "heuristic": ", ".join((*HEURISTICS, TABLE)),
    "exercise": "1, 2, an exercise file (FILE.toml, relative to the lesson file), off",
    "code": "on, off",
}
_FIELDS = {"compare": "searches"}  # a block's key: its State field, where the names differ
_FENCE = re.compile(r"^( {0,3})(`{3,}|~{3,})\s*([^`\s]*)")


@dataclass(frozen=True)
class State:
    """What a section shows: ``step`` None is the end of the search; ``map`` None keeps the
    map shown (or shows an exercise file's own); ``searches`` (the block's ``compare``), when
    set, are shown a pane each, else ``algorithm`` alone."""

    map: Path | None = None
    algorithm: str = DEFAULT_ALGORITHM
    step: int | None = 0
    searches: str | None = None
    order: tuple[str, ...] = DEFAULT_ORDER
    corners: str = "always"
    visit: str = "generate"
    goal_test: str | None = None
    tree_search: bool = False
    heuristic: str = DEFAULT_HEURISTIC
    exercise: int | Exercise | None = None  # the tutorial's 1 or 2, or a file's
    code: bool = False

    @property
    def semantics(self) -> Semantics:
        return Semantics(order=self.order, corners=self.corners, visit=self.visit,
                         goal_test=self.goal_test, tree_search=self.tree_search,
                         heuristic=self.heuristic)

    @property
    def spec(self) -> str:
        """The searches shown, as ``--compare`` spells them (one key: one pane)."""
        return self.searches or self.algorithm


@dataclass(frozen=True)
class Section:
    title: str
    text: str  # the Markdown shown: the heading and the text, not the block
    state: State | None  # None: no block (the app stays as it is)
    line: int  # of the heading


@dataclass(frozen=True)
class Lesson:
    name: str
    path: Path
    title: str
    sections: tuple[Section, ...]


def built_in() -> dict[str, str]:
    """The built-in lessons: name and title."""
    return {p.stem: read_lesson(p).title for p in sorted(LESSON_DIR.glob("*.md"))}


def find_lesson(name: str) -> Path:
    """A built-in lesson's file by name, or ``name`` as a file."""
    if name in {p.stem for p in LESSON_DIR.glob("*.md")}:
        return LESSON_DIR / f"{name}.md"
    path = Path(name)
    if not path.suffix and not path.exists():
        raise MapError(name, f"no such lesson (built in: {', '.join(built_in())})")
    return path


def _value(key: str, text: str, base: Path) -> object:
    """The block's ``key: text`` as the state's value; ``ValueError`` (one line) if bad."""
    choices = {"corners": CORNER_RULES, "visit": VISIT_RULES,
               "heuristic": (*HEURISTICS, TABLE),
               "algorithm": tuple(ALGORITHMS)}
    if key in choices:
        if text not in choices[key]:
            raise ValueError(f"use {KEYS[key]}")
        return text
    if key in ("tree-search", "code"):
        if text not in ON_OFF:
            raise ValueError("use on or off")
        return ON_OFF[text]
    if key == "goal-test":
        if text not in (*GOAL_TESTS, "default"):
            raise ValueError(f"use {KEYS[key]}")
        return None if text == "default" else text
    if key == "step":
        return _step(text)
    if key == "exercise":
        if text in ("1", "2", "off"):
            return None if text == "off" else int(text)
        if not text.endswith(".toml"):
            raise ValueError(f"use {KEYS[key]}")
        from tui_search.engine.course.exercise_file import load_exercise

        try:
            return load_exercise(base / text)
        except MapError as exc:
            raise ValueError(str(exc)) from None
    if key == "order":
        return (text,) if text in GRAPH_ORDERS else parse_order(text)
    if key == "compare":
        if text == "off":
            return None
        parse_compare(text)
        return ",".join(p.strip() for p in text.split(","))
    return _map_path(text, base)


def _step(text: str) -> int | None:
    """``step: N`` or ``step: end`` (None)."""
    if text == "end":
        return None
    if not text.isdigit():
        raise ValueError("use a step number (0, 1, ...) or end")
    return int(text)


def _map_path(text: str, base: Path) -> Path:
    """``map: FILE``, relative to the lesson's folder: a map (or a graph) that loads;
    ``map: romania``, the built-in graph."""
    path = Path(text) if text in BUILT_IN else (base / text).resolve()
    try:
        load_board(path)
    except MapError as exc:
        raise ValueError(str(exc)) from None
    return path


def _block(lines: list[str], first: int, base: Path, name: str,
           state: State) -> tuple[State, dict[str, tuple[int, int]]]:
    """The state after the block's ``key: value`` lines (``first``: the first's line), and
    where each key set is (line, column)."""
    seen: dict[str, Any] = {}
    where: dict[str, tuple[int, int]] = {}
    for n, raw in enumerate(lines, first):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        col = len(raw) - len(raw.lstrip()) + 1
        key, colon, text = line.partition(":")
        key = key.strip()
        if not colon:
            raise MapError(name, f"expected 'key: value', got {line!r}", n, col)
        if key not in KEYS:
            raise MapError(name, f"unknown key {key!r} (use {', '.join(KEYS)})", n, col)
        if key in seen:
            raise MapError(name, f"{key} is set twice in this block", n, col)
        text = text.strip()
        try:
            value = _value(key, text, base)
        except ValueError as exc:
            rest = raw.split(":", 1)[1]
            at = raw.index(":") + 2 + len(rest) - len(rest.lstrip())
            raise MapError(name, f"{key} {text!r}: {exc}", n, at) from None
        seen[key] = value
        where[key] = (n, col)
    state = replace(state, **{_field(key): value for key, value in seen.items()})
    if seen.get("exercise") is not None:
        state = _exercise_rules(state, seen, where, name)
        if not isinstance(state.exercise, int) and "map" not in seen:
            state = replace(state, map=None)  # a file's exercise: on its own map
    return state, where


#: The block's keys that are choices: the State's fields of the same names.
_CHOICES = ("order", "corners", "visit", "goal-test", "tree-search", "heuristic")


def _exercise_rules(state: State, seen: dict[str, Any], where: dict[str, tuple[int, int]],
                    name: str) -> State:
    """``state`` under the rules of the exercise it shows (its searches, and so the panes,
    run under them); a choice the block names that differs is refused at its key."""
    from tui_search.engine.course.exercise_file import built_in_exercise

    exercise = state.exercise
    if isinstance(exercise, int):
        exercise = built_in_exercise(exercise)
    assert exercise is not None
    rules = exercise.semantics
    said = exercise.rules or "the tutorial's"
    for key in _CHOICES:
        if key in seen and getattr(rules, _field(key)) != seen[key]:
            raise MapError(name, f"{key}: the exercise runs under its own rules ({said}): "
                           f"leave out {key}", *where[key])
    return replace(state, **{_field(key): getattr(rules, _field(key)) for key in _CHOICES})


def _field(key: str) -> str:
    """The :class:`State` field a block's ``key`` sets."""
    return _FIELDS.get(key, key.replace("-", "_"))


def _refused(state: State) -> str | None:
    """Why the combination of choices in ``state`` makes no sense (None: it does)."""
    try:
        sem = state.semantics
        if state.searches:
            parse_compare(state.searches, sem, fit=True)
        else:
            sem.check(get_algorithm(state.algorithm))
    except ValueError as exc:
        return str(exc)
    return None


def _check(before: State, state: State, where: dict[str, tuple[int, int]], name: str,
           line: int) -> None:
    """Refuse a combination of choices that makes no sense: at the key the block set last
    without which it would make sense (``where``: the block's keys' places; ``before``: the
    state before the block), else at the block's ``line``."""
    reason = _refused(state)
    if reason is None:
        return
    for key in reversed(list(where)):
        field = _field(key)
        if _refused(replace(state, **{field: getattr(before, field)})) is None:
            raise MapError(name, reason, *where[key])
    raise MapError(name, reason, line, 1)


def _check_sizes(lines: Lines, heads: list[int], shown: str) -> None:
    """Refuse a section (with its block and blank lines; the first with what comes before
    it) of more than :data:`MAX_SECTION_CHARS` characters, at its heading."""
    for s, head in enumerate(heads):
        begin = lines.offset(0 if s == 0 else head)
        end = lines.offset(heads[s + 1]) if s + 1 < len(heads) else len(lines.text) + 1
        if end - begin - 1 > MAX_SECTION_CHARS:
            raise MapError(shown, f"the section has {end - begin - 1:,} characters; a section "
                           f"may have at most {MAX_SECTION_CHARS:,}", head + 1, 1)


def parse_lesson(text: str, path: Path, name: str | None = None) -> Lesson:
    """The lesson in ``text`` (read from ``path``: maps are relative to its folder)."""
    shown = str(path)
    lines = Lines(text)  # (no string a line: a lesson of blank lines is many times its size)
    heads: list[int] = []  # the indexes of the ## lines, outside fenced blocks
    fence = ""
    for i, line in enumerate(lines):
        match = _FENCE.match(line)
        if fence:
            if match and match.group(2).startswith(fence) and not match.group(3):
                fence = ""
        elif match:
            fence = match.group(2)
        elif line.startswith("## "):
            heads.append(i)
            if len(heads) > MAX_SECTIONS:
                raise MapError(shown, f"more than {MAX_SECTIONS} sections", i + 1, 1)
    if fence:
        raise MapError(shown, "a fenced block is not closed by the end of the file")
    if not heads:
        raise MapError(shown, "no sections: start each with a '## ' heading", 1)
    _check_sizes(lines, heads, shown)
    title = next((ln[2:].strip() for ln in lines[:heads[0]] if ln.startswith("# ")),
                 path.stem)
    state = State()
    sections = []
    for s, head in enumerate(heads):
        end = heads[s + 1] if s + 1 < len(heads) else len(lines)
        body = lines[head + 1:end]
        section_state: State | None = None
        first = next((i for i, ln in enumerate(body) if ln.strip()), 0)
        opened = _FENCE.match(body[first]) if body else None
        if opened and opened.group(3) == "lesson":
            close = next((i for i in range(first + 1, len(body)) if
                          body[i].strip().startswith(opened.group(2))), len(body))
            at = head + first + 2  # the block's first line, counted from 1
            before = state
            state, where = _block(body[first + 1:close], at + 1, path.parent, shown, state)
            _check(before, state, where, shown, at)
            section_state = state
            body = body[:first] + body[close + 1:]
        for i, ln in enumerate(body):
            again = _FENCE.match(ln)
            if again and again.group(3) == "lesson":
                raise MapError(shown, "a lesson block must come first in its section",
                               head + i + 2, 1)
        opening = lines[:heads[0]] if s == 0 else []
        shown_text = "\n".join([*opening, lines[head], *body]).strip() + "\n"
        sections.append(Section(lines[head][3:].strip(), shown_text, section_state, head + 1))
    return Lesson(name or path.stem, path, title, tuple(sections))


def read_lesson(path: Path, name: str | None = None) -> Lesson:
    """Read and check the lesson at ``path`` (``MapError`` if it cannot be read or is bad)."""
    text = read_text(str(path), "a lesson", MAX_LESSON_BYTES)
    return parse_lesson(text.replace("\r\n", "\n"), path, name)


__all__ = ["KEYS", "LESSON_DIR", "Lesson", "Section", "State", "built_in", "find_lesson",
           "parse_lesson", "read_lesson"]
