"""One Job -> one child process -> one Result, whatever the child does.

The child runs `python -m tampcli.batch.child ... -- plan|solve DOMAIN
PROBLEM --json --time-limit S` in a session of its own, so that at the limit
(S plus a grace period) the whole process group — the planner and anything
it started — is killed at once. The child is waited for with `waitid(...,
WNOWAIT)` first: while it is an unreaped zombie its process-group id cannot
be reused, so killing stragglers of the group is safe; `wait4` then reaps it
and gives its own peak RSS.
"""

from __future__ import annotations

import os
import select
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from tampcli.batch.discover import Job
from tampcli.batch.outcome import classify
from tampcli.batch.results import Result
from tampcli.errors import UsageError

_POLL_S = 0.05
# How often a running child asks whether its batch was interrupted (Dask: one
# round trip to the scheduler each time).
STOP_POLL_S = 0.5
STOPPED_MESSAGE = "stopped: the batch was interrupted"
PROG = "tampcli batch"  # where a bad flag is reported, as argparse does


@dataclass(frozen=True)
class RunOptions:
    """How each problem is run.

    time_limit: seconds given to the child (`--time-limit`); None = no limit.
    grace: seconds past time_limit before the child's group is killed.
    memory_mb: cap on the child's address space (RLIMIT_AS), MB; None = none.
    symbolic: run `plan` instead of `solve`.
    video_dir: with solve, `--video DIR/<domain>-<problem>.mp4`.
    """

    time_limit: float | None = None
    grace: float = 5.0
    memory_mb: int | None = None
    symbolic: bool = False
    video_dir: str | None = None

    def __post_init__(self):
        if self.time_limit is not None and not self.time_limit > 0:
            raise UsageError(f"must be positive, got {self.time_limit}", path=PROG,
                             key="--time-limit")
        if not self.grace >= 0:
            raise UsageError(f"must be zero or positive, got {self.grace}", path=PROG,
                             key="--grace")
        if self.memory_mb is not None and self.memory_mb <= 0:
            raise UsageError(f"must be positive, got {self.memory_mb}", path=PROG,
                             key="--memory-limit")
        if self.video_dir is not None and self.symbolic:
            raise UsageError("videos need `solve`: drop --symbolic or --video-dir",
                             path=PROG, key="--video-dir")

    @property
    def kill_after(self) -> float | None:
        return None if self.time_limit is None else self.time_limit + self.grace


class LiveGroups:
    """Process groups of running children, so an interrupted batch can kill them."""

    def __init__(self):
        self._lock = threading.Lock()
        self._groups: set[int] = set()
        self._stopping = False

    def add(self, pgid: int) -> None:
        with self._lock:
            if self._stopping:  # started while the batch was being interrupted
                _kill_group(pgid)
            self._groups.add(pgid)

    def discard(self, pgid: int) -> None:
        with self._lock:
            self._groups.discard(pgid)

    def kill_all(self) -> None:
        with self._lock:
            self._stopping = True
            for pgid in self._groups:
                _kill_group(pgid)


def child_command(job: Job, options: RunOptions) -> list[str]:
    command = "plan" if options.symbolic else "solve"
    head = [sys.executable, "-m", "tampcli.batch.child", "--parent", str(os.getpid())]
    if options.memory_mb is not None:
        head += ["--memory-mb", str(options.memory_mb)]
    args = [command, job.domain or "", job.problem, "--json"]
    if not options.symbolic:  # the batch runs problems side by side: one core each
        args += ["--jobs", "1"]
    if options.time_limit is not None:
        args += ["--time-limit", f"{options.time_limit:g}"]
    if options.video_dir is not None:
        args += ["--video", str(video_path(job, options.video_dir))]
    return head + ["--"] + args


def video_path(job: Job, video_dir: str) -> Path:
    return Path(video_dir) / f"{job.label}-{Path(job.problem).stem}.mp4"


def run_job(job: Job, options: RunOptions, live: LiveGroups | None = None,
            stop: Callable[[], bool] | None = None) -> Result:
    """Run one problem in its own process; never raises for what the child does.

    `stop`, polled every STOP_POLL_S while the child runs, says the batch was
    interrupted: the child's group is killed and the Result (status crashed,
    error STOPPED_MESSAGE) is not meant to be recorded. This is how a batch
    reaches children on Dask workers, where `live` cannot.
    """
    if job.domain is None:
        looked = Path(job.problem).parent
        return Result(job.problem, None, "error",
                      error=f"{job.problem}: no domain file found (looked for pNN-domain.pddl, "
                            f"domain_pNN.pddl, domain-pNN.pddl and domain.pddl in {looked} "
                            f"and its parent, and ../../domains/{looked.name}/domain.pddl)")
    if stop is not None and stop():
        return Result(job.problem, job.domain, "crashed", error=STOPPED_MESSAGE)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1",
               MKL_NUM_THREADS="1", NO_COLOR="1")
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        start = time.monotonic()
        try:
            proc = subprocess.Popen(child_command(job, options), stdin=subprocess.DEVNULL,
                                    stdout=out, stderr=err, env=env, start_new_session=True)
        except OSError as exc:
            return Result(job.problem, job.domain, "crashed",
                          error=f"cannot start the child: {exc}")
        if live is not None:
            live.add(proc.pid)
        try:
            ended = _wait_exit(proc.pid, start, options.kill_after, stop)
            # Whatever the child left running in its group goes with it.
            _kill_group(proc.pid)
        finally:
            if live is not None:
                live.discard(proc.pid)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.monotonic() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        stdout, stderr = _read(out), _read(err)
    if ended == "stopped":
        return Result(job.problem, job.domain, "crashed", wall_s=round(wall, 3),
                      error=STOPPED_MESSAGE)
    timed_out = ended == "timeout"
    outcome = classify(proc.returncode, timed_out, stdout, stderr, options.time_limit,
                       options.memory_mb)
    return Result(
        problem=job.problem,
        domain=job.domain,
        status=outcome.status,
        cost=outcome.cost,
        plan_length=outcome.plan_length,
        wall_s=round(wall, 3),
        peak_rss_mb=round(_maxrss_mb(usage.ru_maxrss), 1),
        cpu_s=round(usage.ru_utime + usage.ru_stime, 3),
        stats=outcome.stats or {},
        error=outcome.error,
        exit_code=None if timed_out or proc.returncode < 0 else proc.returncode,
    )


def _wait_exit(pid: int, start: float, kill_after: float | None,
               stop: Callable[[], bool] | None = None) -> str:
    """Block until `pid` has exited (left unreaped); kill its group at the
    deadline or when `stop()` says so. Returns "exited", "timeout" or "stopped"."""
    deadline = None if kill_after is None else start + kill_after
    next_stop_check = time.monotonic() + STOP_POLL_S
    pidfd = _pidfd(pid)
    try:
        while not _exited(pid):
            now = time.monotonic()
            if stop is not None and now >= next_stop_check:
                if stop():
                    _kill_group(pid)
                    os.waitid(os.P_PID, pid, os.WEXITED | os.WNOWAIT)
                    return "stopped"
                next_stop_check = time.monotonic() + STOP_POLL_S
            remaining = None if deadline is None else deadline - now
            if remaining is not None and remaining <= 0:
                _kill_group(pid)
                os.waitid(os.P_PID, pid, os.WEXITED | os.WNOWAIT)
                return "timeout"
            wait = remaining
            if stop is not None:
                until_check = max(0.0, next_stop_check - now)
                wait = until_check if wait is None else min(wait, until_check)
            if pidfd is not None:
                select.select([pidfd], [], [], wait)
            else:
                time.sleep(_POLL_S if wait is None else min(_POLL_S, wait))
    finally:
        if pidfd is not None:
            os.close(pidfd)
    return "exited"


def _exited(pid: int) -> bool:
    return os.waitid(os.P_PID, pid, os.WEXITED | os.WNOWAIT | os.WNOHANG) is not None


def _pidfd(pid: int) -> int | None:
    """A descriptor that becomes readable when `pid` exits (Linux >= 5.3)."""
    if not hasattr(os, "pidfd_open"):
        return None
    try:
        return os.pidfd_open(pid)
    except OSError:
        return None


def _kill_group(pgid: int) -> None:
    try:
        os.killpg(pgid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _read(f) -> str:
    f.seek(0)
    return f.read().decode("utf-8", errors="replace")


def _maxrss_mb(maxrss: int) -> float:
    # Linux reports kilobytes, macOS bytes.
    return maxrss / (1024 * 1024) if sys.platform == "darwin" else maxrss / 1024
