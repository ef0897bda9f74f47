"""A* on a plain list, as many first attempts keep it: sorted by f from the highest down
(``sort(reverse=True)``, which keeps equal entries in the order they came) and the last one
popped, so a tie of f goes to the newest entry; a table of g; no closed set.  It stops when
it takes the goal off.
Matches: -a astar --heuristic manhattan --ties lifo."""

import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")

    def h(p):
        return abs(p[0] - goal[0]) + abs(p[1] - goal[1])

    open_list = [(h(start), start)]
    g = {start: 0}
    lines = []
    while open_list:
        open_list.sort(key=lambda entry: entry[0], reverse=True)
        _f, current = open_list.pop()
        if current == goal:
            break
        added = []
        for m in moves.split(","):
            nxt = (current[0] + STEP[m][0], current[1] + STEP[m][1])
            if cells.get(nxt, "#") == "#":
                continue
            tentative = g[current] + 1
            if tentative < g.get(nxt, float("inf")):
                g[nxt] = tentative
                open_list.append((tentative + h(nxt), nxt))
                added.append(nxt)
        lines.append(json.dumps({"node": current, "successors": added}))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
