"""Branch and bound over ranked skeletons (the seed's §5).

Skeletons arrive lazily from the top-k generator in non-decreasing symbolic
cost; each is evaluated cheap to expensive (final placements, keyframes without
collisions, keyframes, full path) and dropped at the first stage that fails. Geometry comes in only as a
callable `evaluate(skeleton, stage, warm)` (toy functions in the tests), and,
for the reason of a search without a solution, `diagnose(skeleton, result)`
(violations.py: the rows a failed keyframe NLP left violated, by action).
`prefix_tree.py` keeps keyframe results by prefix (memo, warm starts,
infeasible prefixes); `prefix_bounds.py` bounds prefix nodes with `relax(ops)`
(e.g. optimize/relaxed.py's convex QP).

Objective of a solution: trajectory cost + w * symbolic cost.

Bounds, honestly labelled:
- proved: a trajectory cost is >= 0, so every skeleton not yet drawn has an
  objective >= w * (its symbolic cost) >= w * (the cheapest symbolic cost not
  drawn yet: the last one drawn, for a source in non-decreasing cost; the
  source's own `lower_bound()` for one that reorders skeletons by what it
  learned); when that reaches the incumbent, the incumbent is optimal and we
  stop.
  A prefix node whose relaxed trajectory bound (solved to global optimality)
  plus w * the least symbolic cost of a completion reaches the incumbent, or
  whose relaxation is infeasible, prunes every skeleton starting with it;
  each skeleton's proved bound is w * its symbolic cost + its relaxed bound.
  An infeasibility is proved only when the evaluator says so (`proved`,
  e.g. a region out of reach by a distance argument).
- heuristic: the keyframe NLP's optimum (a lower bound of the path cost for
  those keyframes, by Cauchy–Schwarz, but a *local* optimum), and before it
  that of its relaxation without collisions ("reach"), prune a skeleton that
  cannot beat the incumbent; so does the path stage's running bound (motions
  solved plus the least cost through the remaining keyframes, the keyframes
  fixed) once it reaches the cutoff the path stage is given; an NLP that fails to find a
  feasible point marks a skeleton (and, at the keyframe stage, the shortest
  failing prefix, which prunes every skeleton sharing it) infeasible.
`Solution.lower_bound` holds only proved values.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from tampcli.bnb.outcome import (
    SHOWN,
    TIE,
    Ending,
    Failure,
    explain,
    heuristic_prunes,
    stop_label,
)
from tampcli.bnb.prefix_bounds import PrefixBounds, Relax
from tampcli.bnb.prefix_tree import PrefixTree
from tampcli.bnb.stage_steps import BOUNDING, STAGES, StageSteps
from tampcli.bnb.values import (
    BnBOptions,
    BnBResult,
    Diagnose,
    Evaluate,
    Event,
    Judged,
    SkeletonSource,
    StageResult,
)
from tampcli.solution import SkeletonRecord
from tampcli.solution_kkt import KktStages

__all__ = ["BOUNDING", "STAGES", "BnBOptions", "BnBResult", "Diagnose", "Evaluate", "Event", "Judged",
           "SkeletonSource", "StageResult", "branch_and_bound"]



def branch_and_bound(
    skeletons: SkeletonSource | Iterable,
    evaluate: Evaluate,
    options: BnBOptions | None = None,
    is_geometric: Callable[[Any], bool] = lambda op: True,
    on_event: Callable[[Event], None] | None = None,
    clock: Callable[[], float] = time.perf_counter,
    learn: Callable[[Any], None] | None = None,
    relax: Relax | None = None,
    diagnose: Diagnose | None = None,
) -> BnBResult:
    """Search skeletons best-first with staged NLP bounds; see the module docstring.

    `skeletons` yields plans with `.operators` (each with `.name`) and `.cost`.
    `is_geometric(op)` tells which actions end a keyframe (prefixes worth testing).
    `evaluate(ops, stage, warm)` solves one stage; `warm` is the result of an earlier
    stage (or of a prefix's keyframes), passed through untouched. `learn(result)`
    hears of every stage that failed (what geometry found in the way). `relax(ops)`
    bounds the trajectory cost of every completion of a prefix (prefix_bounds.py).
    `diagnose(ops, result)` says more of a failed stage when there is no solution.
    """
    search = _Search(skeletons, evaluate, options or BnBOptions(), is_geometric, on_event,
                     clock, learn, relax, diagnose)
    return search.run()


@dataclass(frozen=True)
class _Incumbent:
    objective: float
    result: Any  # the path-stage result
    plan: tuple[Any, ...]
    symbolic: float
    bound: float  # proved: its skeleton has no trajectory cheaper (its NLP optimum is local)


@dataclass
class _Trial:
    """One drawn skeleton on its way through the stages."""

    rank: int
    ops: tuple[Any, ...]
    names: tuple[str, ...]
    symbolic: float
    proved_bound: float
    started: float
    outcome: str = "solved"
    reason: str | None = None
    reached: str | None = None
    heuristic_bound: float | None = None
    nlp_cost: float | None = None
    path_result: Any = None
    failed: Any = None  # the result of the stage that failed
    failed_stage: str | None = None  # and that stage
    kkt: KktStages = KktStages()  # of the stages solved so far


class _Search(StageSteps):
    """The state of one branch and bound: incumbent, records, statistics."""

    def __init__(self, skeletons, evaluate, options, is_geometric, on_event, clock, learn,
                 relax, diagnose=None):
        self.skeletons, self.evaluate, self.options = skeletons, evaluate, options
        self.bounds = None if relax is None else PrefixBounds(relax, is_geometric)
        self.learn = learn or (lambda result: None)
        self.diagnose = diagnose
        self.is_geometric, self.clock = is_geometric, clock
        self.emit = on_event or (lambda event: None)
        self.w = options.symbolic_weight
        self.started = clock()
        self.tree = PrefixTree()
        self.prefix_reaches: dict[tuple[str, ...], Any] = {}  # prefix -> its reach result
        self.evaluated: dict[tuple[str, ...], int] = {}  # geometric actions -> rank
        self.records: list[SkeletonRecord] = []
        self.judged: dict[tuple[str, ...], Judged] = {}
        self.stats = {"skeletons_generated": 0, "skeletons_optimized": 0,
                      "skeletons_pruned": 0, "skeletons_infeasible": 0, "nlp_solves": 0,
                      "nlp_iterations": 0, "prefixes_forbidden": 0, "optimize_seconds": 0.0,
                      "relaxed_bound_seconds": 0.0}
        self.incumbent: _Incumbent | None = None
        self.improvements: list[tuple[float, float]] = []
        self.failures: list[Failure] = []
        self.learned_prefixes: list[tuple[str, ...]] = []  # forbidden after a local failure
        self.deepest_feasible: tuple[str, ...] = ()
        self.all_proved_infeasible = True
        # Proved bounds (w * symbolic cost + relaxed bound) of drawn skeletons no proof excludes:
        # solved ones that lost (their NLP optimum is local), infeasible ones whose
        # failure is not proved, heuristic prunes. Each may hide a better solution.
        self.unproved: list[float] = []
        self.unproved_ranks: set[int] = set()
        self.rank = 0

    def elapsed(self) -> float:
        return self.clock() - self.started

    def run(self) -> BnBResult:
        iterator = iter(self.skeletons)
        while True:
            if self._out_of_time():
                stop = "time"
                break
            if self.rank >= self.options.skeleton_limit(self.incumbent is not None):
                stop = "skeletons"
                break
            if self.options.first and self.incumbent is not None:
                stop = "first"
                break
            plan = next(iterator, None)
            if self._out_of_time():
                stop = "time"
                break
            if plan is None:
                stop = "exhausted"
                break
            trial = self._draw(plan)
            if self._cannot_beat_incumbent(trial):
                stop = "optimal"
                break
            if self._pruned_before_nlp(trial):
                continue
            self._run_stages(trial)
            self._record(trial)
        return self._result(stop)

    def _out_of_time(self) -> bool:
        """Whether the search's time is up. Asked again after drawing a skeleton too:
        a source that learned orders no plan meets may take tens of seconds to say so
        (blind31 p01: 24 s), and a skeleton drawn past the limit is not evaluated (it
        was, and the run ended 2.4 s after its limit)."""
        return self.elapsed() >= self.options.search_limit(self.incumbent is not None)

    def _draw(self, plan) -> _Trial:
        self.rank += 1
        self.stats["skeletons_generated"] += 1
        ops = tuple(plan.operators)
        names = tuple(op.name for op in ops)
        symbolic = float(plan.cost)
        trial = _Trial(self.rank, ops, names, symbolic, self.w * symbolic, self.clock())
        self.emit(Event("skeleton", trial.rank, names, symbolic, bound=trial.proved_bound,
                        seconds=self.elapsed()))
        return trial

    def _cannot_beat_incumbent(self, trial: _Trial) -> bool:
        """This skeleton and every one not drawn yet are at least this expensive: the
        incumbent is optimal."""
        if self.incumbent is None or trial.proved_bound < self.incumbent.objective - TIE:
            return False
        if self.w * self._undrawn_bound(trial) < self.incumbent.objective - TIE:
            return False
        self.records.append(SkeletonRecord(
            trial.rank, trial.names, trial.symbolic, "not reached", trial.proved_bound,
            "proved", None, None, None, 0.0, "cannot beat the incumbent (symbolic bound)"))
        return True

    def _undrawn_bound(self, trial: _Trial) -> float:
        """A proved bound on the symbolic cost of the skeletons not drawn yet."""
        bound = getattr(self.skeletons, "lower_bound", None)
        return bound() if bound is not None else trial.symbolic

    def _pruned_before_nlp(self, trial: _Trial) -> bool:
        """Pruned by an argument that holds whatever the geometry.

        Symbolic-only actions add no motion and no constraint: a skeleton whose
        geometric actions are those of one already evaluated (say, with `cook`
        moved past the last motion) has the same trajectory NLP, and a symbolic
        cost no lower (skeletons arrive in non-decreasing cost): it cannot win.
        """
        if self._pruned_by_bound(trial):
            return True
        motion = tuple(n for op, n in zip(trial.ops, trial.names, strict=True)
                       if self.is_geometric(op))
        twin = self.evaluated.get(motion)
        blocked = self.tree.blocked(trial.names) if twin is None else None
        if twin is None and blocked is None:
            self.stats["skeletons_optimized"] += 1
            self.evaluated[motion] = trial.rank
            return False
        self.stats["skeletons_pruned"] += 1
        if twin is not None:
            why = f"same geometric actions as #{twin} (differs only in symbolic-only actions)"
            proved = twin not in self.unproved_ranks
            infeasible = False  # (its twin may still be out, in a parallel search)
        else:
            why = f"shares the infeasible prefix {' '.join(blocked)}"
            proved = bool(getattr(self.tree.get(blocked), "proved", False))
            infeasible = True
        self.judged[trial.names] = Judged(trial.rank, "infeasible" if infeasible else "pruned")
        if not proved:
            self._unproved(trial)
        self.records.append(SkeletonRecord(trial.rank, trial.names, trial.symbolic, "pruned",
                                           trial.proved_bound,
                                           "proved" if proved else "heuristic", None, None,
                                           None, 0.0, why))
        self.emit(Event("outcome", trial.rank, trial.names, trial.symbolic, outcome="pruned",
                        message=why, seconds=self.elapsed()))
        return True

    def _pruned_by_bound(self, trial: _Trial) -> bool:
        """Raise the trial's proved bound by its relaxed one; prune it (prefix_bounds.py)."""
        if self.bounds is None:
            return False
        t0, incumbent = self.clock(), getattr(self.incumbent, "objective", None)
        node, prune = self.bounds.judge(trial.ops, trial.names, trial.symbolic,
                                        self._undrawn_bound(trial), self.w, incumbent, TIE)
        self.stats["relaxed_bound_seconds"] += self.clock() - t0
        if node is not None and node.proved:
            trial.proved_bound = self.w * trial.symbolic + node.value
        if prune is None or (self.options.anytime and not prune.node.proved):
            return False
        if not prune.node.proved:  # this skeleton alone, and it stays open in the bound
            self._unproved(trial)
            self.all_proved_infeasible = False
        elif prune.node.prefix != trial.names and hasattr(self.skeletons, "forbid_prefix"):
            self.skeletons.forbid_prefix(prune.node.prefix)
            self.stats["prefixes_forbidden"] += 1
        outcome = "infeasible" if prune.infeasible else "pruned"
        self.stats[f"skeletons_{outcome}"] += 1
        self.learn(prune)  # a body in the way (its worst_constraint), like a failed stage's
        self.records.append(SkeletonRecord(
            trial.rank, trial.names, trial.symbolic, outcome, trial.proved_bound,
            "proved" if prune.node.proved else "heuristic", None, None, None,
            self.clock() - trial.started, prune.reason))
        self.judged[trial.names] = Judged(trial.rank, outcome)
        self.emit(Event("outcome", trial.rank, trial.names, trial.symbolic, "relaxation",
                        outcome, bound=trial.proved_bound, message=prune.reason,
                        seconds=self.elapsed()))
        return True

    def _unproved(self, trial: _Trial) -> None:
        self.unproved.append(trial.proved_bound)
        self.unproved_ranks.add(trial.rank)

    def _record(self, trial: _Trial) -> None:
        total = None
        if trial.outcome == "solved" and trial.path_result is not None:
            total = trial.nlp_cost + self.w * trial.symbolic
            solved = getattr(self.skeletons, "solved", None)
            if solved is not None:
                solved(trial.names)
            if self.incumbent is not None and total >= self.incumbent.objective:
                self._unproved(trial)
            else:
                if self.incumbent is not None:
                    self.unproved.append(self.incumbent.bound)
                self.incumbent = _Incumbent(total, trial.path_result, trial.ops, trial.symbolic,
                                            trial.proved_bound)
                self.improvements.append((self.elapsed(), total))
                self.emit(Event("incumbent", trial.rank, trial.names, trial.symbolic,
                                cost=trial.nlp_cost, bound=total, seconds=self.elapsed()))
        elif trial.outcome == "infeasible":
            self.stats["skeletons_infeasible"] += 1
            # Only the failures the reason names keep their stage's result (a diagnosis).
            named = len(self.failures) < SHOWN
            self.failures.append(Failure(trial.rank, trial.names, trial.reason or "",
                                         trial.ops if named else (),
                                         trial.failed if named else None))
        elif trial.outcome == "pruned":
            self.stats["skeletons_pruned"] += 1
        self.judged[trial.names] = Judged(trial.rank, trial.outcome, trial.path_result,
                                          trial.failed_stage)
        heuristic = trial.heuristic_bound is not None
        self.records.append(SkeletonRecord(
            trial.rank, trial.names, trial.symbolic, trial.outcome,
            trial.heuristic_bound if heuristic else trial.proved_bound,
            "heuristic" if heuristic else "proved", trial.reached, trial.nlp_cost, total,
            self.clock() - trial.started, trial.reason, trial.kkt))
        # The live line tells a proof (a region too small at any yaw...) from a local failure.
        proof = trial.outcome == "infeasible" and getattr(trial.failed, "proved", False) \
            and getattr(trial.failed, "status", None) != "limit"
        self.emit(Event("outcome", trial.rank, trial.names, trial.symbolic, stage=trial.reached,
                        outcome="proved infeasible" if proof else trial.outcome,
                        cost=trial.nlp_cost, bound=total,
                        seconds=self.elapsed(), message=trial.reason))

    def _proved_bound(self, stop: str) -> float | None:
        """No solution has a lower objective: the least proved bound (w * symbolic cost
        + relaxed bound) of the incumbent, the skeletons no proof excluded, those not drawn."""
        candidates = list(self.unproved)
        if self.incumbent is not None:
            candidates.append(self.incumbent.bound)
        if stop != "exhausted" and self.records:
            bound = getattr(self.skeletons, "lower_bound", None)
            undrawn = bound() if bound is not None else self.records[-1].symbolic_cost
            candidates.append(self.w * undrawn)
        if not candidates:
            return None
        low = min(candidates)
        return low if self.incumbent is None else min(low, self.incumbent.objective)

    def _result(self, stop: str) -> BnBResult:
        proved_lb = self._proved_bound(stop)
        objective = None if self.incumbent is None else self.incumbent.objective
        self.stats["stop"] = stop_label(stop, objective, proved_lb, self.unproved)
        self.stats["heuristic_prunes"] = heuristic_prunes(objective, self.unproved)
        self.stats["seconds"] = self.elapsed()
        # When the first solution came: what a user waits for before `--anytime` or the
        # search for a better skeleton goes on.
        self.stats["first_solution_seconds"] = \
            self.improvements[0][0] if self.improvements else None
        self.emit(Event("stop", self.rank, message=self.stats["stop"], seconds=self.elapsed()))
        best = self.incumbent
        if best is not None:
            # Proved optimal only when the proved bound meets the objective: the
            # incumbent's own trajectory is a local optimum of its NLP.
            return BnBResult("solved", None, best.result, best.plan, best.symbolic,
                             best.objective, proved_lb,
                             self.stats["stop"] == "optimal (proved)", self.records,
                             self.stats, self.improvements, self.judged)
        status = "limit"
        if stop == "exhausted" and (self.rank == 0 or self.all_proved_infeasible):
            status = "unsolvable"
        proofs = getattr(self.skeletons, "proofs", 0)
        named = getattr(self.skeletons, "proof_names", None)
        ending = Ending(stop, self.rank, status == "unsolvable", tuple(self.learned_prefixes),
                        getattr(self.skeletons, "scope", None), proofs,
                        named() if named is not None else ())
        reason = explain(ending, self.failures, self.deepest_feasible, self.options,
                         self.diagnose)
        return BnBResult(status, reason, None, (), None, None, proved_lb, False, self.records,
                         self.stats, self.improvements, self.judged)

