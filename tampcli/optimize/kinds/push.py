"""push: the tool slides the object along its support into a region.

Two motion phases: a free approach ending against the object, then the
pushing motion itself (the object moves with the tool, upright at its resting
height, allowed to touch its support). The arm pushes with its finger side at
a yaw offset, the planar robot with its rim at a contact angle: either way one
grip parameter of the keyframe NLP.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize import constraints as C
from tampcli.optimize.bodies import TOUCH_TOLERANCE, pose_matrix
from tampcli.optimize.collide import held_of
from tampcli.optimize.grips import YawGrip
from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.skeleton import LoweringError, Step
from tampcli.optimize.values import GripChoice

PUSH_STANDOFF = 0.012  # m, tool origin to the pushed face (finger half thickness)


class Push(ModeKind):
    name = "push"
    required = ("object", "to")
    places = True
    holds = False

    def lower(self, lo, index, op, mode):
        obj, _, to = lo.roles(op, mode)
        label = op.name
        lo.movable(label, obj)
        if lo.held is not None:
            raise LoweringError(f"{label}: cannot push while holding {lo.held}")
        if to is None or to not in lo.regions:
            raise LoweringError(f"{label}: the scene has no region {to!r}")
        below = lo.support.get(obj)
        if below is None or below != lo.regions[to].on:
            raise LoweringError(f"{label}: {obj} rests on {below}, region {to} is on "
                                f"{lo.regions[to].on}: a push slides on one support")
        if lo.stacked_on(obj):
            raise LoweringError(f"{label}: {obj} is under another object")
        k0 = lo.motion(index, "free", None, None, {obj})
        lo.last_contact = frozenset({below})
        k1 = lo.motion(index, "push", obj, index, set(), {below}, own=True, pushes=True)
        lo.last_contact = frozenset({obj})
        lo.grip_params.append(index)
        return Step(index, op.name, self, obj, to, below, None, None, index, (k0, k1),
                    lo.rest_z[obj])

    def grip(self, problem, step, choice):
        info = problem.bodies[step.obj]
        rho = max(info.half[0], info.half[1]) + PUSH_STANDOFF
        return YawGrip((-rho, 0.0, 0.0))

    def final_rows(self, walk, step):
        walk.place(step)

    def guess(self, walk, step):
        k0, k1 = step.keyframes
        obj_pose = walk.poses[step.obj]
        p = walk.placements[step.index]
        x, y = p.x, p.y
        u = np.array([x, y]) - obj_pose[:2, 3]
        u = u / np.linalg.norm(u) if np.linalg.norm(u) > 1e-9 else np.array([1.0, 0.0])
        grip = walk.grip_of(step)
        if walk.planar:
            phi = walk.angle(u)
            walk.grip[step.index] = phi
            walk.choices[step.index] = GripChoice(z=float(obj_pose[2, 3]),
                                                  yaw=transforms.yaw_of(obj_pose))
            grip = walk.grip_of(step)
            q0 = walk.planar_q(obj_pose[:3, 3], grip, phi)
            q1 = walk.planar_q(np.array([x, y, obj_pose[2, 3]]), grip, phi)
            yaw = transforms.yaw_of(obj_pose)
        else:
            alpha = walk.angle(-u)
            psi = transforms.yaw_of(obj_pose) - alpha
            walk.grip[step.index] = psi
            G = transforms.pose_inverse(grip.matrix(psi))
            q0, _ = walk.best_of([(obj_pose @ G, None)])
            walk.q_prev = q0
            yaw = alpha + psi
            q1, _ = walk.best_of([(pose_matrix(x, y, obj_pose[2, 3], yaw) @ G, None)])
        walk.q[k0], walk.q[k1] = q0, q1
        walk.poses[step.obj] = pose_matrix(x, y, obj_pose[2, 3], yaw)
        walk.q_prev = q1

    def reseed(self, walk, step, k):
        pass

    def keyframe_rows(self, walk, step):
        k0, k1 = step.keyframes
        frame, grip, t, t_block, H0 = walk.gripped(k0, step.index)
        info = walk.problem.bodies[step.obj]
        C.same_pose(walk.rows.eq, walk.rows.ineq, step.name, H0, walk.state[step.obj],
                    walk.planar, yaw=not info.disk and not walk.planar)
        walk.collide(k0, step, None, frame, {step.obj})
        frame, grip, t, t_block, H1 = walk.gripped(k1, step.index)
        if not walk.planar:
            C.upright(walk.rows.eq, step.name, H1, step.obj)
            C.rest_height(walk.rows.eq, step.name, H1, step.rest_z, step.support)
        walk.state.pop(step.obj)
        walk.placement_rows(step, H1)
        walk.collide(k1, step, held_of(step.obj, grip, t, t_block), frame, {step.support})
        walk.state[step.obj] = H1

    def switch(self, walk, step):
        walk.release(step.obj)

    def phases(self, walk, step):
        walk.release(step.obj)

    def check(self, walk, step):
        return self._starts_against(walk, step) + walk.rest(step)

    @staticmethod
    def _starts_against(walk, step) -> list[str]:
        """The pusher starts against the object: within its half extent plus the pusher."""
        problem = walk.problem
        info = problem.bodies[step.obj]
        tool, obj = walk.tool_start(), walk.before(step.obj)
        d = tool[:3, 3] - obj[:3, 3]
        reach = max(info.half[0], info.half[1]) + TOUCH_TOLERANCE
        reach += problem.scene.robot.radius if problem.planar else PUSH_STANDOFF
        gap = math.hypot(d[0], d[1]) - reach
        if gap > 0:
            return [f"{step.name}: the push starts {100 * gap:.1f} cm away from {step.obj}"]
        if not problem.planar and abs(d[2]) > info.half[2]:
            return [f"{step.name}: the push starts above or below {step.obj}"]
        return []
