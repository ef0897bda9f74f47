"""The textbook's iterative deepening: a recursive depth-limited tree search (no check of
any kind), called with limits 0, 1, 2, ...; each call's line lists its children, and the goal
is tested when a call begins.
Matches: -a iddfs --recursive --tree-search --no-path-check --goal-test expand."""

import itertools
import json
import sys

STEP = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def search(rows, moves="N,E,S,W"):
    cells = {(x, y): c for y, row in enumerate(rows) for x, c in enumerate(row)}
    start = next(p for p, c in cells.items() if c == "S")
    goal = next(p for p, c in cells.items() if c == "G")
    lines = []

    def recursive_dls(node, limit):
        line = {"node": node, "successors": []}
        lines.append(line)
        if node == goal:
            return "found"
        if limit == 0:
            return "cutoff"
        children = []
        for m in moves.split(","):
            child = (node[0] + STEP[m][0], node[1] + STEP[m][1])
            if cells.get(child, "#") != "#":
                children.append(child)
        line["successors"] = children
        cutoff = False
        for child in children:
            result = recursive_dls(child, limit - 1)
            if result == "cutoff":
                cutoff = True
            elif result == "found":
                return result
        return "cutoff" if cutoff else "failure"

    for depth in itertools.count():
        if recursive_dls(start, depth) != "cutoff":
            break
    return "".join(json.dumps(line) + "\n" for line in lines)


if __name__ == "__main__":
    sys.stdout.write(search(open(sys.argv[1]).read().split()))
