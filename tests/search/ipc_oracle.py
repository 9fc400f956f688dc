"""The IPC benchmark folders and unified-planning as a second opinion on plans.

Shared by the validator tests (plans by Fast Downward) and the search tests
(plans by our own searches).
"""

from __future__ import annotations

import re
import tempfile
from functools import cache
from pathlib import Path

import pytest

IPC = Path(__file__).resolve().parents[2] / "benchmarks" / "ipc"


def natural(name: str):
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def problems(domain: str) -> list[Path]:
    files = [p for p in (IPC / domain).glob("*.pddl") if "domain" not in p.name]
    return sorted(files, key=lambda p: natural(p.name))


def domains() -> list[str]:
    return sorted(p.name for p in IPC.iterdir() if p.is_dir())


def domain_of(problem: Path) -> Path:
    stem = problem.stem.split("-")[0]
    for name in (f"{stem}-domain.pddl", f"domain_{stem}.pddl", "domain.pddl"):
        if (problem.parent / name).exists():
            return problem.parent / name
    raise FileNotFoundError(problem)


@cache
def up_problem(problem: Path):
    """unified-planning's reading of `problem`, or None where it has no validator for it.

    None when it cannot parse the domain (derived predicates; logistics00, whose
    predicate `in` it confuses with its own operator; zenotravel's `aircraft?a`)
    or when no validator supports what it read (elevators and transport define
    their travel costs for some pairs only: "undefined initial numeric").
    """
    up_io = pytest.importorskip("unified_planning.io")
    from unified_planning.shortcuts import PlanValidator, get_environment

    get_environment().credits_stream = None
    try:
        pb = up_io.PDDLReader().parse_problem(str(domain_of(problem)), str(problem))
        PlanValidator(problem_kind=pb.kind)
    except Exception:  # noqa: BLE001 - whatever it cannot read, it has no opinion on
        return None
    return pb


def up_verdict(problem: Path, plan: list[str]):
    """(valid, cost, index of the inapplicable step, or "ill-typed") by unified-planning.

    None when unified-planning has no validator for the problem (see `up_problem`).
    """
    pb = up_problem(problem)
    if pb is None:
        return None
    from unified_planning.engines import ValidationResultStatus
    from unified_planning.exceptions import UPTypeError
    from unified_planning.io import PDDLReader
    from unified_planning.plans import SequentialPlan
    from unified_planning.shortcuts import PlanValidator

    with tempfile.TemporaryDirectory() as folder:
        plan_path = Path(folder) / "plan"
        plan_path.write_text("\n".join(plan) + "\n")
        try:
            up_plan = PDDLReader().parse_plan(pb, str(plan_path))
        except UPTypeError:
            return False, None, "ill-typed"
    actions = list(up_plan.actions)
    with PlanValidator(problem_kind=pb.kind) as validator:
        result = validator.validate(pb, SequentialPlan(actions))
    failing = None
    if result.inapplicable_action is not None:
        failing = next(i for i, a in enumerate(actions) if a is result.inapplicable_action)
    cost = None
    if result.metric_evaluations:
        cost = float(next(iter(result.metric_evaluations.values())))
    return result.status == ValidationResultStatus.VALID, cost, failing
