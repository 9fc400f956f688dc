"""What every search shares: limits, results, the budget that enforces the
limits and counts the work, and the plan read back from parent links."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

from tampcli.errors import UsageError
from tampcli.task.task import Operator

INF = float("inf")
_CHECK_EVERY = 64  # expansions between two clock reads


@dataclass(frozen=True)
class SearchLimits:
    """time_limit in seconds (None: none); max_expansions (None: none); weight for wastar;
    bound: astar and wastar look only for plans cheaper than it (None: any plan)."""

    time_limit: float | None = None
    max_expansions: int | None = None
    weight: float = 2.0
    bound: float | None = None

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


class Budget:
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


def path_to(parents: dict, state) -> list[Operator]:
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


NO_LIMITS = SearchLimits()
