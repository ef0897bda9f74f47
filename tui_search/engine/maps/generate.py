"""Generated maps: a recipe -- kind, size and seed -- made into a text map with S and G.

Kinds (:data:`KINDS`):

- ``random:P``: each cell an obstacle with probability P percent (0-100, decimals allowed),
  independently; the start (top left) and goal (bottom right) are free and connected under
  the four moves N, E, S, W (when the draw leaves them apart, the fewest obstacles that join
  them are cleared);
- ``maze``: the recursive backtracker, which is depth-first search carving its own maze;
- ``prim``, ``kruskal``: randomised Prim's and Kruskal's spanning trees;
- ``division``: recursive division, walls with one gap each;
- ``rooms``: recursive division that stops at rooms of up to 7 x 7 cells, joined by doors.

The four mazes are perfect: their open cells form a tree under the four moves, and the start
and goal are at its top-left and bottom-right nodes (:mod:`~tui_search.engine.maps.mazes`).  The
same recipe gives the same bytes on every platform and Python
(:mod:`~tui_search.engine.util.prng`), and a generated map's first line records its recipe
(``; generated: maze 15x15 seed 7``), which :func:`parse_recipe` reads back.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from decimal import Decimal
from fractions import Fraction
from typing import NamedTuple

from tui_search.engine.maps import mazes
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.recipes import DEFAULT_SEED, DEFAULT_SIZE, KINDS, MAX_SIDE
from tui_search.engine.maps.text import parse_text_map, text_rows
from tui_search.engine.util.prng import SplitMix64, seed_value

__all__ = [
    "DEFAULT_SEED",
    "DEFAULT_SIZE",
    "KINDS",
    "MAX_SIDE",
    "Recipe",
    "generate",
    "generated_text",
    "make_recipe",
    "next_recipe",
    "parse_recipe",
    "recipe_of",
]

MAX_SEED_CHARS = 100
ROOM_NODES = 4  # a room is up to 4 nodes across: 7 cells
COMMENT = "; generated: "


class Recipe(NamedTuple):
    """How a map is made: ``kind`` (a key of :data:`KINDS`), ``percent`` (random's P, else
    None), the size, and the seed as typed (a whole number or any text)."""

    kind: str
    percent: Fraction | None
    width: int
    height: int
    seed: str

    @property
    def spec(self) -> str:
        """The kind as typed: ``maze``, ``random:30``."""
        return self.kind if self.percent is None else f"{self.kind}:{_number(self.percent)}"

    @property
    def title(self) -> str:
        """``maze 15x15 seed 7``: what the map's first line and the app's title say."""
        return f"{self.spec} {self.width}x{self.height} seed {self.seed}"


def _number(value: Fraction) -> str:
    """P written back exactly as a decimal (its denominator divides 10**6)."""
    return format((Decimal(value.numerator) / Decimal(value.denominator)).normalize(), "f")


_SIZE = re.compile(r"([0-9]{1,6})[xX]([0-9]{1,6})")
_PERCENT = re.compile(r"[0-9]{1,3}(\.[0-9]{1,6})?")


def make_recipe(kind: str, size: str = DEFAULT_SIZE, seed: str = DEFAULT_SEED) -> Recipe:
    """The recipe for a kind (``maze``, ``random:30``), a size (``15x15``) and a seed, or a
    ValueError saying in one line what is wrong."""
    name, colon, p_text = kind.strip().partition(":")
    name = name.lower()
    if name not in KINDS:
        raise ValueError(f"unknown kind {kind.strip()!r} (kinds: random:P, "
                         f"{', '.join(k for k in KINDS if k != 'random')})")
    percent: Fraction | None = None
    if name == "random":
        if not colon or not p_text:
            raise ValueError("random needs its percentage of obstacles: random:P, e.g. random:30")
        if not _PERCENT.fullmatch(p_text) or Fraction(p_text) > 100:
            raise ValueError(f"random:{p_text}: P must be a number from 0 to 100")
        percent = Fraction(p_text)
    elif colon:
        raise ValueError(f"{name} takes no ':{p_text}'")
    match = _SIZE.fullmatch(size.strip())
    if match is None:
        raise ValueError(f"size {size.strip()!r}: expected WIDTHxHEIGHT, e.g. 15x15")
    width, height = int(match[1]), int(match[2])
    low_w, low_h = KINDS[name].minimum
    if width < low_w or height < low_h:
        raise ValueError(f"size {width}x{height}: {name} needs at least {low_w}x{low_h}")
    if width > MAX_SIDE or height > MAX_SIDE:
        raise ValueError(f"size {width}x{height}: at most {MAX_SIDE}x{MAX_SIDE}")
    seed = seed.strip()
    if not seed:
        raise ValueError("the seed is empty: a whole number or any text")
    if len(seed) > MAX_SEED_CHARS or not seed.isprintable():
        raise ValueError(f"the seed must be printable text of at most {MAX_SEED_CHARS} characters")
    return Recipe(name, percent, width, height, seed)


def parse_recipe(text: str) -> Recipe:
    """``KIND WxH SEED`` (``maze 15x15 7``; ``seed`` may come before the seed, as in a
    generated map's first line; the seed is the rest of the line, spaces and all)."""
    parts = text.strip().split(None, 2)
    if len(parts) < 3:
        raise ValueError(f"{text.strip()!r}: expected KIND WxH SEED, e.g. maze 15x15 7")
    kind, size, seed = parts
    seed = seed.removeprefix("seed ")
    return make_recipe(kind, size, seed)


def recipe_of(grid: Grid) -> Recipe | None:
    """The recipe a generated map's first line records (None for any other map)."""
    source = grid.source
    if source is None or not source.lines or not source.lines[0].startswith(COMMENT):
        return None
    try:
        return parse_recipe(source.lines[0][len(COMMENT):].rstrip("\r"))
    except ValueError:
        return None


def next_recipe(recipe: Recipe) -> Recipe:
    """The same kind and size with the next seed: a whole number plus one; text whose end is
    a number, that number plus one (``alice7``: ``alice8``); other text with ``2`` after it."""
    match = re.fullmatch(r"(.*?)([0-9]+)", recipe.seed)
    seed = f"{match[1]}{int(match[2]) + 1}" if match else f"{recipe.seed}2"
    return recipe._replace(seed=seed)


_MAKERS: dict[str, Callable[[int, int, SplitMix64], bytearray]] = {
    "maze": mazes.backtracker,
    "prim": mazes.prim,
    "kruskal": mazes.kruskal,
    "division": mazes.divide,
    "rooms": lambda w, h, rng: mazes.divide(w, h, rng, room=ROOM_NODES),
}


def _cells(recipe: Recipe) -> Grid:
    w, h = recipe.width, recipe.height
    rng = SplitMix64(seed_value(recipe.seed))
    if recipe.percent is not None:
        p = recipe.percent
        blocked = mazes.random_fill(w, h, rng, p.numerator, p.denominator)
        return Grid(w, h, blocked, (0, 0), (w - 1, h - 1))
    cw, ch = mazes.node_size(w, h)
    return Grid(w, h, _MAKERS[recipe.kind](w, h, rng), (0, 0), (2 * cw - 2, 2 * ch - 2))


def generated_text(recipe: Recipe) -> str:
    """The text map for ``recipe``: its recipe line, then its rows, each ending in ``\\n``."""
    rows = text_rows(_cells(recipe))
    return "".join(f"{line}\n" for line in (COMMENT + recipe.title, *rows))


def generate(recipe: Recipe, name: str = "<generated>") -> Grid:
    """The map for ``recipe``, read from :func:`generated_text` as a file would be (so a save
    keeps its recipe line)."""
    return parse_text_map(generated_text(recipe), name)
