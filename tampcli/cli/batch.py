"""`tampcli batch PATH...`: solve (or plan) every problem under PATH, one JSON line each.

Each problem runs in a child process with its own limits; its outcome —
including a crash, a timeout or bad input — is one line of the results file,
written as soon as it is known. The exit code is 0 whenever the batch ran.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import signal
import threading
from collections import Counter

from tampcli.batch.discover import discover, largest_first
from tampcli.batch.results import STATUSES, Result, ResultsFile
from tampcli.batch.runner import PROG, RunOptions
from tampcli.batch.summary import summarize, table, write_csv
from tampcli.errors import ExitCode, UsageError

# A hung problem must not stall a batch of hundreds: each has a limit unless
# the user asks for none (`--time-limit none`).
DEFAULT_TIME_LIMIT_S = 300.0
DEFAULT_GRACE_S = 5.0
VIDEO_GRACE_S = 120.0


def _seconds_or_none(text: str) -> float | None:
    if text.strip().lower() == "none":
        return None
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected seconds or `none`, got {text!r}") from None


def add_parser(p) -> None:
    p.add_argument("paths", nargs="+", metavar="PATH",
                   help="problem files or folders (searched recursively)")
    p.add_argument("--jobs", "-j", type=int, default=None,
                   help="problems run at once (default: the number of cores)")
    p.add_argument("--time-limit", type=_seconds_or_none, default=DEFAULT_TIME_LIMIT_S,
                   metavar="S",
                   help="seconds per problem, given to the planner; killed at S + --grace "
                        f"(default {DEFAULT_TIME_LIMIT_S:g}; `none`: no limit, and a hung "
                        "problem stalls the batch)")
    p.add_argument("--grace", type=float, default=None, metavar="S",
                   help="seconds past --time-limit before a problem is killed (default 5; "
                        f"{VIDEO_GRACE_S:g} with --video-dir: the video is rendered after "
                        "the solve, within the grace period)")
    p.add_argument("--memory-limit", type=int, default=None, metavar="MB",
                   help="address-space cap per problem, in MB")
    p.add_argument("--out", default="results.jsonl", metavar="FILE",
                   help="results file, one JSON line per problem (default results.jsonl)")
    p.add_argument("--resume", action="store_true",
                   help="skip the problems already in --out (and repair a torn last line)")
    p.add_argument("--symbolic", action="store_true",
                   help="run `plan` (symbolic only) instead of `solve`")
    p.add_argument("--video-dir", metavar="DIR",
                   help="with solve: write DIR/<domain>-<problem>.mp4 for each problem")
    p.add_argument("--csv", metavar="FILE", help="also write the results as a CSV table")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on a Dask distributed cluster (needs tampcli[cluster])")


def run(args, ui) -> int:
    grace = args.grace
    if grace is None:
        grace = VIDEO_GRACE_S if args.video_dir else DEFAULT_GRACE_S
    options = RunOptions(time_limit=args.time_limit, grace=grace,
                         memory_mb=args.memory_limit, symbolic=args.symbolic,
                         video_dir=args.video_dir)
    workers = args.jobs if args.jobs is not None else (os.cpu_count() or 1)
    if workers < 1:
        raise UsageError(f"must be at least 1, got {workers}", path=PROG, key="--jobs")
    jobs = discover(args.paths)
    if args.video_dir:
        try:
            os.makedirs(args.video_dir, exist_ok=True)
        except OSError as err:
            raise UsageError(f"cannot create: {err.strerror}", path=args.video_dir,
                             key="--video-dir") from None
    if args.csv:
        _check_writable(args.csv, "--csv")
    with ResultsFile(args.out, resume=args.resume) as results:
        if results.repaired_bytes:
            ui.warn(f"{args.out}: cut a torn last line ({results.repaired_bytes} bytes) left "
                    "by an interrupted batch; that problem runs again")
        done = results.latest(job.problem for job in jobs)
        todo = largest_first([job for job in jobs if job.problem not in done])
        if len(todo) < len(jobs):
            ui.info(f"resuming {args.out}: {len(jobs) - len(todo)} of {len(jobs)} problems "
                    "already recorded")
        with _sigterm_interrupts(), \
                _Progress(ui, total=len(jobs), already=len(jobs) - len(todo)) as progress:

            def on_result(result: Result) -> None:
                results.append(result)
                progress.advance(result)

            if args.scheduler:
                from tampcli.batch.dask_backend import run_on_cluster

                run_on_cluster(args.scheduler, todo, options, on_result)
            else:
                from tampcli.batch.local import run_local

                run_local(todo, options, workers, on_result)
        latest = results.latest(job.problem for job in jobs)
        records = [latest[job.problem] for job in jobs if job.problem in latest]
    if args.csv:
        write_csv(args.csv, records)
    summary = summarize(records)
    summary.update(out=args.out, ran=len(todo), skipped=len(jobs) - len(todo))
    if ui.json:
        ui.emit_json(summary)
    else:
        ui.print(table(summary, title=f"batch: {len(records)} problems -> {args.out}"))
    return ExitCode.OK


def _check_writable(path: str, flag: str) -> None:
    """Refuse an unwritable output before the batch runs, not after."""
    folder = os.path.dirname(os.path.abspath(path))
    if os.path.isdir(path):
        raise UsageError("is a folder", path=path, key=flag)
    if not os.path.isdir(folder):
        raise UsageError("its folder does not exist", path=path, key=flag)
    if not os.access(folder, os.W_OK) or (os.path.exists(path) and not os.access(path, os.W_OK)):
        raise UsageError("not writable", path=path, key=flag)


@contextlib.contextmanager
def _sigterm_interrupts():
    """SIGTERM (`kill`, a cluster job's time limit) stops the batch as Ctrl-C
    does: the running children are killed with their process groups."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGTERM, interrupt)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _shown(path: str) -> str:
    """A problem as progress lines name it: relative to the working directory
    when it is inside it (results lines keep the absolute path)."""
    relative = os.path.relpath(path)
    outside = relative == os.pardir or relative.startswith(os.pardir + os.sep)
    return path if outside else relative


class _Progress:
    """A rich progress bar with ETA on a terminal; one plain line per problem otherwise."""

    def __init__(self, ui, total: int, already: int):
        self.ui, self.total, self.count = ui, total, already
        self.counts: Counter[str] = Counter()
        self._bar = None

    def __enter__(self) -> _Progress:
        if self.ui.interactive:
            from rich.progress import (
                BarColumn,
                MofNCompleteColumn,
                Progress,
                TextColumn,
                TimeElapsedColumn,
                TimeRemainingColumn,
            )

            self._bar = Progress(TextColumn("{task.description}"), BarColumn(),
                                 MofNCompleteColumn(), TimeElapsedColumn(),
                                 TextColumn("ETA"), TimeRemainingColumn(),
                                 console=self.ui.out, transient=False)
            self._bar.__enter__()
            self._task = self._bar.add_task("batch", total=self.total, completed=self.count)
        return self

    def advance(self, result: Result) -> None:
        self.count += 1
        self.counts[result.status] += 1
        if self._bar is not None:
            text = " ".join(f"{s} {self.counts[s]}" for s in STATUSES if self.counts[s])
            self._bar.update(self._task, advance=1, description=text)
            if result.status in ("crashed", "timeout"):
                self._bar.console.print(f"{result.status}: {_shown(result.problem)}",
                                        markup=False, highlight=False)
            return
        line = f"[{self.count}/{self.total}] {result.status:<10} {_shown(result.problem)} " \
               f"{result.wall_s:.2f} s"
        if result.error:
            line += f"  {result.error.splitlines()[0]}"
        self.ui.info(line)

    def __exit__(self, *exc) -> None:
        if self._bar is not None:
            self._bar.__exit__(*exc)
