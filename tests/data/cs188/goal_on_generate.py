"""A student's BFS that tests the goal when it generates a state (a common bug)."""
import util


def breadthFirstSearch(problem):
    start = problem.getStartState()
    if problem.isGoalState(start):
        return []
    frontier = util.Queue()
    frontier.push((start, []))
    closed = set()
    while not frontier.isEmpty():
        state, actions = frontier.pop()
        if state in closed:
            continue
        closed.add(state)
        for successor, action, _ in problem.getSuccessors(state):
            if problem.isGoalState(successor):
                return actions + [action]
            frontier.push((successor, actions + [action]))
    return []
