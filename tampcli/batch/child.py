"""The entry point of one batch child: `python -m tampcli.batch.child [opts] -- ARGS`.

ARGS are a `tampcli` command line (`plan|solve DOMAIN PROBLEM ...`). The child
caps its address space (--memory-mb, RLIMIT_AS) and asks the kernel to kill it
if the batch that started it dies (--parent PID), so a batch killed with
SIGKILL leaves no planner running behind it; then it becomes `python -m
tampcli ARGS` (exec: the cap and the parent-death signal carry over). The
batch thus runs the command line it documents, and imports nothing of it.

Two hooks let tests exercise the batch against real failures; each is an
environment variable holding a glob matched against the problem path (whole
or file name):

    TAMPCLI_BATCH_CRASH_GLOB  the child aborts (SIGABRT) before planning
    TAMPCLI_BATCH_HANG_GLOB   the child ignores its time limit and SIGTERM and
                              sleeps, with a sleeping grandchild in its
                              process group (argv: HANG_MARKER, the problem)
"""

from __future__ import annotations

import fnmatch
import os
import signal
import subprocess
import sys
import time

CRASH_ENV = "TAMPCLI_BATCH_CRASH_GLOB"
HANG_ENV = "TAMPCLI_BATCH_HANG_GLOB"
HANG_MARKER = "tampcli-batch-hang-grandchild"
_PR_SET_PDEATHSIG = 1


def main(argv: list[str]) -> None:
    memory_mb, parent, args = _parse(argv)
    if parent is not None:
        _die_with_parent(parent)
    if memory_mb is not None:
        import resource

        limit = memory_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    problem = args[2] if len(args) > 2 else ""
    if _matches(os.environ.get(CRASH_ENV), problem):
        os.abort()
    if _matches(os.environ.get(HANG_ENV), problem):
        _hang(problem)
    # The same interpreter and package the batch runs (its path and environment).
    os.execv(sys.executable, [sys.executable, "-m", "tampcli", *args])


def _parse(argv: list[str]) -> tuple[int | None, int | None, list[str]]:
    if "--" not in argv:
        raise SystemExit("usage: python -m tampcli.batch.child [--memory-mb N] [--parent PID] "
                         "-- COMMAND DOMAIN PROBLEM ...")
    split = argv.index("--")
    head, args = argv[:split], argv[split + 1:]
    opts = dict(zip(head[::2], head[1::2], strict=False))
    memory = opts.get("--memory-mb")
    parent = opts.get("--parent")
    return (int(memory) if memory else None, int(parent) if parent else None, args)


def _die_with_parent(parent: int) -> None:
    """Linux: SIGKILL this process when the batch dies; elsewhere a no-op."""
    if not sys.platform.startswith("linux"):
        return
    import ctypes

    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
    except (OSError, AttributeError):
        return
    # The batch may have died before prctl took effect.
    if os.getppid() != parent:
        os._exit(1)


def _matches(pattern: str | None, problem: str) -> bool:
    if not pattern or not problem:
        return False
    return fnmatch.fnmatch(problem, pattern) or fnmatch.fnmatch(os.path.basename(problem), pattern)


def _hang(problem: str) -> None:
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    subprocess.Popen([sys.executable, "-c", "import time; time.sleep(3600)", HANG_MARKER,
                      problem])
    while True:
        time.sleep(3600)


if __name__ == "__main__":
    main(sys.argv[1:])
