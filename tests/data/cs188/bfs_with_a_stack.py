"""A student's BFS written with a stack (a common bug): it is a DFS."""
import util


def breadthFirstSearch(problem):
    frontier = util.Stack()
    frontier.push((problem.getStartState(), []))
    closed = set()
    while not frontier.isEmpty():
        state, actions = frontier.pop()
        if problem.isGoalState(state):
            return actions
        if state in closed:
            continue
        closed.add(state)
        for successor, action, _ in problem.getSuccessors(state):
            frontier.push((successor, actions + [action]))
    return []
