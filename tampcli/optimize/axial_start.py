"""An arm motion's start that leaves its first keyframe and enters its last along the
tool's approach axis, tried where the NLP from the via points (a lift over the
obstacles) failed, before the sampler. In an enclosure the lift runs into the roof
and the sampler has to find the way in or out at random; the hand came in along its
approach, so a start along it is often one the NLP solves. Measured: blind29 p01's
sample carried out of a closed booth, through its 28 cm window, onto a rack outside
(the lift start failed; the sampler took 27 s, or the stage's 30 s ran out first):
solved from this start in 0.9 s, the rungs at the rack's end (at the booth's, the
hand meets the window's jamb at once); blind33 p03, the items of a roofed cubby
swapped by the xArm6: solved (8 actions), where every carry out of the cubby had
failed.

Each end backs off along minus the approach axis (z of the tool), the orientation
kept: rungs RUNG apart up to REACH, each an inverse kinematics solution seeded by the
one before, each (and the points between two) the tight margin clear of everything,
or where the keyframe itself is nearer, no nearer than it less SLACK
(approach.axis_rungs, the straight ends' rule); the first rung that fails ends that
side, what came before kept. The start runs q_a, its rungs out, a straight joint-space line to the last
rung of the other end, its rungs in, q_b, resampled to the motion's waypoints. It is
a start only: the NLP then solves the motion with its rows as from any other.
"""

from __future__ import annotations

import numpy as np

from tampcli.geometry.sampled_path import resample
from tampcli.optimize.approach import SLACK, axis_rungs
from tampcli.optimize.collide import held_spec
from tampcli.optimize.path import allowed_contacts

RUNG = 0.03  # m: between two rungs along the axis
REACH = 0.24  # m: the farthest rung from the keyframe


def axial_start(run, ctx, T: int) -> np.ndarray | None:
    """Interior waypoints ((T - 1) * n) of the start above for motion `ctx`, or None
    where neither end has a rung (nothing to add to the other starts), for the planar
    robot and for a push (whose tool follows its face)."""
    problem = run.problem
    m = problem.motions[ctx.index]
    if problem.planar or m.pushes:
        return None
    ignore = allowed_contacts(m)
    out = _back_off(problem, run.checker, ctx.q_a, ctx, ignore)
    back = _back_off(problem, run.checker, ctx.q_b, ctx, ignore)
    if not out and not back:
        return None
    points = np.array([ctx.q_a, *out, *reversed(back), ctx.q_b], dtype=float)
    return resample(points, T + 1)[1:-1].reshape(-1)


def _back_off(problem, checker, q, ctx, ignore) -> list[np.ndarray]:
    """The rungs from keyframe q back along the tool's approach axis, nearest first."""
    world, opts = problem.world, problem.options
    q = np.asarray(q, dtype=float)
    held = held_spec(ctx.held)
    here = checker.min_distance(q, ctx.moved, held, ignore, static=False,
                                horizon=opts.margin)
    clear = min(opts.tight_margin, here) - SLACK
    _, rungs = axis_rungs(problem, q, -world.tool_pose(q)[:3, 2], RUNG, int(round(REACH / RUNG)),
                          ctx.held, ctx.moved, ignore, clear, checker, limits=True)
    return rungs
