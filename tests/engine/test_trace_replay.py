"""``--replay`` without Textual (:mod:`tui_search.engine.trace_replay`): what the trace's pane
says of it, its steps beside its search's, and a recursive DFS's pattern named."""

from __future__ import annotations

from tests.engine.student_searches import bfs
from tests.helpers import TUTORIAL, TUTORIAL_ROWS
from tui_search.engine.mapfile import load_map
from tui_search.engine.semantics import Semantics
from tui_search.engine.trace_read import read_trace
from tui_search.engine.trace_replay import replay_of

GRID = load_map(TUTORIAL)


def test_the_traces_pane_names_its_file_not_the_searchs_moves() -> None:
    """Beside -a's search the trace declares no order: its line says the file's name, and
    the search's the moves it was given."""
    trace = read_trace(bfs(TUTORIAL_ROWS, "N,W,S,E"), GRID, "/some/where/trace.jsonl")
    ours, theirs = replay_of(trace, GRID, "bfs", Semantics(order=("N", "W", "S", "E"))).runs(GRID)
    assert ours.differences() == ["trace.jsonl"]
    assert theirs.differences() == ["moves N,W,S,E"]


def test_a_diagnosed_order_is_said_as_inferred() -> None:
    trace = read_trace(bfs(TUTORIAL_ROWS, "N,E,S,W"), GRID, "t\x1b.jsonl")
    replay = replay_of(trace, GRID, None, Semantics())
    order = ",".join(replay.semantics.order)  # the moves the trace shows, in its order
    assert replay.algorithm == "bfs" and order == "E,N,S"
    assert replay.runs(GRID)[0].differences() == ["t\\x1b.jsonl", "order E,N,S inferred"]
