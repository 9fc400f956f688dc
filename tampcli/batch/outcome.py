"""A finished child -> status, cost, plan length, stats and error of its Result.

The child contract (`plan --json` / `solve --json`): one JSON object on
stdout; exit 0 solved, 1 unsolvable or limit, 2 bad input (the object is
`{"status": "error", "message": ...}`), 70 internal error. Anything else —
killed by a signal, no JSON where one was due — is a crash.
"""

from __future__ import annotations

import json
import signal
from dataclasses import dataclass
from typing import Any

from tampcli.errors import ExitCode

_STDERR_TAIL = 2000


@dataclass(frozen=True)
class Outcome:
    status: str
    cost: float | None = None
    plan_length: int | None = None
    stats: dict[str, Any] | None = None
    error: str | None = None


def classify(returncode: int, timed_out: bool, stdout: str, stderr: str,
             time_limit: float | None, memory_mb: int | None) -> Outcome:
    """`returncode` as Popen reports it (negative: killed by that signal)."""
    if timed_out:
        return Outcome("timeout", error=f"killed after exceeding the time limit "
                                        f"({time_limit:g} s) and its grace period")
    if returncode < 0:
        return Outcome("crashed", error=_signal_message(-returncode, stderr, memory_mb))
    data = _last_json_object(stdout)
    if returncode == ExitCode.BAD_INPUT:
        message = None
        if data is not None:
            message = data.get("message") or (data.get("error") or {}).get("message")
        return Outcome("error", error=message or _tail(stderr) or "bad input (exit 2)")
    if returncode != ExitCode.OK and _out_of_memory(stderr):
        limit = f"memory limit {memory_mb} MB" if memory_mb is not None else "no memory limit"
        return Outcome("crashed", error=f"out of memory ({limit})")
    if returncode == ExitCode.INTERNAL:
        return Outcome("crashed", error=_error_lines(stderr) or "internal error (exit 70)")
    if returncode not in (ExitCode.OK, ExitCode.NO_SOLUTION):
        return Outcome("crashed", error=_with_tail(f"exit code {returncode}", stderr))
    if data is None:
        return Outcome("crashed", error=_with_tail(
            f"exit code {returncode} without a JSON result on stdout", stderr))
    return _from_json(returncode, data)


def _from_json(returncode: int, data: dict[str, Any]) -> Outcome:
    status = data.get("status")
    stats = data.get("stats") if isinstance(data.get("stats"), dict) else {}
    if returncode == ExitCode.OK:
        status = "solved"
    elif status not in ("unsolvable", "limit"):
        return Outcome("crashed", stats=stats,
                       error=f"exit code 1 with status {status!r} (expected unsolvable or limit)")
    cost, length = None, None
    if "plans" in data:  # plan --json
        plans = data.get("plans") or []
        if plans and isinstance(plans[0], dict):
            cost = plans[0].get("cost")
            length = len(plans[0].get("actions") or [])
    else:  # solve --json: the solution.json keys
        cost = data.get("cost")
        if cost is None or data.get("scene") is None:  # solved symbolically: no trajectory
            cost = data.get("symbolic_cost")
        if data.get("plan") is not None:
            length = len(data["plan"])
        if data.get("symbolic_cost") is not None:
            stats = {**stats, "symbolic_cost": data["symbolic_cost"]}
    error = None
    if status != "solved":
        error = data.get("reason") or data.get("message") or status
    return Outcome(status, _number(cost), length if status == "solved" else None, stats, error)


def _last_json_object(stdout: str) -> dict[str, Any] | None:
    for line in reversed(stdout.strip().splitlines()):
        line = line.strip()
        if not line.startswith("{"):
            continue
        try:
            value = json.loads(line)
        except json.JSONDecodeError:
            continue
        return value if isinstance(value, dict) else None
    # A pretty-printed object spans lines.
    try:
        value = json.loads(stdout)
    except json.JSONDecodeError:
        return None
    return value if isinstance(value, dict) else None


def _out_of_memory(stderr: str) -> bool:
    # Only the last lines: the CLI's `internal error: MemoryError` or a traceback's
    # last line (an earlier line could quote a user's file).
    tail = stderr.strip().splitlines()[-2:]
    return any("MemoryError" in line for line in tail)


def _signal_message(signum: int, stderr: str, memory_mb: int | None) -> str:
    try:
        name = signal.Signals(signum).name
    except ValueError:
        name = f"signal {signum}"
    message = f"killed by {name}"
    if memory_mb is not None and signum in (signal.SIGSEGV, signal.SIGABRT, signal.SIGKILL):
        message += f" (the memory limit, {memory_mb} MB, may have been reached)"
    return _with_tail(message, stderr)


def _error_lines(stderr: str) -> str:
    """The CLI's `error: ...` lines, without what libraries print on stderr
    (PyBullet's build banner, warnings); all of stderr when there are none."""
    lines = [line[len("error: "):] for line in stderr.splitlines() if line.startswith("error: ")]
    return _tail("\n".join(lines)) if lines else _tail(stderr)


def _with_tail(message: str, stderr: str) -> str:
    tail = _tail(stderr)
    return f"{message}: {tail}" if tail else message


def _tail(text: str) -> str:
    text = text.strip()
    return text if len(text) <= _STDERR_TAIL else "..." + text[-_STDERR_TAIL:]


def _number(value: Any) -> float | None:
    return value if isinstance(value, (int, float)) and not isinstance(value, bool) else None
