"""The map generators' random numbers: the same seed gives the same numbers on every platform
and every Python, so a generated map can be made again from its recipe.

Python's :mod:`random` is not used: its algorithms (``randrange``, ``shuffle``) have changed
between releases, and ``hash()`` of a text is salted per process.  Instead:

- **the seed**: a whole number (``7``, ``-3``, ``007``) is itself, taken modulo 2**64; any other
  text is the first 8 bytes, big-endian, of the SHA-256 of its UTF-8 bytes
  (:func:`seed_value`);
- **the generator**: SplitMix64 (Steele, Lea and Flood, 2014; the seeding generator of
  xoshiro), on Python ints masked to 64 bits (:class:`SplitMix64`);
- **a number below n**: rejection sampling, so every value is equally likely
  (:meth:`SplitMix64.below`).

Stdlib only.
"""

from __future__ import annotations

import hashlib
import re
from collections.abc import MutableSequence
from typing import TypeVar

__all__ = ["SplitMix64", "seed_value"]

MASK = (1 << 64) - 1
_WHOLE = re.compile(r"[+-]?[0-9]+")
T = TypeVar("T")


def seed_value(seed: str) -> int:
    """The 64-bit number a seed stands for: a whole number modulo 2**64, else the first 8
    bytes (big-endian) of SHA-256 of the text's UTF-8."""
    text = seed.strip()
    if _WHOLE.fullmatch(text):
        return int(text) & MASK
    return int.from_bytes(hashlib.sha256(text.encode("utf-8")).digest()[:8], "big")


class SplitMix64:
    """SplitMix64: a 64-bit state advanced by the golden-ratio constant, each output the
    state mixed by two multiply-xorshift rounds."""

    def __init__(self, seed: int) -> None:
        self.state = seed & MASK

    def next(self) -> int:
        """The next number, 0 <= n < 2**64."""
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def below(self, n: int) -> int:
        """A number 0 <= k < n, each equally likely (draws past the last whole multiple of
        n below 2**64 are drawn again)."""
        if n < 1:
            raise ValueError("below() needs n >= 1")
        limit = ((1 << 64) // n) * n
        while True:
            z = self.next()
            if z < limit:
                return z % n

    def choice(self, items: list[T]) -> T:
        return items[self.below(len(items))]

    def shuffle(self, items: MutableSequence[T]) -> None:
        """Fisher-Yates, from the last item down."""
        for i in range(len(items) - 1, 0, -1):
            j = self.below(i + 1)
            items[i], items[j] = items[j], items[i]
