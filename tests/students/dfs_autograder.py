"""A course's graph-search DFS (a stack, a visited set checked when a state is popped, the
goal tested when popped) and what its autograder records: the states passed to the successor
function, in order -- lines with a node and no successors.  The successor function gives the
moves N, S, E, W.  Matches: -a dfs --visit expand --goal-test expand --order N,S,E,W."""

import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,S,E,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    expanded = []

    def get_successors(state):
        expanded.append(state)
        out = []
        for m in moves.split(","):
            nxt = (state[0] + STEP[m][0], state[1] + STEP[m][1])
            if cells.get(nxt, "#") != "#":
                out.append(nxt)
        return out

    stack = [start]
    visited = set()
    while stack:
        state = stack.pop()
        if state == goal:
            break
        if state in visited:
            continue
        visited.add(state)
        for succ in get_successors(state):
            if succ not in visited:
                stack.append(succ)
    return "".join(json.dumps({"node": s}) + "\n" for s in expanded)


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
