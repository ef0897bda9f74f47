"""The textbook's tree search with a FIFO queue: no explored set, nothing skipped -- not even
the parent.  It tests the goal when it takes a node off.
Matches: -a bfs --tree-search --no-path-check --goal-test expand."""

import json
import sys
from collections import deque

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    frontier = deque([start])
    lines = []
    while frontier:
        node = frontier.popleft()
        if node == goal:
            lines.append(json.dumps({"node": node, "successors": []}))
            break
        children = []
        for m in moves.split(","):
            child = (node[0] + STEP[m][0], node[1] + STEP[m][1])
            if cells.get(child, "#") != "#":
                children.append(child)
        frontier.extend(children)
        lines.append(json.dumps({"node": node, "successors": children}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
