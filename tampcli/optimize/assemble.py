"""Numeric walk over a solved skeleton: who holds what at each motion, and the output.

The object held from a grasp keeps the pose it had relative to the tool at
the grasp keyframe (computed from the numbers, so it does not jump when
picked up); it ends where the tool leaves it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize.bodies import pose_matrix
from tampcli.optimize.collide import Held
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.world_state import grip_of
from tampcli.solution import Phase


@dataclass(frozen=True)
class MotionContext:
    index: int
    q_a: np.ndarray
    q_b: np.ndarray
    held: Held | None  # the grip model (used by the path NLP)
    grasp: np.ndarray | None  # numeric object-in-tool pose while attached
    moved: dict  # name -> 4x4 for resting objects not at their start pose
    rest_z: float | None  # push: height of the pushed object


def walk(problem: TrajectoryProblem, kf: dict, choices: dict, start) -> list[MotionContext]:
    world = problem.world
    resting = {n: pose_matrix(*i.pose) for n, i in problem.bodies.items() if not i.fixed}
    moved: set[str] = set()
    grasp = None
    out: list[MotionContext] = []
    q_prev = np.asarray(start, dtype=float)

    def t_of(step_index, grip):
        return float(kf[f"g{step_index}"][0]) if grip.has_param else 0.0

    for step in problem.steps:
        if step.kind == "none":
            continue
        for k in step.keyframes:
            m = problem.motions[k]
            q = np.asarray(kf[f"k{k}"], dtype=float)
            if m.kind == "push":
                tool = world.tool_pose(q_prev)
                grasp = transforms.pose_inverse(tool) @ resting[step.obj]
            held = None
            if m.attached is not None:
                gstep = problem.steps[m.grip_step]
                grip = grip_of(problem, gstep, choices)
                held = Held(m.attached, grip, t_of(gstep.index, grip), None, grasp)
            out.append(MotionContext(k, q_prev, q, held,
                                     grasp if m.attached is not None else None,
                                     {n: resting[n] for n in moved},
                                     step.rest_z if m.kind == "push" else None))
            q_prev = q
        tool = world.tool_pose(q_prev)
        if step.kind == "grasp":
            grasp = transforms.pose_inverse(tool) @ resting[step.obj]
        elif step.kind in ("place", "push"):
            resting[step.obj] = tool @ grasp
            moved.add(step.obj)
            if step.kind == "place":
                grasp = None
    return out


def assemble(problem: TrajectoryProblem, start, waypoints: dict, contexts: list[MotionContext]):
    """(trajectory (N, n), phases, object poses per phase boundary, grasps used)."""
    world = problem.world
    T = problem.options.waypoints
    traj = [np.asarray(start, dtype=float)]
    ctx_of = {c.index: c for c in contexts}
    for k in range(problem.n_keyframes):
        traj.extend(waypoints[k])
        traj.append(ctx_of[k].q_b)
    traj = np.array(traj)
    resting = {n: pose_matrix(*i.pose) for n, i in problem.bodies.items() if not i.fixed}
    movable = list(resting)
    attached: tuple[str, np.ndarray] | None = None
    phases: list[Phase] = []
    poses = {n: [transforms.xyzquat_from_pose(resting[n])] for n in movable}
    grasps = {}
    idx = 0

    def boundary(at: int):
        for n in movable:
            if attached is not None and attached[0] == n:
                t = world.tool_pose(traj[at]) @ attached[1]
            else:
                t = resting[n]
            poses[n].append(transforms.xyzquat_from_pose(t))

    for step in problem.steps:
        if step.kind == "none":
            phases.append(Phase(step.name, idx, idx, attached[0] if attached else None))
            boundary(idx)
            continue
        for k in step.keyframes:
            c = ctx_of[k]
            m = problem.motions[k]
            if m.kind == "push":
                attached = (m.attached, c.grasp)
                grasps[m.attached] = c.grasp
                phases.append(Phase(step.name, idx, idx + T, m.attached))
            elif step.kind == "move":
                phases.append(Phase(step.name, idx, idx + T, m.attached))
            else:
                phases.append(Phase(None, idx, idx + T, m.attached))
            idx += T
            boundary(idx)
        tool = world.tool_pose(traj[idx])
        if step.kind == "grasp":
            g = transforms.pose_inverse(tool) @ resting[step.obj]
            attached = (step.obj, g)
            grasps[step.obj] = g
        elif step.kind in ("place", "push"):
            resting[step.obj] = tool @ attached[1]
            attached = None
        if step.kind in ("grasp", "place"):
            phases.append(Phase(step.name, idx, idx, attached[0] if attached else None))
            boundary(idx)
    return traj, tuple(phases), poses, grasps
