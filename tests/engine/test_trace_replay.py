"""``--replay`` without Textual (:mod:`tui_search.engine.traces.replay`): what the trace's pane
says of it, its steps beside its search's, and a recursive DFS's pattern named."""

from __future__ import annotations

from tests.engine.student_searches import _search, bfs, bfs_visit_on_expand, dfs_recursive
from tests.engine.test_trace import app_trace
from tests.helpers import TUTORIAL, TUTORIAL_ROWS
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run, Step
from tui_search.engine.search.choices import Semantics
from tui_search.engine.traces.check import check_trace
from tui_search.engine.traces.read import read_trace
from tui_search.engine.traces.replay import replay_of

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


def steps(run: Run) -> list[tuple[object, ...]]:
    run.advance()
    return [(s.node, [c for _, c in s.successors], s.discarded) for s in run.steps.all()]


def test_the_discarded_pops_a_trace_left_out_are_put_back_where_the_search_discards_them() -> None:
    """A student's BFS that visits on expand leaves out the pops of cells done already; the
    app's own trace of that BFS lists them ("discarded": true).  Replayed, both give the same
    steps, numbered as the search's: the panes keep in step."""
    sem = Semantics(order=("N", "W", "S", "E"), visit="expand")
    without = read_trace(bfs_visit_on_expand(TUTORIAL_ROWS, "N,W,S,E"), GRID, "t.jsonl")
    listed = read_trace(app_trace(GRID, "bfs", sem), GRID, "t.jsonl")
    assert not any(s.discarded for s in without.steps)
    assert any(s.discarded for s in listed.steps)
    replays = [replay_of(trace, GRID, "bfs", sem) for trace in (without, listed)]
    assert all(r.verdict.matches for r in replays)
    (left, search), (right, _) = (r.runs(GRID) for r in replays)
    assert steps(left) == steps(right)
    assert [(s.node, s.discarded) for s in steps_of_search(search)] == [
        (s[0], s[2]) for s in steps(left)]
    assert [(s.node, s.successors, s.discarded) for s in replays[0].trace.steps] == [
        (s.node, s.successors, s.discarded) for s in listed.steps]
    assert replays[0].verdict.steps == len(listed.steps)


def steps_of_search(run: Run) -> list[Step]:
    run.advance()
    return list(run.steps.all())


def test_a_difference_after_left_out_pops_is_said_as_the_check_numbers_it() -> None:
    """The sentence numbers the step as --check-trace does (the trace's own lines, from 1),
    and says which step of the panes it is (the search's pops put back there); d takes both
    panes to that step."""
    sem = Semantics(order=("N", "W", "S", "E"), visit="expand")
    newest_at = 14  # the student's step that takes the queue's back once
    text = _search(TUTORIAL_ROWS, "N,W,S,E", lambda q, n: q.pop() if n + 1 == newest_at
                   else q.popleft(), visit_on_expand=True)
    trace = read_trace(text, GRID, "t.jsonl")
    replay = replay_of(trace, GRID, "bfs", sem)
    ours, theirs = replay.runs(GRID)
    assert replay.step is not None
    put_back = sum(s.discarded for s in replay.trace.steps[:replay.step])
    assert put_back > 0 and replay.step == newest_at + put_back
    for run in (ours, theirs):
        run.goto(replay.step)
    assert replay.marks() == [ours.now.current_node(), theirs.now.current_node()]
    checked = check_trace(trace, GRID, "bfs", sem)
    assert checked.difference is not None and checked.difference.step == newest_at
    assert replay.sentence().startswith(f"step {newest_at}: your trace expands ")
    assert replay.sentence().endswith(
        f"(the panes' step {replay.step}: BFS's discarded pops, which your trace leaves out, "
        "are put back)")


def test_a_recursive_dfs_is_replayed_beside_the_recursion_it_is() -> None:
    """A recursive DFS's trace cut short: beside it the recursive DFS (its pane so named),
    in the student's own order, and where they part."""
    lines = dfs_recursive(TUTORIAL_ROWS, "E,S,W,N").splitlines()
    trace = read_trace("\n".join(lines[:-3]) + "\n", GRID, "rec.jsonl")
    replay = replay_of(trace, GRID, None, Semantics())
    assert replay.labels == ["your trace", "DFS (recursive)"]
    assert replay.algorithm == "dfs" and replay.semantics.recursive == "neighbours"
    assert replay.semantics.order[:2] == ("E", "S")
    assert replay.step == len(trace.steps) + 1
    assert replay.sentence().startswith(
        f"step {replay.step}: your trace ends after step {replay.step - 1}; this DFS goes on "
        "and expands")
