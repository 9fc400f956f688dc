"""The SLSQP driver: one skeleton, one stage -> TrajectoryResult.

final     -> one small NLP over the placements (no robot);
reach     -> the keyframe NLP with collisions dropped: a cheap relaxation whose cost
             bounds the keyframes' (heuristically: both are local optima);
keyframes -> the final NLP (for placements), IK keyframes, one NLP over keyframes;
path      -> keyframes (unless `warm` has them for this skeleton), then one NLP per
             motion phase with its two keyframes fixed; nothing is called solved
             before `verify` passes at 10x the waypoint resolution.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from tampcli.optimize.keyframe_stage import final, keyframes, reach
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.path_stage import path
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.result import STAGES, TrajectoryResult
from tampcli.optimize.run import Run


def solve(problem: TrajectoryProblem, stage: str, warm: TrajectoryResult | None = None,
          options: OptimizeOptions | None = None, cutoff: float | None = None
          ) -> TrajectoryResult:
    """Solve `stage` of the skeleton's NLP; never raises for a failed solve.

    `cutoff`: a trajectory cost at which the answer is of no use (branch and bound's
    incumbent less this skeleton's symbolic part): the path stage stops, "bounded",
    once the motions solved plus the least cost through the remaining keyframes
    reach it."""
    if stage not in STAGES:
        raise ValueError(f"stage must be one of {', '.join(STAGES)}, got {stage!r}")
    if options is not None and options != problem.options:
        problem = dataclasses.replace(problem, options=options)
    run = Run(problem, stage)
    run.cutoff = cutoff
    if problem.error is not None:
        proved = problem.error_proved
        return run.result("infeasible", worst_constraint=problem.error, proved=proved,
                          bound_kind="proved" if proved else "heuristic", violation=math.inf,
                          impossible=problem.impossible,
                          failed_actions=None if problem.error_at is None
                          else problem.error_at + 1)
    try:
        if stage == "final":
            return final(run)
        if stage == "reach":
            return reach(run, warm)
        if stage == "keyframes":
            return keyframes(run, warm)
        return path(run, warm)
    except np.linalg.LinAlgError as err:
        return run.result("infeasible", worst_constraint=f"numerical failure: {err}",
                          violation=math.inf)
