"""No useless action in a returned plan: greedy action elimination, judged by geometry.

After the search, each action of the incumbent is dropped in turn, with every
later action that is then inapplicable (`without_step`, symbolic); when the
rest still reaches the goal, the shorter skeleton goes through the three
stages like any other (a record of its own in the skeleton list). The answer's
prefixes come first (`_candidates`), their path stage started from the answer's
own keyframes and motions (`_truncated`), no keyframe NLP. If its
trajectory is feasible, it replaces the incumbent, whatever its objective: a
plan with an action that can go is never the answer (the robot must not end
holding a block it had no reason to touch). Passes repeat until nothing drops.

The shorter skeleton has a lower symbolic cost than the answer, so the search
has often drawn it already (the blocker moved away, less the move, is the
skeleton that failed first). It is not optimized again when the search found it
infeasible before its path stage (no record: the search's says why; those NLPs
would fail again), nor when its path stage failed on a body the skeleton leaves
in the way (optimize/motion.py: it would meet that body again) or on a row naming
a movable body (the search's blocker lesson: the same skeleton meets it again), nor
when it solved it (its path is taken, a record saying so); one pruned by a bound, or
that failed otherwise at its path stage (sampled starts:
blind7 p03's carry through a maze failed in the 2-action skeleton and passed in
a 4-action one), is evaluated, its record naming the search's: a plan with an
action fewer is taken whatever its objective. Once actions were dropped, a plan the
search solved with no action to drop and a lower objective is the answer instead
(`_cheapest_minimal`). `stats["elimination_skeletons"]` counts the records added here, after
the search's `skeletons_generated`; `stats["elimination_skipped"]` the shorter
skeletons known infeasible.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable, Sequence
from typing import Any

from tampcli.bnb.values import Judged
from tampcli.optimize.blockers import blocker_of
from tampcli.optimize.motion import IN_THE_WAY
from tampcli.solution import SkeletonRecord
from tampcli.solution_kkt import KktStages

STAGES = ("final", "keyframes", "path")
ELIMINATION_SHARE = 0.1  # of solve's time limit, kept for action elimination once answered


def eliminate_useless(result, evaluate, without_step: Callable[[Sequence, int], Any],
                      symbolic_weight: float, deadline: float,
                      operators: dict[str, Any] | None = None,
                      movable: frozenset[str] = frozenset()):
    """`result` (a BnBResult) with the incumbent's useless actions removed; where some
    were, and the task's `operators` (by name) are given, the cheapest of that answer
    and the plans the search solved with no action to drop (`_cheapest_minimal`).
    `movable`: the scene's movable bodies (a path failure naming one is not rerun)."""
    if result.status != "solved":
        return result
    dropped = added = skipped = 0
    changed = True
    while changed and time.perf_counter() < deadline:
        changed = False
        plan = tuple(result.best_plan)
        for _i, shorter in _candidates(plan, without_step):
            if time.perf_counter() >= deadline:
                break
            names = tuple(op.name for op in shorter)
            known = result.judged.get(names)
            if known is not None and known.outcome == "infeasible" and (
                    known.stage != "path" or _met_in_the_way(result, known, movable)):
                skipped += 1
                continue
            symbolic = float(sum(op.cost for op in shorter))
            started = time.perf_counter()
            source = result.judged.get(tuple(op.name for op in plan))
            of = f" (#{source.rank})" if source is not None else ""
            why = (f"the answer{of} less {' '.join(_removed(plan, shorter))} "
                   "(action elimination")
            if known is not None and known.outcome == "solved" and known.path is not None:
                stage, path = "path", known.path
                kkt = getattr(path, "kkt", None) or KktStages()
                why += f"; solved as #{known.rank}, its path taken, not optimized again)"
            else:
                warm = _truncated(result.best, names, plan)
                stage, path, kkt = _last_stage(shorter, evaluate, warm)
                why += _again(known) + (
                    "; from the answer's keyframes and motions" if warm else "") + ")"
            objective = None if path is None else float(path.cost) + symbolic_weight * symbolic
            added += 1
            rank = len(result.skeletons) + 1
            result.skeletons.append(SkeletonRecord(
                rank, names, symbolic, "infeasible" if path is None else "solved",
                symbolic_weight * symbolic, "proved", stage,
                None if path is None else float(path.cost), objective,
                time.perf_counter() - started, why, kkt))
            result.judged[names] = Judged(rank, "infeasible" if path is None else "solved", path)
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
    result.stats["elimination_skeletons"] = added
    result.stats["elimination_skipped"] = skipped
    if dropped and operators is not None:
        result = _cheapest_minimal(result, without_step, symbolic_weight, operators)
    return result


def _removed(plan, shorter) -> list[str]:
    """The actions of `plan` that `shorter` (a subsequence of it) leaves out, in order
    (blind36 DOC_GAPS 3: a pick and its place dropped together were named as one)."""
    kept, out, j = [op.name for op in shorter], [], 0
    for op in plan:
        if j < len(kept) and kept[j] == op.name:
            j += 1
        else:
            out.append(op.name)
    return out


def _cheapest_minimal(result, without_step, symbolic_weight: float, operators: dict):
    """The answer, or a plan the search solved that has no action to drop (every
    `without_step` of it misses the goal) and a lower objective. Dropping actions
    can leave a plan much dearer than one the search had (blind15 p02: the 6-action
    answer, objective 1.39, less its can's second move, 9.89; the 4-action #1 had
    1.56)."""
    best = result
    for names, judged in result.judged.items():
        if judged.outcome != "solved" or judged.path is None \
                or any(n not in operators for n in names):
            continue
        ops = tuple(operators[n] for n in names)
        if any(without_step(ops, i) is not None for i in range(len(ops))):
            continue
        symbolic = float(sum(op.cost for op in ops))
        objective = float(judged.path.cost) + symbolic_weight * symbolic
        if objective < best.best_objective - 1e-9:
            low = result.lower_bound
            best = dataclasses.replace(
                result, best=judged.path, best_plan=ops, best_symbolic_cost=symbolic,
                best_objective=objective, optimal=False,
                lower_bound=None if low is None else min(low, objective))
    return best


def _met_in_the_way(result, known: Judged, movable: frozenset[str]) -> bool:
    """Whether the search's path stage failed that skeleton on a body it leaves in the
    way (optimize.motion: a path exists only with the body out of it), or on a row
    naming a movable body the failing action does not move (the search's lesson, a
    blocker: optimize/blockers.py): run again, the same skeleton meets the same body
    (blind15 p06: the answer less the push of the crate out of the corridor, 12 s to
    fail again; blind21 p06: the crate's push into the cube, 11 s)."""
    record = next((r for r in result.skeletons if r.rank == known.rank), None)
    if record is None:
        return False
    reason = record.reason or ""
    return IN_THE_WAY in reason or blocker_of(reason, movable) is not None


def _again(known: Judged | None) -> str:
    """Why a skeleton the search drew is optimized again."""
    if known is None:
        return ""
    return (f"; #{known.rank} again, {known.outcome} there with its feasibility unknown: a "
            "plan with an action fewer is taken whatever its objective")


def _candidates(plan: tuple, without_step) -> list[tuple[int, tuple]]:
    """(i, the plan less action i and what then cannot apply) for each i it reaches the
    goal, the answer's prefixes first, shortest first: an action after the goal's last
    (the robot ending with a block in hand) is the common useless one, and a prefix's
    path starts from the answer's own (`_truncated`): cheap to confirm, where a
    search of the others can take a stage's whole time limit (blind19 p04: the answer
    less its first action, 26 s, left no time to drop its last)."""
    found = [(i, tuple(shorter)) for i in range(len(plan))
             if (shorter := without_step(plan, i)) is not None]
    return sorted(found, key=lambda c: (c[1] != plan[:len(c[1])], len(c[1]), c[0]))


def _truncated(best, names: tuple, plan: tuple):
    """The answer's path result as the path stage's warm start for `names`, its
    prefix: its placements, grips, keyframes and motions (the stage cuts off the
    later ones), no certificate; None when `names` is no prefix of the plan or the result carries no
    keyframes."""
    if names != tuple(op.name for op in plan[:len(names)]) \
            or not getattr(best, "keyframes", None) or not dataclasses.is_dataclass(best):
        return None
    return dataclasses.replace(best, names=names, kkt=KktStages())


def _last_stage(ops, evaluate, answer=None):
    """(the last stage reached, its path-stage result or None when one failed, the KKT
    certificates of the stages solved). `answer`: `_truncated`'s, for a prefix of the
    answer: its path stage starts from the answer's keyframes, placements and motions
    (optimize/path_stage.py), no keyframe NLP."""
    warm, kkt = None, KktStages()
    for stage in STAGES:
        if answer is not None and stage == "keyframes":
            continue
        if answer is not None and stage == "path":
            warm = answer
        warm = evaluate(ops, stage, warm)
        if warm.status != "solved":
            return stage, None, kkt
        kkt = getattr(warm, "kkt", None) or kkt
    return "path", warm, kkt
