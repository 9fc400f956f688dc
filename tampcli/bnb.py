"""Branch and bound over ranked skeletons (the seed's §5).

Skeletons arrive lazily from the top-k generator in non-decreasing symbolic
cost. Each is evaluated cheap to expensive — final placements, keyframes,
full path — and dropped at the first stage that fails. Geometry reaches this
module only as a plain callable `evaluate(skeleton, stage, warm)`, so the
search can be tested with toy functions.

Objective of a solution: trajectory cost + w * symbolic cost.

Bounds, honestly labelled:
- proved: a trajectory cost is >= 0, so every skeleton not yet drawn has an
  objective >= w * (its symbolic cost) >= w * (the last symbolic cost drawn);
  when that reaches the incumbent, the incumbent is optimal and we stop.
  An infeasibility is proved only when the evaluator says so (`proved`,
  e.g. a region out of reach by a distance argument).
- heuristic: the keyframe NLP's optimum (a lower bound of the path cost for
  those keyframes, by Cauchy–Schwarz, but a *local* optimum) prunes a
  skeleton that cannot beat the incumbent; an NLP that fails to find a
  feasible point marks a skeleton (and, at the keyframe stage, the shortest
  failing prefix, which prunes every skeleton sharing it) infeasible.
`Solution.lower_bound` holds only proved values.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

from tampcli.solution import SkeletonRecord

STAGES = ("final", "keyframes", "path")
DEFAULT_SYMBOLIC_WEIGHT = 0.1


@dataclass(frozen=True)
class BnBOptions:
    """Options of the skeleton search.

    max_skeletons: skeletons drawn at most (`-k`).
    time_limit: seconds for the whole search (checked between NLP solves).
    symbolic_weight: w in objective = trajectory cost (rad^2 or m^2) + w * symbolic cost;
        the default 0.1 makes ten unit-cost actions weigh as much as one rad^2 of motion:
        a tie-breaker towards shorter plans that rarely overrides geometry.
    anytime: keep improving until a limit instead of stopping at the first solution
        whose optimality cannot be improved by a cheaper skeleton.
    prefix_pruning: when a skeleton's keyframe problem fails, find its shortest failing
        prefix and forbid every skeleton that starts with it.
    """

    max_skeletons: int = 20
    time_limit: float = 120.0
    symbolic_weight: float = DEFAULT_SYMBOLIC_WEIGHT
    anytime: bool = False
    prefix_pruning: bool = True

    def __post_init__(self):
        if self.max_skeletons < 1:
            raise ValueError("max_skeletons must be >= 1")
        if not self.time_limit > 0:
            raise ValueError("time_limit must be > 0")
        if self.symbolic_weight < 0:
            raise ValueError("symbolic_weight must be >= 0")


class StageResult(Protocol):
    status: str  # "solved" | "infeasible" | "limit"
    cost: float | None
    worst_constraint: str | None


class SkeletonSource(Protocol):
    """What branch and bound needs of the top-k generator."""

    def __iter__(self): ...

    def forbid_prefix(self, names: tuple[str, ...]) -> None: ...


Evaluate = Callable[[Sequence[Any], str, Any], StageResult]


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


class _PrefixTree:
    """Results of keyframe problems by action-name prefix (memo + warm starts)."""

    def __init__(self):
        self._results: dict[tuple[str, ...], Any] = {}
        self.infeasible: set[tuple[str, ...]] = set()

    def get(self, prefix: tuple[str, ...]):
        return self._results.get(prefix)

    def put(self, prefix: tuple[str, ...], result) -> None:
        self._results[prefix] = result
        if result.status != "solved":
            self.infeasible.add(prefix)

    def blocked(self, names: tuple[str, ...]) -> tuple[str, ...] | None:
        for i in range(1, len(names) + 1):
            if names[:i] in self.infeasible:
                return names[:i]
        return None

    def warm_for(self, names: tuple[str, ...]):
        """The solved result of the longest evaluated proper prefix, if any."""
        for i in range(len(names), 0, -1):
            result = self._results.get(names[:i])
            if result is not None and result.status == "solved":
                return result
        return None


def branch_and_bound(
    skeletons: SkeletonSource | Iterable,
    evaluate: Evaluate,
    options: BnBOptions = BnBOptions(),
    is_geometric: Callable[[Any], bool] = lambda op: True,
    on_event: Callable[[Event], None] | None = None,
    clock: Callable[[], float] = time.perf_counter,
) -> BnBResult:
    """Search skeletons best-first with staged NLP bounds; see the module docstring.

    `skeletons` yields plans with `.operators` (each with `.name`) and `.cost`.
    `is_geometric(op)` tells which actions end a keyframe (prefixes worth testing).
    """
    started = clock()
    w = options.symbolic_weight
    emit = on_event or (lambda event: None)
    tree = _PrefixTree()
    evaluated: dict[tuple[str, ...], int] = {}  # geometric actions -> rank that had them
    records: list[SkeletonRecord] = []
    stats = {"skeletons_generated": 0, "skeletons_optimized": 0, "skeletons_pruned": 0,
             "skeletons_infeasible": 0, "nlp_solves": 0, "nlp_iterations": 0,
             "prefixes_forbidden": 0, "optimize_seconds": 0.0}
    incumbent: dict | None = None
    improvements: list[tuple[float, float]] = []
    stop_reason = "exhausted"
    failures: list[tuple[int, tuple[str, ...], str, str]] = []  # rank, plan, stage, why
    deepest_feasible: tuple[str, ...] = ()
    all_proved_infeasible = True

    def elapsed() -> float:
        return clock() - started

    def run_stage(ops, stage, warm):
        t0 = clock()
        result = evaluate(ops, stage, warm)
        stats["nlp_solves"] += getattr(result, "nlp_solves", 1) or 1
        stats["nlp_iterations"] += getattr(result, "iterations", 0) or 0
        stats["optimize_seconds"] += clock() - t0
        return result

    iterator = iter(skeletons)
    rank = 0
    while True:
        if elapsed() >= options.time_limit:
            stop_reason = "time"
            break
        if rank >= options.max_skeletons:
            stop_reason = "skeletons"
            break
        try:
            plan = next(iterator)
        except StopIteration:
            stop_reason = "exhausted"
            break
        rank += 1
        stats["skeletons_generated"] += 1
        ops = tuple(plan.operators)
        names = tuple(op.name for op in ops)
        symbolic = float(plan.cost)
        proved_bound = w * symbolic
        t_skel = clock()
        emit(Event("skeleton", rank, names, symbolic, bound=proved_bound, seconds=elapsed()))

        if incumbent is not None and proved_bound >= incumbent["objective"] - 1e-12:
            # Every skeleton from here on is at least this expensive: optimal.
            records.append(SkeletonRecord(rank, names, symbolic, "not reached", proved_bound,
                                          "proved", None, None, None, 0.0,
                                          "cannot beat the incumbent (symbolic bound)"))
            stop_reason = "optimal"
            break

        # Symbolic-only actions add no motion and no constraint: a skeleton whose
        # geometric actions are those of one already evaluated (say, with `cook`
        # moved past the last motion) has the same trajectory NLP, and a symbolic
        # cost no lower (skeletons arrive in non-decreasing cost): it cannot win.
        motion = tuple(n for op, n in zip(ops, names, strict=True) if is_geometric(op))
        twin = evaluated.get(motion)
        blocked = tree.blocked(names) if twin is None else None
        if twin is not None or blocked is not None:
            # Pruned before any NLP, by an argument that holds whatever the geometry.
            stats["skeletons_pruned"] += 1
            why = (f"same geometric actions as #{twin} (differs only in symbolic-only actions)"
                   if twin is not None else f"shares the infeasible prefix {' '.join(blocked)}")
            records.append(SkeletonRecord(rank, names, symbolic, "pruned", proved_bound,
                                          "proved", None, None, None, 0.0, why))
            emit(Event("outcome", rank, names, symbolic, outcome="pruned", message=why))
            continue

        stats["skeletons_optimized"] += 1
        evaluated[motion] = rank
        outcome, reason, reached, heuristic_bound, nlp_cost = "solved", None, None, None, None
        warm = tree.warm_for(names)
        path_result = None
        for stage in STAGES:
            reached = stage
            emit(Event("stage", rank, names, symbolic, stage=stage, seconds=elapsed()))
            result = run_stage(ops, stage, warm)
            if stage == "keyframes":
                tree.put(names, result)
            if result.status != "solved":
                outcome = "infeasible"
                reason = f"{stage} stage {result.status}: {result.worst_constraint or 'no detail'}"
                if not getattr(result, "proved", False):
                    all_proved_infeasible = False
                if result.status == "limit":
                    all_proved_infeasible = False
                if (stage == "keyframes" and options.prefix_pruning
                        and result.status == "infeasible"):
                    prefix = _shortest_failing_prefix(ops, names, tree, run_stage, is_geometric)
                    if prefix is not None and prefix != names and hasattr(skeletons,
                                                                          "forbid_prefix"):
                        skeletons.forbid_prefix(prefix)
                        stats["prefixes_forbidden"] += 1
                        reason += f" (prefix {' '.join(prefix)} is infeasible)"
                break
            warm = result
            if stage == "keyframes" and result.cost is not None:
                heuristic_bound = result.cost + w * symbolic
                if (incumbent is not None and not options.anytime
                        and heuristic_bound >= incumbent["objective"]):
                    outcome = "pruned"
                    reason = (f"keyframe bound {heuristic_bound:.4g} >= incumbent "
                              f"{incumbent['objective']:.4g} (heuristic)")
                    break
                if len(names) > len(deepest_feasible):
                    deepest_feasible = names
            if stage == "path":
                path_result = result
                nlp_cost = result.cost

        seconds = clock() - t_skel
        total = None
        if outcome == "solved" and path_result is not None:
            total = nlp_cost + w * symbolic
            if incumbent is None or total < incumbent["objective"]:
                incumbent = {"objective": total, "result": path_result, "plan": ops,
                             "symbolic": symbolic}
                improvements.append((elapsed(), total))
                emit(Event("incumbent", rank, names, symbolic, cost=nlp_cost, bound=total,
                           seconds=elapsed()))
        elif outcome == "infeasible":
            stats["skeletons_infeasible"] += 1
            failures.append((rank, names, reached, reason or ""))
        elif outcome == "pruned":
            stats["skeletons_pruned"] += 1
        records.append(SkeletonRecord(
            rank, names, symbolic, outcome,
            heuristic_bound if heuristic_bound is not None else proved_bound,
            "heuristic" if heuristic_bound is not None else "proved",
            reached, nlp_cost, total, seconds, reason))
        emit(Event("outcome", rank, names, symbolic, stage=reached, outcome=outcome,
                   cost=nlp_cost, bound=total, seconds=elapsed(), message=reason))

    # A trajectory cost is >= 0 and skeletons come in non-decreasing symbolic
    # cost, so no solution has an objective below w * (the first symbolic cost).
    proved_lb = w * records[0].symbolic_cost if records else None
    # "optimal" here means: no skeleton not yet drawn can beat the incumbent. The
    # incumbent's own trajectory is a local optimum of its NLP, which we do not claim.
    optimal = stop_reason == "optimal"
    stats["stop"] = stop_reason
    stats["seconds"] = elapsed()
    # When the first solution came: what a user waits for before `--anytime` or the
    # search for a better skeleton goes on.
    stats["first_solution_seconds"] = improvements[0][0] if improvements else None
    emit(Event("stop", rank, message=stop_reason, seconds=elapsed()))

    if incumbent is not None:
        return BnBResult("solved", None, incumbent["result"], incumbent["plan"],
                         incumbent["symbolic"], incumbent["objective"], proved_lb, optimal,
                         records, stats, improvements)
    status = "limit"
    if stop_reason == "exhausted" and (rank == 0 or all_proved_infeasible):
        status = "unsolvable"
    reason = _explain(stop_reason, rank, failures, deepest_feasible, options)
    return BnBResult(status, reason, None, (), None, None, proved_lb, False, records, stats,
                     improvements)


def _shortest_failing_prefix(ops, names, tree: _PrefixTree, run_stage, is_geometric):
    """Shortest prefix (ending at a geometric action) whose keyframe problem fails."""
    for i in range(1, len(ops)):
        if not is_geometric(ops[i - 1]):
            continue
        prefix = names[:i]
        known = tree.get(prefix)
        if known is None:
            known = run_stage(ops[:i], "keyframes", tree.warm_for(prefix[:-1]))
            tree.put(prefix, known)
        if known.status == "infeasible":
            return prefix
    return names


def _explain(stop_reason, tried, failures, deepest_feasible, options) -> str:
    if tried == 0:
        return "no skeleton: the task is symbolically unsolvable"
    parts = []
    limits = {"time": f"time limit ({options.time_limit:g} s) reached",
              "skeletons": f"skeleton limit ({options.max_skeletons}) reached",
              "exhausted": "every skeleton was tried"}
    parts.append(f"{limits.get(stop_reason, stop_reason)} after {tried} skeleton(s), "
                 "none geometrically feasible")
    if deepest_feasible:
        parts.append(f"deepest feasible keyframe sequence: {' '.join(deepest_feasible)}")
    for rank, plan, _stage, why in failures[:3]:
        parts.append(f"#{rank} {' '.join(plan)}: {why}")
    if len(failures) > 3:
        parts.append(f"... and {len(failures) - 3} more")
    return "; ".join(parts)
