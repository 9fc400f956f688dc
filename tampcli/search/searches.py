"""State-space searches: `SEARCHES[name](task, heuristic, limits) -> SearchResult`.

A* and weighted A* re-open states reached again more cheaply, so A* with an
admissible heuristic returns an optimal plan; GBFS (eager or lazy) is for
satisficing (`lama`, in lama.py, is LAMA's first search). GBFS tells a
path-dependent heuristic (the landmark count) each state's parent through
its `progress`. A dead end (h = inf) is pruned; the heuristics here are all
safe (relaxed-unreachable implies unreachable), so an exhausted open list
proves the task unsolvable. Limits end a search with status "limit".
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
from tampcli.search.lama import lama
from tampcli.task.task import Task

__all__ = ["INF", "SEARCHES", "Heuristic", "SearchLimits", "SearchResult", "astar", "gbfs",
           "lama", "lazy_gbfs", "wastar"]


def astar(task: Task, heuristic: Heuristic, limits: SearchLimits = NO_LIMITS,
          weight: float = 1.0) -> SearchResult:
    """A* (weight 1) or weighted A* (f = g + weight * h), goal test at expansion.

    Evaluation is deferred: a successor is queued with the bound its parent
    gives, max(0, h(parent) - cost(op)) (admissible whenever h is), and only
    evaluated when it reaches the front; if its own h raises its f it is
    queued again. Most generated states are never evaluated.
    """
    budget = Budget(limits)
    init = task.init
    h0 = heuristic(init)
    budget.evaluated += 1
    if h0 == INF:
        return budget.result("unsolvable", reason="the initial state is a dead end")
    # g >= bound can never lead to a cheaper plan; g + h >= bound cannot only
    # when h never overestimates
    bound = INF if limits.bound is None else limits.bound
    h_bound = bound if getattr(heuristic, "admissible", False) else INF
    counter = itertools.count()
    g = {init: 0.0}
    hcache = {init: h0}
    parents: dict = {init: None}
    # ties broken towards larger g (deeper), then FIFO
    open_list = [(weight * h0, -0.0, next(counter), init)]
    pop, push = heapq.heappop, heapq.heappush
    successors, is_goal = task.successors, task.is_goal
    while open_list:
        f, neg_g, _, state = pop(open_list)
        gs = -neg_g
        if gs > g[state]:
            continue
        h = hcache.get(state)
        if h is None:
            h = heuristic(state)
            budget.evaluated += 1
            hcache[state] = h
            if h == INF:
                continue
            if gs + h >= h_bound:
                continue
            if gs + weight * h > f:
                push(open_list, (gs + weight * h, neg_g, next(counter), state))
                continue
        elif h == INF:
            continue
        if is_goal(state):
            return budget.result("solved", path_to(parents, state))
        if budget.exhausted():
            return budget.limit()
        budget.expanded += 1
        for op, succ in successors(state):
            budget.generated += 1
            ng = gs + op.cost
            if ng >= bound:
                continue
            old = g.get(succ)
            if old is not None and old <= ng:
                continue
            known = hcache.get(succ)
            if known == INF:
                continue
            estimate = known if known is not None else max(h - op.cost, 0.0)
            if ng + estimate >= h_bound:
                continue
            g[succ] = ng
            parents[succ] = (state, op)
            push(open_list, (ng + weight * estimate, -ng, next(counter), succ))
    return budget.result("unsolvable", reason="search space exhausted")


def wastar(task: Task, heuristic: Heuristic, limits: SearchLimits = NO_LIMITS) -> SearchResult:
    return astar(task, heuristic, limits, weight=limits.weight)


def gbfs(task: Task, heuristic: Heuristic, limits: SearchLimits = NO_LIMITS) -> SearchResult:
    """Eager greedy best-first search on h (ties: lower g, then FIFO); goal test at generation."""
    budget = Budget(limits)
    init = task.init
    if task.is_goal(init):
        return budget.result("solved", ())
    h0 = heuristic(init)
    budget.evaluated += 1
    if h0 == INF:
        return budget.result("unsolvable", reason="the initial state is a dead end")
    counter = itertools.count()
    parents: dict = {init: None}
    progress = getattr(heuristic, "progress", None)
    open_list = [(h0, 0.0, next(counter), init)]
    pop, push = heapq.heappop, heapq.heappush
    successors, is_goal = task.successors, task.is_goal
    while open_list:
        _, gs, _, state = pop(open_list)
        if budget.exhausted():
            return budget.limit()
        budget.expanded += 1
        for op, succ in successors(state):
            budget.generated += 1
            if succ in parents:
                continue
            parents[succ] = (state, op)
            if progress is not None:
                progress(state, succ)
            ng = gs + op.cost
            if is_goal(succ):
                return budget.result("solved", path_to(parents, succ))
            h = heuristic(succ)
            budget.evaluated += 1
            if h != INF:
                push(open_list, (h, ng, next(counter), succ))
    return budget.result("unsolvable", reason="search space exhausted")


def lazy_gbfs(task: Task, heuristic: Heuristic, limits: SearchLimits = NO_LIMITS) -> SearchResult:
    """Lazy GBFS: successors queued with their parent's h, evaluated when popped.

    With h_FF, the operators of the parent's relaxed plan go first
    (preferred operators), which is where lazy search pays off.
    """
    budget = Budget(limits)
    init = task.init
    relaxed_plan = getattr(heuristic, "relaxed_plan", None)
    progress = getattr(heuristic, "progress", None)
    counter = itertools.count()
    parents: dict = {}
    open_list = [(0.0, 0, next(counter), None, None, init)]
    pop, push = heapq.heappop, heapq.heappush
    successors, is_goal = task.successors, task.is_goal
    operators = task.operators
    while open_list:
        _, _, _, parent, op, state = pop(open_list)
        if state in parents:
            continue
        parents[state] = None if parent is None else (parent, op)
        if progress is not None and parent is not None:
            progress(parent, state)
        if is_goal(state):
            return budget.result("solved", path_to(parents, state))
        if relaxed_plan is not None:
            h, used = relaxed_plan(state)
            preferred = {id(operators[i]) for i in used}
        else:
            h, preferred = heuristic(state), ()
        budget.evaluated += 1
        if h == INF:
            continue
        if budget.exhausted():
            return budget.limit()
        budget.expanded += 1
        for succ_op, succ in successors(state):
            budget.generated += 1
            if succ in parents:
                continue
            rank = 0 if id(succ_op) in preferred else 1
            push(open_list, (h, rank, next(counter), state, succ_op, succ))
    return budget.result("unsolvable", reason="search space exhausted")


SEARCHES = {
    "astar": astar,
    "lama": lama,
    "gbfs": gbfs,
    "lazy-gbfs": lazy_gbfs,
    "wastar": wastar,
}
