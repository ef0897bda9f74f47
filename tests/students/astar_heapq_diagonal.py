"""The most copied A* in Python on eight moves (a diagonal costs sqrt 2), with Manhattan's
estimate: a heap of ``(f, (x, y))`` pairs, a table of g, a cell pushed again when reached
cheaper, and nothing checked when an entry is taken off -- an out-of-date entry (its cell
pushed again since, cheaper) is expanded again, and adds nothing.  It stops when it takes the
goal off.
Matches: -a astar --heuristic manhattan --ties node --cost-tolerance 0
--order N,NE,E,SE,S,SW,W,NW."""

import heapq
import json
import math
import sys

MOVES = [(0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1)]


def search(rows):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")

    def h(p):
        return abs(p[0] - goal[0]) + abs(p[1] - goal[1])

    heap = [(h(start), start)]
    g = {start: 0}
    lines = []
    while heap:
        _f, current = heapq.heappop(heap)
        if current == goal:
            break
        added = []
        for dx, dy in MOVES:
            nxt = (current[0] + dx, current[1] + dy)
            if cells.get(nxt, "#") == "#":
                continue
            new_g = g[current] + (math.sqrt(2) if dx and dy else 1)
            if new_g < g.get(nxt, float("inf")):
                g[nxt] = new_g
                heapq.heappush(heap, (new_g + h(nxt), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": current, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
