"""MovingAI ``.scen`` files: benchmark problems (a start and goal on a named map, with the
optimal length), read and checked against the map they are for.

The format is https://movingai.com/benchmarks/formats.html: a ``version`` line, then one
problem per line in nine fields.
"""

from __future__ import annotations

import math
import os
import re
from typing import NamedTuple

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import (
    MAX_DIGITS,
    NUMBER,
    MapError,
    check_cell,
    quoted,
    read_text,
    stripped_lines,
)

__all__ = [
    "Optimum",
    "Scenario",
    "check_scenario_map",
    "check_scenario_matches",
    "load_scenario",
    "parse_scenarios",
    "read_scenarios",
]


class Scenario(NamedTuple):
    """One benchmark problem: a start and goal on a named map, with its optimal length."""

    bucket: int
    map_name: str  # as written in the file; may include directories (match by basename)
    width: int
    height: int
    start: Cell
    goal: Cell
    optimal_length: float
    line: int  # 1-based line in the .scen file, for error messages


#: Bigger scenario files are refused before reading (MovingAI's are a few hundred KB; every
#: row is read, each on its own).
MAX_SCEN_BYTES = 16 * 1024 * 1024
_VERSION = re.compile(r"version\s+[0-9]+(\.[0-9]+)?", re.IGNORECASE)
_FIELDS = (
    "bucket", "map", "map width", "map height",
    "start x", "start y", "goal x", "goal y", "optimal length",
)  # fmt: skip


def read_scenarios(path: str | os.PathLike[str]) -> list[Scenario]:
    """Every problem in a ``.scen`` file, in file order."""
    where = os.fsdecode(path)
    return parse_scenarios(read_text(where, "a scenario file", MAX_SCEN_BYTES), where)


def parse_scenarios(text: str, path: str = "<scen>") -> list[Scenario]:
    """Every problem in the text of a ``.scen`` file (``path`` is only for messages)."""
    return _read_rows(text, path)[0]


def _read_rows(text: str, path: str, only: int | None = None) -> tuple[list[Scenario], int]:
    """The problems in the text of a ``.scen`` file, or only problem number ``only`` (every
    row is checked all the same), and how many there are."""
    lines = stripped_lines(text)
    first = next(lines)
    if not _VERSION.fullmatch(first.strip()):
        found = quoted(first) if first else "an empty line"
        raise MapError(path, f"expected 'version 1' on the first line, found {found}", 1)
    out = []
    count = 0
    fast = _PLAIN_ROW.fullmatch
    for number, line in enumerate(lines, start=2):
        m = fast(line)
        if m is not None:  # the common row, checked at once (benchmarks/README.md, "startup")
            b, name, w, h, sx, sy, gx, gy, length = m.groups()
            width, height = int(w), int(h)
            start, goal = (int(sx), int(sy)), (int(gx), int(gy))
            if name == name.strip() and 0 < width and 0 < height and start[0] < width \
                    and goal[0] < width and start[1] < height and goal[1] < height:
                if only is None or only == count:
                    out.append(Scenario(int(b), name, width, height, start, goal,
                                        float(length), number))
                count += 1
                continue
        if line.strip():  # any other row, read field by field: each error said exactly
            row = _parse_row(line, number, path)
            if only is None or only == count:
                out.append(row)
            count += 1
    return out, count


#: A row as the files write it: tab-separated, whole numbers of at most MAX_DIGITS digits, a
#: plain decimal length.  Any other row goes through ``_parse_row``, which reads it the same
#: way or says what is wrong.
_N = f"([0-9]{{1,{MAX_DIGITS}}})"
_PLAIN_ROW = re.compile("\t".join([_N, "([^\t]+)", *[_N] * 6, r"([0-9]+(?:\.[0-9]+)?)"]))


def _parse_row(line: str, number: int, path: str) -> Scenario:
    """The problem on ``line`` (line ``number`` of the file), or a MapError saying why not."""
    fields = [f.strip() for f in line.split("\t")]
    if len(fields) != 9:
        fields = line.split()
    if len(fields) != 9:
        raise MapError(
            path,
            f"expected 9 fields ({', '.join(_FIELDS)}), found {len(fields)}",
            number,
        )
    ints = []
    for k in (0, 2, 3, 4, 5, 6, 7):
        word = fields[k]
        if not NUMBER.fullmatch(word) or len(word.lstrip("0")) > MAX_DIGITS:
            raise MapError(
                path, f"{_FIELDS[k]} is not a whole number >= 0: {quoted(word)}", number
            )
        ints.append(int(word))
    bucket, width, height, sx, sy, gx, gy = ints
    try:
        length = float(fields[8])
    except ValueError:
        length = math.nan
    if not (math.isfinite(length) and length >= 0):
        raise MapError(
            path, f"optimal length is not a number >= 0: {quoted(fields[8])}", number
        )
    if not fields[1]:
        raise MapError(path, "the map name is empty", number)
    if width < 1 or height < 1:
        raise MapError(path, f"map size {width}x{height} is empty", number)
    for what, (x, y) in (("start", (sx, sy)), ("goal", (gx, gy))):
        if x >= width or y >= height:
            raise MapError(
                path, f"{what} ({x},{y}) is outside the {width}x{height} map", number
            )
    return Scenario(bucket, fields[1], width, height, (sx, sy), (gx, gy), length, number)


def load_scenario(path: str | os.PathLike[str], row: int) -> Scenario:
    """Problem number ``row`` (from 0, after the version line) of a ``.scen`` file."""
    where = os.fsdecode(path)
    found, count = _read_rows(read_text(where, "a scenario file", MAX_SCEN_BYTES), where, row)
    if found:
        return found[0]
    if not count:
        raise MapError(where, f"no row {row}: the file has no scenario rows")
    rows = "1 row (row 0)" if count == 1 else f"{count} rows (0 to {count - 1})"
    raise MapError(where, f"no row {row}: the file has {rows}")


def _basename(name: str) -> str:
    """Basename for either separator: scenario files written on Windows use backslashes."""
    return re.split(r"[\\/]", name)[-1]


def check_scenario_map(
    scen: Scenario, scen_path: str | os.PathLike[str], map_path: str | os.PathLike[str]
) -> None:
    """Raise MapError (at the scenario's line) unless ``scen`` names the map ``map_path``.

    Check this before the scenario's start and goal are put on the grid: on another map they
    would be refused for the wrong reason ("start is on an obstacle").  Maps are matched by
    basename because older files give a path (``maps/dao/x.map``).
    """
    where = os.fsdecode(scen_path)
    map_name = _basename(os.fsdecode(map_path))
    wanted = _basename(scen.map_name)
    if wanted != map_name:
        raise MapError(
            where, f"{_basename(where)} is for {wanted}, not {map_name}", scen.line
        )


def check_scenario_matches(
    scen: Scenario, grid: Grid, scen_path: str | os.PathLike[str], map_path: str | os.PathLike[str]
) -> None:
    """Raise MapError (at the scenario's line) unless ``scen`` is a problem on this map:
    its name (:func:`check_scenario_map`), its size, then its start and goal.

    The spec's "scale the map to the scenario's size" is not supported: sizes must match.
    """
    check_scenario_map(scen, scen_path, map_path)
    where = os.fsdecode(scen_path)
    map_name = _basename(os.fsdecode(map_path))
    if (scen.width, scen.height) != (grid.width, grid.height):
        raise MapError(
            where,
            f"scenario says the map is {scen.width}x{scen.height}, "
            f"but {map_name} is {grid.width}x{grid.height}",
            scen.line,
        )
    check_cell(grid, scen.start, "start", where, scen.line)
    check_cell(grid, scen.goal, "goal", where, scen.line)


def _map_key(grid: Grid) -> tuple[bytes, bytes | None]:
    return bytes(grid.blocked), None if grid.costs is None else bytes(grid.costs)


class Optimum:
    """A scenario's optimal length on ``grid`` as it is now: it holds while the map's
    obstacles and terrain, its start and goal and the benchmark's rules (8 moves, no corner
    cutting) stay so (an obstacle or a cost painted lapses it; undone, it holds again)."""

    def __init__(self, grid: Grid, cost: float) -> None:
        self.cost = cost
        self._ends, self._map = (grid.start, grid.goal), _map_key(grid)

    def on(self, grid: Grid, corners: str, moves: int) -> float | None:
        """The optimal cost if it holds on ``grid`` under a search's corner rule and number of
        moves, else None."""
        same_map = (grid.start, grid.goal) == self._ends and _map_key(grid) == self._map
        rules = corners == "never" and moves == 8
        return self.cost if same_map and rules else None
