"""`tampcli validate DOMAIN PROBLEM PLAN`: check a plan file or a solution.json.

Exit 0 when valid ("valid, cost N"), 1 when invalid (each violation listed:
step, action, why), 2 on bad input. A solution.json has its `plan` checked
symbolically, then its trajectory geometrically when the geometric verifier
(`tampcli.optimize.verify`) is installed.
"""

from __future__ import annotations

import contextlib
import ctypes
import importlib
import json
import os
import sys
from pathlib import Path

from tampcli.errors import ExitCode, SolutionFileError, source_line_at
from tampcli.pddl import parser
from tampcli.search.plan_text import parse_plan
from tampcli.search.validate import PlanReport, read_plan_file, validate_plan


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", help="PDDL problem file")
    p.add_argument("plan", help="plan in IPC format, or a solution.json")


def run(args, ui) -> int:
    domain = parser.parse_domain_file(args.domain)
    problem = parser.parse_problem_file(args.problem)
    text = read_plan_file(args.plan)
    is_solution = args.plan.endswith(".json") or text.lstrip().startswith("{")
    if is_solution:
        report = validate_plan(domain, problem, solution_plan(text, args.plan))
    else:
        report = validate_plan(domain, problem, parse_plan(text, args.plan))
    violations = []
    if report.failure is not None:
        f = report.failure
        violations.append({"kind": "symbolic", "step": f.step, "line": f.line,
                           "action": f.action, "reason": f.reason, "text": f.describe()})
    geometry = None
    if is_solution:
        geometry, found = _geometric_violations(args.plan, domain, problem)
        violations.extend({"kind": "geometric", "step": None, "line": None, "action": None,
                           "reason": v, "text": v} for v in found)
    valid = not violations
    if ui.json:
        ui.emit_json({"status": "valid" if valid else "invalid", "valid": valid,
                      "cost": report.cost if valid else None, "unit_cost": report.unit_cost,
                      "steps": report.steps, "declared_cost": report.declared_cost,
                      "geometry": geometry, "violations": violations})
    else:
        _print(ui, report, valid, violations, geometry)
    return ExitCode.OK if valid else ExitCode.NO_SOLUTION


def solution_plan(text: str, path: str) -> list[str]:
    """The `plan` of a solution.json, checked to be a list of strings."""
    try:
        data = json.loads(text)
    except json.JSONDecodeError as err:
        raise SolutionFileError(f"not valid JSON: {err.msg}", path, err.lineno, err.colno,
                                source_line_at(text, err.lineno)) from None
    if not isinstance(data, dict):
        raise SolutionFileError("expected a JSON object (a solution.json)", path, 1, 1)
    if "plan" not in data:
        raise SolutionFileError("missing key: a solution.json needs `plan`", path, key="plan")
    plan = data["plan"]
    if not isinstance(plan, list):
        raise SolutionFileError("expected a list of \"(action arg ...)\" strings", path,
                                key="plan")
    for i, step in enumerate(plan):
        if not isinstance(step, str):
            raise SolutionFileError(f"expected a string \"(action arg ...)\", found {step!r}",
                                    path, key=f"plan[{i}]")
    return plan


def _geometric_violations(path, domain, problem) -> tuple[str, list[str]]:
    """("checked", violations), or ("unavailable", []) without the geometric verifier."""
    try:
        verify = importlib.import_module("tampcli.optimize.verify")
    except ModuleNotFoundError as err:
        if err.name not in ("tampcli.optimize", "tampcli.optimize.verify"):
            raise
        return "unavailable", []
    with _c_stdout_to_stderr():
        found = list(verify.verify_solution_file(Path(path), domain, problem))
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
