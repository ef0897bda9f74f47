"""The rebuild's bulk loops (:mod:`tui_search.engine.run.rebuild`): the compiled core's C twins
write what the Python ones write, array for array, on the records of random runs under
random choices, in pieces of any size; and a whole rebuild lands on the same state under
either core."""

from __future__ import annotations

from array import array

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.cores import using_core
from tests.engine.test_core import semantics
from tests.engine.test_run import snapshot
from tests.engine.test_search import random_grids
from tui_search.engine.run import rebuild
from tui_search.engine.run.recorded import Run, recording_of

LIMIT = 400
checks = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def compiled_kernels() -> rebuild.Kernels:
    with using_core("compiled"):
        return rebuild.kernels()


def expanded_pieces(run: Run, piece: int) -> list:
    """The events run's steps expanded, in pieces (int arrays, or ranges for BFS)."""
    rec = recording_of(run).rec
    exp = rec.step_exp
    out = []
    for lo in range(1, rec.steps + 1, piece):
        hi = min(lo + piece, rec.steps + 1)
        out.append(exp[lo:hi] if isinstance(exp, array) else range(lo - 1, hi - 1))
    return out


@checks
@given(random_grids(max_side=7), semantics(), st.integers(1, 50))
def test_the_c_rebuild_loops_write_what_the_python_ones_write(grid, choice, piece) -> None:
    c_kernels = compiled_kernels()
    key, sem = choice
    run = Run(grid, key, sem, LIMIT)
    run.advance()
    rec = recording_of(run).rec
    size = len(recording_of(run).problem.walls)
    end = len(rec.gen_node)
    written = []
    for kernels in (rebuild.PYTHON, c_kernels):
        n_gen, n_exp, latest = (array("i", [v]) * size for v in (0, 0, -1))
        flags = bytearray(b"\x01") * end
        for lo in range(0, end, piece):
            kernels.count_generated(rec.gen_node, lo, min(lo + piece, end), n_gen, latest)
        for events in expanded_pieces(run, piece):
            kernels.count_expanded(rec.gen_node, events, n_exp)
            kernels.clear_events(flags, events, 0)
        root = rec.iter_root[-1]  # the open events of the last iteration, listed in pieces
        listed = [kernels.open_events(flags[root:], root, lo, min(lo + piece, end))
                  for lo in range(root, end, piece)]
        written.append((n_gen, n_exp, latest, flags, listed))
    assert written[0] == written[1]


def test_the_c_rebuild_loops_refuse_an_index_out_of_range() -> None:
    c_kernels = compiled_kernels()
    gen_node, counts, latest = array("i", [0, 5]), array("i", [0]) * 3, array("i", [0]) * 3
    with pytest.raises(IndexError):
        c_kernels.count_generated(gen_node, 0, 2, counts, latest)
    with pytest.raises(IndexError):
        c_kernels.count_generated(gen_node, 0, 3, counts, latest)
    with pytest.raises(IndexError):
        c_kernels.count_expanded(gen_node, range(2), counts)
    with pytest.raises(IndexError):
        c_kernels.clear_events(bytearray(2), array("i", [1, 2]), 0)
    with pytest.raises(IndexError):
        c_kernels.open_events(bytearray(2), 1, 0, 2)
    with pytest.raises(IndexError):
        c_kernels.open_events(bytearray(2), 0, 0, 3)
    with pytest.raises(TypeError):
        c_kernels.count_expanded(gen_node, array("l", [0]), counts)


@checks
@given(random_grids(max_side=7), semantics(), st.integers(0, LIMIT), st.integers(1, 5))
def test_a_rebuild_lands_on_the_same_state_under_either_core(grid, choice, k, piece) -> None:
    key, sem = choice
    states = []
    for core in ("python", "compiled"):
        with using_core(core):
            run = Run(grid, key, sem, LIMIT)
            run.REBUILD_PIECE = piece
            run.advance()
            for _ in run.rebuild_pieces(k % (run.total + 1)):
                pass
            states.append(snapshot(run))
    assert states[0] == states[1]


@checks
@given(random_grids(max_side=7), semantics())
def test_the_c_walk_up_the_parents_is_the_python_one(grid, choice) -> None:
    """``ancestors`` of every event (the path, the tree panel's chain) under either core."""
    key, sem = choice
    chains, moves = [], []
    for core in ("python", "compiled"):
        with using_core(core):
            run = Run(grid, key, sem, LIMIT)
            run.advance()
            chains.append([run.nodes.ancestors(g) for g in range(-1, run.now.generated)])
            moves.append(run.moves())
    assert chains[0] == chains[1] and moves[0] == moves[1]
    if moves[0] is not None:  # each move the one gen_dir gives the event it reached
        assert moves[0] == [run.nodes.move(g) for g in run.nodes.path()[1:]]


def test_the_c_walk_refuses_a_record_out_of_range() -> None:
    core = pytest.importorskip("tui_search.engine.search._core")
    with pytest.raises(IndexError):
        core.ancestors(array("i", [1, 3]), None, 0, 5)
    with pytest.raises(IndexError):
        core.ancestors(array("i", [1, 3]), array("i", [-1]), 0, 2)
    assert core.ancestors(array("i", [1, 3]), None, 0, 2) == [0, 2]
    assert core.ancestors(array("i", [1]), None, 0, -1) == []
