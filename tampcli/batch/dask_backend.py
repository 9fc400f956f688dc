"""Run jobs on a Dask distributed cluster (`--scheduler ADDRESS`).

Each Dask task is `runner.run_job` on a worker, so a problem runs in a child
process there with the same limits and the same statuses as on one machine.
Results come back to this process, which alone writes the results file, as
futures complete. Dask is an optional extra (`tampcli[cluster]`), imported
only here and only when asked for.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from tampcli.batch.discover import Job
from tampcli.batch.results import Result
from tampcli.batch.runner import PROG, RunOptions, run_job
from tampcli.errors import UsageError

CONNECT_TIMEOUT_S = 10


def run_on_cluster(address: str, jobs: Iterable[Job], options: RunOptions,
                   on_result: Callable[[Result], None]) -> None:
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise UsageError("needs Dask distributed, which is not installed: "
                         "pip install 'tampcli[cluster]'", path=PROG,
                         key="--scheduler") from None
    from distributed.comm import parse_address
    from distributed.comm.registry import get_backend

    try:
        # Checked before connecting: a Client that failed on a bad scheme
        # stalls the exit of the process for 20 s while it is collected.
        get_backend(parse_address(address)[0])
    except ValueError as err:
        raise UsageError(f"not a Dask scheduler address: {err}", path=PROG,
                         key="--scheduler") from None
    try:
        client = Client(address, timeout=CONNECT_TIMEOUT_S, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as err:
        raise UsageError(f"cannot connect to the Dask scheduler at {address!r}: {err}",
                         path=PROG, key="--scheduler") from None
    with client:
        futures = {}
        for job in jobs:
            future = client.submit(run_job, job, options, pure=False, retries=0)
            futures[future] = job
        try:
            for future in as_completed(futures, loop=client.loop):
                on_result(_result_of(future, futures[future]))
        except BaseException:
            client.cancel(list(futures))
            raise


def _result_of(future, job: Job) -> Result:
    try:
        result = future.result()
    except Exception as err:  # the worker died, or the task could not run there
        return Result(job.problem, job.domain, "crashed",
                      error=f"Dask task failed: {type(err).__name__}: {err}")
    if not isinstance(result, Result):
        return Result(job.problem, job.domain, "crashed",
                      error=f"Dask task returned {type(result).__name__}, not a Result")
    return result
