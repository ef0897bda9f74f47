"""``--export run.trace.json`` / ``run.trace.yaml``: the run as Posthoc's search trace, without
the app (no film: the search the other exports film, searched).  The trace validates against
Posthoc's schema (tests/data/posthoc/trace-1.4.0.schema.json, written from
ShortestPathLab/posthoc-app's client/src/language/schema.ts at commit
dc42d6d054851b60e228067531bd2e5cea1672a8 and protocol/Trace-v140.ts at commit
6b9336e912c69d52c560e4e77b77a1557c55bab4), reads back through the app's own reader as the
run's expansions, its map beside it is the map (a MovingAI ``.map``, what Posthoc opens), the
same run gives the same bytes, and nothing is replaced without ``--force``."""

from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest
import yaml

from tests.helpers import MAPS, ROOT
from tests.test_cli import run_cli
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.source import MOVINGAI
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.traces.posthoc import ABOUT_KEY, load_any_trace
from tui_search.export.files import make_export
from tui_search.export.job import Job
from tui_search.export.kinds import kind_of, map_of
from tui_search.export.posthoc import ONE_SEARCH

TUTORIAL = str(MAPS / "tutorial.txt")
SCHEMA = json.loads((ROOT / "tests" / "data" / "posthoc" / "trace-1.4.0.schema.json")
                   .read_text())
ARENA = str(ROOT / "tests" / "data" / "movingai" / "arena.map")
ENDINGS = (".trace.json", ".trace.yaml")


def trace_job(target: Path, **changes: object) -> Job:
    values: dict[str, object] = dict(
        target=str(target), grid=load_map(TUTORIAL), path=Path(TUTORIAL),
        unsaved_name="tutorial (built-in)", algorithm="bfs", semantics=Semantics(),
        compare=None, max_steps=1_000_000, theme=None, fps=2.0, view="full", force=False,
        handout_steps=10)
    values.update(changes)
    return Job(**values)  # type: ignore[arg-type]


def document(path: Path) -> dict[str, object]:
    text = path.read_text(encoding="utf-8")
    value = json.loads(text) if path.name.endswith(".json") else yaml.safe_load(text)
    assert isinstance(value, dict)
    return value


def test_the_kind_is_the_last_two_endings_and_json_or_yaml_alone_is_none() -> None:
    assert kind_of("run.trace.json") == kind_of("RUN.Trace.YAML") == "trace"
    assert map_of("out/run.trace.yaml") == "out/run.map"
    for name in ("run.json", "run.yaml", "run.trace", "run.trace.yml"):
        with pytest.raises(ValueError) as caught:
            kind_of(name)
        assert str(caught.value) == (f"--export {name}: the kind is the file's ending, one of "
                                     ".svg, .cast, .gif, .md, .trace.json, .trace.yaml")


@pytest.mark.parametrize("ending", ENDINGS)
@pytest.mark.parametrize("key", ["bfs", "dfs", "astar"])
def test_the_trace_is_posthocs_and_reads_back_as_the_run(tmp_path: Path, key: str,
                                                         ending: str) -> None:
    target = tmp_path / f"run{ending}"
    written = make_export(trace_job(target, algorithm=key))
    assert written == [str(target), str(tmp_path / "run.map")]
    value = document(target)
    jsonschema.validate(value, SCHEMA)
    events = value["events"]
    assert isinstance(events, list)
    assert {e["type"] for e in events} == {"source", "destination", "expanding", "generating",
                                           "closing", "end"}
    grid = load_map(TUTORIAL)
    trace = load_any_trace(str(target), grid)
    run = Run(grid, key, Semantics(), 1_000_000)
    steps = list(run.steps.all())
    assert [s.node for s in trace.steps] == [s.node for s in steps]
    assert [s.successors for s in trace.steps] == [tuple(c for _, c in s.successors)
                                                   for s in steps]
    assert (trace.start, trace.goal) == (grid.start, grid.goal)
    end = events[-1]
    assert end["type"] == "end" and (end["x"], end["y"]) == run.outcome().path[-1]
    assert value[ABOUT_KEY] == {"map": "run.map", "search": key,
                                "choices": Semantics().as_json(get_algorithm(key)),
                                "max_steps": 1_000_000}


def test_yaml_and_json_hold_the_same_document(tmp_path: Path) -> None:
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    make_export(trace_job(tmp_path / "a" / "run.trace.json"))
    make_export(trace_job(tmp_path / "b" / "run.trace.yaml"))
    assert document(tmp_path / "a" / "run.trace.json") == document(tmp_path / "b" /
                                                                   "run.trace.yaml")
    text = (tmp_path / "b" / "run.trace.yaml").read_text()
    assert text.splitlines()[0] == 'version: "1.4.0"' and "  - {type: \"expanding\"" in text


def test_the_map_beside_it_is_the_map(tmp_path: Path) -> None:
    make_export(trace_job(tmp_path / "run.trace.json"))
    grid, beside = load_map(TUTORIAL), load_map(str(tmp_path / "run.map"))
    assert beside.source is not None and beside.source.kind == MOVINGAI  # what Posthoc opens
    assert (beside.width, beside.height, beside.blocked) == (grid.width, grid.height,
                                                             grid.blocked)
    assert (tmp_path / "run.map").read_text().startswith("type octile\nheight 6\nwidth 6\nmap\n")


@pytest.mark.parametrize("ending", ENDINGS)
def test_the_same_run_gives_the_same_bytes(tmp_path: Path, ending: str) -> None:
    made = []
    for folder in ("one", "two"):
        (tmp_path / folder).mkdir()
        target = tmp_path / folder / f"run{ending}"
        make_export(trace_job(target, algorithm="astar"))
        made.append((target.read_bytes(), (tmp_path / folder / "run.map").read_bytes()))
    assert made[0] == made[1]


@pytest.mark.parametrize("there", ["run.trace.json", "run.map"])
def test_nothing_is_replaced_without_force(tmp_path: Path, there: str) -> None:
    (tmp_path / there).write_text("mine")
    target = tmp_path / "run.trace.json"
    with pytest.raises(ValueError) as caught:
        make_export(trace_job(target))
    assert str(caught.value) == f"{tmp_path / there} exists: --force replaces it"
    assert [p.name for p in tmp_path.iterdir()] == [there]
    assert (tmp_path / there).read_text() == "mine"
    make_export(trace_job(target, force=True))
    assert target.read_text().startswith('{"version": "1.4.0"')
    assert (tmp_path / "run.map").read_text().startswith("type octile")


def test_a_movingai_map_on_disk_is_named_not_copied(tmp_path: Path) -> None:
    grid = load_map(ARENA)
    grid.start, grid.goal = (20, 20), (25, 25)
    target = tmp_path / "run.trace.json"
    assert make_export(trace_job(target, grid=grid, path=Path(ARENA))) == [str(target)]
    value = document(target)
    jsonschema.validate(value, SCHEMA)
    named = value[ABOUT_KEY]["map"]  # type: ignore[index]
    assert (tmp_path / named).resolve() == Path(ARENA).resolve()
    edited = load_map(ARENA)
    edited.start, edited.goal = (20, 20), (25, 25)
    edited.set_blocked((5, 5), not edited.is_blocked((5, 5)))
    again = tmp_path / "edited.trace.json"
    make_export(trace_job(again, grid=edited, path=Path(ARENA)))
    assert load_map(str(tmp_path / "edited.map")).blocked == edited.blocked


def test_a_comparison_is_no_trace(tmp_path: Path) -> None:
    with pytest.raises(ValueError) as caught:
        make_export(trace_job(tmp_path / "run.trace.json", compare="bfs,dfs"))
    assert str(caught.value) == ONE_SEARCH and list(tmp_path.iterdir()) == []


def test_the_command_line_writes_a_trace_posthoc_opens(capsys, tmp_path: Path,
                                                        monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli(capsys, TUTORIAL, "-a", "dfs", "--headless", "--export",
                             "run.trace.yaml")
    assert (code, out, err) == (0, "Wrote run.trace.yaml, run.map\n", "")
    jsonschema.validate(document(tmp_path / "run.trace.yaml"), SCHEMA)
    code, out, _ = run_cli(capsys, TUTORIAL, "-a", "dfs", "--headless", "--check-trace",
                           "run.trace.yaml")
    assert code == 0 and out.startswith("matches "), out
    code, _, err = run_cli(capsys, TUTORIAL, "--headless", "--export", "run.trace.yaml")
    assert code == 2 and err.strip().endswith("run.trace.yaml exists: --force replaces it")
