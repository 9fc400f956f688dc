"""Greedy action elimination (Nakhost & Mueller 2010): plans without redundant steps.

For each step in turn, the step is dropped, and so is every later step that
is then no longer applicable; if the rest still reaches the goal, the shorter
plan is kept (costs are never negative, so it is never dearer). Passes repeat
until none drops anything. Only the grounded semantics of the Task is used,
axioms and conditional effects included.
"""

from __future__ import annotations

import time
from collections.abc import Sequence

from tampcli.task.task import Operator, Task


def eliminate_redundant(task: Task, plan: Sequence[Operator],
                        deadline: float | None = None) -> tuple[Operator, ...]:
    """The plan with redundant steps removed; `plan` itself when the deadline
    (a time.perf_counter() value) passes first or nothing is redundant."""
    best = list(plan)
    changed = True
    while changed:
        changed = False
        states = _states(task, best)
        i = 0
        while i < len(best):
            if deadline is not None and time.perf_counter() > deadline:
                return tuple(best)
            shorter = _without(task, best, i, states[i])
            if shorter is None or _cost(shorter) > _cost(best):
                i += 1
                continue
            best = shorter
            states = _states(task, best)
            changed = True
    return tuple(best)


def without_step(task: Task, plan: Sequence[Operator], skip: int) -> list[Operator] | None:
    """The plan less step `skip` and every later step then inapplicable, when the rest
    still reaches the goal; else None (one move of the elimination, for callers that
    judge each candidate further, like `solve`'s geometry)."""
    state = task.init
    for op in plan[:skip]:
        state = task.apply(state, op)
    return _without(task, list(plan), skip, state)


def _states(task: Task, plan: list[Operator]) -> list[frozenset[int]]:
    """The state before each step (and after the last)."""
    state = task.init
    states = [state]
    for op in plan:
        state = task.apply(state, op)
        states.append(state)
    return states


def _without(task: Task, plan: list[Operator], skip: int, state) -> list[Operator] | None:
    kept = plan[:skip]
    for op in plan[skip + 1:]:
        if op.pre.holds(task.closure(state)):
            kept.append(op)
            state = task.apply(state, op)
    return kept if task.is_goal(state) else None


def _cost(plan: Sequence[Operator]) -> float:
    return sum(op.cost for op in plan)
