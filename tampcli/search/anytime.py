"""Anytime improvement of a first plan, as LAMA does after its first search.

Weighted A* restarts with decreasing weights (5, 3, 2, 1), each looking only
for plans cheaper than the incumbent: a state whose g reaches the
incumbent's cost is pruned (always sound), and so is one whose g + h does
when the heuristic is admissible. Each better plan has its redundant steps
removed and becomes the incumbent. When a restart exhausts its search space
under the bound without pruning on h, no cheaper plan exists: the incumbent
is optimal (what was pruned could not lead to a cheaper plan) and the
improvement stops.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass

from tampcli.search.budget import SearchLimits
from tampcli.search.eliminate import eliminate_redundant
from tampcli.search.searches import astar
from tampcli.task.task import Operator, Task

WEIGHTS = (5.0, 3.0, 2.0, 1.0)


@dataclass(frozen=True)
class Improvement:
    plan: tuple[Operator, ...]
    cost: float
    weight: float
    seconds: float  # since `improve` started


@dataclass(frozen=True)
class Outcome:
    """How the improvement ended: "limit" (time), "weights" (all restarts done)
    or "optimal" (a restart proved that no cheaper plan exists)."""

    reason: str


def improve(task: Task, plan: Sequence[Operator], make_heuristic: Callable[[Task], Callable],
            time_limit: float | None,
            weights: Sequence[float] = WEIGHTS) -> Iterator[Improvement | Outcome]:
    """Yield each cheaper plan found, then one Outcome."""
    start = time.perf_counter()
    deadline = None if time_limit is None else start + time_limit
    cost = sum(op.cost for op in plan)
    heuristic = make_heuristic(task)
    for weight in weights:
        left = None if deadline is None else deadline - time.perf_counter()
        if left is not None and left <= 0:
            yield Outcome("limit")
            return
        result = astar(task, heuristic, SearchLimits(time_limit=left, bound=cost), weight=weight)
        if result.status == "limit":
            yield Outcome("limit")
            return
        if result.status == "unsolvable":
            yield Outcome("optimal")
            return
        better = eliminate_redundant(task, result.plan, deadline)
        cost = sum(op.cost for op in better)
        yield Improvement(better, cost, weight, time.perf_counter() - start)
    yield Outcome("weights")
