"""A recursive DFS that, entering a cell, marks it visited and lists the neighbours not yet
visited, then calls itself on each (skipping one visited meanwhile, deeper down); it tests the
goal when it enters it.  Matches: -a dfs --recursive --goal-test expand."""

import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    sys.setrecursionlimit(10_000)
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    visited = set()
    lines = []

    def dfs(node):
        visited.add(node)
        if node == goal:
            lines.append(json.dumps({"node": node, "successors": []}))
            return True
        todo = []
        for m in moves.split(","):
            nxt = (node[0] + STEP[m][0], node[1] + STEP[m][1])
            if cells.get(nxt, "#") != "#" and nxt not in visited:
                todo.append(nxt)
        lines.append(json.dumps({"node": node, "successors": todo}))
        for nxt in todo:
            if nxt not in visited and dfs(nxt):
                return True
        return False

    dfs(start)
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
