"""The figures of a run after step k (compare mode's live table)."""

from __future__ import annotations

import pytest

from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.algorithms import ALGORITHMS
from tui_search.engine.run import Run


@pytest.mark.parametrize("algorithm", list(ALGORITHMS))
def test_the_figures_after_each_step_and_at_the_last_the_whole_outcome(algorithm) -> None:
    run = Run(grid_from_rows(TUTORIAL_ROWS), algorithm)
    whole = run.outcome()
    for k in range(run.recorded + 1):
        run.goto(k)
        so_far = run.outcome_so_far(k)
        assert (so_far.expanded, so_far.discarded, so_far.generated, so_far.max_frontier) == (
            run.expanded, run.discarded, run.generated, run.peak_frontier())
        if k < run.recorded:
            assert so_far.path is None and so_far.moves is None and not so_far.gave_up
    assert run.outcome_so_far(run.recorded) == whole


def test_a_run_that_gave_up_says_so_only_at_its_last_step() -> None:
    run = Run(grid_from_rows(TUTORIAL_ROWS), "bfs", max_steps=5)
    assert run.outcome().gave_up
    assert not run.outcome_so_far(4).gave_up and run.outcome_so_far(run.recorded).gave_up
