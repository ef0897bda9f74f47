"""Exercise files: a teacher's exercise in TOML (docs/04-exercises.md, "Exercise files").

    title = "Greedy is not optimal"
    text = "Move obstacles so that greedy best-first's path costs more than A*'s."
    map = "tutorial.txt"              # relative to this file; or generate = "maze 15x15 7"
    searches = ["greedy", "astar"]    # as --compare takes them (astar:manhattan allowed)
    edits = ["obstacles"]             # what the student may change
    solved = "greedy.found and astar.found and greedy.cost > astar.cost"
    hint = "Greedy looks only at h."  # optional
    order = "N,E,S,W"                 # optional: the rules every search of it runs under,
    corners = "never"                 # as the settings name them (the tutorial's otherwise)

A by-hand exercise (``by_hand = true``, its one search run by the student, step by step) has
no ``solved``: it is solved when the run is finished within ``mistakes`` (its allowance).  A
generated map's seed may be ``seed = "student"``: each student's own map, from their name
(:meth:`Exercise.for_student`).

The tutorial's two exercises ship as two such files (``tui_search/exercises/``), named ``1``
and ``2``.  A bad file is a :class:`~tui_search.engine.maps.read.MapError` naming the file, the
line and the column.  Plain Python, no UI.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any

from tui_search.engine.course.condition import ConditionError, Node, names, parse_condition
from tui_search.engine.course.toml_places import condition_position, key_position, toml_error
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid, parse_order
from tui_search.engine.maps.read import MapError, bad_file, read_text
from tui_search.engine.search.choices import (
    CORNER_RULES,
    DEFAULT_SEMANTICS,
    GOAL_TESTS,
    VISIT_RULES,
    Semantics,
)
from tui_search.engine.search.compare import Contender, parse_compare
from tui_search.engine.search.heuristics import HEURISTICS
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.util.untrusted import BadInput, check_nesting, check_values

if TYPE_CHECKING:
    from tui_search.engine.maps.generate import Recipe


def toml_parser() -> ModuleType:
    """The TOML parser: the standard library's ``tomllib`` (Python 3.11 on), else ``tomli``, the
    same parser as a package (Python 3.10; pyproject.toml requires it there).  A function, so a
    test can take ``tomllib`` away and see ``tomli`` chosen."""
    try:
        return importlib.import_module("tomllib")
    except ImportError:  # Python 3.10
        return importlib.import_module("tomli")


_toml = toml_parser()

#: Bigger exercise files are refused before reading (one is a few hundred bytes).
MAX_EXERCISE_BYTES = 64 * 1024
#: What a student may be allowed to change.
EDITS = ("start", "goal", "obstacles", "terrain")
OTHER_EDITS = ("fail", "hint")
#: The figures a verdict can show, in the words of its reason.
FIGURES = ("found", "moves", "cost", "expanded", "generated", "max_frontier")
BUILT_IN = Path(__file__).resolve().parents[2] / "exercises"  # tui_search/exercises
BUILT_IN_FILES = {1: "1-bfs-expands-less.toml", 2: "2-dfs-not-optimal.toml"}
#: The rules' keys (the search choices, :mod:`tui_search.engine.search.choices`).
RULE_KEYS = ("order", "corners", "visit", "goal_test", "heuristic", "tree_search")
_KEYS = ("title", "text", "map", "generate", "graph", "seed", "searches", "edits", "solved", "hint",
         "other_edits", "figures", "by_hand", "mistakes", *RULE_KEYS)
#: ``seed = "student"``: each student's own map, from their name.
STUDENT_SEED = "student"
#: A by-hand exercise's allowance at most (a mistake a step of a big map).
MAX_MISTAKES = 1_000_000


@dataclass(frozen=True, eq=False)
class Exercise:
    """An exercise read from its file: what to show, the map it starts from, the searches,
    what may change and the condition that solves it."""

    path: str
    number: int | None  # the tutorial's 1 or 2; None for a teacher's file
    title: str
    text: str
    board: Grid | Graph  # the exercise's map or graph, as the student starts
    searches: tuple[tuple[str, Contender], ...]  # (the condition's name, the search)
    edits: frozenset[str]
    condition: Node
    solved_text: str
    fields: tuple[str, ...]  # the condition's SEARCH.FIELD names, in order
    figures: tuple[str, ...]  # the fields the reason shows
    hint: str
    other_edits: str
    semantics: Semantics = DEFAULT_SEMANTICS  # the rules every search of it runs under
    #: Done by hand (its one search stepped by the student): solved when the run is
    #: finished with at most ``mistakes`` mistakes; no condition then.
    by_hand: bool = False
    mistakes: int = 0
    #: ``seed = "student"``: the map is each student's own (:meth:`for_student`); ``grid``
    #: is then the map of the seed "student" until a student is named.
    recipe: Recipe | None = None
    student_seed: bool = False
    student: str = ""  # the student whose map ``grid`` is ("" none)

    @property
    def grid(self) -> Grid:
        """The exercise's map (an exercise on a graph has none: :attr:`board`)."""
        assert isinstance(self.board, Grid), "an exercise on a graph has no grid"
        return self.board

    @property
    def graph(self) -> Graph | None:
        """The exercise's graph (``graph = "FILE"``), else None."""
        return None if isinstance(self.board, Grid) else self.board

    @property
    def rules(self) -> str:
        """Its rules where they are not the tutorial's, in a few words ("moves N,E,S,W ·
        corners: never"); "" for the tutorial's."""
        return " · ".join(self.semantics.differences())

    def for_student(self, name: str) -> Exercise:
        """The exercise on ``name``'s own map (``seed = "student"``; any other exercise is
        everyone's, itself)."""
        from dataclasses import replace

        from tui_search.engine.maps.generate import MAX_SEED_CHARS, generate

        seed = "".join(ch for ch in name if ch.isprintable()).strip()[:MAX_SEED_CHARS]
        if not self.student_seed or self.recipe is None or not seed:
            return self
        recipe = self.recipe._replace(seed=seed)
        return replace(self, board=generate(recipe, recipe.title), recipe=recipe, student=seed)

    @property
    def name(self) -> str:
        """What a headless line calls it: ``exercise 1``, or ``exercise greedy`` (the file)."""
        return f"exercise {self.number if self.number is not None else Path(self.path).stem}"


def search_name(spec: str) -> str:
    """The condition's name for one of ``searches``: ``astar:manhattan`` -> astar_manhattan,
    weighted A*'s ``astar:w=2`` -> astar_w_2 (``astar:w=1.5`` -> astar_w_1_5), a stopping
    rule's ``biastar:first-meeting`` -> biastar_first_meeting."""
    return (spec.strip().replace(":", "_").replace("=", "_").replace(".", "_")
            .replace("-", "_"))


class KeyReader:
    """The file's keys, each checked, a MapError at its line for a bad one."""

    def __init__(self, path: str, text: str, data: dict[str, Any],
                 number: int | None = None) -> None:
        self.path, self.text, self.data = path, text, data
        self.number = number  # the tutorial's exercise's, None for a teacher's file

    def error(self, key: str, message: str) -> MapError:
        line, col = key_position(self.text, key)
        return MapError(self.path, f"{key}: {message}", line, col)

    def string(self, key: str, default: str | None = None) -> str:
        value = self.data.get(key, default)
        if value is None:
            raise MapError(self.path, f"the exercise has no {key} (docs/04-exercises.md)")
        if not isinstance(value, str):
            raise self.error(key, "expected a string")
        return value

    def strings(self, key: str, default: list[str] | None = None) -> list[str]:
        value = self.data.get(key, default)
        if value is None:
            raise MapError(self.path, f"the exercise has no {key} (docs/04-exercises.md)")
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise self.error(key, "expected a list of strings, as in [\"bfs\", \"dfs\"]")
        return value


def _semantics(reader: KeyReader) -> Semantics:
    """The rules the file's keys set (the tutorial's for those it leaves out)."""
    data = reader.data
    choices: dict[str, Any] = {}
    if "order" in data:
        try:
            choices["order"] = parse_order(reader.string("order"))
        except ValueError as exc:
            raise reader.error("order", f"{exc} (as in \"N,E,S,W\")") from None
    for key, allowed in (("corners", CORNER_RULES), ("visit", VISIT_RULES),
                         ("goal_test", GOAL_TESTS), ("heuristic", tuple(HEURISTICS))):
        if key in data:
            value = reader.string(key)
            if value not in allowed:
                raise reader.error(key, f"{value!r}: use {', '.join(allowed)}")
            choices[key] = value
    if "tree_search" in data:
        if not isinstance(data["tree_search"], bool):
            raise reader.error("tree_search", "expected true or false")
        choices["tree_search"] = data["tree_search"]
        if data["tree_search"] and "visit" in data:
            raise reader.error("visit", "does not apply with tree_search = true (it has no "
                               "visited set)")
    try:
        return Semantics(**choices)
    except ValueError as exc:  # each was checked: only a combination is left
        raise reader.error(next(k for k in RULE_KEYS if k in data), str(exc)) from None


def _contenders(reader: KeyReader, specs: list[str], semantics: Semantics) -> list[Contender]:
    """``searches`` under the rules: a bad search named at ``searches``, a rule that does not
    apply to one of them at the rule's key."""
    try:
        parse_compare(",".join(specs), fewest=1)
    except ValueError as exc:
        raise reader.error("searches", str(exc)) from None
    informed = any(get_algorithm(s.partition(":")[0].strip()).informed for s in specs)
    if "heuristic" in reader.data and not informed:
        raise reader.error("heuristic", "none of the searches uses a heuristic (greedy "
                               "and astar do)")
    try:
        return parse_compare(",".join(specs), semantics, fewest=1)
    except ValueError as exc:  # only the visit rule is refused for a search
        raise reader.error("visit", str(exc)) from None


def _grid(reader: KeyReader) -> tuple[Grid, Recipe | None, bool]:
    """The exercise's map, its recipe when generated, and whether it is each student's own
    (``seed = "student"``)."""
    from tui_search.engine.maps.generate import generate, make_recipe, parse_recipe
    from tui_search.engine.maps.load import load_map

    has = [k for k in ("map", "generate") if k in reader.data]
    if len(has) != 1:
        raise MapError(reader.path, "give the exercise a map = \"FILE\" or a generate = "
                       "\"KIND WxH SEED\" (one of the two)")
    if has[0] == "map":
        if "seed" in reader.data:
            raise reader.error("seed", "goes with generate = \"KIND WxH\", not a map file")
        where = Path(reader.path).parent / reader.string("map")
        try:
            return load_map(where), None, False
        except MapError as exc:
            raise reader.error("map", str(exc)) from None
    recipe_text = reader.string("generate")
    seed = reader.string("seed") if "seed" in reader.data else None
    try:
        if seed is None:
            recipe = parse_recipe(recipe_text)
        else:
            parts = recipe_text.split()
            if len(parts) != 2:
                raise ValueError(f"{recipe_text.strip()!r}: with seed = ..., expected KIND WxH "
                                 "(the seed given once), e.g. maze 15x15")
            recipe = make_recipe(parts[0], parts[1], seed)
    except ValueError as exc:
        raise reader.error("seed" if seed is not None and "seed" in str(exc) else "generate",
                           str(exc)) from None
    return generate(recipe, recipe.title), recipe, seed == STUDENT_SEED


def _by_hand(reader: KeyReader, specs: list[str]) -> tuple[bool, int]:
    """``by_hand`` and its ``mistakes`` allowance, checked against the other keys."""
    data = reader.data
    by_hand = data.get("by_hand", False)
    if not isinstance(by_hand, bool):
        raise reader.error("by_hand", "expected true or false")
    if not by_hand:
        if "mistakes" in data:
            raise reader.error("mistakes", "goes with by_hand = true")
        return False, 0
    if len(specs) != 1:
        raise reader.error("searches", "a by-hand exercise names one search, the one the "
                           "student steps (as [\"bfs\"])")
    for key in ("solved", "edits", "other_edits", "figures"):
        if key in data:
            raise reader.error(key, "not for a by-hand exercise: it is solved when the run is "
                               "finished within its mistakes")
    mistakes = data.get("mistakes", 0)
    if (not isinstance(mistakes, int) or isinstance(mistakes, bool)
            or not 0 <= mistakes <= MAX_MISTAKES):
        raise reader.error("mistakes", f"expected a whole number of mistakes allowed, 0 to "
                           f"{MAX_MISTAKES:,}")
    return True, mistakes


def _rules(reader: KeyReader) -> tuple[Graph | None, Semantics]:
    """The exercise's graph (``graph = "FILE"``; None: its map is a grid) and the rules its
    searches run under (a graph's are a graph's)."""
    if "graph" not in reader.data:
        return None, _semantics(reader)
    from tui_search.engine.course.graph_exercise import graph_semantics, read_graph

    if "map" in reader.data or "generate" in reader.data:
        raise reader.error("graph", "give the exercise a map, a generate or a graph (one)")
    graph = read_graph(reader)
    return graph, graph_semantics(reader, graph)


def _edits(reader: KeyReader, graph: Graph | None, by_hand: bool) -> list[str]:
    """``edits``, each one a grid's (or a graph's) edit."""
    edits = reader.strings("edits", [])
    if graph is not None:
        from tui_search.engine.course.graph_exercise import check_graph_edits

        check_graph_edits(reader, edits)
        if by_hand:
            raise reader.error("by_hand", "runs on a grid's map, not on a graph")
        return edits
    for edit in edits:
        if edit not in EDITS:
            raise reader.error("edits", f"unknown edit {edit!r} (use {', '.join(EDITS)})")
    return edits


def parse_exercise(text: str, path: str, number: int | None = None) -> Exercise:
    """The exercise ``text`` (the file ``path``'s contents) says; MapError when it is bad."""
    try:
        check_nesting(text, toml=True)  # before tomllib, which recurses
        check_values(text, 8 * len(text) + MAX_EXERCISE_BYTES, "[{,=")
        data: dict[str, Any] = _toml.loads(text)
    except BadInput as err:
        raise bad_file(path, err) from None
    except _toml.TOMLDecodeError as exc:
        raise toml_error(path, exc) from None
    except RecursionError:  # (a guard: check_nesting refuses anything this deep)
        raise MapError(path, "nested too deep") from None
    reader = KeyReader(path, text, data, number)
    unknown = [k for k in data if k not in _KEYS]
    if unknown:
        raise reader.error(unknown[0], f"unknown key (use {', '.join(_KEYS)})")
    specs = reader.strings("searches")
    graph, semantics = _rules(reader)
    contenders = _contenders(reader, specs, semantics)
    labels = [search_name(s) for s in specs]
    if len(set(labels)) != len(labels):
        raise reader.error("searches", "a search is named twice")
    by_hand, mistakes = _by_hand(reader, specs)
    edits = _edits(reader, graph, by_hand)
    other = reader.string("other_edits", "fail")
    if other not in OTHER_EDITS:
        raise reader.error("other_edits", f"{other!r}: use \"fail\" or \"hint\"")
    solved = reader.string("solved", "1 == 1" if by_hand else None)  # by hand: no condition
    try:
        condition = parse_condition(solved, labels)
    except ConditionError as exc:
        line, col = condition_position(text, exc.offset)
        raise MapError(path, f"solved: {exc.message}", line, col) from None
    fields = tuple(names(condition))
    figures = reader.strings("figures", [])
    for figure in figures:
        if figure not in FIGURES:
            raise reader.error("figures", f"unknown field {figure!r} (use "
                               f"{', '.join(FIGURES)})")
    shown = tuple(figures) or tuple(dict.fromkeys(f.split(".")[1] for f in fields))
    board: Grid | Graph
    if graph is not None:
        board, recipe, student_seed = graph, None, False
        return _made(reader, board, labels, contenders, edits, condition, solved, fields, shown,
                     other, semantics, by_hand, mistakes, recipe, student_seed)
    grid, recipe, student_seed = _grid(reader)
    if grid.start is None or grid.goal is None:
        raise reader.error("generate" if "generate" in data else "map",
                           "the exercise's map needs a start (S) and a goal (G)")
    return _made(reader, grid, labels, contenders, edits, condition, solved, fields, shown,
                 other, semantics, by_hand, mistakes, recipe, student_seed)


def _made(reader: KeyReader, board: Grid | Graph, labels: list[str],
          contenders: list[Contender], edits: list[str], *rest: Any) -> Exercise:
    """The exercise, its searches named (the rest: :class:`Exercise`'s fields from
    ``condition`` on)."""
    searches = tuple(zip(labels, contenders, strict=False))  # as before: not checked equal
    condition, solved, fields, shown, other, semantics, by_hand, mistakes, recipe, seed = rest
    return Exercise(reader.path, reader.number, reader.string("title"), reader.string("text"),
                    board, searches, frozenset(edits), condition, solved, fields, shown,
                    reader.string("hint", ""), other, semantics, by_hand, mistakes, recipe, seed)


def load_exercise(path: str | Path, number: int | None = None) -> Exercise:
    """Read the exercise file at ``path``."""
    where = str(path)
    text = read_text(where, "an exercise file", MAX_EXERCISE_BYTES)
    # A byte order mark (some Windows editors write one) is no part of the TOML.
    return parse_exercise(text.removeprefix("\ufeff"), where, number)


@cache
def built_in_exercise(number: int) -> Exercise:
    """The tutorial's exercise 1 or 2, from its shipped file (read once)."""
    if number not in BUILT_IN_FILES:
        raise ValueError("the tutorial has exercises 1 and 2")
    return load_exercise(BUILT_IN / BUILT_IN_FILES[number], number)


def find_exercise(name: str) -> Exercise:
    """``--exercise NAME``: ``1`` or ``2``, or an exercise file.  ValueError for another
    number, MapError for a bad file."""
    if name.strip().isdigit():
        return built_in_exercise(int(name))
    return load_exercise(name)


__all__ = ["EDITS", "STUDENT_SEED", "Exercise", "built_in_exercise", "find_exercise",
           "load_exercise", "parse_exercise", "search_name"]
