"""A frontier entry wider than its panel: its figures on rows of their own under its cell,
the move and the marker going first, never a figure."""

from __future__ import annotations

from tui_search.tui.view.frontier_rows import EntryRows, plan_rows

FIGURES = [5, 5, 5]  # "f6.41", "g3.41", "h3.00"


def test_the_figures_go_together_on_an_indented_row_while_they_fit() -> None:
    assert plan_rows(20, 5, 0, 2, FIGURES) == EntryRows(
        True, ((0, ("move",)), (3, ("0", "1", "2"))), 20)


def test_then_on_as_many_rows_as_they_need_and_the_move_goes_rather_than_take_a_row() -> None:
    assert plan_rows(14, 5, 0, 2, FIGURES).rows == ((0, ("move",)), (3, ("0", "1")),
                                                    (3, ("2",)))
    assert plan_rows(9, 5, 0, 2, FIGURES) == EntryRows(
        True, ((0, ()), (3, ("0",)), (3, ("1",)), (3, ("2",))), 8)


def test_the_marker_goes_when_the_cell_does_not_fit_beside_it_and_no_figure_ever() -> None:
    plan = plan_rows(6, 5, 0, 2, FIGURES)
    assert not plan.marker
    assert plan.rows == ((0, ()), (0, ("0",)), (0, ("1",)), (0, ("2",)))


def test_iterative_deepening_s_depth_stays_beside_the_cell_while_it_fits() -> None:
    assert plan_rows(12, 5, 3, 2, []).rows == ((0, ("depth",)),)
    assert plan_rows(9, 5, 3, 2, []).rows == ((0, ()), (3, ("depth", "move")))  # beside it
