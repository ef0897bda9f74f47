"""Numbers as the app writes them: digits grouped in thousands."""

from __future__ import annotations


def group_digits(n: int) -> str:
    """``1234567`` -> ``1,234,567``: the one digit grouping of every count the app shows (the
    status line, the panels' titles, the headless output)."""
    return f"{n:,}"
