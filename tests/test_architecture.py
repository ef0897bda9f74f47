"""The app reads a recorded run through the run's named queries only: nothing under
``tui_search/tui/`` reaches the raw record (its arrays are the engine's to lay out, and the
run's parts keep them consistent), whatever the attribute is called, nor imports the
record's or the recording's class or module, nor opens the engine-only door to the recording
(``tui_search.engine.run.recorded.recording_of``, for the engine's own checks and the
benchmarks)."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TUI = ROOT / "tui_search" / "tui"

#: Attribute names under which a run's raw record (or its holder) is or was reachable.
RECORD_ATTRIBUTES = frozenset({"rec", "record", "recording", "_rec", "_record", "_recording"})
#: The record's and the recording's classes.
RECORD_CLASSES = frozenset({"Record", "Recording"})
#: The engine-only door to a run's recording: the engine's checks and benchmarks use it.
ENGINE_DOORS = frozenset({"recording_of"})
#: Their modules (``record`` is where the record's class is headed).
RECORD_MODULES = frozenset({"tui_search.engine.run.recording", "tui_search.engine.search.record"})

WHY = ("the app must not read the raw record: ask the Run for it by a named query "
       "(tui_search/engine/run/recorded.py; add one there if none fits)")


def record_uses(source: str) -> list[tuple[int, str]]:
    """Where ``source`` reaches the raw record: (line, what)."""
    found: list[tuple[int, str]] = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Attribute) and (node.attr in RECORD_ATTRIBUTES
                                                 or node.attr in RECORD_CLASSES
                                                 or node.attr in ENGINE_DOORS):
            found.append((node.lineno, f".{node.attr}"))
        elif isinstance(node, ast.Name) and node.id in ENGINE_DOORS:
            found.append((node.lineno, node.id))
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
              and node.func.id in ("getattr", "setattr", "hasattr") and len(node.args) > 1
              and isinstance(node.args[1], ast.Constant)
              and node.args[1].value in RECORD_ATTRIBUTES):
            found.append((node.lineno, f"{node.func.id}(..., {node.args[1].value!r})"))
        elif isinstance(node, ast.Import):
            found += [(node.lineno, f"import {a.name}") for a in node.names
                      if a.name in RECORD_MODULES]
        elif isinstance(node, ast.ImportFrom):
            module = node.module or ""
            if module in RECORD_MODULES:  # once a line: the names need not be listed too
                found.append((node.lineno, f"from {module} import ..."))
                continue
            found += [(node.lineno, f"from {module} import {a.name}") for a in node.names
                      if a.name in RECORD_CLASSES or a.name in ENGINE_DOORS
                      or f"{module}.{a.name}" in RECORD_MODULES]
    return sorted(found)


def test_the_check_sees_every_way_to_the_record() -> None:
    source = """run.rec.exp(k)
run.record.goal_gen
x = run._rec
getattr(run, 'rec')
import tui_search.engine.run.recording
from tui_search.engine.run.recording import MAX_STEPS
from tui_search.engine.search.record import Record
from tui_search.engine.search import record
search.Record()
from tui_search.engine.run.recorded import Run, recording_of
run_module.recording_of(run)
recording_of(run)
run._recording
"""
    assert [line for line, _ in record_uses(source)] == list(range(1, 14))
    fine = ("run.steps.expanded_event(k)\nrun.nodes.goal\n"
            "from tui_search.engine.run.recorded import Run\n")
    assert record_uses(fine) == []


def test_the_app_reads_no_raw_record() -> None:
    files = sorted(TUI.rglob("*.py"))
    assert len(files) > 10, "the app's modules are not where this test looks"
    bad = [f"{path.relative_to(ROOT)}:{line}: {what}"
           for path in files
           for line, what in record_uses(path.read_text(encoding="utf-8"))]
    assert not bad, f"{WHY}:\n" + "\n".join(bad)


def test_the_app_never_opens_the_engine_only_door() -> None:
    """``recording_of`` is for the engine's checks and the benchmarks: named nowhere in the app."""
    bad = [f"{path.relative_to(ROOT)}:{line}: {what}"
           for path in sorted(TUI.rglob("*.py"))
           for line, what in record_uses(path.read_text(encoding="utf-8"))
           if what.split()[-1].lstrip(".") in ENGINE_DOORS]
    assert not bad, f"{WHY}:\n" + "\n".join(bad)
