"""What a failed keyframe NLP leaves violated at its best point, grouped by action.

A stage's failure names one row: the worst at the best point the NLP found.
That row may belong to an action that is not the one that cannot be done (the
NLP gave up a little at an easy pick to hold a hopeless place: blind4 p01's
first version said `(pick cube counter): tool tilted by 0.5 deg` while the
hand sat in a bottle at the place). Every row violated there, by action, shows
where the NLP was pulled from. The rows are evaluated again at the point the
result carries (its keyframes and grip choices), at the margin whose worst
violation is the one the NLP reported (it may have been solved again with the
tight margin).

The one module of bnb that knows the optimizer: the search itself gets this as
a callable (`branch_and_bound(diagnose=...)`, from the pipeline).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.optimize.grips import Kinematics
from tampcli.optimize.hand import with_hand
from tampcli.optimize.nlp import FEASIBILITY
from tampcli.optimize.result import TrajectoryResult
from tampcli.optimize.stages import keyframe_rows

ROWS_PER_ACTION = 3  # the worst rows of each action named; the others counted


@dataclass(frozen=True)
class Violation:
    """One violated row: its action (or "phase N"), what it says, by how much (m or rad)."""

    step: str
    words: str  # "collision panda_hand vs bottle3 (margin 1 mm) by 1.2 cm"
    amount: float


def violated_rows(problem, result: TrajectoryResult, kin: Kinematics) -> tuple[Violation, ...]:
    """The rows violated beyond the NLP's feasibility tolerance at a failed keyframe
    result's point, worst first; () when the result carries no point (failed before
    the keyframe NLP, or another stage)."""
    if result.stage != "keyframes" or result.solved or not result.keyframes.q:
        return ()
    if result.narrowed:
        problem = with_hand(problem, result.choices)
    options = problem.options
    vals = result.keyframes.blocks()
    start = np.asarray(problem.world.start, dtype=float)
    best: tuple[float, tuple[Violation, ...]] | None = None
    for margin in dict.fromkeys((options.margin, options.tight_margin)):
        at = problem.at_margin(margin)
        rows = keyframe_rows(at, vals, result.choices, kin, problem.checker, start)
        found = _violations(rows)
        worst = found[0].amount if found else 0.0
        if best is None or abs(worst - result.violation) < best[0]:
            best = (abs(worst - result.violation), found)
    return best[1]


def _violations(rows) -> tuple[Violation, ...]:
    found = []
    for row_set, equality in ((rows.eq, True), (rows.ineq, False)):
        values = np.concatenate(row_set.values) if row_set.values else np.zeros(0)
        amounts = np.abs(values) if equality else np.maximum(-values, 0.0)
        for label, amount in zip(row_set.labels, amounts, strict=True):
            if amount > FEASIBILITY:
                words = f"{label.what} by {_amount(amount, label.unit)}"
                found.append(Violation(label.step, words, float(amount)))
    return tuple(sorted(found, key=lambda v: -v.amount))


def _amount(amount: float, unit: str) -> str:
    """Two significant figures: rows just past the tolerance (0.1 mm) read as such,
    not as "0.0 cm" (Label.words's one decimal)."""
    if unit == "m":
        return f"{100 * amount:.2g} cm"
    if unit == "rad":
        return f"{np.degrees(amount):.2g} deg"
    return f"{amount:.2g}"


def by_action(violations: tuple[Violation, ...], order: tuple[str, ...] = ()) -> str | None:
    """The rows in words, one group per action in plan order (`order`: the action
    names), each group's worst rows first; None when there is none."""
    if not violations:
        return None
    groups: dict[str, list[Violation]] = {}
    for v in violations:
        groups.setdefault(v.step, []).append(v)
    rank = {name: i for i, name in enumerate(order)}
    parts = []
    for step in sorted(groups, key=lambda s: (rank.get(s, len(rank)), s)):
        rows = groups[step]
        words = ", ".join(v.words for v in rows[:ROWS_PER_ACTION])
        more = len(rows) - ROWS_PER_ACTION
        parts.append(f"{step} {words}" + (f" (+{more} more)" if more > 0 else ""))
    return "; ".join(parts)
