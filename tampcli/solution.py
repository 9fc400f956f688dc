"""The solution file (solution.json): the value `solve` produces and `render`
and `validate` read back.

`Solution` is plain data (no numpy) so it can cross process boundaries (batch)
and be written exactly as docs/formats.md lays it out. Reading it back, with its
checks, is solution_read's business.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from tampcli.errors import SolutionFileError
from tampcli.solution_kkt import KktStages, stages_to_dict

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
    stage: str | None = None  # deepest stage reached: "final" | "reach" | "keyframes" | "path"
    nlp_cost: float | None = None
    total_cost: float | None = None
    seconds: float = 0.0
    reason: str | None = None
    kkt: KktStages = KktStages()  # of each stage it solved


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
    kkt: KktStages = KktStages()  # the answer's NLPs, one certificate per stage
    grasps: tuple = ()  # per grasp action: how it holds its object (optimize/grasp_report.py)

    @property
    def solved(self) -> bool:
        return self.status == "solved"

    @property
    def gap(self) -> float | None:
        """(objective - lower_bound) / |objective|: how far the proved bound leaves the
        answer from a proved optimum (0: proved optimal)."""
        if self.objective is None or self.lower_bound is None:
            return None
        return (self.objective - self.lower_bound) / max(abs(self.objective), 1e-12)


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
        "gap": _num(solution.gap),
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
                "kkt": stages_to_dict(s.kkt),
            }
            for s in solution.skeletons
        ],
        "stats": solution.stats,
        "kkt": stages_to_dict(solution.kkt),
        "grasps": [dict(g) for g in solution.grasps],
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

