"""Branch and bound with whole skeletons evaluated elsewhere (worker processes).

The main process draws skeletons, prunes them before any NLP, and keeps the
books; each skeleton that needs its NLPs goes out as a `SkeletonJob` and
comes back as a `SkeletonRun` (every stage run, the keyframe problems of its
prefixes). At most `2 * jobs` skeletons are out at once: `jobs` solving and as
many queued, so that a worker done early goes on with the next skeleton while
an older, slower one holds up the books (results are taken in rank order).

Deterministic like the serial search: results are taken in rank order, one
at a time, and the next skeleton is drawn right after each; so what the
books hold when a skeleton is drawn (incumbent, learned obstructions,
infeasible prefixes, keyframe warm starts) depends on ranks, not on which
worker finished first. What differs from `--jobs 1`: a skeleton is drawn
while up to `2 * jobs - 1` before it are still out, so it knows nothing of
their results (no warm start from them, their learning not applied yet; learning
is applied in rank order as results come back). Its keyframe bound is
judged against the incumbent when it is taken, as the serial search would;
a path solved meanwhile is then thrown away.

Stopping: a time limit cancels everything out (a worker's NLPs end by the
same deadline); an optimal proof cancels the skeletons out whose proved
bound cannot beat the incumbent and waits for the others; running out of
skeletons waits for all. A job that raised (or whose worker died) is a
failed skeleton, the reason in its record.
"""

from __future__ import annotations

import math
import time
from collections import deque
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, Future, wait
from dataclasses import dataclass
from typing import Any, Protocol

from tampcli.bnb import BOUNDING, STAGES, _Search, _Trial, prefix_reach
from tampcli.bnb.outcome import TIE
from tampcli.bnb.prefix_bounds import Relax
from tampcli.bnb.prefix_tree import PrefixTree, shortest_failing_prefix
from tampcli.bnb.stage_steps import call_stage
from tampcli.bnb.values import BnBOptions, BnBResult, Diagnose, Evaluate, Event, SkeletonSource
from tampcli.solution import SkeletonRecord


@dataclass(frozen=True)
class SkeletonJob:
    """One skeleton's NLPs, as a worker needs them (picklable)."""

    rank: int
    names: tuple[str, ...]
    symbolic: float
    known: tuple[tuple[tuple[str, ...], Any], ...]  # keyframe results of its prefixes
    incumbent: float | None  # objective when sent: a keyframe bound above it stops there
    weight: float
    anytime: bool
    prefix_pruning: bool
    per_action: float | None = None  # the incumbent's cost per geometric action (prefix_reach)


@dataclass(frozen=True)
class SkeletonRun:
    """What a worker found: each stage run in order, and the keyframe results of
    the prefixes it solved (its own included)."""

    stages: tuple[tuple[str, Any], ...]
    keyframes: tuple[tuple[tuple[str, ...], Any], ...]
    nlp_solves: int
    iterations: int
    seconds: float


class Workers(Protocol):
    """Where skeletons are solved: `submit` gives a Future of the SkeletonRun;
    `found` hears of each path a skeleton found, by its rank, as soon as its run
    is done (whether or not the books have taken it yet): its objective and its
    trajectory cost per geometric action. A skeleton out of a higher rank may stop
    where it cannot beat it: at its reach or keyframe bound, its path stage's
    cutoff, or a prefix's reach (prefix_reach.py). Only lower ranks count, so
    what a skeleton is judged against is what the books will hold when it is
    taken, whichever worker finished first."""

    def submit(self, job: SkeletonJob) -> Future: ...

    def found(self, rank: int, objective: float, each: float | None = None) -> None: ...


def run_skeleton(job: SkeletonJob, ops, evaluate: Evaluate,
                 is_geometric: Callable[[Any], bool],
                 incumbent: Callable[[], float] = lambda: math.inf,
                 per_action: Callable[[], float | None] = lambda: None) -> SkeletonRun:
    """The serial search's stages for one skeleton (run in a worker).

    `incumbent()` is the best objective of the lower ranks known now
    (`Workers.found`), maybe lower than the job's: it saves the later stages of a
    skeleton that cannot win. The books come out the same whatever it says, as
    its stages are applied in order when the run is taken, against an incumbent
    no higher (_ParallelSearch._take: the rare answer the books then reject is
    the exception, recorded as such).
    """
    started = time.perf_counter()
    tree, stages, counts = PrefixTree(), [], [0, 0]
    for prefix, result in job.known:
        tree.put(prefix, result)

    def stage(prefix_ops, name, warm, cutoff=None):
        result = call_stage(evaluate, prefix_ops, name, warm, cutoff)
        counts[0] += getattr(result, "nlp_solves", 1) or 1
        counts[1] += getattr(result, "iterations", 0) or 0
        return result

    warm = tree.warm_for(job.names)
    early = _prefix_reach(job, ops, is_geometric, incumbent, per_action, stage, tree)
    for name in STAGES if early is None else ():
        best = min(math.inf if job.incumbent is None else job.incumbent, incumbent())
        cutoff = best - job.weight * job.symbolic \
            if name == "path" and math.isfinite(best) and not job.anytime else None
        result = stage(ops, name, warm, cutoff)
        stages.append((name, result))
        if name == "keyframes":
            tree.put(job.names, result)
        if result.status != "solved":
            if name == "reach":  # as the serial search: the relaxation decides nothing
                continue
            if name == "keyframes" and job.prefix_pruning and result.status == "infeasible":
                shortest_failing_prefix(ops, job.names, tree, stage, is_geometric)
            break
        warm = result
        best = min(math.inf if job.incumbent is None else job.incumbent, incumbent())
        if name in BOUNDING and result.cost is not None and not job.anytime \
                and result.cost + job.weight * job.symbolic >= best:
            break
    if early is not None:
        stages.append(("reach", early))
    known = {prefix for prefix, _ in job.known}
    keyframes = tuple((job.names[:i], tree.get(job.names[:i]))
                      for i in range(1, len(job.names) + 1)
                      if job.names[:i] not in known and tree.get(job.names[:i]) is not None)
    return SkeletonRun(tuple(stages), keyframes, counts[0], counts[1],
                       time.perf_counter() - started)


def _prefix_reach(job: SkeletonJob, ops, is_geometric, incumbent, per_action, stage, tree):
    """The reach result of a short prefix that prunes the skeleton, or None
    (bnb/prefix_reach.py; the serial search's StageSteps._prefix_reach_prunes)."""
    best = min(math.inf if job.incumbent is None else job.incumbent, incumbent())
    if job.anytime or not math.isfinite(best):
        return None
    symbolic = job.weight * job.symbolic
    each = job.per_action if job.per_action is not None else per_action()
    i = prefix_reach.prefix_length(ops, is_geometric, best - symbolic, each)
    if i is None:
        return None
    result = stage(ops[:i], "reach", tree.warm_for(job.names[:i]))
    return result if prefix_reach.prunes(result, symbolic, best) else None


def parallel_branch_and_bound(
    skeletons: SkeletonSource | Iterable,
    workers: Workers,
    evaluate: Evaluate,
    options: BnBOptions,
    is_geometric: Callable[[Any], bool] = lambda op: True,
    on_event: Callable[[Event], None] | None = None,
    learn: Callable[[Any], None] | None = None,
    relax: Relax | None = None,
    diagnose: Diagnose | None = None,
) -> BnBResult:
    """branch_and_bound with each skeleton's NLPs sent to `workers` (`options.jobs`
    of them); `evaluate` (in this process) serves the odd prefix
    the books lack. See the module docstring. `stats["optimize_seconds"]` is
    summed over the workers."""
    search = _ParallelSearch(skeletons, evaluate, options, is_geometric, on_event,
                             time.perf_counter, learn, relax, diagnose)
    search.workers = workers
    search.stats["jobs"] = options.jobs
    return search.run()


@dataclass
class _Out:
    trial: _Trial
    future: Future


class _ParallelSearch(_Search):
    workers: Workers

    def run(self) -> BnBResult:
        iterator = iter(self.skeletons)
        out: deque[_Out] = deque()
        self.heard: set[int] = set()  # ranks whose finished runs the workers heard of
        stop = None
        while True:
            if self.elapsed() >= self.options.search_limit(self.incumbent is not None):
                stop = "time"
                break
            if stop is None and len(out) < 2 * self.options.jobs and not self._waits(out):
                stop = self._draw_next(iterator, out)
                continue
            if not out or stop == "first":
                break
            self._tell_found(out)
            if out[0].future.done():
                self._take(out.popleft())
                continue
            wait([item.future for item in out if item.trial.rank not in self.heard],
                 timeout=max(self.options.search_limit(self.incumbent is not None)
                             - self.elapsed(), 0.0),
                 return_when=FIRST_COMPLETED)
        self._cancel(out, stop)
        self.records.sort(key=lambda record: record.rank)
        return self._result(stop)

    def _waits(self, out: deque[_Out]) -> bool:
        """Whether the next skeleton waits for those out: the source says what comes
        next is theirs to decide (search.learned.LearningSource.waiting_on_results),
        as the serial search would have their results when it draws it."""
        waiting = getattr(self.skeletons, "waiting_on_results", None)
        return bool(out) and waiting is not None and waiting()

    def _draw_next(self, iterator, out: deque[_Out]) -> str | None:
        """Draw one skeleton: a stop reason, or None (sent out, or pruned here)."""
        if self.rank >= self.options.skeleton_limit(self.incumbent is not None):
            return "skeletons"
        if self.options.first and self.incumbent is not None:
            return "first"
        plan = next(iterator, None)
        if plan is None:
            return "exhausted"
        trial = self._draw(plan)
        if self._cannot_beat_incumbent(trial):
            self._drop_hopeless(out)
            return "optimal"
        if not self._pruned_before_nlp(trial):
            self.emit(Event("stage", trial.rank, trial.names, trial.symbolic,
                            stage=STAGES[0], seconds=self.elapsed()))
            out.append(_Out(trial, self.workers.submit(self._job(trial))))
        return None

    def _job(self, trial: _Trial) -> SkeletonJob:
        prefixes = (trial.names[:i] for i in range(1, len(trial.names) + 1))
        known = tuple((p, self.tree.get(p)) for p in prefixes if self.tree.get(p) is not None)
        return SkeletonJob(trial.rank, trial.names, trial.symbolic, known,
                           getattr(self.incumbent, "objective", None), self.w,
                           self.options.anytime, self.options.prefix_pruning, self._each())

    def _each(self) -> float | None:
        """The incumbent's trajectory cost per geometric action (prefix_reach.py)."""
        if self.incumbent is None:
            return None
        return prefix_reach.per_action(getattr(self.incumbent.result, "cost", None),
                                       self.incumbent.plan, self.is_geometric)

    def _tell_found(self, out: deque[_Out]) -> None:
        """Tell the workers of each path a finished run found, before its turn in the
        books comes (Workers.found): the skeletons of higher ranks still out can stop
        at the bound it sets (arm-sort: #3 and #4 ran their keyframes and path while
        #2's answer waited on #1's)."""
        for item in out:
            rank = item.trial.rank
            if rank in self.heard or not item.future.done():
                continue
            self.heard.add(rank)
            if item.future.cancelled() or item.future.exception() is not None:
                continue
            for stage, result in item.future.result().stages:
                if stage == "path" and result.status == "solved" and result.cost is not None:
                    self.workers.found(rank, result.cost + self.w * item.trial.symbolic,
                                       prefix_reach.per_action(result.cost, item.trial.ops,
                                                               self.is_geometric))

    def _take(self, done: _Out) -> None:
        """A skeleton's results into the books, as the serial search would have them."""
        trial = done.trial
        try:
            run = done.future.result()
        except Exception as err:  # noqa: BLE001 - a worker's failure is that skeleton's
            self._failed(trial, f"worker failed: {type(err).__name__}: {err}")
            return
        self.stats["nlp_solves"] += run.nlp_solves
        self.stats["nlp_iterations"] += run.iterations
        self.stats["optimize_seconds"] += run.seconds
        for prefix, result in run.keyframes:
            self.tree.put(prefix, result)
        for stage, result in run.stages:
            trial.reached = stage
            if not self._apply_stage(trial, stage, result):
                break
        else:
            if trial.outcome == "solved" and trial.path_result is None:
                self._stopped_early(trial, run)
        self._record(trial)

    def _stopped_early(self, trial: _Trial, run: SkeletonRun) -> None:
        """The run stopped at a bound an answer of a lower rank set, an answer the
        books did not keep (pruned there by a bound of its own): pruned all the
        same, heuristically, and said so."""
        stage, result = run.stages[-1]
        trial.outcome = "pruned"
        cost = getattr(result, "cost", None)
        trial.heuristic_bound = None if cost is None else cost + self.w * trial.symbolic
        trial.reason = (f"stopped after {stage}: it could not beat a path a skeleton of "
                        f"a lower rank found, which the books did not keep (heuristic)")
        self._unproved(trial)

    def _record(self, trial: _Trial) -> None:
        before = self.incumbent
        super()._record(trial)
        if self.incumbent is not before:
            self.workers.found(trial.rank, self.incumbent.objective, self._each())

    def _failed(self, trial: _Trial, reason: str) -> None:
        trial.outcome, trial.reason = "infeasible", reason
        self.all_proved_infeasible = False
        self._unproved(trial)
        self._record(trial)
        del self.judged[trial.names]  # a crash says nothing of the plan

    def _drop_hopeless(self, out: deque[_Out]) -> None:
        """The incumbent is optimal among skeletons not drawn: those out that cannot
        beat it either are not waited for (a running one is ended with the pool)."""
        for item in list(out):
            if item.trial.proved_bound >= self.incumbent.objective - TIE:
                item.future.cancel()
                out.remove(item)
                self._not_reached(item.trial, "cannot beat the incumbent (symbolic bound)")

    def _cancel(self, out: deque[_Out], stop: str | None) -> None:
        for item in out:
            item.future.cancel()
            self._unproved(item.trial)
            self._not_reached(item.trial, f"cancelled: {stop}")

    def _not_reached(self, trial: _Trial, why: str) -> None:
        self.records.append(SkeletonRecord(
            trial.rank, trial.names, trial.symbolic, "not reached", trial.proved_bound,
            "proved", None, None, None, self.clock() - trial.started, why))
