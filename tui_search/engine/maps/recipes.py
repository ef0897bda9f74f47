"""What ``--generate`` offers, as plain data: the kinds of map, the default size and seed, the
largest side.  The command line's help reads them without importing the generators
(:mod:`~tui_search.engine.maps.generate`, which uses them)."""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import NamedTuple

__all__ = ["DEFAULT_SEED", "DEFAULT_SIZE", "KINDS", "MAX_SIDE", "Kind"]

MAX_SIDE = 999  # the largest width or height of a generated map
DEFAULT_SIZE = "21x15"
DEFAULT_SEED = "1"


class Kind(NamedTuple):
    name: str
    minimum: tuple[int, int]  # the smallest width and height
    help: str
    perfect: bool


KINDS: dict[str, Kind] = {k.name: k for k in (
    Kind("random", (2, 2), "random:P, P% (0-100) of cells obstacles, S and G joined", False),
    Kind("maze", (3, 3), "recursive backtracker: depth-first search carving a maze", True),
    Kind("prim", (3, 3), "randomised Prim: a tree grown from one cell", True),
    Kind("kruskal", (3, 3), "randomised Kruskal: passages opened in random order", True),
    Kind("division", (3, 3), "recursive division: walls with one gap each", True),
    Kind("rooms", (9, 9), "rooms of up to 7x7 joined by doors (recursive division)", False),
)}
