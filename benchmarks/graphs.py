"""Section **graph** (issue 37, "Scale"): headless UCS with ``--json`` on a generated graph of
100,000 nodes against networkx's ``dijkstra_path`` on the same graph, on the CPU clock, one run.

The graph is a 316x316 grid written as a ``.graph`` (:func:`write_grid_graph`: a node line with
its place per node, then an ``edge`` line per neighbour pair with a cost 1-9 from a seeded
random, ``start`` and ``goal`` at opposite corners), about 6.8 MB.

Rows, each on the CPU clock (``time.process_time``; the app's command through ``os.wait4``):

* the floors: Python reading the file and splitting its lines; reading it into a dict of names
  and flat arrays (what any parser of the format does at least); a plain heapq Dijkstra over
  int lists (compressed rows), with its build;
* networkx reading the file into an ``nx.Graph`` and its ``dijkstra_path``;
* the app in this process: the file read (``load_graph``), the recorded UCS run to its end with
  its outcome (what ``--headless --json`` does), beside networkx's ``dijkstra_path`` alone;
* the app's whole command, ``tui-search G.graph -a ucs --headless --json`` in a process of its
  own (Python's start-up and the JSON included), against networkx's read plus
  ``dijkstra_path``: the target, at most 1;
* the command's peak memory (its maximum resident size) beside the file's size.

Both searches must find the same cost (checked).  ``python benchmarks/graphs.py`` runs it alone.
"""

from __future__ import annotations

import heapq
import os
import random
import subprocess
import sys
import tempfile
import time
from array import array
from collections.abc import Callable
from pathlib import Path
from typing import Any

if __name__ == "__main__":  # run as a script: the checkout first, as bench.py does
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.table import Row, add

SECTION = "graph"
SIDE = 316  # 99,856 nodes
INF = float("inf")


def write_grid_graph(path: Path, side: int = SIDE, seed: int = 1) -> None:
    """A ``side`` x ``side`` grid as a ``.graph``: nodes ``xAyB`` with their places, a road
    of cost 1-9 between each pair of neighbours, from the corner (0, 0) to the opposite one."""
    rng = random.Random(seed)
    lines = [f"node x{x}y{y} {x} {y}\n" for y in range(side) for x in range(side)]
    for y in range(side):
        for x in range(side):
            if x + 1 < side:
                lines.append(f"edge x{x}y{y} x{x + 1}y{y} {rng.randint(1, 9)}\n")
            if y + 1 < side:
                lines.append(f"edge x{x}y{y} x{x}y{y + 1} {rng.randint(1, 9)}\n")
    lines.append(f"start x0y0\ngoal x{side - 1}y{side - 1}\n")
    path.write_text("".join(lines), encoding="utf-8")


def cpu(fn: Callable[[], Any]) -> tuple[float, Any]:
    """``fn()``'s CPU seconds in this process, and its value."""
    t0 = time.process_time()
    value = fn()
    return time.process_time() - t0, value


# -- the floors --------------------------------------------------------------------------------
def split_floor(path: Path) -> int:
    """Read the file and split every line into words: no parser does less."""
    text = path.read_text(encoding="utf-8")
    words = 0
    for line in text.splitlines():
        words += len(line.split())
    return words


Parsed = tuple[dict[str, int], array, array, array, int, int]


def parse_floor(path: Path) -> Parsed:
    """Read the file into a dict of names and flat arrays (no checks, no columns)."""
    text = path.read_text(encoding="utf-8")
    index: dict[str, int] = {}
    road_a, road_b, cost = array("i"), array("i"), array("d")
    xs, ys = array("d"), array("d")
    start = goal = -1
    for line in text.splitlines():
        w = line.split()
        if not w:
            continue
        key = w[0]
        if key == "edge":
            road_a.append(index[w[1]])
            road_b.append(index[w[2]])
            cost.append(float(w[3]))
        elif key == "node":
            index[w[1]] = len(index)
            xs.append(float(w[2]))
            ys.append(float(w[3]))
        elif key == "start":
            start = index[w[1]]
        elif key == "goal":
            goal = index[w[1]]
    return index, road_a, road_b, cost, start, goal


def compressed_rows(n: int, road_a: array, road_b: array, cost: array
                    ) -> tuple[list[int], list[int], list[float]]:
    """Each node's neighbours and costs as compressed rows (undirected roads)."""
    starts = [0] * (n + 1)
    for a in road_a:
        starts[a + 1] += 1
    for b in road_b:
        starts[b + 1] += 1
    for i in range(n):
        starts[i + 1] += starts[i]
    fill = starts[:]
    node, weight = [0] * starts[n], [0.0] * starts[n]
    for a, b, c in zip(road_a, road_b, cost, strict=True):
        node[fill[a]], weight[fill[a]] = b, c
        fill[a] += 1
        node[fill[b]], weight[fill[b]] = a, c
        fill[b] += 1
    return starts, node, weight


def bare_dijkstra(n: int, rows: tuple[list[int], list[int], list[float]], s: int, t: int
                  ) -> tuple[float, list[int]]:
    """A plain heapq Dijkstra (lazy deletion) from ``s`` to ``t``: its cost and path."""
    starts, node, weight = rows
    best = [INF] * n
    parent = [-1] * n
    best[s] = 0.0
    heap = [(0.0, s)]
    pop, push = heapq.heappop, heapq.heappush
    while heap:
        g, u = pop(heap)
        if g > best[u]:
            continue
        if u == t:
            break
        for j in range(starts[u], starts[u + 1]):
            v, ng = node[j], g + weight[j]
            if ng < best[v]:
                best[v], parent[v] = ng, u
                push(heap, (ng, v))
    path = [t]
    while path[-1] != s:
        path.append(parent[path[-1]])
    return best[t], path[::-1]


# -- networkx ----------------------------------------------------------------------------------
def networkx_read(path: Path) -> tuple[Any, str, str]:
    """The file as an ``nx.Graph`` (roads weighted), its start and goal."""
    import networkx as nx

    graph = nx.Graph()
    start = goal = ""
    with open(path, encoding="utf-8") as handle:
        for line in handle:
            w = line.split()
            if not w:
                continue
            if w[0] == "node":
                graph.add_node(w[1], pos=(float(w[2]), float(w[3])))
            elif w[0] == "edge":
                graph.add_edge(w[1], w[2], weight=float(w[3]))
            elif w[0] == "start":
                start = w[1]
            elif w[0] == "goal":
                goal = w[1]
    return graph, start, goal


# -- the app -----------------------------------------------------------------------------------
def app_in_process(path: Path) -> tuple[float, float, float]:
    """The app's read of the file and its recorded UCS run to the end with the outcome (what
    ``--headless --json`` runs), CPU seconds each, and the path's cost."""
    from tui_search.engine.maps.graph_file import load_graph
    from tui_search.engine.run.each_step import search_each_step
    from tui_search.engine.search.choices import Semantics

    read, graph = cpu(lambda: load_graph(path))
    sem = Semantics(order=("file",), heuristic="zero")
    search, outcome = cpu(lambda: search_each_step(graph, "ucs", sem, 10**9))
    return read, search, outcome.cost


#: Runs the command as ``python -m tui_search`` does, then writes the process's peak resident
#: size (``VmHWM``, of the program itself: ``ru_maxrss`` after a vfork counts the parent's)
#: to stderr.
_RUN_AND_MEASURE = """
import runpy, sys
sys.argv = ["tui-search", *sys.argv[1:]]
try:
    runpy.run_module("tui_search", run_name="__main__", alter_sys=True)
finally:
    for line in open("/proc/self/status"):
        if line.startswith("VmHWM:"):
            sys.stderr.write(f"\\npeak {int(line.split()[1]) * 1024}\\n")
"""


def app_command(path: Path) -> tuple[float, int, str]:
    """``tui-search G.graph -a ucs --headless --json`` in a process of its own: its CPU
    seconds (user + system), its peak resident size in bytes (0 where /proc is not), and its
    output."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(
            [sys.executable, "-c", _RUN_AND_MEASURE, str(path), "-a", "ucs", "--headless",
             "--json"], stdout=out, stderr=err)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        text, said = out.read().decode(), err.read().decode()
    if proc.returncode != 0:
        raise RuntimeError(f"tui-search exited {proc.returncode}: {said[-300:]}")
    peaks = [line for line in said.splitlines() if line.startswith("peak ")]
    return usage.ru_utime + usage.ru_stime, int(peaks[-1].split()[1]) if peaks else 0, text


def floors(path: Path) -> tuple[float, float, float, float, float]:
    """The floors' CPU seconds (split, parse, rows, Dijkstra) and the cost found."""
    t_split, _ = cpu(lambda: split_floor(path))
    t_parse, parsed = cpu(lambda: parse_floor(path))
    index, road_a, road_b, cost, s, t = parsed
    t_rows, rows = cpu(lambda: compressed_rows(len(index), road_a, road_b, cost))
    t_dijkstra, (found, _) = cpu(lambda: bare_dijkstra(len(index), rows, s, t))
    return t_split, t_parse, t_rows, t_dijkstra, found


def networkx_times(path: Path) -> tuple[float, float, float]:
    """networkx's read and ``dijkstra_path`` (CPU seconds) and the path's cost."""
    import networkx as nx

    t_read, (graph, start, goal) = cpu(lambda: networkx_read(path))
    t_path, found = cpu(lambda: nx.dijkstra_path(graph, start, goal))
    return t_read, t_path, nx.path_weight(graph, found, "weight")


def bench_graph(quick: bool = False) -> None:
    """The rows of this section (one run each: ``quick`` changes nothing)."""
    import json

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / f"grid{SIDE}.graph"
        write_grid_graph(path)
        size = path.stat().st_size
        print(f"[graph] {path.name}: {SIDE * SIDE:,} nodes, {size / 1e6:.1f} MB",
              file=sys.stderr)
        t_split, t_parse, t_rows, t_dijkstra, floor_cost = floors(path)
        add(Row(SECTION, "floor: read + split every line", f"{t_split:.3f} s"))
        add(Row(SECTION, "floor: read into a dict of names + flat arrays", f"{t_parse:.3f} s"))
        add(Row(SECTION, "floor: heapq Dijkstra over int lists (+ rows build "
                f"{t_rows:.3f} s)", f"{t_dijkstra:.3f} s"))
        try:
            import networkx  # noqa: F401
        except ImportError:
            add(Row(SECTION, "networkx dijkstra_path", "not installed"))
            return
        t_nx_read, t_nx, nx_cost = networkx_times(path)
        add(Row(SECTION, "networkx: read into nx.Graph", f"{t_nx_read:.3f} s"))
        add(Row(SECTION, "networkx: dijkstra_path", f"{t_nx:.3f} s"))
        t_read, t_search, app_cost = app_in_process(path)
        add(Row(SECTION, "app: load_graph (the .graph parser)", f"{t_read:.3f} s",
                f"floor {t_parse:.3f} s", t_read / t_parse, "report"))
        add(Row(SECTION, "app: recorded UCS run + outcome vs dijkstra_path",
                f"{t_search:.3f} s", f"networkx {t_nx:.3f} s", t_search / t_nx, "≤ 1",
                t_search <= t_nx, floor=t_dijkstra / t_nx))
        t_app, peak, output = app_command(path)
        found = json.loads(output)["cost"]
        if not (found == app_cost == floor_cost == nx_cost):
            raise RuntimeError(f"costs differ: app {found}, in process {app_cost}, "
                               f"floor {floor_cost}, networkx {nx_cost}")
        nx_total = t_nx_read + t_nx
        add(Row(SECTION, "app: tui-search G -a ucs --headless --json (CPU, own process) vs "
                "networkx read + dijkstra_path", f"{t_app:.3f} s", f"networkx {nx_total:.3f} s",
                t_app / nx_total, "≤ 1", t_app <= nx_total,
                floor=(t_parse + t_rows + t_dijkstra) / nx_total))
        add(Row(SECTION, "app: the command's peak memory vs the file's size",
                f"{peak / 1e6:.0f} MB", f"file {size / 1e6:.1f} MB", peak / size, "report"))


if __name__ == "__main__":
    from benchmarks.table import ROWS, print_table

    bench_graph()
    print_table(ROWS)
