"""A student's breadth-first search, written without tui_search: it reads a text map and
writes the trace that `tui-search MAP --check-trace FILE --headless -a bfs --order N,W,S,E`
checks.  Usage: python student_bfs.py MAP > trace.jsonl"""
import json
import sys
from collections import deque

rows = [ln.rstrip("\n") for ln in open(sys.argv[1]) if ln.strip() and not ln.startswith(";")]
cells = {(x, y): ch for y, row in enumerate(rows) for x, ch in enumerate(row)}
start = next(c for c, ch in cells.items() if ch == "S")
goal = next(c for c, ch in cells.items() if ch == "G")
print(json.dumps({"start": start, "goal": goal}))
queue, visited = deque([start]), {start}
while queue:
    x, y = queue.popleft()
    added = []
    for dx, dy in [(0, -1), (-1, 0), (0, 1), (1, 0)]:  # N, W, S, E
        nxt = (x + dx, y + dy)
        if cells.get(nxt, "#") != "#" and nxt not in visited:
            visited.add(nxt)
            queue.append(nxt)
            added.append(nxt)
            if nxt == goal:
                break
    print(json.dumps({"node": [x, y], "successors": added}))
    if goal in visited:
        break
