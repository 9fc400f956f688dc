"""The values branch and bound takes and gives: options, the skeleton source's
protocol, events for live displays, the result."""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol

from tampcli.errors import require_int, require_number
from tampcli.solution import SkeletonRecord

DEFAULT_SKELETONS = 20  # drawn at most once there is an answer, unless `-k` says otherwise


# The most processes `jobs = 0` gives, whatever the cores: each worker holds a World of
# its own (about 170 MB with a Panda scene, measured), and a many-core machine (a CI runner's 64)
# would spawn dozens for every solve. Measured: 2 (bench/results/parallel*.md).
DEFAULT_JOBS_CAP = 4


@dataclass(frozen=True)
class BnBOptions:
    """Options of the skeleton search (checked when built).

    max_skeletons: skeletons drawn at most (a count, `-k`); None (the default):
        DEFAULT_SKELETONS once there is an answer and no cap before one, so that the
        time limit, not a count, ends a search that has found nothing (gen1's planar
        instances: 24 orders of equally cheap pushes used up a cap of 20, and the
        picks and places that solve them were never drawn).
    time_limit: seconds for the whole search, drawing skeletons included (checked
        between NLP solves); infinity is no limit.
    symbolic_weight: w (>= 0) in objective = trajectory cost (rad^2 or m^2) + w * symbolic
        cost; the default 0.1 makes ten unit-cost actions weigh as much as one rad^2 of
        motion: a tie-breaker towards shorter plans that rarely overrides geometry.
    anytime: keep improving until a limit instead of stopping at the first solution
        whose optimality cannot be improved by a cheaper skeleton.
    prefix_pruning: when a skeleton's keyframe problem fails, find its shortest failing
        prefix and forbid every skeleton that starts with it.
    first: stop at the first feasible skeleton (its solution verified), without
        looking for a better one.
    jobs: skeletons whose NLPs are solved at once once there is a first solution, each
        in a worker process with a World of its own (bnb/parallel.py); 1 solves them
        here, one after another; 0 (the default): one per core this process may use
        (`processes`; at most DEFAULT_JOBS_CAP). Before a first solution the search
        is serial whatever `jobs`.
    reserve: seconds of `time_limit` left to a pass after the search (action
        elimination): with an answer, the search stops at `time_limit - reserve`.
    """

    max_skeletons: int | None = None
    time_limit: float = 120.0
    symbolic_weight: float = 0.1
    anytime: bool = False
    prefix_pruning: bool = True
    first: bool = False
    jobs: int = 0
    reserve: float = 0.0

    def processes(self) -> int:
        """`jobs`, 0 read as the cores this process may run on, at most DEFAULT_JOBS_CAP."""
        if self.jobs:
            return self.jobs
        if hasattr(os, "sched_getaffinity"):
            cores = len(os.sched_getaffinity(0))
        else:
            cores = os.cpu_count() or 1
        return max(1, min(cores, DEFAULT_JOBS_CAP))

    def skeleton_limit(self, answered: bool) -> float:
        """How many skeletons the search draws at most, with or without an answer."""
        if self.max_skeletons is not None:
            return self.max_skeletons
        return DEFAULT_SKELETONS if answered else math.inf

    def search_limit(self, answered: bool) -> float:
        """When the search stops: the reserve is only for an answer's elimination."""
        return self.time_limit - self.reserve if answered else self.time_limit

    def __post_init__(self):
        if self.max_skeletons is not None:
            require_int(self.max_skeletons, "max_skeletons", 1)
        require_int(self.jobs, "jobs", 0)
        require_number(self.time_limit, "time_limit", positive=True, unit="s", finite=False)
        require_number(self.symbolic_weight, "symbolic_weight")
        require_number(self.reserve, "reserve")


class StageResult(Protocol):
    status: str  # "solved" | "infeasible" | "limit" | "bounded" (reached the cutoff)
    cost: float | None
    worst_constraint: str | None


class SkeletonSource(Protocol):
    """What branch and bound needs of the top-k generator.

    Optional, used when present: `solved(names)` hears of each feasible
    skeleton; `lower_bound()` is a proved bound on the symbolic cost of every
    skeleton not yet drawn (needed when the source does not draw skeletons
    in non-decreasing cost, as one that learns from failures does); `scope`, which
    skeletons it yields, in words (say "loopless: no symbolic state twice"), named
    when it runs out without a solution."""

    def __iter__(self): ...

    def forbid_prefix(self, names: tuple[str, ...]) -> None: ...


# diagnose(ops, result): more of a failed stage's result than its worst row, in words
# (bnb/violations.py: the rows violated at the NLP's best point, by action), or None;
# called only for the failures a search without a solution names in its reason.
Diagnose = Callable[[tuple[Any, ...], Any], "str | None"]

# evaluate(ops, stage, warm), and for the path stage once there is an incumbent,
# evaluate(ops, "path", warm, cutoff=C): C is the trajectory cost at which the
# skeleton cannot beat the incumbent; the stage may stop there ("bounded").
Evaluate = Callable[..., StageResult]


@dataclass
class Event:
    """One step of the search, for live displays."""

    kind: str  # "skeleton" | "stage" | "outcome" | "incumbent" | "stop"
    rank: int
    plan: tuple[str, ...] = ()
    symbolic_cost: float | None = None
    stage: str | None = None
    outcome: str | None = None
    cost: float | None = None
    bound: float | None = None
    seconds: float = 0.0
    message: str | None = None


@dataclass(frozen=True)
class Judged:
    """What the search found of one plan, for a pass after it that meets the plan
    again (bnb/eliminate.py: the answer less an action may be a skeleton already
    drawn). `outcome`: "infeasible" (a stage or a relaxation failed, or a prefix it
    starts with was found infeasible), "solved" (`path`: its path-stage result) or
    "pruned" (by a bound, or the same geometric actions as a plan already solved:
    nothing said of its feasibility)."""

    rank: int
    outcome: str
    path: Any = None
    stage: str | None = None  # the stage an infeasible one failed at, when one did


@dataclass
class BnBResult:
    status: str  # "solved" | "unsolvable" | "limit"
    reason: str | None
    best: Any  # the path-stage result of the incumbent, or None
    best_plan: tuple[Any, ...] = ()
    best_symbolic_cost: float | None = None
    best_objective: float | None = None
    lower_bound: float | None = None
    optimal: bool = False
    skeletons: list[SkeletonRecord] = field(default_factory=list)
    stats: dict = field(default_factory=dict)
    improvements: list[tuple[float, float]] = field(default_factory=list)  # (seconds, objective)
    judged: dict[tuple[str, ...], Judged] = field(default_factory=dict)  # by action names
