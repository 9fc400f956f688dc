"""LAMA's first search (Fast Downward's `lama-first`): lazy greedy best-first
search alternating h_FF with a second heuristic, landmark count by default.

    lazy_greedy([hff, hlm], preferred=[hff], boost=1000), unit costs

Four open lists: by h_FF, by h_FF of the preferred successors only, by the
second heuristic, and by it for preferred successors. Each pick takes the
front of the list picked least often so far; whenever a state improves the
best value of either heuristic, the preferred lists are boosted (1000 free
picks), which is most of LAMA's speed. Preferred operators are those of the
state's h_FF relaxed plan; like FD's, this h_FF must also achieve the facts
that conditions need false. Evaluation is lazy: successors are queued with
their parent's values and evaluated when picked. Both heuristics count
steps, not costs (as lama-first does); the plan's real cost is reported.
A second heuristic that says it is not `informative` (a landmark count
without landmarks) is left out: h_FF alone, with its preferred list.
"""

from __future__ import annotations

import heapq
import itertools

from tampcli.search.budget import (
    INF,
    NO_LIMITS,
    Budget,
    Heuristic,
    SearchLimits,
    SearchResult,
    path_to,
)
from tampcli.search.heuristics.additive import HFF
from tampcli.task.task import Task

BOOST = 1000


def lama(task: Task, heuristic: Heuristic, limits: SearchLimits = NO_LIMITS) -> SearchResult:
    budget = Budget(limits)
    hff = HFF(task, unit_cost=True, negations=True)
    progress = getattr(heuristic, "progress", None)
    counter = itertools.count()
    # hff, hff preferred, second, second preferred
    lists: list[list] = [[], [], [], []]
    picks = [0, 0, 0, 0]
    # a heuristic without information (no landmarks found) would only turn
    # half the picks into breadth-first search
    alternate = getattr(heuristic, "informative", True)
    lists[0].append((0.0, next(counter), None, None, task.init))
    best = [INF, INF]
    parents: dict = {}
    pop, push = heapq.heappop, heapq.heappush
    successors, closure, goal, operators = task.successors, task.closure, task.goal, task.operators
    while True:
        chosen = min((i for i in range(4) if lists[i]), key=picks.__getitem__, default=None)
        if chosen is None:
            return budget.result("unsolvable", reason="search space exhausted")
        picks[chosen] += 1
        _, _, parent, op, state = pop(lists[chosen])
        if state in parents:
            continue
        parents[state] = None if parent is None else (parent, op)
        if progress is not None and parent is not None:
            progress(parent, state)
        closed = closure(state)
        if goal.holds(closed):
            return budget.result("solved", path_to(parents, state))
        h1, used = hff.relaxed_plan(state)
        budget.evaluated += 1
        if h1 == INF:
            continue
        h2 = heuristic(state) if alternate else 0.0
        if h2 == INF:
            continue
        if h1 < best[0] or h2 < best[1]:
            best = [min(h1, best[0]), min(h2, best[1])]
            picks[1] -= BOOST
            picks[3] -= BOOST
        if budget.exhausted():
            return budget.limit()
        budget.expanded += 1
        preferred = {id(operators[i]) for i in used}
        for succ_op, succ in successors(state, closed):
            budget.generated += 1
            if succ in parents:
                continue
            c = next(counter)
            push(lists[0], (h1, c, state, succ_op, succ))
            if alternate:
                push(lists[2], (h2, c, state, succ_op, succ))
            if id(succ_op) in preferred:
                push(lists[1], (h1, c, state, succ_op, succ))
                if alternate:
                    push(lists[3], (h2, c, state, succ_op, succ))
