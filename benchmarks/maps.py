"""The maps the benchmarks run on: an open square and the MovingAI maze512 (read from outside
the repository: ``/work/shared/maps/movingai``, or ``TUI_SEARCH_MAPS``)."""

from __future__ import annotations

import os
from pathlib import Path

from tui_search.engine.maps.grid import Grid

ROOT = Path(__file__).resolve().parent.parent
#: Where the MovingAI maps are (not shipped in the package); override with TUI_SEARCH_MAPS.
MAPS = Path(os.environ.get("TUI_SEARCH_MAPS", "/work/shared/maps/movingai"))
TUTORIAL = ROOT / "maps" / "tutorial.txt"
MAZE, MAZE_SCEN = "maze512-1-0.map", "maze512-1-0.map.scen"
OPEN_SIZE = 1024


def open_grid(n: int = OPEN_SIZE) -> Grid:
    return Grid(n, n, start=(0, 0), goal=(n - 1, n - 1))


def maze_grid() -> Grid | None:
    """maze512-1-0 with the start and goal of the last (longest) row of its .scen."""
    m, s = MAPS / MAZE, MAPS / MAZE_SCEN
    if not m.exists() or not s.exists():
        return None
    rows = [ln for ln in s.read_text().splitlines()[1:] if ln.strip()]
    last = len(rows) - 1
    try:
        from tui_search.engine.maps.load import load_map
        from tui_search.engine.maps.scenarios import load_scenario

        scen = load_scenario(s, last)
        return load_map(m, start=scen.start, goal=scen.goal)
    except ImportError:  # the parser is not there: read the two formats here
        f = rows[last].split("\t")
        lines = m.read_text().splitlines()
        h, w = int(lines[1].split()[1]), int(lines[2].split()[1])
        body = "".join(lines[4 : 4 + h])
        blocked = bytearray(0 if ch in ".GS" else 1 for ch in body)
        return Grid(w, h, blocked, (int(f[4]), int(f[5])), (int(f[6]), int(f[7])))


def big_maps(section: str) -> list[tuple[str, Grid]]:
    """The maps the engine and choices rows run on, by the names the rows print: open 1024²
    and maze512 -- or a "skipped" row of ``section`` when maze512 is not in MAPS."""
    from benchmarks.table import Row, add

    maps = [(f"open {OPEN_SIZE}²", open_grid())]
    maze = maze_grid()
    if maze is None:
        add(Row(section, MAZE, "skipped", f"not found in {MAPS}"))
    else:
        maps.append(("maze512", maze))
    return maps


def maze_cli_args() -> list[str]:
    rows = [ln for ln in (MAPS / MAZE_SCEN).read_text().splitlines()[1:] if ln.strip()]
    return [str(MAPS / MAZE), "--scen", str(MAPS / MAZE_SCEN), "--scen-row", str(len(rows) - 1)]
