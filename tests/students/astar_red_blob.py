"""A* as a popular tutorial's grid writes it (Red Blob Games' "Implementation of A*"): a
cell's neighbours east, west, north, south, the list reversed on every other cell (where
x + y is even) so that straight paths zigzag rather than bend once; a heap of
``(priority, (x, y))`` pairs (a tie of f goes to the smallest cell); a table of g, a cell
pushed again when reached cheaper; it stops when it takes the goal off.
Matches: -a astar --heuristic manhattan --ties node --order E,W,N,S --flip-even."""

import heapq
import json
import sys


def search(rows):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")

    def neighbours(cell):
        x, y = cell
        around = [(x + 1, y), (x - 1, y), (x, y - 1), (x, y + 1)]
        if (x + y) % 2 == 0:
            around.reverse()
        return [c for c in around if cells.get(c, "#") != "#"]

    def h(p):
        return abs(p[0] - goal[0]) + abs(p[1] - goal[1])

    frontier = [(0, start)]
    cost_so_far = {start: 0}
    lines = []
    while frontier:
        _priority, current = heapq.heappop(frontier)
        if current == goal:
            break
        added = []
        for nxt in neighbours(current):
            new_cost = cost_so_far[current] + 1
            if nxt not in cost_so_far or new_cost < cost_so_far[nxt]:
                cost_so_far[nxt] = new_cost
                heapq.heappush(frontier, (new_cost + h(nxt), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": current, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
