"""A library's A*: it tests ``came_from`` to tell a new cell, and the start has no entry there
(it came from nothing), so a neighbour pushes the start again (at g 2; it is then expanded
again, adding nothing).  Ties by a counter, the oldest first.
Matches: -a astar --heuristic manhattan --mark-start no."""

import heapq
import itertools
import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")

    def heuristic(p):
        return abs(p[0] - goal[0]) + abs(p[1] - goal[1])

    counter = itertools.count()
    frontier = [(heuristic(start), next(counter), start)]
    came_from = {}
    cost_so_far = {start: 0}
    lines = []
    while frontier:
        _, _, current = heapq.heappop(frontier)
        if current == goal:
            break
        added = []
        for m in moves.split(","):
            nxt = (current[0] + STEP[m][0], current[1] + STEP[m][1])
            if cells.get(nxt, "#") == "#":
                continue
            new_cost = cost_so_far[current] + 1
            if nxt not in came_from or new_cost < cost_so_far[nxt]:
                cost_so_far[nxt] = new_cost
                came_from[nxt] = current
                heapq.heappush(frontier, (new_cost + heuristic(nxt), next(counter), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": current, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
