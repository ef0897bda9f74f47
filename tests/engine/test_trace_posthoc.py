"""Posthoc's search trace (version 1.4.0): the app writes it (``--trace-format posthoc``) and
reads it back as a trace, JSON or YAML, as Posthoc's documents write them; a malformed one,
or one with YAML anchors, is one line naming the file and where."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.helpers import MAPS, TUTORIAL_ROWS, grid_from_rows
from tests.test_cli import run_cli
from tui_search.engine.maps.read import MapError
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import ALGORITHMS
from tui_search.engine.traces.check import EXPANSIONS_ONLY, check_trace
from tui_search.engine.traces.diagnose import diagnose
from tui_search.engine.traces.posthoc import VERSION, read_posthoc
from tui_search.engine.traces.posthoc import load_any_trace as load_trace

TUTORIAL = str(MAPS / "tutorial.txt")
GRID = grid_from_rows(TUTORIAL_ROWS)

#: A Posthoc trace as its documents write one: YAML, events in flow style, the 1.4.0 names
#: (expand, generate, close), an expansion naming its node by id alone.
YAML = """\
version: 1.4.0
views:
  main:
    - $: rect
      x: ${{ $.x }}
      y: ${{ $.y }}
events:
  - { type: source, id: 0, x: 0, y: 0 }
  - { type: expand, id: 0, x: 0, y: 0, f: 0, g: 0 }
  - { type: generate, id: 6, pId: 0, x: 0, y: 1, f: 1, g: 1 }
  - { type: close, id: 0 }
  - { type: expand, id: 6 }
  - { type: generate, id: 12, pId: 6, x: 0, y: 2 }
  - { type: generate, id: 13, pId: 6, x: 1, y: 2 }
"""


@pytest.mark.parametrize("key", sorted(ALGORITHMS))
def test_the_apps_posthoc_trace_reads_back_as_its_search(capsys, tmp_path: Path,
                                                         key: str) -> None:
    trace = tmp_path / "run.trace.json"
    code, _, err = run_cli(capsys, TUTORIAL, "--headless", "-a", key, "--trace", str(trace),
                           "--trace-format", "posthoc")
    assert code == 0 and err == ""
    document = json.loads(trace.read_text())
    assert document["version"] == VERSION and "main" in document["views"]
    kinds = {e["type"] for e in document["events"]}
    assert {"source", "destination", "expanding", "generating", "closing", "end"} <= kinds
    assert all({"id", "pId", "x", "y"} <= set(e) for e in document["events"])
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", key, "--check-trace",
                           str(trace))
    assert code == 0 and out.startswith("matches "), out


def test_a_yaml_trace_as_posthoc_s_documents_write_it(tmp_path: Path) -> None:
    path = tmp_path / "mine.trace.yaml"
    path.write_text(YAML)
    trace = load_trace(str(path), GRID)
    assert [(t.node, t.successors) for t in trace.steps] == [
        ((0, 0), ((0, 1),)), ((0, 1), ((0, 2), (1, 2)))]
    assert [t.line for t in trace.steps] == [2, 5]  # their expanding events
    verdict = check_trace(trace, GRID, "bfs", Semantics())
    assert verdict.difference is not None and verdict.difference.kind == "ends"
    assert diagnose(trace, GRID).best  # diagnosed as any trace


def test_expanding_events_alone_are_a_trace_of_expansions_only() -> None:
    events = [{"type": "expanding", "id": i, "x": x, "y": y}
              for i, (x, y) in enumerate([(0, 0), (0, 1), (1, 2)])]
    text = json.dumps({"version": "1.4.0", "events": events})
    trace = read_posthoc(text, GRID, "e.trace.json")
    assert all(not t.listed for t in trace.steps)
    verdict = check_trace(trace, GRID, "dfs", Semantics())
    assert EXPANSIONS_ONLY in verdict.notes


@pytest.mark.parametrize(("name", "text", "words"), [
    ("a.trace.yaml", "version: 1.4.0\nevents:\n  - &e { type: expand, x: 0, y: 0 }\n  - *e\n",
     "a.trace.yaml:3:5: YAML anchors and aliases are not read"),
    ("a.trace.yaml", "version: 1.4.0\nevents: [\n", "a.trace.yaml:3:1: not YAML"),
    ("a.trace.json", '{"events": [}', "a.trace.json:1:13: not JSON"),
    ("a.trace.json", '{"version": "1.0.5", "events": []}', "version 1.0.5: tui-search reads"),
    ("a.trace.json", '{"version": "1.4.0"}', 'a document with "events"'),
    ("a.trace.json", '{"events": [{"type": "expanding", "id": 3}]}',
     "event 1: an expansion needs x and y"),
    ("a.trace.json", '{"events": [{"type": "expanding", "x": "0", "y": 0}]}',
     "event 1: x and y should be whole numbers"),
    ("a.trace.json", '{"events": [{"type": "expanding", "x": 0, "y": 0}, '
                     '{"type": "generating", "x": 0, "y": 1}, '
                     '{"type": "expanding", "x": 5, "y": 5}]}',
     "event 3: expands (5,5), which no earlier line added"),
    ("a.trace.json", '{"events": [{"type": "source", "x": 0, "y": 1}, '
                     '{"type": "expanding", "x": 0, "y": 0}]}',
     "the trace starts at (0,1), the map at (0,0)"),
])
def test_a_malformed_posthoc_trace_is_one_line(tmp_path: Path, name: str, text: str,
                                               words: str) -> None:
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(MapError) as raised:
        load_trace(str(path), GRID)
    said = str(raised.value)
    assert words in said and "\n" not in said


def test_the_posthoc_format_goes_with_a_trace_file(capsys) -> None:
    code, _, err = run_cli(capsys, TUTORIAL, "--headless", "--trace-format", "posthoc")
    assert code == 2 and "--trace-format goes with --trace FILE" in err
