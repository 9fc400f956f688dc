"""Worker processes that solve whole skeletons (bnb/parallel.py), each with a
World of its own.

PyBullet is not fork-safe once a client is connected, so workers are spawned
fresh: each builds what it needs once, in its initializer (`build`, a
module-level function so that it pickles by name: the pipeline's reads the
inputs again and makes a World, a CollisionChecker and an evaluator), then
serves skeleton after skeleton. A worker's stdout and stderr go to the null
device (PyBullet writes to them from C): nothing from a worker reaches the
terminal.
"""

from __future__ import annotations

import math
import multiprocessing
import os
import threading
import time
from collections.abc import Callable
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool

import numpy as np

from tampcli.bnb.skeleton_run import SkeletonJob, SkeletonRun, answer, run_skeleton

RANKS = 1 << 14  # the ranks whose answers the workers hear of one by one
ORPHAN_POLL = 1.0  # s: how often a worker looks whether its parent is still there

# build(*args, deadline) -> (evaluate, operators by name, is_geometric); `deadline`
# is a perf_counter time of the worker's own.
Build = Callable[..., tuple]


class SkeletonPool:
    """`jobs` spawned workers, each set up by `build(*args, deadline)`; the solve's
    `deadline` (a perf_counter time in this process) bounds their NLPs too. Use as
    a context manager: on exit, work not started is cancelled and running workers
    are ended."""

    def __init__(self, build: Build, args: tuple, jobs: int, deadline: float):
        self._context = multiprocessing.get_context("spawn")
        # Each rank's answer (Workers.found): its objective, its cost per geometric
        # action; read by every worker for the ranks below its skeleton's.
        self._best = self._context.RawArray("d", [math.inf] * RANKS)
        self._each = self._context.RawArray("d", [math.nan] * RANKS)
        # perf_counter is per process: workers get the deadline on the wall clock.
        self._init = (build, args, time.time() + (deadline - time.perf_counter()), self._best,
                      self._each)
        self._jobs = jobs
        self._executor: ProcessPoolExecutor | None = None

    def __enter__(self) -> SkeletonPool:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def start(self) -> None:
        """Spawn the workers now, each setting itself up while this process solves
        (an empty task each: the pool spawns a worker per task it cannot give to an
        idle one)."""
        for _ in range(self._jobs):
            self._pool().submit(_ready)

    def submit(self, job: SkeletonJob) -> Future:
        """The skeleton's SkeletonRun, to come; a dead worker's skeletons fail (their
        futures raise) and the next ones go to fresh workers."""
        try:
            return self._pool().submit(_run, job)
        except BrokenProcessPool:
            self.close()
            return self._pool().submit(_run, job)

    def found(self, rank: int, objective: float, each: float | None = None) -> None:
        _store(self._best, self._each, rank, objective, each)

    def below(self, rank: int) -> tuple[float, float | None]:
        return _below(self._best, self._each, rank)

    def _pool(self) -> ProcessPoolExecutor:
        if self._executor is None:
            self._executor = ProcessPoolExecutor(
                self._jobs, mp_context=self._context, initializer=_start, initargs=self._init)
        return self._executor

    def close(self) -> None:
        if self._executor is None:
            return
        # Python 3.11 has no public way to end a running worker (3.14's
        # terminate_workers): one still busy with a skeleton nobody waits for
        # would hold the solve's exit for as long as its NLP runs.
        processes = list(getattr(self._executor, "_processes", {}).values())
        self._executor.shutdown(wait=False, cancel_futures=True)
        for process in processes:
            if process.is_alive():
                process.terminate()
        for process in processes:
            process.join(timeout=5)
        self._executor = None


class _Worker:
    def __init__(self, build: Build, args: tuple, deadline: float, best, each):
        local_deadline = time.perf_counter() + (deadline - time.time())
        self.evaluate, self.ops, self.is_geometric = build(*args, local_deadline)
        self.best, self.each = best, each

    def run(self, job: SkeletonJob) -> SkeletonRun:
        ops = tuple(self.ops[name] for name in job.names)
        run = run_skeleton(job, ops, self.evaluate, self.is_geometric,
                           lambda: _below(self.best, self.each, job.rank)[0],
                           lambda: _below(self.best, self.each, job.rank)[1])
        # Told at once, to the skeletons of higher ranks this and the other workers
        # hold, whatever the main process is busy with (it may be solving one itself).
        found = answer(job, run, ops, self.is_geometric)
        if found is not None:
            _store(self.best, self.each, job.rank, *found)
        return run


def _ready() -> None:
    """The task `SkeletonPool.start` sends: nothing, once the worker is set up."""


def _store(best, each, rank: int, objective: float, per_action: float | None) -> None:
    """Rank `rank`'s answer into the shared arrays, where better (ranks beyond RANKS:
    not kept)."""
    if rank < RANKS and objective < best[rank]:
        each[rank] = math.nan if per_action is None else per_action
        best[rank] = objective


def _below(best, each, rank: int) -> tuple[float, float | None]:
    """The best answer of a rank below `rank`: (objective, cost per action)."""
    lower = np.frombuffer(best, dtype=float)[:min(rank, RANKS)]
    if not len(lower) or not np.isfinite(lower.min()):
        return math.inf, None
    i = int(lower.argmin())
    return float(lower[i]), None if math.isnan(each[i]) else float(each[i])


# The one piece of state of a worker process: built by the pool's initializer,
# used by every task the process runs (a pool task cannot carry a World).
_worker: list[_Worker] = []


def _start(build: Build, args: tuple, deadline: float, best, each) -> None:
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    os.dup2(null, 2)
    threading.Thread(target=_end_with, args=(os.getppid(),), daemon=True).start()
    _worker.append(_Worker(build, args, deadline, best, each))


def _end_with(parent: int) -> None:
    """End this worker once its parent is gone (killed without the chance to end its
    pool: a worker blocked on the pool's queue would wait for ever)."""
    while os.getppid() == parent:
        time.sleep(ORPHAN_POLL)
    os._exit(0)


def _run(job: SkeletonJob) -> SkeletonRun:
    return _worker[0].run(job)
