"""A "BFS" that takes the newest cell off its list (``pop()``, a stack): a DFS in truth.
Matches: -a dfs."""

import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    frontier = [start]
    seen = {start}
    lines = []
    while frontier:
        node = frontier.pop()  # meant: frontier.pop(0)
        added = []
        for m in moves.split(","):
            nxt = (node[0] + STEP[m][0], node[1] + STEP[m][1])
            if cells.get(nxt, "#") != "#" and nxt not in seen:
                seen.add(nxt)
                frontier.append(nxt)
                added.append(nxt)
                if nxt == goal:
                    break
        lines.append(json.dumps({"node": node, "successors": added}))
        if goal in seen:
            break
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
