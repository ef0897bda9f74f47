"""Posthoc's search trace (version 1.4.0: ``.trace.yaml`` or ``.trace.json``), read as a trace
and written from a search, so a run opens in that visualiser.

A Posthoc trace is one document: ``version``, optional views, and ``events``, each with a
``type``, an ``id`` (a node), its parent's ``pId`` and here its cell ``x``, ``y``.  Read: each
``expanding`` (or ``expand``) event is a step taking off its cell, the ``generating`` (or
``generate``) events after it are the successors it added, in order; ``source`` and
``destination`` are the start and the goal (checked against the map's when they give a
cell); ``closing``, ``end`` and any other type are read and ignored.  An event with an ``id``
and no ``x``, ``y`` takes the cell an earlier event gave that ``id``.  A trace with no
``generating`` event after an expansion is of expansions only.  YAML is read by PyYAML's safe
loader, and a document with anchors or aliases is refused (a few lines of them can stand for
billions of events).  Written as JSON or as YAML (with no YAML library: block style, each
event a line in flow style), a rectangle a cell as its view, every node's id its cell's index
``y * width + x``; what the app says of the run (its search, the map's file) under a key of
its own, which Posthoc leaves alone.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from dataclasses import replace
from typing import Any

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import MapError, bad_file, read_text
from tui_search.engine.run.each_step import search_each_step
from tui_search.engine.run.recording import Step
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.state import State
from tui_search.engine.traces.read import Trace, load_trace, read_trace
from tui_search.engine.util.untrusted import MAX_DEPTH, BadInput, check_nesting, check_values

#: The version Posthoc's visualiser needs declared.
VERSION = "1.4.0"
#: The file names read as Posthoc's, by their ending.
#: Bigger Posthoc files are refused before reading.  A document is parsed whole (json,
#: PyYAML), at up to 20 (JSON) and 100 (YAML) times its size: smaller caps than the app's
#: own traces', which are read a line at a time.
MAX_POSTHOC_JSON_BYTES = 32 * 1024 * 1024
MAX_POSTHOC_YAML_BYTES = 8 * 1024 * 1024
#: What a document's values may take: bytes a byte of its text, and a megabyte beside
#: (:func:`~tui_search.engine.util.untrusted.check_values`: each bracket and separator stands
#: for an object's bytes).  A trace's events are small objects, a separator every few bytes.
VALUES_BUDGET, VALUES_FIXED = 32, 1 << 20
SUFFIXES = (".trace.json", ".trace.yaml", ".trace.yml")

_EXPAND, _GENERATE = ("expanding", "expand"), ("generating", "generate")


def is_posthoc(name: str) -> bool:
    """Is ``name`` a Posthoc trace's file name (``.trace.json``, ``.trace.yaml``)?"""
    return name.lower().endswith(SUFFIXES)


def _document(text: str, name: str, as_json: bool) -> dict[str, Any]:
    """The document: JSON, or YAML without anchors or aliases."""
    if as_json:
        _check_shape(text, name, "[{,:")  # before json recurses or builds objects
        try:
            value = json.loads(text)
        except RecursionError:  # (a guard: the check refuses anything this deep)
            raise MapError(name, "nested too deep") from None
        except ValueError as exc:
            raise MapError(name, f"not JSON: {getattr(exc, 'msg', exc)}",
                           getattr(exc, "lineno", None), getattr(exc, "colno", None)) from None
    else:
        value = _yaml(text, name)
    if not isinstance(value, dict) or not isinstance(value.get("events"), list):
        raise MapError(name, 'a Posthoc trace is a document with "events": a list of events')
    version = value.get("version")
    if version is not None and str(version) != VERSION:
        raise MapError(name, f"Posthoc trace version {version}: tui-search reads {VERSION}")
    return value


def _check_shape(text: str, name: str, separators: str) -> None:
    """Refuse a document nested too deep or with more values than :data:`VALUES_BUDGET`
    allows, before a parser recurses or builds its objects."""
    try:
        check_nesting(text)
        check_values(text, VALUES_BUDGET * len(text) + VALUES_FIXED, separators)
    except BadInput as err:
        raise bad_file(name, err) from None


def _check_blocks(text: str, name: str) -> None:
    """Refuse YAML whose block nesting may go deeper than :data:`MAX_DEPTH` (libyaml's parser
    recurses in C: a line of 40,000 ``- `` ends the process).  A line can open at most a level
    a column of indentation, a ``- `` and a ``: ``: a cautious bound (a trace nests a few
    levels), linear in the text."""
    for number, line in enumerate(text.split("\n"), 1):
        body = line.lstrip(" ")
        indent = len(line) - len(body)
        if indent + body.count("- ") + body.count(": ") > MAX_DEPTH:
            raise MapError(name, f"nested more than {MAX_DEPTH} deep", number, indent + 1)


def _yaml(text: str, name: str) -> Any:
    import yaml  # only for a .trace.yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    _check_shape(text, name, "[{,:-")  # flow brackets ([[[[...), too many values
    _check_blocks(text, name)  # "- - - ..." and deep indentation: libyaml would crash
    try:
        for token in yaml.scan(text, Loader=loader):
            if isinstance(token, (yaml.AnchorToken, yaml.AliasToken)):
                mark = token.start_mark
                raise MapError(name, "YAML anchors and aliases are not read (a few of them "
                               "can stand for billions of events)", mark.line + 1,
                               mark.column + 1)
        return yaml.load(text, Loader=loader)
    except RecursionError:  # block nesting (indentation, "- - - ...") the checks do not see
        raise MapError(name, "YAML nested too deep") from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        problem = getattr(exc, "problem", None) or "not YAML"
        raise MapError(name, f"not YAML: {problem}", mark.line + 1 if mark else None,
                       mark.column + 1 if mark else None) from None


def _cell(event: dict[str, Any], cells: dict[object, Cell], i: int, name: str
          ) -> Cell | None:
    """An event's cell: its ``x``, ``y``, else the cell its ``id`` had (None: neither)."""
    x, y = event.get("x"), event.get("y")
    if x is None and y is None:
        return cells.get(_key(event.get("id")))
    if not (isinstance(x, int) and isinstance(y, int)) or isinstance(x, bool) or isinstance(
            y, bool):
        raise MapError(name, f"event {i}: x and y should be whole numbers, not "
                       f"{json.dumps([x, y], default=str)[:40]}")
    cell = (x, y)
    if "id" in event:
        cells[_key(event["id"])] = cell
    return cell


def _key(value: object) -> object:
    """An id as a dictionary key (a list or a mapping as its JSON)."""
    return json.dumps(value, sort_keys=True) if isinstance(value, (list, dict)) else value


def load_any_trace(path: str, grid: Grid | Graph, both_ways: bool | None = False) -> Trace:
    """A trace file of either format, by its name: Posthoc's (:data:`SUFFIXES`, a grid's:
    one-directional), else the app's own (:func:`~tui_search.engine.traces.read.load_trace`,
    ``both_ways`` as it takes it)."""
    if not is_posthoc(path):
        return load_trace(path, grid, both_ways)
    if not isinstance(grid, Grid):
        raise MapError(path, "a Posthoc trace is read for a grid; a graph's trace is the "
                       "app's own (JSON lines naming the nodes)")
    return load_posthoc(path, grid)


def load_posthoc(path: str, grid: Grid, as_json: bool | None = None) -> Trace:
    """The Posthoc trace in the file ``path``, read as the app's own traces are: a size cap
    before reading, UTF-8 and no NUL, every fault at its line and column; then its document
    checked for depth and size before it is parsed (``as_json``: by the suffix when None)."""
    if as_json is None:
        as_json = path.lower().endswith(".json")
    limit = MAX_POSTHOC_JSON_BYTES if as_json else MAX_POSTHOC_YAML_BYTES
    return read_posthoc(read_text(path, "a Posthoc trace", limit), grid, path, as_json)


def read_posthoc(text: str, grid: Grid, name: str, as_json: bool | None = None) -> Trace:
    """The Posthoc trace in ``text`` (file ``name``) as a trace of ``grid``: its steps read
    through :func:`~tui_search.engine.traces.read.read_trace` (the same checks), each step's
    line the number of its ``expanding`` event (from 1).  ``as_json``: JSON or YAML (by the
    name's suffix when None)."""
    if as_json is None:
        as_json = name.lower().endswith(".json")
    events = _document(text, name, as_json)["events"]
    steps: list[dict[str, Any]] = []
    numbers: list[int] = []  # each step's event number
    cells: dict[object, Cell] = {}
    first: dict[str, object] = {}
    listed = False
    for i, event in enumerate(events, 1):
        if not isinstance(event, dict):
            raise MapError(name, f"event {i} should be a mapping (type, id, x, y, ...)")
        kind = event.get("type")
        cell = _cell(event, cells, i, name)
        if kind in ("source", "destination") and cell is not None:
            first["start" if kind == "source" else "goal"] = list(cell)
        elif kind in _EXPAND:
            if cell is None:
                raise MapError(name, f"event {i}: an expansion needs x and y (or an id an "
                               "earlier event gave them)")
            steps.append({"node": list(cell), "successors": []})
            numbers.append(i)
        elif kind in _GENERATE and steps:
            if cell is None:
                raise MapError(name, f"event {i}: a generated node needs x and y")
            steps[-1]["successors"].append(list(cell))
            listed = True
    if not steps:
        raise MapError(name, "the trace has no expanding events")
    lines = [json.dumps(first)] if first else []
    lines += [json.dumps(s if listed else {"node": s["node"]}) for s in steps]
    try:
        trace = read_trace("\n".join(lines) + "\n", grid, name)
    except MapError as exc:  # its line: ours; said as Posthoc's event
        at = exc.line
        if at is not None and first:
            at -= 1
        where = f"event {numbers[at - 1]}: " if at is not None and 0 < at <= len(numbers) else ""
        raise MapError(name, where + exc.message) from None
    offset = 1 if first else 0
    return replace(trace, steps=tuple(step._replace(line=numbers[step.line - 1 - offset])
                                      for step in trace.steps))


class PosthocWriter:
    """A search's steps as a Posthoc trace: ``add`` each step, ``text`` the document."""

    def __init__(self, grid: Grid | Graph) -> None:
        self.grid = grid
        self.events: list[dict[str, object]] = []
        start: State | None
        goals: tuple[State, ...]
        if isinstance(grid, Graph):
            start, goals = grid.start, grid.goals
        else:
            start, goals = grid.start, (() if grid.goal is None else (grid.goal,))
        assert start is not None and goals  # a search ran on it
        self.parent: dict[State, int | None] = {start: None}
        self.events.append(self._event("source", start))
        for goal in goals:
            self.events.append(self._event("destination", goal))

    def _id(self, state: State) -> int:
        """A cell's number on the grid (row by row), a node's in the graph."""
        if isinstance(state, str):
            assert isinstance(self.grid, Graph)
            return self.grid.index[state]
        assert isinstance(self.grid, Grid)
        return state[1] * self.grid.width + state[0]

    def _place(self, state: State) -> tuple[float, float]:
        """Where it is drawn: a cell's column and row, a node's place (y down, as on a page;
        its number and 0 when the graph has no places)."""
        if not isinstance(state, str):
            return state
        assert isinstance(self.grid, Graph)
        i = self.grid.index[state]
        if not self.grid.has_places:
            return float(i), 0.0
        x, y = self.grid.place(i)
        return x, -y

    def _event(self, kind: str, cell: State, parent: State | None = None) -> dict[str, object]:
        x, y = self._place(cell)
        return {"type": kind, "id": self._id(cell),
                "pId": None if parent is None else self._id(parent), "x": x, "y": y}

    def add(self, step: Step) -> None:
        node = step.node
        parent_id = self.parent.get(node)
        expanding = self._event("expanding", node)
        expanding["pId"] = parent_id
        self.events.append(expanding)
        for _, cell in step.successors:
            self.parent[cell] = self._id(node)
            self.events.append(self._event("generating", cell, node))
        self.events.append({**expanding, "type": "closing"})

    def text(self, path: Iterable[State] | None = None, *, as_yaml: bool = False,
             about: dict[str, object] | None = None) -> str:
        """The document (its last event ``end`` at the goal when a path was found): JSON, or
        with ``as_yaml`` YAML (block style, an event a line in flow style, its scalars as
        JSON's, which YAML reads alike); ``about``: what the app says of the run, under its
        own key (:data:`ABOUT_KEY`), which Posthoc does not read."""
        events = list(self.events)
        cells = list(path or ())
        if cells:
            parent = cells[-2] if len(cells) > 1 else None
            events.append(self._event("end", cells[-1], parent))
        head: dict[str, object] = {"version": VERSION, "views": {"main": [VIEW]}}
        if about is not None:
            head[ABOUT_KEY] = about
        if as_yaml:
            return _yaml_text(head, events)
        lines = ",\n".join(f"  {json.dumps(event)}" for event in events)
        return f'{json.dumps(head)[:-1]}, "events": [\n{lines}\n]}}\n'  # an event a line


#: How Posthoc draws each event: a cell's square at its ``x``, ``y``.
VIEW = {"$": "rect", "width": 1, "height": 1, "x": "${{ $.x }}", "y": "${{ $.y }}",
        "fill": "${{ theme.foreground }}"}
#: The key of what the app says of the run (the search, its map's file) in a trace it writes.
ABOUT_KEY = "tui-search"


def _flow(value: object) -> str:
    """``value`` in YAML's flow style: mappings and lists as JSON's, but a key that is a
    plain word unquoted (``type: "expanding"``)."""
    if isinstance(value, dict):
        pairs = (f"{_key_text(k)}: {_flow(v)}" for k, v in value.items())
        return "{" + ", ".join(pairs) + "}"
    if isinstance(value, list):
        return "[" + ", ".join(_flow(v) for v in value) + "]"
    text = json.dumps(value)
    if isinstance(value, float) and "e" in text and "." not in text:
        text = text.replace("e", ".0e")  # 1.0e-09: a float to YAML 1.1 readers too
    return text


def _key_text(key: object) -> str:
    text = str(key)
    plain = text.replace("-", "_").isidentifier() and text[0] != "-"
    return text if plain and text not in _YAML_WORDS else json.dumps(text)


#: Words YAML would read as another value than the string.
_YAML_WORDS = frozenset({"null", "true", "false", "yes", "no", "on", "off", "y", "n"})


def _yaml_text(head: dict[str, object], events: list[dict[str, object]]) -> str:
    """The document as YAML: the head's keys a line each (a view a list item), then
    ``events:`` an event a line."""
    lines = []
    for key, value in head.items():
        if key == "views" and isinstance(value, dict):
            lines.append("views:")
            for name, view in value.items():
                lines.append(f"  {_key_text(name)}:")
                lines += [f"    - {_flow(part)}" for part in view]
        else:
            lines.append(f"{_key_text(key)}: {_flow(value)}")
    lines.append("events:")
    lines += [f"  - {_flow(event)}" for event in events]
    return "\n".join(lines) + "\n"


def posthoc_trace(grid: Grid, key: str, semantics: Semantics, max_steps: int, *,
                  as_yaml: bool = False, about: dict[str, object] | None = None
                  ) -> tuple[str, Outcome]:
    """The search ``key`` on ``grid`` (under ``semantics``, at most ``max_steps`` steps) as a
    Posthoc trace (:meth:`PosthocWriter.text`), and its outcome."""
    writer = PosthocWriter(grid)
    found = search_each_step(grid, key, semantics, max_steps, writer.add)
    return writer.text(found.path, as_yaml=as_yaml, about=about), found


__all__ = ["ABOUT_KEY", "SUFFIXES", "VERSION", "PosthocWriter", "is_posthoc", "load_any_trace",
           "posthoc_trace", "read_posthoc"]
