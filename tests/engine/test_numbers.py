"""Numbers as the app writes them: a power written short past 13 digits, its first digits
from its logarithm past 600, so that no figure meets Python's limit on writing an int (issue:
``end`` on a 301x301 maze raised ``ValueError: Exceeds the limit (4300 digits)``)."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from decimal import Decimal, localcontext

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tui_search.engine.maps.read import MAX_MAP_BYTES
from tui_search.engine.util.numbers import EXACT_DIGITS, leading_digits, power_text, superscript


@contextmanager
def int_digits(limit: int) -> Iterator[None]:
    """Python's limit on writing an int in decimal set to ``limit`` (0: none) for a while."""
    before = sys.get_int_max_str_digits()
    sys.set_int_max_str_digits(limit)
    try:
        yield
    finally:
        sys.set_int_max_str_digits(before)


def exact(base: int, exponent: int) -> tuple[str, int]:
    with int_digits(0):
        digits = str(base**exponent)
    return digits[:2], len(digits) - 1


def test_small_powers_are_written_whole_and_big_ones_short() -> None:
    assert power_text(7, 8) == "7⁸ = 5,764,801"
    assert power_text(3, 4) == "3⁴ = 81"
    assert power_text(1, 10**9) == "1¹⁰⁰⁰⁰⁰⁰⁰⁰⁰ = 1"
    assert power_text(7, 15) == "7¹⁵ = 4,747,561,509,943"  # 13 digits: whole
    assert power_text(7, 16) == "7¹⁶ ≈ 3.3×10¹³"
    assert power_text(7, 140) == "7¹⁴⁰ ≈ 2.0×10¹¹⁸"
    assert power_text(7, 10_296) == "7¹⁰²⁹⁶ ≈ 1.3×10⁸⁷⁰¹"  # the 301x301 maze's bound


@given(st.integers(2, 7), st.integers(4, 4000))
def test_the_first_digits_from_the_logarithm_are_the_exact_ones(base: int, exponent: int) -> None:
    assert leading_digits(base, exponent) == exact(base, exponent)


@pytest.mark.parametrize("base", [2, 3, 5, 7])
def test_the_text_is_the_same_on_either_side_of_the_exact_digits(base: int) -> None:
    """Around :data:`EXACT_DIGITS`, where the text stops being worked out exactly."""
    for exponent in range(1, 3 * EXACT_DIGITS):
        lead, power = exact(base, exponent)
        value = f"≈ {lead[0]}.{lead[1]}×10{superscript(power)}" if power >= 13 else (
            f"= {base**exponent:,}")
        assert power_text(base, exponent) == f"{base}{superscript(exponent)} {value}"


def test_the_largest_exponent_any_map_allows_is_written_short_at_the_lowest_limit() -> None:
    """A path is shorter than the cells of the largest map file (at most one a byte), and
    a cell has at most 8 moves: ``7^(d+1)``, written at Python's lowest digit limit."""
    exponent = MAX_MAP_BYTES + 1
    with int_digits(640):
        text = power_text(7, exponent)
    with localcontext() as ctx:  # the same logarithm, to twice the digits
        ctx.prec = 120
        log = Decimal(7).log10() * exponent
        power = int(log)
        lead = str(int(Decimal(10) ** (log - power + 1)))
    assert text == f"7⁶⁷¹⁰⁸⁸⁶⁵ ≈ {lead[0]}.{lead[1]}×10{superscript(power)}" and len(text) < 40
    lead, power = exact(7, 123_457)
    assert leading_digits(7, 123_457) == (lead, power)


def test_a_power_of_less_than_one_or_to_a_negative_exponent_is_refused() -> None:
    for base, exponent in ((0, 3), (7, -1)):
        with pytest.raises(ValueError):
            power_text(base, exponent)
