"""Run jobs on a Dask distributed cluster (`--scheduler ADDRESS`).

Each Dask task is `runner.run_job` on a worker, so a problem runs in a child
process there with the same limits and the same statuses as on one machine.
Results come back to this process, which alone writes the results file, as
futures complete. Dask is an optional extra (`tampcli[cluster]`), imported
only here and only when asked for.

Dask cannot stop a task that is running, so an interrupted batch (Ctrl-C,
SIGTERM) sets a distributed Event of its own before cancelling its futures;
each running task polls it and kills its child's process group. A batch that
dies without a word (SIGKILL, a lost connection) sets nothing, but the
scheduler then releases its tasks, and a task whose worker marks it
cancelled kills its child the same way.
"""

from __future__ import annotations

import contextlib
import uuid
from collections.abc import Callable, Iterable

from tampcli.batch.discover import Job
from tampcli.batch.results import Result
from tampcli.batch.runner import PROG, RunOptions, run_job
from tampcli.errors import UsageError

CONNECT_TIMEOUT_S = 10


def run_on_cluster(address: str, jobs: Iterable[Job], options: RunOptions,
                   on_result: Callable[[Result], None]) -> None:
    try:
        from distributed import Client, Event, as_completed
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
        stop_name = f"tampcli-batch-stop-{uuid.uuid4().hex}"
        futures = {}
        for job in jobs:
            future = client.submit(run_on_worker, job, options, stop_name, pure=False,
                                   retries=0)
            futures[future] = job
        try:
            for future in as_completed(futures, loop=client.loop):
                on_result(_result_of(future, futures[future]))
        except BaseException:
            # The Event first: a task cancelled before it saw the Event would
            # leave its child running until the time limit. A scheduler that
            # is gone must not turn the interrupt into an internal error.
            with contextlib.suppress(Exception):
                Event(stop_name, client=client).set()
                client.cancel(list(futures))
            raise


def run_on_worker(job: Job, options: RunOptions, stop_name: str) -> Result:
    """The Dask task: `run_job`, stopped when the batch sets the Event
    `stop_name` or the worker cancels this task."""
    from distributed import Event, get_worker

    worker = get_worker()
    key = worker.get_current_task()
    event = Event(stop_name)

    def stop() -> bool:
        try:
            if event.is_set():
                return True
        except Exception:  # the scheduler is unreachable: rely on the cancel and the limit
            pass
        return _cancelled(worker, key)

    return run_job(job, options, stop=stop)


def _cancelled(worker, key) -> bool:
    """Whether the worker has given up this running task (its client is
    gone). Worker internals: without them, only the Event and the limit."""
    try:
        task = worker.state.tasks.get(key)
    except AttributeError:
        return False
    return task is None or task.state in ("cancelled", "released", "forgotten")


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
