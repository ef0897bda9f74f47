"""Greedy best-first that breaks a tie of h by the deeper entry: a heap of
``(h, -g, count, (x, y))``, so of two cells as near the goal it takes the one reached at the
higher cost, then the oldest; a table of g, and a cell pushed again when reached cheaper.
It stops when it takes the goal off.
Matches: -a greedy --heuristic manhattan --ties high-g."""

import heapq
import itertools
import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")

    def h(p):
        return abs(p[0] - goal[0]) + abs(p[1] - goal[1])

    count = itertools.count()
    open_heap = [(h(start), 0, next(count), start)]
    g = {start: 0}
    lines = []
    while open_heap:
        _h, _g, _n, current = heapq.heappop(open_heap)
        if current == goal:
            break
        added = []
        for m in moves.split(","):
            nxt = (current[0] + STEP[m][0], current[1] + STEP[m][1])
            if cells.get(nxt, "#") == "#":
                continue
            tentative = g[current] + 1
            if tentative < g.get(nxt, float("inf")):
                g[nxt] = tentative
                heapq.heappush(open_heap, (h(nxt), -tentative, next(count), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": current, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
