"""State-space searches: `SEARCHES[name](task, heuristic, limits) -> SearchResult`.

A* and weighted A* re-open states reached again more cheaply, so A* with an
admissible heuristic returns an optimal plan; GBFS (eager or lazy) is for
satisficing. A dead end (h = inf) is pruned; the heuristics here are all
safe (relaxed-unreachable implies unreachable), so an exhausted open list
proves the task unsolvable. Limits end a search with status "limit".
"""

from __future__ import annotations

import heapq
import itertools
import time
from collections.abc import Callable
from dataclasses import dataclass, field

from tampcli.errors import UsageError
from tampcli.task.task import Operator, Task

INF = float("inf")
_CHECK_EVERY = 64  # expansions between two clock reads


@dataclass(frozen=True)
class SearchLimits:
    """time_limit in seconds (None: none); max_expansions (None: none); weight for wastar."""

    time_limit: float | None = None
    max_expansions: int | None = None
    weight: float = 2.0

    def __post_init__(self):
        if self.time_limit is not None and not self.time_limit > 0:
            raise UsageError(f"the time limit must be positive, got {self.time_limit}", key="--time-limit")
        if self.max_expansions is not None and self.max_expansions < 0:
            raise UsageError(f"the expansion limit must be >= 0, got {self.max_expansions}",
                             key="--max-expansions")
        if not self.weight >= 1:
            raise UsageError(f"the weight must be >= 1, got {self.weight}", key="--weight")


@dataclass(frozen=True)
class SearchResult:
    status: str  # "solved" | "unsolvable" | "limit"
    plan: tuple[Operator, ...] = ()
    cost: float | None = None
    stats: dict = field(default_factory=dict)


class _Budget:
    def __init__(self, limits: SearchLimits):
        self.start = time.perf_counter()
        self.deadline = None if limits.time_limit is None else self.start + limits.time_limit
        self.max_expansions = limits.max_expansions
        self.expanded = 0
        self.generated = 0
        self.evaluated = 0

    def exhausted(self) -> bool:
        if self.max_expansions is not None and self.expanded >= self.max_expansions:
            return True
        if self.deadline is not None and self.expanded % _CHECK_EVERY == 0:
            return time.perf_counter() > self.deadline
        return False

    def result(self, status: str, plan=(), reason: str | None = None) -> SearchResult:
        stats = {"expanded": self.expanded, "generated": self.generated,
                 "evaluated": self.evaluated,
                 "seconds": round(time.perf_counter() - self.start, 4)}
        if reason:
            stats["reason"] = reason
        if status != "solved":
            return SearchResult(status, (), None, stats)
        plan = tuple(plan)
        stats["length"] = len(plan)
        return SearchResult("solved", plan, float(sum(op.cost for op in plan)), stats)

    def limit(self) -> SearchResult:
        if self.max_expansions is not None and self.expanded >= self.max_expansions:
            return self.result("limit", reason=f"expansion limit ({self.max_expansions}) reached")
        return self.result("limit", reason="time limit reached")


def _path(parents: dict, state) -> list[Operator]:
    plan = []
    while True:
        prev = parents[state]
        if prev is None:
            break
        state, op = prev
        plan.append(op)
    plan.reverse()
    return plan


Heuristic = Callable[[frozenset], float]


def astar(task: Task, heuristic: Heuristic, limits: SearchLimits = SearchLimits(),
          weight: float = 1.0) -> SearchResult:
    """A* (weight 1) or weighted A* (f = g + weight * h), goal test at expansion.

    Evaluation is deferred: a successor is queued with the bound its parent
    gives, max(0, h(parent) - cost(op)) (admissible whenever h is), and only
    evaluated when it reaches the front; if its own h raises its f it is
    queued again. Most generated states are never evaluated.
    """
    budget = _Budget(limits)
    init = task.init
    h0 = heuristic(init)
    budget.evaluated += 1
    if h0 == INF:
        return budget.result("unsolvable", reason="the initial state is a dead end")
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
            if gs + weight * h > f:
                push(open_list, (gs + weight * h, neg_g, next(counter), state))
                continue
        elif h == INF:
            continue
        if is_goal(state):
            return budget.result("solved", _path(parents, state))
        if budget.exhausted():
            return budget.limit()
        budget.expanded += 1
        for op, succ in successors(state):
            budget.generated += 1
            ng = gs + op.cost
            old = g.get(succ)
            if old is not None and old <= ng:
                continue
            known = hcache.get(succ)
            if known == INF:
                continue
            estimate = known if known is not None else max(h - op.cost, 0.0)
            g[succ] = ng
            parents[succ] = (state, op)
            push(open_list, (ng + weight * estimate, -ng, next(counter), succ))
    return budget.result("unsolvable", reason="search space exhausted")


def wastar(task: Task, heuristic: Heuristic, limits: SearchLimits = SearchLimits()) -> SearchResult:
    return astar(task, heuristic, limits, weight=limits.weight)


def gbfs(task: Task, heuristic: Heuristic, limits: SearchLimits = SearchLimits()) -> SearchResult:
    """Eager greedy best-first search on h (ties: lower g, then FIFO); goal test at generation."""
    budget = _Budget(limits)
    init = task.init
    if task.is_goal(init):
        return budget.result("solved", ())
    h0 = heuristic(init)
    budget.evaluated += 1
    if h0 == INF:
        return budget.result("unsolvable", reason="the initial state is a dead end")
    counter = itertools.count()
    parents: dict = {init: None}
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
            ng = gs + op.cost
            if is_goal(succ):
                return budget.result("solved", _path(parents, succ))
            h = heuristic(succ)
            budget.evaluated += 1
            if h != INF:
                push(open_list, (h, ng, next(counter), succ))
    return budget.result("unsolvable", reason="search space exhausted")


def lazy_gbfs(task: Task, heuristic: Heuristic, limits: SearchLimits = SearchLimits()) -> SearchResult:
    """Lazy GBFS: successors queued with their parent's h, evaluated when popped.

    With h_FF, the operators of the parent's relaxed plan go first
    (preferred operators), which is where lazy search pays off.
    """
    budget = _Budget(limits)
    init = task.init
    relaxed_plan = getattr(heuristic, "relaxed_plan", None)
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
        if is_goal(state):
            return budget.result("solved", _path(parents, state))
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
    "gbfs": gbfs,
    "lazy-gbfs": lazy_gbfs,
    "wastar": wastar,
}
