"""A student's UCS that lowers a state's priority with PriorityQueue.update: the state keeps
its place among equal priorities, where a re-push would put it last."""
import util


def uniformCostSearch(problem):
    start = problem.getStartState()
    frontier = util.PriorityQueue()
    frontier.push(start, 0)
    best = {start: (0, [])}
    closed = set()
    while not frontier.isEmpty():
        state = frontier.pop()
        cost, actions = best[state]
        if problem.isGoalState(state):
            return actions
        if state in closed:
            continue
        closed.add(state)
        for successor, action, step in problem.getSuccessors(state):
            if successor in closed:
                continue
            if successor not in best or cost + step < best[successor][0]:
                best[successor] = (cost + step, actions + [action])
                frontier.update(successor, cost + step)
    return []
