"""`tampcli validate DOMAIN PROBLEM PLAN`: check a plan file or a solution.json.

Exit 0 when valid ("valid, cost N"), 1 when invalid (each violation listed:
step, action, why), 2 on bad input. A solution.json is read and checked for
structure (solution_read), its `plan` checked symbolically, then its trajectory
geometrically (validate_geometry) when the geometric verifier
(`tampcli.optimize.verify`) is installed. With `--physics` the trajectory is also
replayed with dynamics (render/physics.py, the replay `render --physics` shows)
and an object that ends beyond `--max-drift` / `--max-turn` of its planned pose
is a violation.
"""

from __future__ import annotations

import contextlib
import ctypes
import importlib
import os
import sys

from tampcli.errors import ExitCode, UsageError
from tampcli.pddl.load import load
from tampcli.search.plan_text import parse_plan, parse_step
from tampcli.search.validate import PlanReport, read_plan_file, validate_plan
from tampcli.solution_read import read_solution


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", help="PDDL problem file")
    p.add_argument("plan", help="plan in IPC format, or a solution.json")
    p.add_argument("--physics", action="store_true",
                   help="also replay a solution.json with PyBullet dynamics: invalid when an "
                        "object ends beyond --max-drift / --max-turn of its planned pose")
    p.add_argument("--max-drift", type=float, default=0.01, metavar="M",
                   help="with --physics: position drift allowed per object (default 0.01 m)")
    p.add_argument("--max-turn", type=float, default=5.0, metavar="DEG",
                   help="with --physics: rotation drift allowed per object (default 5 degrees)")


def run(args, ui) -> int:
    loaded = load(args.domain, args.problem)
    for warning in loaded.warnings:
        ui.warn(warning)
    domain, problem = loaded.domain, loaded.problem
    text = read_plan_file(args.plan)
    checked = None
    is_solution = args.plan.endswith(".json") or text.lstrip().startswith("{")
    physics_flags(args, is_solution)
    if is_solution:
        checked = read_solution(args.plan)
        steps = [parse_step(s, args.plan, f"plan[{i}]") for i, s in enumerate(checked.raw.plan)]
        report = validate_plan(domain, problem, steps)
    else:
        report = validate_plan(domain, problem, parse_plan(text, args.plan))
    violations = []
    if report.failure is not None:
        f = report.failure
        violations.append({"kind": "symbolic", "step": f.step, "line": f.line,
                           "action": f.action, "reason": f.reason, "text": f.describe()})
    geometry = None
    if checked is not None:
        geometry, found = _geometric_violations(checked, domain, problem, args.domain)
        violations.extend({"kind": "geometric", "step": None, "line": None, "action": None,
                           "reason": v, "text": v} for v in found)
    physics = None
    if args.physics and not checked.raw.trajectory:
        # Nothing moves: the replay has nothing to judge, the verdict above says why
        # (an unsolved solution.json is invalid, not bad input).
        ui.warn(f"--physics: nothing replayed: the solution has no trajectory "
                f"(status {checked.raw.status})")
    elif args.physics:
        physics, drifted, overlaps = _physics(args)
        violations.extend({"kind": "physics", "step": None, "line": None, "action": None,
                           "phase": v.first.phase if v.first else None,
                           "phase_label": v.first.label if v.first else None,
                           "object": v.drift.name, "reason": v.describe(),
                           "text": v.describe()} for v in drifted)
        violations.extend({"kind": "physics", "step": None, "line": None, "action": None,
                           "phase": o.phase, "phase_label": o.label, "object": o.name,
                           "reason": o.describe(args.max_drift),
                           "text": o.describe(args.max_drift)} for o in overlaps)
    valid = not violations
    if ui.json:
        ui.emit_json({"status": "valid" if valid else "invalid", "valid": valid,
                      "cost": report.cost if valid else None, "unit_cost": report.unit_cost,
                      "steps": report.steps, "declared_cost": report.declared_cost,
                      "geometry": geometry, "violations": violations,
                      **({"physics": physics.as_json()} if physics is not None else {})})
    else:
        _print(ui, report, valid, violations, geometry)
        if physics is not None:
            ui.plain(f"physics: {len(physics.objects)} object(s) replayed for "
                     f"{physics.seconds:.1f} s; largest drift {physics.max_distance:.4f} m")

    return ExitCode.OK if valid else ExitCode.NO_SOLUTION


def physics_flags(args, is_solution: bool) -> None:
    """Refuse physics flags that cannot apply (UsageError, exit 2)."""
    for flag, value in (("--max-drift", args.max_drift), ("--max-turn", args.max_turn)):
        if not value > 0:
            raise UsageError(f"expected a positive number, got {value:g}", path="validate",
                             key=flag)
    if args.physics and not is_solution:
        raise UsageError("--physics replays a solution.json's trajectory; a plan file has "
                         "none", path=args.plan)


def _physics(args):
    """The physics replay of the solution, the objects it finds beyond tolerance, and
    the robot's passes into objects deeper than the replay grants."""
    from tampcli.render.inputs import load_inputs, mode_kind_of
    from tampcli.render.physics import replay_physics
    from tampcli.render.physics_values import drift_violations, overlap_violations

    inputs = load_inputs(args.plan)
    with _c_stdout_to_stderr():
        replay = replay_physics(inputs, mode_kind_of(inputs.modes))
    return (replay, drift_violations(replay, args.max_drift, args.max_turn),
            overlap_violations(replay, args.max_drift))


def _geometric_violations(checked, domain, problem, domain_path) -> tuple[str, list[str]]:
    """("checked", violations), or ("unavailable", []) without the geometric verifier."""
    try:
        importlib.import_module("tampcli.optimize.verify")
    except ModuleNotFoundError as err:
        if err.name not in ("tampcli.optimize", "tampcli.optimize.verify"):
            raise
        return "unavailable", []
    from tampcli.cli.validate_geometry import geometric_violations

    with _c_stdout_to_stderr():
        found = geometric_violations(checked, domain, problem, domain_path)
    return "checked", found


@contextlib.contextmanager
def _c_stdout_to_stderr():
    """PyBullet prints a banner on the C-level stdout, which would corrupt --json."""
    sys.stdout.flush()
    try:
        saved = os.dup(1)
    except OSError:  # no real file descriptor 1: nothing to protect
        yield
        return
    os.dup2(2, 1)
    try:
        yield
    finally:
        try:
            ctypes.CDLL(None).fflush(None)
        except (OSError, AttributeError):
            pass
        os.dup2(saved, 1)
        os.close(saved)


def _number(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else f"{x:g}"


def _print(ui, report: PlanReport, valid: bool, violations: list[dict], geometry) -> None:
    if geometry == "unavailable":
        ui.warn("the trajectory was not checked: the geometric verifier "
                "(tampcli.optimize.verify) is not installed")
    if valid:
        kind = "unit cost" if report.unit_cost else "general cost"
        ui.plain(f"valid, cost {_number(report.cost)} ({kind}, {report.steps} steps)")
        if report.declared_cost is not None and report.declared_cost != report.cost:
            ui.warn(f"the plan file declares cost {_number(report.declared_cost)}, "
                    f"its actions cost {_number(report.cost)}")
        return
    ui.plain(f"invalid: {len(violations)} violation(s)")
    for v in violations:
        ui.plain(f"  {v['text']}")
