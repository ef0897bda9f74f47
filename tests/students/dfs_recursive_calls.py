"""A recursive DFS whose line lists the cells it recursed into, in order (the line is made on
entry and filled as the calls are made), and that tests the goal when it finds it as a
neighbour.  Matches: -a dfs --recursive-lines calls."""

import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    sys.setrecursionlimit(10_000)
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    visited = set()
    trace = []

    def dfs(node):
        visited.add(node)
        line = {"node": node, "successors": []}
        trace.append(line)
        for m in moves.split(","):
            nxt = (node[0] + STEP[m][0], node[1] + STEP[m][1])
            if cells.get(nxt, "#") == "#" or nxt in visited:
                continue
            line["successors"].append(nxt)
            if nxt == goal:
                return True
            if dfs(nxt):
                return True
        return False

    dfs(start)
    return "".join(json.dumps(line) + "\n" for line in trace)


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
