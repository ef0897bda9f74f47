"""A student's search.py for a CS188-style course, written for tui-search's tests: not the
course's code.  Graph search with a closed set; each state is checked when it comes off the
frontier (expanded once), the goal when it comes off."""

import util


def tinyMazeSearch(problem):
    from game import Directions

    return [Directions.SOUTH, Directions.SOUTH, Directions.WEST]


def _graph_search(problem, frontier, push):
    closed = set()
    push(frontier, (problem.getStartState(), [], 0))
    while not frontier.isEmpty():
        state, actions, cost = frontier.pop()
        if problem.isGoalState(state):
            return actions
        if state in closed:
            continue
        closed.add(state)
        for successor, action, step_cost in problem.getSuccessors(state):
            if successor not in closed:
                push(frontier, (successor, actions + [action], cost + step_cost))
    return []


def depthFirstSearch(problem):
    return _graph_search(problem, util.Stack(), lambda f, node: f.push(node))


def breadthFirstSearch(problem):
    return _graph_search(problem, util.Queue(), lambda f, node: f.push(node))


def uniformCostSearch(problem):
    return _graph_search(problem, util.PriorityQueue(), lambda f, node: f.push(node, node[2]))


def nullHeuristic(state, problem=None):
    return 0


def aStarSearch(problem, heuristic=nullHeuristic):
    def push(frontier, node):
        frontier.push(node, node[2] + heuristic(node[0], problem))

    return _graph_search(problem, util.PriorityQueue(), push)


bfs = breadthFirstSearch
dfs = depthFirstSearch
astar = aStarSearch
ucs = uniformCostSearch
