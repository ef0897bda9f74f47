"""The figures of a run after step k (compare mode's live table)."""

from __future__ import annotations

import pytest

from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.registry import ALGORITHMS


@pytest.mark.parametrize("algorithm", list(ALGORITHMS))
def test_the_figures_after_each_step_and_at_the_last_the_whole_outcome(algorithm) -> None:
    """Counted here as the run steps: the steps not discarded, the events each step added
    (and each iteration's root), the largest frontier met."""
    run = Run(grid_from_rows(TUTORIAL_ROWS), algorithm)
    whole = run.outcome()
    discarded, generated, peak = 0, 1, run.now.frontier_len()
    for k in range(run.recorded + 1):
        if k:
            run.forward()
            discarded += run.steps.is_discarded(k)
            generated += len(run.steps.succ_range(k)) + (run.steps.first_of_iteration(
                run.steps.iteration_of(k)) == k and run.steps.iteration_of(k) > 0)
            peak = max(peak, run.now.frontier_len())
        assert run.k == k
        so_far = run.outcome_so_far(k)
        assert (so_far.expanded, so_far.discarded, so_far.generated, so_far.max_frontier) == (
            k - discarded, discarded, generated, peak)
        if k < run.recorded:
            assert so_far.path is None and so_far.moves is None and not so_far.gave_up
    assert run.outcome_so_far(run.recorded) == whole


def test_a_run_that_gave_up_says_so_only_at_its_last_step() -> None:
    run = Run(grid_from_rows(TUTORIAL_ROWS), "bfs", max_steps=5)
    assert run.outcome().gave_up
    assert not run.outcome_so_far(4).gave_up and run.outcome_so_far(run.recorded).gave_up
