"""A correct BFS that stops when it takes the goal off the queue, and writes no line for that
pop (nothing says it must).  Matches: -a bfs --goal-test expand."""

import json
import sys
from collections import deque

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    queue = deque([start])
    parent = {start: None}
    lines = []
    while queue:
        node = queue.popleft()
        if node == goal:
            break
        added = []
        for m in moves.split(","):
            nxt = (node[0] + STEP[m][0], node[1] + STEP[m][1])
            if cells.get(nxt, "#") != "#" and nxt not in parent:
                parent[nxt] = node
                queue.append(nxt)
                added.append(nxt)
        lines.append(json.dumps({"node": node, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
