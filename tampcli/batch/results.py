"""Result (one problem's outcome) and the results file that survives SIGKILL.

Each Result is one JSON line, written with a single `os.write` on an
O_APPEND descriptor and then fsynced, so a line is either wholly in the file
or, if the batch dies inside that write, a trailing fragment without its
newline. Opening the file for `--resume` truncates such a fragment; every
other line must be a whole result, or the file is refused as not ours.

A line names its problem twice: `problem`, the absolute path, and
`problem_rel`, the path relative to the results file's folder (`/`-separated).
`--resume` matches a problem by absolute path first, then by that relative
path, so it works from any working directory and also after the results file
and its problem set were moved together to another folder or machine.
"""

from __future__ import annotations

import json
import math
import os
import posixpath
from collections.abc import Iterable
from dataclasses import asdict, dataclass, field
from typing import Any

from tampcli.errors import InputError, UsageError, source_line_at

STATUSES = ("solved", "unsolvable", "limit", "timeout", "error", "crashed")


@dataclass(frozen=True)
class Result:
    problem: str  # absolute path
    domain: str | None
    status: str  # one of STATUSES
    cost: float | None = None
    plan_length: int | None = None
    wall_s: float = 0.0
    peak_rss_mb: float | None = None
    cpu_s: float | None = None  # user + system time of the child and what it waited for
    stats: dict[str, Any] = field(default_factory=dict)
    error: str | None = None
    exit_code: int | None = None  # of the child; None when no child ran or it was killed

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"unknown status {self.status!r}")

    def to_json(self) -> dict[str, Any]:
        return asdict(self)


class ResultsFile:
    """The append-only results file of one batch; use as a context manager."""

    def __init__(self, path: str, resume: bool):
        self.path = path
        self.folder = os.path.dirname(os.path.abspath(path))
        self.records: list[dict[str, Any]] = []
        self.repaired_bytes = 0
        if os.path.isdir(path):
            raise UsageError("is a folder; --out wants a file", path=path)
        if not resume and os.path.exists(path) and os.path.getsize(path) > 0:
            raise UsageError("results file exists: pass --resume to continue it, or remove "
                             "it to start over", path=path, key="--out")
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        try:
            self._fd = os.open(path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        except OSError as err:
            raise UsageError(f"cannot write: {err.strerror}", path=path, key="--out") from None
        try:
            _lock(self._fd, path)
            if resume:
                self.repaired_bytes = _truncate_torn_tail(path)
                self.records = read_results(path)
        except BaseException:
            self.close()
            raise

    def latest(self, problems: Iterable[str]) -> dict[str, dict[str, Any]]:
        """The last record of each of `problems` (absolute paths) that has one.

        Records whose absolute path is one of `problems` are matched first; a
        problem none of them names is then matched by its path relative to
        this file's folder (the file was moved with its set).
        """
        wanted = set(problems)
        latest: dict[str, dict[str, Any]] = {}
        unmatched = []
        for record in self.records:
            absolute = os.path.abspath(record["problem"])
            if absolute in wanted:
                latest[absolute] = record
            else:
                unmatched.append(record)
        by_relative = {}
        for problem in wanted - set(latest):
            relative = self.relative(problem)
            if relative is not None:
                by_relative[relative] = problem
        moved: dict[str, dict[str, Any]] = {}
        for record in unmatched:
            problem = by_relative.get(_relative_of(record))
            if problem is not None:
                moved[problem] = record
        return latest | moved

    def relative(self, problem: str) -> str | None:
        """`problem` relative to this file's folder, `/`-separated; None when
        there is no such path (another drive on Windows)."""
        try:
            relative = os.path.relpath(problem, self.folder)
        except ValueError:
            return None
        return relative.replace(os.sep, "/")

    def append(self, result: Result) -> None:
        fields = result.to_json()
        fields = {"problem": fields.pop("problem"),
                  "problem_rel": self.relative(result.problem), **fields}
        record = _strict(fields)
        line = (json.dumps(record, default=_jsonable, allow_nan=False) + "\n").encode()
        written = os.write(self._fd, line)
        if written != len(line):
            # A short write on a regular file means the disk is full: the
            # fragment is cut away by the next --resume.
            raise OSError(f"{self.path}: short write ({written} of {len(line)} bytes)")
        os.fsync(self._fd)
        self.records.append(record)

    def close(self) -> None:
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1

    def __enter__(self) -> ResultsFile:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _relative_of(record: dict[str, Any]) -> str | None:
    """A record's path relative to its results file: `problem_rel`, or for a
    line that has none (written by hand, or by an older tampcli) a relative
    `problem` taken as relative to the file's folder."""
    relative = record.get("problem_rel")
    if isinstance(relative, str):
        return posixpath.normpath(relative)
    problem = record["problem"]
    if os.path.isabs(problem):
        return None
    return posixpath.normpath(problem.replace(os.sep, "/"))


def _lock(fd: int, path: str) -> None:
    """One batch per results file: a second one would interleave and repeat work.
    The lock dies with its process, even under SIGKILL."""
    try:
        import fcntl
    except ImportError:  # not POSIX: no guard
        return
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        raise UsageError("another batch is writing to this results file", path=path,
                         key="--out") from None


def read_results(path: str) -> list[dict[str, Any]]:
    """Every line of a results file; a line that is not a result is bad input."""
    records = []
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
        except json.JSONDecodeError as err:
            raise InputError(f"not a results line: {err.msg}", path, number, err.colno,
                             source_line_at(text, number)) from None
        if not isinstance(record, dict) or not isinstance(record.get("problem"), str):
            raise InputError("not a results line: expected an object with a \"problem\"",
                             path, number, 1, source_line_at(text, number))
        records.append(record)
    return records


def _truncate_torn_tail(path: str) -> int:
    """Cut a trailing fragment that has no newline; return how many bytes."""
    with open(path, "rb+") as f:
        size = f.seek(0, os.SEEK_END)
        if size == 0:
            return 0
        keep = size
        chunk = 4096
        while keep > 0:
            start = max(0, keep - chunk)
            f.seek(start)
            block = f.read(keep - start)
            newline = block.rfind(b"\n")
            if newline >= 0:
                keep = start + newline + 1
                break
            keep = start
        if keep == size:
            return 0
        f.truncate(keep)
        f.flush()
        os.fsync(f.fileno())
        return size - keep


def _strict(value: Any) -> Any:
    """Strict JSON: a non-finite float (an infinite bound, say) becomes null."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {str(k): _strict(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_strict(v) for v in value]
    return value


def _jsonable(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (set, frozenset, tuple)):
        return list(value)
    return str(value)
