"""Numbers as the app writes them: digits grouped in thousands, and a power written short."""

from __future__ import annotations

import math

_SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
#: A power is written in full up to this many digits, and short (``≈ 4.2×10¹¹⁷``) above.
SHORT_DIGITS = 13
#: Below this many digits a power is worked out exactly; above, from its logarithm.  Under
#: Python's lowest limit on writing an int in decimal (640 digits, ``sys.int_info``), so no
#: figure the app writes can meet that limit, whatever the map.
EXACT_DIGITS = 600


def group_digits(n: int) -> str:
    """``1234567`` -> ``1,234,567``: the one digit grouping of every count the app shows (the
    status line, the panels' titles, the headless output)."""
    return f"{n:,}"


def superscript(n: int) -> str:
    """``10296`` -> ``¹⁰²⁹⁶``."""
    return str(n).translate(_SUPERSCRIPT)


def power_text(base: int, exponent: int) -> str:
    """``base`` to the ``exponent``, as the status line writes it: ``7⁸ = 5,764,801``, and past
    :data:`SHORT_DIGITS` digits its first two and its size, ``7¹⁰²⁹⁶ ≈ 1.3×10⁸⁷⁰¹`` (the
    digits cut, not rounded).  A big power is never computed: its first digits come from its
    logarithm, so an exponent of millions (a path across the largest map) takes no time and
    makes no number Python would refuse to write."""
    if base < 1 or exponent < 0:
        raise ValueError("a power of a whole number >= 1, to an exponent >= 0")
    head = f"{base}{superscript(exponent)}"
    if exponent * math.log10(base) < EXACT_DIGITS:
        value = base**exponent
        digits = str(value)
        if len(digits) <= SHORT_DIGITS:
            return f"{head} = {value:,}"
        lead, power = digits[:2], len(digits) - 1
    else:
        lead, power = leading_digits(base, exponent)
    return f"{head} ≈ {lead[0]}.{lead[1]}×10{superscript(power)}"


def leading_digits(base: int, exponent: int, count: int = 2) -> tuple[str, int]:
    """The first ``count`` digits of ``base ** exponent`` and the power of ten below it (its
    number of digits less one), from its logarithm worked out to 60 digits: even for an
    exponent of a billion, 50 of them are right, far more than the few shown.  For a power of
    two digits or more (``count`` digits are given)."""
    from decimal import Context, Decimal  # only for powers of more than 600 digits

    ctx = Context(prec=60)
    log = ctx.multiply(ctx.log10(Decimal(base)), Decimal(exponent))
    power = int(log)  # the whole part: log >= 0
    mantissa = ctx.power(Decimal(10), ctx.add(ctx.subtract(log, Decimal(power)), count - 1))
    # Far above the logarithm's error, far below the step to the next lead: a power that is
    # its lead exactly (81) must not read as 80.999...
    lead = min(int(ctx.add(mantissa, Decimal("1e-30"))), 10**count - 1)
    return str(lead), power
