"""Greedy best-first search as much published code writes it: a heap by h (a counter breaks
ties, the oldest first), a table of g, a closed set (a cell taken off again is skipped, one
reached cheaper after its expansion is not pushed again).
Matches: -a greedy --heuristic manhattan --reopen no --order N,E,S,W."""

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

    counter = itertools.count()
    heap = [(h(start), next(counter), start)]
    g = {start: 0}
    closed = set()
    lines = []
    while heap:
        _, _, node = heapq.heappop(heap)
        if node in closed:
            continue
        closed.add(node)
        if node == goal:
            break
        added = []
        for m in moves.split(","):
            nxt = (node[0] + STEP[m][0], node[1] + STEP[m][1])
            if cells.get(nxt, "#") == "#" or nxt in closed:
                continue
            if g[node] + 1 < g.get(nxt, float("inf")):
                g[nxt] = g[node] + 1
                heapq.heappush(heap, (h(nxt), next(counter), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": node, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
