"""A* with a closed set, eight moves and the Manhattan distance (too much with diagonals, so a
cell can be reached cheaper after it was expanded: this code never re-opens one).  Ties by a
counter, the oldest first; it logs the goal's line too.
Matches: -a astar --heuristic manhattan --reopen no --order N,NE,E,SE,S,SW,W,NW."""

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

    def h(p):
        return abs(p[0] - goal[0]) + abs(p[1] - goal[1])

    counter = itertools.count()
    open_heap = [(h(start), next(counter), start)]
    g = {start: 0.0}
    closed = set()
    lines = []
    while open_heap:
        _, _, current = heapq.heappop(open_heap)
        if current in closed:
            continue
        closed.add(current)
        if current == goal:
            lines.append(json.dumps({"node": current, "successors": []}))
            break
        added = []
        for m in moves.split(","):
            dx, dy = STEP[m]
            nxt = (current[0] + dx, current[1] + dy)
            if cells.get(nxt, "#") == "#" or nxt in closed:
                continue
            tentative = g[current] + (math.sqrt(2) if dx and dy else 1.0)
            if tentative < g.get(nxt, float("inf")):
                g[nxt] = tentative
                heapq.heappush(open_heap, (tentative + h(nxt), next(counter), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": current, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
