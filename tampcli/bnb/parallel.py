"""Branch and bound with whole skeletons evaluated at once: in this process and in
worker processes.

The main process draws skeletons, prunes them before any NLP, and keeps the
books; each skeleton that needs its NLPs becomes a `SkeletonJob`, run by
`skeleton_run.run_skeleton` into a `SkeletonRun` (every stage run, the keyframe
problems of its prefixes). With `jobs` N, N skeletons are solved at once: one
here, between the books' turns, and N - 1 by the workers (worker processes).
The main process takes the lowest rank not started (a problem of one skeleton
is solved as the serial search solves it, no worker started), the workers the
next ones. Before a first solution the search is the serial one: one skeleton
out at a time, solved here, each drawn knowing every result before it (the
failures' lessons decide which skeleton comes next, and one drawn without them
is mostly wasted: blind27 p04's first answer came at 33 s with two out at once,
16 s serially; blind18 p04's at 50 s against 30 s). After one, `WINDOW * jobs`
are out at once, so that a worker done early goes on with the next skeletons
while an older, slower one holds up the books (results are taken in rank
order). The workers are started once the search has gone on for WARM_AFTER
without an answer (`Workers.start`), so that they are set up by the time the
first solution opens the window; a search answered sooner starts them at its
first hand-out.

Deterministic like the serial search: results are taken in rank order, one
at a time, and the next skeleton is drawn right after each; so what the
books hold when a skeleton is drawn (incumbent, learned obstructions,
infeasible prefixes, keyframe warm starts) depends on ranks, not on which
worker finished first. What differs from `--jobs 1`, once there is a first
solution: a skeleton is drawn while up to `WINDOW * jobs - 1` before it are
still out, so it knows nothing of their results (no warm start from them, their learning not applied yet; learning
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

import time
from collections import deque
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, Future, wait
from dataclasses import dataclass
from typing import Any, Protocol

from tampcli.bnb import STAGES, _Search, _Trial
from tampcli.bnb.outcome import TIE
from tampcli.bnb.prefix_bounds import Relax
from tampcli.bnb.skeleton_run import SkeletonJob, SkeletonRun, answer, run_skeleton
from tampcli.bnb.values import BnBOptions, BnBResult, Diagnose, Evaluate, Event, SkeletonSource
from tampcli.solution import SkeletonRecord

# Skeletons out at once per job once there is an incumbent (one in all before one: a
# skeleton drawn then may fail, and teach those after it, or, with --first, be one too
# many).
# arm-sort's slow skeletons are #8, #13 and #17 (2.5-4 s each, the others 0.1 s, pruned
# at their reach against the incumbent): with 2 per job, #13 could not start before #8
# was taken, and the three ran one after another (--jobs 2: 14.5 s, serial 16.4 s);
# with 8, side by side with the cheap ones (12.9 s). What a larger window costs: a
# skeleton is drawn knowing less of those before it (Workers.found tells it their paths
# as they finish, and a learning source makes it wait: _waits).
WINDOW = 8
# Seconds of search without an answer after which the workers are set up, so that they
# are ready when the first answer opens the window (each takes about a second). Not from
# the start: spawned there they cost a small solve about 0.04 s of this process's time
# (arm-pick-place p03, 4 runs back to back: 0.96 s against 0.92 s); a search answered
# sooner starts them at its first hand-out.
WARM_AFTER = 1.0


class Workers(Protocol):
    """Where skeletons are solved besides this process (`jobs - 1` workers, the
    pipeline's); `submit` gives a Future of the SkeletonRun;
    `found` hears of each path a skeleton found, by its rank, as soon as its run
    is done (whether or not the books have taken it yet): its objective and its
    trajectory cost per geometric action. A skeleton out of a higher rank may stop
    where it cannot beat it: at its reach or keyframe bound, its path stage's
    cutoff, or a prefix's reach (prefix_reach.py). Only lower ranks count, so
    what a skeleton is judged against is what the books will hold when it is
    taken, whichever worker finished first."""

    def start(self) -> None:
        """Set the workers up now (a World each), while this process looks for the
        first solution alone."""

    def submit(self, job: SkeletonJob) -> Future: ...

    def found(self, rank: int, objective: float, each: float | None = None) -> None: ...

    def below(self, rank: int) -> tuple[float, float | None]:
        """The best answer of a lower rank heard of (told, or found by a worker
        itself): (objective, cost per geometric action), (inf, None) for none."""


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
    """branch_and_bound with `options.jobs` skeletons solved at once: by `evaluate`
    in this process, and by `workers` (`jobs - 1` of them). See the module
    docstring. `stats["optimize_seconds"]` is summed over the processes."""
    search = _ParallelSearch(skeletons, evaluate, options, is_geometric, on_event,
                             time.perf_counter, learn, relax, diagnose)
    search.workers = workers
    search.stats["jobs"] = options.jobs
    return search.run()


@dataclass
class _Out:
    trial: _Trial
    job: SkeletonJob
    future: Future | None = None  # None: not started (this process or a worker takes it)


class _ParallelSearch(_Search):
    workers: Workers

    def run(self) -> BnBResult:
        iterator = iter(self.skeletons)
        out: deque[_Out] = deque()
        self.heard: set[int] = set()  # ranks whose finished runs the workers heard of
        stop = None
        started = False
        while True:
            if self._out_of_time():
                stop = "time"
                break
            if not started and not self.options.first and self.elapsed() > WARM_AFTER:
                self.workers.start()
                started = True
            window = 1 if self.incumbent is None else WINDOW * self.options.jobs
            if stop is None and len(out) < window and not self._waits(out):
                stop = self._draw_next(iterator, out)
                continue
            if not out or stop == "first":
                break
            self._tell_found(out)
            if out[0].future is not None and out[0].future.done():
                self._take(out.popleft())
                continue
            waiting = self._hand_out(out) or self._take_back(out)
            if waiting is not None:
                self._run_here(waiting)
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
        if self._out_of_time():
            return "time"
        if plan is None:
            return "exhausted"
        trial = self._draw(plan)
        if self._cannot_beat_incumbent(trial):
            self._drop_hopeless(out)
            return "optimal"
        if not self._pruned_before_nlp(trial):
            self.emit(Event("stage", trial.rank, trial.names, trial.symbolic,
                            stage=STAGES[0], seconds=self.elapsed()))
            out.append(_Out(trial, self._job(trial)))
        return None

    def _hand_out(self, out: deque[_Out]) -> _Out | None:
        """The skeletons not started go to the workers, all but the lowest rank, which
        this process solves: returned (None when all are started). The workers queue
        what they cannot start yet, so that they go on while this process solves (new
        skeletons are handed out only between this process's own)."""
        waiting = [item for item in out if item.future is None]
        for item in waiting[1:]:
            item.future = self.workers.submit(item.job)
        return waiting[0] if waiting else None

    def _take_back(self, out: deque[_Out]) -> _Out | None:
        """The lowest rank a worker holds but has not started, taken back (its Future
        cancelled) for this process to solve, rather than wait idle while it sits
        queued behind a slow one (arm-sort: #9 to #12 behind #8); None when there is
        none."""
        for item in out:
            if item.future is not None and item.future.cancel():
                item.future = None
                return item
        return None

    def _run_here(self, item: _Out) -> None:
        """Solve `item`'s skeleton in this process, now (its result as a done Future)."""
        rank = item.trial.rank
        future: Future = Future()
        try:
            future.set_result(run_skeleton(
                item.job, item.trial.ops, self.evaluate, self.is_geometric,
                lambda: self.workers.below(rank)[0], lambda: self.workers.below(rank)[1]))
        except Exception as err:  # noqa: BLE001 - as a worker's: that skeleton's failure
            future.set_exception(err)
        item.future = future

    def _job(self, trial: _Trial) -> SkeletonJob:
        prefixes = (trial.names[:i] for i in range(1, len(trial.names) + 1))
        known = tuple((p, self.tree.get(p)) for p in prefixes if self.tree.get(p) is not None)
        return SkeletonJob(trial.rank, trial.names, trial.symbolic, known,
                           getattr(self.incumbent, "objective", None), self.w,
                           self.options.anytime, self.options.prefix_pruning, self._each())

    def _tell_found(self, out: deque[_Out]) -> None:
        """Tell the workers of each path a finished run found, before its turn in the
        books comes (Workers.found): the skeletons of higher ranks still out can stop
        at the bound it sets (arm-sort: #3 and #4 ran their keyframes and path while
        #2's answer waited on #1's)."""
        for item in out:
            rank = item.trial.rank
            if rank in self.heard or item.future is None or not item.future.done():
                continue
            self.heard.add(rank)
            if item.future.cancelled() or item.future.exception() is not None:
                continue
            found = answer(item.job, item.future.result(), item.trial.ops, self.is_geometric)
            if found is not None:
                self.workers.found(rank, *found)

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
                if item.future is not None:
                    item.future.cancel()
                out.remove(item)
                self._not_reached(item.trial, "cannot beat the incumbent (symbolic bound)")

    def _cancel(self, out: deque[_Out], stop: str | None) -> None:
        for item in out:
            if item.future is not None:
                item.future.cancel()
            self._unproved(item.trial)
            self._not_reached(item.trial, f"cancelled: {stop}")

    def _not_reached(self, trial: _Trial, why: str) -> None:
        self.records.append(SkeletonRecord(
            trial.rank, trial.names, trial.symbolic, "not reached", trial.proved_bound,
            "proved", None, None, None, self.clock() - trial.started, why))
