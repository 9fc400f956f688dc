"""Plan validation with our own lifted semantics (see `lifted.py`).

`validate_plan(domain, problem, plan)` runs the plan from the initial state:
each step must name a known action with the right number of known objects of
the right types, its precondition must hold (derived predicates included),
and its effects are applied (conditions read before the step, deletes before
adds). The goal must hold at the end. The result is a `PlanReport`; an
invalid plan is a result, not an exception. Only bad plan syntax raises
(`plan_text.PlanSyntaxError`, exit 2).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from tampcli.errors import InputError
from tampcli.pddl import ast
from tampcli.search.lifted import UndefinedValue, World
from tampcli.search.plan_text import PlanStep, PlanText, parse_plan, parse_step


@dataclass(frozen=True)
class Failure:
    """Why a plan is invalid: `step` is 1-based, None when the goal fails at the end."""

    step: int | None
    action: str | None
    reason: str
    line: int | None = None

    def describe(self) -> str:
        where = "at the end" if self.step is None else f"step {self.step}"
        if self.line is not None:
            where += f" (line {self.line})"
        if self.action:
            where += f" {self.action}"
        return f"{where}: {self.reason}"


@dataclass(frozen=True)
class PlanReport:
    valid: bool
    cost: float | None  # None when invalid
    steps: int  # actions in the plan
    failure: Failure | None = None
    unit_cost: bool = True
    declared_cost: float | None = None  # from a `; cost = N` line, if any


def validate_plan(domain: ast.Domain, problem: ast.Problem,
                  plan: PlanText | Sequence[str] | Sequence[PlanStep]) -> PlanReport:
    steps, declared = _steps(plan)
    world = World(domain, problem)
    state = world.initial_state()
    cost = 0.0
    for index, step in enumerate(steps, start=1):
        problem_text = _check_signature(world, step)
        if problem_text is not None:
            return _invalid(world, steps, declared, index, step, problem_text)
        action = domain.action(step.action)
        binding = {p.name: a for p, a in zip(action.params, step.args, strict=True)}
        closed = world.closure(state)
        if not world.holds(action.precondition, binding, closed):
            reasons = world.why_false(action.precondition, binding, closed)
            return _invalid(world, steps, declared, index, step,
                            "; ".join(f"precondition {r}" for r in reasons))
        try:
            eff = world.effects(action.effect, binding, closed)
        except UndefinedValue as err:
            return _invalid(world, steps, declared, index, step,
                            f"the cost term {err} has no value in the problem's :init")
        state = (state - eff.delete) | eff.add
        cost += 1.0 if world.unit_cost else eff.cost
    closed = world.closure(state)
    if not world.holds(problem.goal, {}, closed):
        reasons = world.why_false(problem.goal, {}, closed)
        failure = Failure(None, None, "goal not reached: " + "; ".join(reasons))
        return PlanReport(False, None, len(steps), failure, world.unit_cost, declared)
    return PlanReport(True, cost, len(steps), None, world.unit_cost, declared)


def validate_plan_file(domain: ast.Domain, problem: ast.Problem, path: str | Path) -> PlanReport:
    return validate_plan(domain, problem, parse_plan(read_plan_file(path), str(path)))


def read_plan_file(path: str | Path) -> str:
    try:
        return Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError("file not found", str(path)) from None
    except IsADirectoryError:
        raise InputError("is a directory, expected a plan file", str(path)) from None
    except UnicodeDecodeError:
        raise InputError("not UTF-8 text", str(path)) from None
    except OSError as err:
        raise InputError(f"cannot read: {err.strerror}", str(path)) from None


def _steps(plan) -> tuple[tuple[PlanStep, ...], float | None]:
    if isinstance(plan, PlanText):
        return plan.steps, plan.declared_cost
    steps = tuple(s if isinstance(s, PlanStep) else parse_step(s, key=f"plan[{i}]")
                  for i, s in enumerate(plan))
    return steps, None


def _check_signature(world: World, step: PlanStep) -> str | None:
    """Why `step` cannot be an instance of a domain action, or None."""
    action = world.domain.action(step.action)
    if action is None:
        return f"unknown action {step.action}"
    if len(step.args) != len(action.params):
        return (f"{step.action} takes {len(action.params)} argument(s), "
                f"the plan gives {len(step.args)}")
    for param, arg in zip(action.params, step.args, strict=True):
        if arg not in world.object_types:
            return f"unknown object {arg} (for {param.name})"
        if not world.is_of_type(arg, param.types):
            have = " ".join(world.object_types[arg])
            want = " or ".join(param.types)
            return f"object {arg} is of type {have}, {param.name} must be of type {want}"
    return None


def _invalid(world, steps, declared, index, step, reason) -> PlanReport:
    return PlanReport(False, None, len(steps), Failure(index, step.text, reason, step.line),
                      world.unit_cost, declared)


