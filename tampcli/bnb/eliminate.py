"""No useless action in a returned plan: greedy action elimination, judged by geometry.

After the search, each action of the incumbent is dropped in turn, with every
later action that is then inapplicable (`without_step`, symbolic); when the
rest still reaches the goal, the shorter skeleton goes through the three
stages like any other. If its trajectory is feasible, it replaces the
incumbent, whatever its objective: a plan with an action that can go is never
the answer (the issue it answers: a robot that ends holding a block it had
no reason to touch). Passes repeat until nothing drops.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Sequence
from typing import Any

STAGES = ("final", "keyframes", "path")


def eliminate_useless(result, evaluate, without_step: Callable[[Sequence, int], Any],
                      symbolic_weight: float, deadline: float):
    """`result` (a BnBResult) with the incumbent's useless actions removed."""
    if result.status != "solved":
        return result
    dropped = 0
    changed = True
    while changed and time.perf_counter() < deadline:
        changed = False
        plan = tuple(result.best_plan)
        for i in range(len(plan)):
            if time.perf_counter() >= deadline:
                break
            shorter = without_step(plan, i)
            if shorter is None:
                continue
            path = _feasible_path(tuple(shorter), evaluate)
            if path is None:
                continue
            symbolic = float(sum(op.cost for op in shorter))
            dropped += len(plan) - len(shorter)
            result = dataclasses.replace(
                result, best=path, best_plan=tuple(shorter), best_symbolic_cost=symbolic,
                best_objective=float(path.cost) + symbolic_weight * symbolic)
            changed = True
            break
    result.stats["actions_eliminated"] = dropped
    return result


def _feasible_path(ops, evaluate):
    warm = None
    for stage in STAGES:
        warm = evaluate(ops, stage, warm)
        if warm.status != "solved":
            return None
    return warm
