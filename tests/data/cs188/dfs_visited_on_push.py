"""A student's DFS that marks a state visited when it pushes it (a common bug)."""
import util


def depthFirstSearch(problem):
    start = problem.getStartState()
    frontier = util.Stack()
    frontier.push((start, []))
    visited = {start}
    while not frontier.isEmpty():
        state, actions = frontier.pop()
        if problem.isGoalState(state):
            return actions
        for successor, action, _ in problem.getSuccessors(state):
            if successor not in visited:
                visited.add(successor)
                frontier.push((successor, actions + [action]))
    return []
