"""Uniform-cost search on eight moves that compares float costs with ``<``: a cell reached
again at a cost lower by 1e-15 (the same cost summed in another order) is pushed again.  A
heap of (g, counter, cell); a stale entry is skipped.
Matches: -a ucs --cost-tolerance 0 --order N,NE,E,SE,S,SW,W,NW."""

import heapq
import itertools
import json
import math
import sys

STEP = {"N": (0, -1), "NE": (1, -1), "E": (1, 0), "SE": (1, 1), "S": (0, 1), "SW": (-1, 1),
        "W": (-1, 0), "NW": (-1, -1)}


def search(rows, moves="N,NE,E,SE,S,SW,W,NW"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    counter = itertools.count()
    heap = [(0.0, next(counter), start)]
    dist = {start: 0.0}
    lines = []
    while heap:
        d, _, node = heapq.heappop(heap)
        if d > dist[node]:
            continue  # stale
        if node == goal:
            break
        added = []
        for m in moves.split(","):
            dx, dy = STEP[m]
            nxt = (node[0] + dx, node[1] + dy)
            if cells.get(nxt, "#") == "#":
                continue
            nd = d + (math.sqrt(2) if dx and dy else 1.0)
            if nd < dist.get(nxt, float("inf")):
                dist[nxt] = nd
                heapq.heappush(heap, (nd, next(counter), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": node, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
