"""The solution file (solution.json): the value `solve` produces and `render`
and `validate` read back.

`Solution` is plain data (no numpy) so it can cross process boundaries (batch)
and be written exactly as docs/formats.md lays it out. `read` checks every required
key and points at the one that is missing or malformed.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from tampcli.errors import SolutionFileError

VERSION = 1
STATUSES = ("solved", "unsolvable", "limit")
OUTCOMES = ("solved", "pruned", "infeasible", "not reached")


@dataclass(frozen=True)
class Phase:
    """A span of `trajectory` (inclusive indices). `action` is None for motion."""

    action: str | None
    start: int
    end: int
    attached: str | None = None


@dataclass(frozen=True)
class SkeletonRecord:
    """One ranked skeleton that branch and bound looked at."""

    rank: int
    plan: tuple[str, ...]
    symbolic_cost: float
    outcome: str  # one of OUTCOMES
    bound: float | None = None
    bound_kind: str | None = None  # "proved" | "heuristic"
    stage: str | None = None  # deepest stage reached: "final" | "keyframes" | "path"
    nlp_cost: float | None = None
    total_cost: float | None = None
    seconds: float = 0.0
    reason: str | None = None


@dataclass(frozen=True)
class Solution:
    domain: str
    problem: str
    scene: str | None
    status: str
    reason: str | None = None
    plan: tuple[str, ...] = ()
    symbolic_cost: float | None = None
    cost: float | None = None
    lower_bound: float | None = None
    robot: dict = field(default_factory=dict)
    trajectory: tuple[tuple[float, ...], ...] = ()
    phases: tuple[Phase, ...] = ()
    objects: dict = field(default_factory=dict)  # name -> list of [x y z qx qy qz qw]
    skeletons: tuple[SkeletonRecord, ...] = ()
    stats: dict = field(default_factory=dict)
    modes: str | None = None
    objective: float | None = None  # cost + symbolic_weight * symbolic_cost
    symbolic_weight: float | None = None

    @property
    def solved(self) -> bool:
        return self.status == "solved"


def to_dict(solution: Solution) -> dict[str, Any]:
    return {
        "version": VERSION,
        "domain": solution.domain,
        "problem": solution.problem,
        "scene": solution.scene,
        "modes": solution.modes,
        "status": solution.status,
        "reason": solution.reason,
        "plan": list(solution.plan),
        "symbolic_cost": _num(solution.symbolic_cost),
        "cost": _num(solution.cost),
        "objective": _num(solution.objective),
        "symbolic_weight": _num(solution.symbolic_weight),
        "lower_bound": _num(solution.lower_bound),
        "robot": solution.robot,
        "trajectory": [[float(v) for v in q] for q in solution.trajectory],
        "phases": [
            {"action": p.action, "start": p.start, "end": p.end, "attached": p.attached}
            for p in solution.phases
        ],
        "objects": {k: [[float(v) for v in pose] for pose in poses]
                    for k, poses in solution.objects.items()},
        "skeletons": [
            {
                "rank": s.rank,
                "plan": list(s.plan),
                "symbolic_cost": _num(s.symbolic_cost),
                "bound": _num(s.bound),
                "bound_kind": s.bound_kind,
                "stage": s.stage,
                "outcome": s.outcome,
                "nlp_cost": _num(s.nlp_cost),
                "total_cost": _num(s.total_cost),
                "seconds": round(s.seconds, 4),
                "reason": s.reason,
            }
            for s in solution.skeletons
        ],
        "stats": solution.stats,
    }


def _num(value: float | None) -> float | None:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return None
    return float(value)


def write(solution: Solution, path: str | Path) -> None:
    """Write atomically: a reader never sees a half-written file."""
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    try:
        with open(tmp, "w") as handle:
            json.dump(to_dict(solution), handle, indent=1)
            handle.write("\n")
        os.replace(tmp, path)
    except OSError as err:
        raise SolutionFileError(f"cannot write: {err.strerror}", str(path)) from None


_REQUIRED = ("version", "domain", "problem", "scene", "status", "reason", "plan",
             "symbolic_cost", "cost", "lower_bound", "robot", "trajectory", "phases",
             "objects", "skeletons", "stats")


def read(path: str | Path) -> Solution:
    """Read and check a solution.json; errors name the offending key."""
    path = str(path)
    try:
        text = Path(path).read_text()
    except FileNotFoundError:
        raise SolutionFileError("file not found", path) from None
    except OSError as err:
        raise SolutionFileError(f"cannot read: {err.strerror}", path) from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as err:
        raise SolutionFileError(f"not valid JSON: {err.msg}", path, err.lineno, err.colno,
                                text.splitlines()[err.lineno - 1] if text else None) from None
    if not isinstance(data, dict):
        raise SolutionFileError("expected a JSON object", path, 1, 1)
    for key in _REQUIRED:
        if key not in data:
            raise SolutionFileError("missing", path, key=key)
    if data["version"] != VERSION:
        raise SolutionFileError(f"unsupported version {data['version']!r} (expected {VERSION})",
                                path, key="version")
    if data["status"] not in STATUSES:
        raise SolutionFileError(f"must be one of {', '.join(STATUSES)}", path, key="status")
    trajectory = _matrix(data["trajectory"], path, "trajectory")
    width = {len(q) for q in trajectory}
    if len(width) > 1:
        raise SolutionFileError("waypoints of different lengths", path, key="trajectory")
    phases = tuple(_phase(p, i, len(trajectory), path) for i, p in enumerate(_list(
        data["phases"], path, "phases")))
    objects = data["objects"]
    if not isinstance(objects, dict):
        raise SolutionFileError("expected an object of name -> poses", path, key="objects")
    for name, poses in objects.items():
        for pose in _matrix(poses, path, f"objects.{name}"):
            if len(pose) != 7:
                raise SolutionFileError("each pose needs 7 numbers [x y z qx qy qz qw]", path,
                                        key=f"objects.{name}")
        if phases and len(poses) != len(phases) + 1:
            raise SolutionFileError(f"expected {len(phases) + 1} poses (one per phase boundary), "
                                    f"found {len(poses)}", path, key=f"objects.{name}")
    robot = data["robot"]
    if not isinstance(robot, dict):
        raise SolutionFileError("expected an object", path, key="robot")
    if trajectory and len(robot.get("joints", ())) != len(trajectory[0]):
        raise SolutionFileError("joint names do not match the waypoint length", path,
                                key="robot.joints")
    skeletons = tuple(
        SkeletonRecord(
            rank=int(s.get("rank", i + 1)), plan=tuple(s.get("plan", ())),
            symbolic_cost=s.get("symbolic_cost"), outcome=s.get("outcome", "not reached"),
            bound=s.get("bound"), bound_kind=s.get("bound_kind"), stage=s.get("stage"),
            nlp_cost=s.get("nlp_cost"), total_cost=s.get("total_cost"),
            seconds=float(s.get("seconds") or 0.0), reason=s.get("reason"))
        for i, s in enumerate(_list(data["skeletons"], path, "skeletons")))
    return Solution(
        domain=data["domain"], problem=data["problem"], scene=data["scene"],
        status=data["status"], reason=data["reason"], plan=tuple(data["plan"]),
        symbolic_cost=data["symbolic_cost"], cost=data["cost"],
        lower_bound=data["lower_bound"], robot=robot,
        trajectory=tuple(tuple(q) for q in trajectory), phases=phases,
        objects={k: [list(p) for p in v] for k, v in objects.items()},
        skeletons=skeletons, stats=data["stats"], modes=data.get("modes"),
        objective=data.get("objective"), symbolic_weight=data.get("symbolic_weight"))


def resolve_input(solution_path: str | Path, recorded: str | None) -> Path | None:
    """A path recorded in a solution: beside the solution file first, then the cwd."""
    if recorded is None:
        return None
    recorded_path = Path(recorded)
    if recorded_path.is_absolute():
        return recorded_path
    beside = Path(solution_path).resolve().parent / recorded_path
    if beside.exists():
        return beside
    return recorded_path.resolve()


def _list(value, path, key) -> list:
    if not isinstance(value, list):
        raise SolutionFileError("expected a list", path, key=key)
    return value


def _matrix(value, path, key) -> list[list[float]]:
    rows = _list(value, path, key)
    for i, row in enumerate(rows):
        if not isinstance(row, list) or not all(
                isinstance(v, (int, float)) and not isinstance(v, bool) for v in row):
            raise SolutionFileError(f"entry {i} is not a list of numbers", path, key=key)
    return rows


def _phase(p, i, n_waypoints, path) -> Phase:
    key = f"phases[{i}]"
    if not isinstance(p, dict) or not {"action", "start", "end", "attached"} <= set(p):
        raise SolutionFileError("needs action, start, end, attached", path, key=key)
    start, end = p["start"], p["end"]
    if not (isinstance(start, int) and isinstance(end, int) and 0 <= start <= end < max(
            n_waypoints, 1)):
        raise SolutionFileError(f"start/end out of range (trajectory has {n_waypoints} "
                                "waypoints)", path, key=key)
    return Phase(p["action"], start, end, p["attached"])
