"""A long advance: the compiled core runs on in C past the chunk (a number of steps sent to
its loop), and records exactly what the run records a chunk at a time."""

from __future__ import annotations

import pytest

from tests.engine.cores import CORES, using_core
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.record import CHUNK

FIELDS = ("gen_node", "step_end", "step_g", "discarded", "gen_depth",
          "iter_first_step", "iter_root", "iter_limit", "goal_gen", "done", "gave_up")


def _record(run: Run) -> tuple:
    rec = recording_of(run).rec
    values = [getattr(rec, name) for name in FIELDS]
    exp = [rec.step_exp[k] for k in range(1, rec.steps + 1)]  # BFS's is worked out, not kept
    return (exp, *(v if v is None or isinstance(v, int) else list(v) for v in values))


def _grid() -> Grid:
    grid = Grid(90, 90, start=(3, 5), goal=(88, 80))  # 8,100 cells: about two chunks
    for y in range(0, 85, 2):
        grid.set_blocked((40 + y % 7, y), True)
    grid.set_cost((60, 60), 4.0)
    return grid


@pytest.mark.parametrize("core", CORES)
@pytest.mark.parametrize("key", ["bfs", "dfs", "astar", "ucs", "iddfs"])
@pytest.mark.parametrize("limit", [None, CHUNK + 500, 2 * CHUNK, 3 * CHUNK - 1])
def test_one_long_advance_records_what_chunks_record(core: str, key: str, limit: int | None
                                                     ) -> None:
    if key == "iddfs" and limit is None:
        limit = 5 * CHUNK  # the whole of it is millions of steps
    sem = Semantics(visit="expand") if key == "dfs" else Semantics()
    with using_core(core):
        kw = {} if limit is None else {"max_steps": limit}
        whole = Run(_grid(), key, sem, **kw)
        whole.advance()
        chunks = Run(_grid(), key, sem, **kw)
        while not chunks.advance_some():
            pass
        part = Run(_grid(), key, sem, **kw)
        part.goto(CHUNK + 123)  # as far as that, then the rest
        part.advance()
        assert _record(whole) == _record(chunks) == _record(part)
        assert whole.outcome() == chunks.outcome()
