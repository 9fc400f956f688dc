"""Grips, reach and the resting geometry a skeleton walks through (shared by the stages)."""

from __future__ import annotations

import math

import numpy as np

from tampcli.optimize.bodies import REST_TOLERANCE
from tampcli.optimize.grips import Grip, SideGrip
from tampcli.optimize.values import NO_CHOICE

PANDA_REACH = 0.855  # m, from the shoulder
PANDA_SHOULDER = 0.333  # m above the base
REACH_SAMPLES = 300  # random configurations: the farthest tool position, x 1.05, is the ball


def grip_of(problem, step, choices) -> Grip:
    """How `step`'s object hangs from the tool (step = the grasp or push).

    `choices`: step index -> values.GripChoice. The planar robot holds by
    suction on the object's side whatever the kind; the arm as the kind says.
    """
    choice = choices.get(step.index, NO_CHOICE)
    info = problem.bodies[step.obj]
    if problem.planar and not step.kind.planar_grip:
        # The object touches the rim wherever it is taken (a box's corners included).
        touching = not info.disk
        base_z = float(problem.scene.robot.base_pose[2, 3])
        rim = problem.scene.robot.radius
        z = choice.z if choice.z is not None else info.pose[2]
        return SideGrip((0.0, 0.0, z - base_z), rho=rim + max(info.half[0], info.half[1]),
                        yaw=choice.yaw if choice.yaw is not None else info.pose[3],
                        half=(info.half[0], info.half[1]) if touching else None, rim=rim)
    return step.kind.grip(problem, step, choice)


def reach_of(problem) -> tuple[np.ndarray, float]:
    """(centre, radius) of a ball the tool cannot leave; infinite for the planar robot."""
    base = problem.scene.robot.base_pose
    if problem.planar:
        return base[:3, 3], math.inf
    if problem.scene.robot.model == "panda":
        return base[:3, 3] + base[:3, 2] * PANDA_SHOULDER, PANDA_REACH
    # Sampled once per lowered skeleton (the final NLP asks at every evaluation: 300
    # forward kinematics each were 95 % of blind18 p05's final stage, 11 s), batched.
    memo = problem.memo  # World measurements, kept by dataclasses.replace
    if "reach" not in memo:
        world = problem.world
        lo = np.where(np.isfinite(world.lower), world.lower, -math.pi)
        hi = np.where(np.isfinite(world.upper), world.upper, math.pi)
        qs = np.random.default_rng(0).uniform(lo, hi, size=(REACH_SAMPLES, len(lo)))
        far = np.linalg.norm(world.tool_poses(qs)[:, :3, 3] - base[:3, 3], axis=1).max()
        memo["reach"] = (base[:3, 3], 1.05 * float(far))
    return memo["reach"]


def vertical_overlap(z_a: float, half_a: float, z_b: float, half_b: float) -> bool:
    """Two upright bodies whose height ranges overlap by more than the rest tolerance."""
    return min(z_a + half_a, z_b + half_b) - max(z_a - half_a, z_b - half_b) > REST_TOLERANCE
