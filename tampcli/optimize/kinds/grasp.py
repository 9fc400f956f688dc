"""grasp: the object moves with the hand from here on.

A free motion ends at the grasp keyframe (the fingers may touch the object in
its last segment); the arm holds it from the top (fingers along the tool's y
axis, at a fixed yaw offset chosen by the guess), the planar robot by
suction on its side (at a contact angle, a grip parameter).
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize import constraints as C
from tampcli.optimize.bodies import REST_TOLERANCE, TOUCH_TOLERANCE
from tampcli.optimize.grips import TopGrip, touch_distance
from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.skeleton import LoweringError, Step
from tampcli.optimize.values import GripChoice

PANDA_OPENING = 0.08  # m, fingers fully open
GRIPPER_SLACK = 0.005  # m: an object this much narrower than the opening fits between
PANDA_FINGER_DEPTH = 0.015  # m, at most this far below the object's top is the grasp point
PANDA_FINGERTIP = 0.01  # m, fingertips below the grasp target (collision mesh, measured)
MIN_DEPTH = 0.002  # m, the grasp point at least this far below the object's top


def fits_gripper(info, width: float) -> bool:
    """The Panda's fingers close on `width` (disks fit in every direction they fit at all)."""
    return info.disk or width <= PANDA_OPENING - GRIPPER_SLACK


class Grasp(ModeKind):
    name = "grasp"
    required = ("object",)
    fingers = True

    def lower(self, lo, index, op, mode):
        obj, _, _ = lo.roles(op, mode)
        label = op.name
        lo.movable(label, obj)
        if lo.held is not None:
            raise LoweringError(f"{label}: already holding {lo.held}")
        if lo.stacked_on(obj):
            raise LoweringError(f"{label}: {obj} is under another object")
        info = lo.infos[obj]
        if not lo.planar and not fits_gripper(info, 2 * min(info.half[:2])):
            raise LoweringError(f"{label}: {obj} is {200 * min(info.half[:2]):.1f} cm wide; "
                                f"the gripper opens {100 * PANDA_OPENING:.0f} cm")
        k = lo.motion(index, "free", None, None, {obj})
        lo.last_contact = frozenset({lo.support.get(obj)} - {None})
        step = Step(index, op.name, self, obj, held_before=None, held_after=obj,
                    grasp_step=index, keyframes=(k,))
        lo.held, lo.held_grip = obj, index
        if lo.planar:
            lo.grip_params.append(index)
        lo.support[obj] = None
        return step

    def grip(self, problem, step, choice):
        # Deep enough to hold, shallow enough that the fingertips stay clear of
        # whatever the object stands on (thin discs, trays with rims).
        info = problem.bodies[step.obj]
        clear = 2 * info.half[2] - PANDA_FINGERTIP - problem.options.margin - REST_TOLERANCE
        depth = float(np.clip(min(PANDA_FINGER_DEPTH, clear), MIN_DEPTH, info.half[2]))
        return TopGrip((0.0, 0.0, info.half[2] - depth),
                       psi=choice.psi if choice.psi is not None else 0.0)

    def final_rows(self, walk, step):
        walk.state.pop(step.obj, None)

    def guess(self, walk, step):
        (k,) = step.keyframes
        obj_pose = walk.poses[step.obj]
        if walk.planar:
            p_prev = walk.world.tool_pose(walk.q_prev)[:2, 3]
            phi = walk.angle(obj_pose[:2, 3] - p_prev) + (
                walk.rng.normal(0.0, 4 * walk.jitter) if walk.jitter else 0.0)
            walk.choices[step.index] = GripChoice(z=float(obj_pose[2, 3]),
                                                  yaw=transforms.yaw_of(obj_pose))
            grip = walk.grip_of(step)
            walk.grip[step.index] = float(phi)
            q = walk.planar_q(obj_pose[:3, 3], grip, phi)
        else:
            info = walk.problem.bodies[step.obj]
            targets = []
            for psi in walk.QUARTERS:
                # Fingers close along the tool's y axis: the object's width there.
                width = 2 * (info.half[1] if abs(math.cos(psi)) > 0.5 else info.half[0])
                if not fits_gripper(info, width):
                    continue
                walk.choices[step.index] = GripChoice(psi=psi)
                grip = walk.grip_of(step)
                targets.append((obj_pose @ transforms.pose_inverse(grip.matrix(0.0)), psi))
            q, psi = walk.best_of(targets, ignore={step.obj})
            walk.choices[step.index] = GripChoice(psi=psi)
        walk.q[k] = q
        walk.q_prev = q

    def reseed(self, walk, step, k):
        pass

    def keyframe_rows(self, walk, step):
        (k,) = step.keyframes
        frame, _, _, _, H = walk.gripped(k, step.index)
        info = walk.problem.bodies[step.obj]
        C.same_pose(walk.rows.eq, walk.rows.ineq, step.name, H, walk.state[step.obj],
                    walk.planar, yaw=not info.disk and not walk.planar)
        walk.collide(k, step, walk.held_now(), frame, {step.obj})
        walk.held = (step.obj, step.index)
        walk.state.pop(step.obj)

    def switch(self, walk, step):
        walk.grasp = transforms.pose_inverse(walk.tool()) @ walk.resting[step.obj]

    def phases(self, walk, step):
        g = transforms.pose_inverse(walk.tool()) @ walk.resting[step.obj]
        walk.attached = (step.obj, g)
        walk.grasps[step.obj] = g
        walk.instant(step)

    def check(self, walk, step):
        problem = walk.problem
        info = problem.bodies[step.obj]
        tool, obj = walk.tool_end(), walk.after(step.obj)
        d = tool[:3, 3] - obj[:3, 3]
        if problem.planar:
            a = math.atan2(d[1], d[0]) - transforms.yaw_of(obj)
            touch, _ = touch_distance(a, None if info.disk else tuple(info.half[:2]),
                                      problem.scene.robot.radius, info.half[0])
            reach = touch + TOUCH_TOLERANCE
            if math.hypot(d[0], d[1]) > reach:
                return [f"{step.name}: the robot does not touch {step.obj} "
                        f"({100 * (math.hypot(d[0], d[1]) - reach):.1f} cm away)"]
            return []
        local = obj[:3, :3].T @ d
        if np.any(np.abs(local) > np.array(info.half) + TOUCH_TOLERANCE):
            return [f"{step.name}: the grasp point is outside {step.obj}"]
        if tool[2, 2] > -0.99:
            return [f"{step.name}: the gripper does not point down"]
        return []
