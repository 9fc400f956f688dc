"""Numeric walk over a solved skeleton: who holds what at each motion, and the output.

The object held from a grasp keeps the pose it had relative to the tool at
the grasp keyframe (computed from the numbers, so it does not jump when
picked up); it ends where the tool leaves it. Each step's kind says what its
mode switch does (kinds/*.py: switch, phases).
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


class MotionWalk:
    """Where every object rests and how the attached one hangs, keyframe by keyframe."""

    def __init__(self, problem: TrajectoryProblem, start):
        self.world = problem.world
        self.resting = {n: pose_matrix(*i.pose) for n, i in problem.bodies.items()
                        if not i.fixed}
        self.moved: set[str] = set()
        self.grasp = None
        self.q_prev = np.asarray(start, dtype=float)

    def tool(self) -> np.ndarray:
        return self.world.tool_pose(self.q_prev)

    def release(self, obj: str) -> None:
        """obj rests where the tool leaves it."""
        self.resting[obj] = self.tool() @ self.grasp
        self.moved.add(obj)


def walk(problem: TrajectoryProblem, keyframes, choices, start) -> list[MotionContext]:
    """`keyframes`: values.Keyframes; `choices`: step index -> values.GripChoice."""
    w = MotionWalk(problem, start)
    out: list[MotionContext] = []
    for step in problem.steps:
        for k in step.keyframes:
            m = problem.motions[k]
            q = np.asarray(keyframes.q[k], dtype=float)
            if m.pushes:
                w.grasp = transforms.pose_inverse(w.tool()) @ w.resting[step.obj]
            held = None
            if m.attached is not None:
                gstep = problem.steps[m.grip_step]
                grip = grip_of(problem, gstep, choices)
                t = keyframes.grip[gstep.index] if grip.has_param else 0.0
                held = Held(m.attached, grip, t, None, w.grasp)
            out.append(MotionContext(k, w.q_prev, q, held,
                                     w.grasp if m.attached is not None else None,
                                     {n: w.resting[n] for n in w.moved},
                                     step.rest_z if m.pushes else None))
            w.q_prev = q
        step.kind.switch(w, step)
    return out


class PhaseWalk:
    """The trajectory's phases and the objects' poses at their boundaries, as they build."""

    def __init__(self, problem: TrajectoryProblem, traj: np.ndarray):
        self.world = problem.world
        self.traj = traj
        self.resting = {n: pose_matrix(*i.pose) for n, i in problem.bodies.items()
                        if not i.fixed}
        self.attached: tuple[str, np.ndarray] | None = None
        self.phases: list[Phase] = []
        self.poses = {n: [transforms.xyzquat_from_pose(t)] for n, t in self.resting.items()}
        self.grasps = {}
        self.idx = 0
        self.events: list[tuple[int, object]] = []  # (waypoint where a step ends, step)

    def tool(self) -> np.ndarray:
        return self.world.tool_pose(self.traj[self.idx])

    def boundary(self) -> None:
        for n in self.poses:
            if self.attached is not None and self.attached[0] == n:
                t = self.world.tool_pose(self.traj[self.idx]) @ self.attached[1]
            else:
                t = self.resting[n]
            self.poses[n].append(transforms.xyzquat_from_pose(t))

    def instant(self, step) -> None:
        """The step as a phase of no duration (a mode switch, a symbolic action)."""
        self.phases.append(Phase(step.name, self.idx, self.idx,
                                 self.attached[0] if self.attached else None))
        self.boundary()

    def release(self, obj: str) -> None:
        self.resting[obj] = self.tool() @ self.attached[1]
        self.attached = None


def assemble(problem: TrajectoryProblem, start, waypoints: dict, contexts: list[MotionContext]):
    """(trajectory (N, n), phases, object poses per phase boundary, grasps used,
    (waypoint where each step ends, step) in order).
    `waypoints[k]`: motion k's interior waypoints (T_k - 1, n), its T_k segments its own."""
    traj = [np.asarray(start, dtype=float)]
    ctx_of = {c.index: c for c in contexts}
    for k in range(problem.n_keyframes):
        traj.extend(waypoints[k])
        traj.append(ctx_of[k].q_b)
    w = PhaseWalk(problem, np.array(traj))
    for step in problem.steps:
        for k in step.keyframes:
            c = ctx_of[k]
            m = problem.motions[k]
            if m.pushes:
                w.attached = (m.attached, c.grasp)
                w.grasps[m.attached] = c.grasp
            T = len(waypoints[k]) + 1
            w.phases.append(Phase(step.name if m.own else None, w.idx, w.idx + T, m.attached))
            w.idx += T
            w.boundary()
        step.kind.phases(w, step)
        w.events.append((w.idx, step))
    return w.traj, tuple(w.phases), w.poses, w.grasps, w.events
