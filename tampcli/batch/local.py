"""Run jobs on this machine: a thread pool whose threads each wait on a child."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from concurrent.futures import Future, ThreadPoolExecutor, as_completed

from tampcli.batch.discover import Job
from tampcli.batch.results import Result
from tampcli.batch.runner import LiveGroups, RunOptions, run_job


def run_local(jobs: Iterable[Job], options: RunOptions, workers: int,
              on_result: Callable[[Result], None]) -> None:
    """Call `on_result` in this thread as each job finishes, in completion order.

    When interrupted (Ctrl-C), queued jobs are dropped and running children
    killed: they run in sessions of their own, out of reach of the terminal's
    SIGINT.
    """
    live = LiveGroups()
    pool = ThreadPoolExecutor(max_workers=workers, thread_name_prefix="tampcli-batch")
    try:
        futures = {pool.submit(run_job, job, options, live): job for job in jobs}
        for future in as_completed(futures):
            on_result(result_of(future, futures[future]))
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        live.kill_all()
        raise
    pool.shutdown()


def result_of(future: Future, job: Job) -> Result:
    """The job's Result; a failure of the runner itself is recorded, not raised."""
    try:
        return future.result()
    except Exception as err:
        return Result(job.problem, job.domain, "crashed",
                      error=f"batch runner failed: {type(err).__name__}: {err}")
