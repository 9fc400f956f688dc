"""No useless action in a returned plan: greedy action elimination, judged by geometry.

After the search, each action of the incumbent is dropped in turn, with every
later action that is then inapplicable (`without_step`, symbolic); when the
rest still reaches the goal, the shorter skeleton goes through the three
stages like any other (a record of its own in the skeleton list). If its
trajectory is feasible, it replaces the incumbent, whatever its objective: a
plan with an action that can go is never the answer (the robot must not end
holding a block it had no reason to touch). Passes repeat until nothing drops.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Sequence
from typing import Any

from tampcli.solution import SkeletonRecord
from tampcli.solution_kkt import KktStages

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
            shorter = tuple(shorter)
            symbolic = float(sum(op.cost for op in shorter))
            started = time.perf_counter()
            stage, path, kkt = _last_stage(shorter, evaluate)
            objective = None if path is None else float(path.cost) + symbolic_weight * symbolic
            result.skeletons.append(SkeletonRecord(
                len(result.skeletons) + 1, tuple(op.name for op in shorter), symbolic,
                "infeasible" if path is None else "solved", symbolic_weight * symbolic,
                "proved", stage, None if path is None else float(path.cost), objective,
                time.perf_counter() - started,
                f"the answer less {plan[i].name} (action elimination)", kkt))
            if path is None:
                continue
            dropped += len(plan) - len(shorter)
            low = result.lower_bound
            result = dataclasses.replace(
                result, best=path, best_plan=shorter, best_symbolic_cost=symbolic,
                best_objective=objective, optimal=False,
                lower_bound=None if low is None else min(low, objective))
            changed = True
            break
    result.stats["actions_eliminated"] = dropped
    return result


def _last_stage(ops, evaluate):
    """(the last stage reached, its path-stage result or None when one failed, the KKT
    certificates of the stages solved)."""
    warm, kkt = None, KktStages()
    for stage in STAGES:
        warm = evaluate(ops, stage, warm)
        if warm.status != "solved":
            return stage, None, kkt
        kkt = getattr(warm, "kkt", None) or kkt
    return "path", warm, kkt
