"""push: the tool slides the object along its support into a region, pushing one
of its side faces (the contact model and the push rule: push_contact.py).

Two motion phases: a free approach ending against the chosen face, then the
pushing motion itself (the object moves with the tool, upright at its resting
height, without turning, and only into the face: within the friction cone).
The face is a discrete choice of the initial guess (the faces best aligned
with the displacement first; for the arm the contact reachable and in
nothing at both ends of the push); the contact point's offset along the face
is the step's grip parameter. The planar disk touches the face with its rim;
the arm with the side of its open fingers, the hand pointing down, or with
its fingertips, the hand level (which passes under a low ceiling).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize import constraints as C
from tampcli.optimize.bodies import TOUCH_TOLERANCE, pose_matrix
from tampcli.optimize.collide import held_of
from tampcli.optimize.grips import held_pose
from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.kinds.push_check import check_push, touch_at
from tampcli.optimize.kinds.push_contact import (
    BOX_FACES,
    CONTACT_GAP,
    PUSH_FRICTION,
    arm_face_grip,
    candidate_faces,
    cone_rows,
    cross_face_grip,
    face_of,
    finger_shift,
    level_face_grip,
    level_lift,
    offset_rows,
    path_rows,
    planar_face_grip,
    pushing_fingers,
    same_yaw,
)
from tampcli.optimize.layout import grip_block, waypoint_block
from tampcli.optimize.skeleton import LoweringError, Step
from tampcli.optimize.values import GripChoice

MEASURE_LIMIT = 0.01  # m: one measurement corrects the reach by at most this ...
MEASURE_TOTAL = 0.04  # m: ... and all of them together by at most this
MEASURE_ROUNDS = 5  # measurements of the touch, each after IK at the corrected reach
MEASURE_TOLERANCE = 1e-3  # m: a touch this close to CONTACT_GAP needs no correction
SWEEP_SAMPLES = 3  # poses between a push's ends where a contact's hand is judged too


def _clear_at_both_ends(walk, step, obj_pose, end, choices):
    """(start keyframe, choice) of the contact whose hand is reachable, and least deep
    in anything where the push starts, on its way (SWEEP_SAMPLES points) and where it
    ends (then the nearest): a top-down hand clear at the start can end in a low roof
    the object is pushed under (a level hand passes); a crosswise hand's back finger,
    clear at both ends, can cross a kerb on the way (blind21 p06)."""
    problem = walk.problem
    checker = problem.checker
    q_prev, best = walk.q_prev, None
    for c in choices:
        G = transforms.pose_inverse(face_grip(problem, step, c).matrix(0.0))
        walk.q_prev = q_prev
        unreachable, depth, first = False, 0.0, None
        way = [obj_pose.copy() for _ in range(SWEEP_SAMPLES)]
        for k, pose in enumerate(way, start=1):
            pose[:3, 3] += (end[:3, 3] - obj_pose[:3, 3]) * k / (SWEEP_SAMPLES + 1)
        for pose in (obj_pose, *way, end):
            q, res = walk.solve_ik(pose @ G)
            walk.q_prev = q
            first = q if first is None else first
            unreachable |= res > walk.IK_TOLERANCE
            if checker is not None:
                poses = {**walk.poses, step.obj: pose}
                # How deep in something, to the millimetre: the IK solution of a level
                # hand hugs the table by a fraction of one (the NLP moves it off).
                d = checker.min_distance(q, poses, None, frozenset({step.obj}),
                                         static=False, horizon=0.0)
                depth += max(0.0, -d)
        score = (unreachable, round(depth, 3), c.crosswise,
                 float(np.linalg.norm(first - q_prev)))
        if best is None or score < best[0]:
            best = (score, first, c)
    walk.q_prev = q_prev
    return best[1], best[2]


def _measured_touch(walk, step, obj_pose, choice, q0):
    """The start keyframe with the contact's reach measured on the arm's own collision
    shapes (the fingers' extent behind the tool origin is the arm's), corrected and
    measured again until the touch is CONTACT_GAP: a flat face needs one round; a
    drum between the open fingers touches their inner edges, 2.4 cm nearer than
    their outer sides' tangent plane (blind3 p08: 9 cm across). One finger alone on a
    drum is also moved along the face until it touches on the line of the push: a
    finger's rounded or tapered side meets a drum off its middle (blind14 p08: 1.1
    cm aside, so the can went off 27 degrees)."""
    problem = walk.problem
    info = problem.bodies[step.obj]
    nominal = face_grip(problem, step, choice).reach
    reach = nominal
    lateral = info.disk and choice.finger != 0
    tangent = face_of(info, choice.face).tangent
    shift = start = finger_shift(choice.finger, problem.world.finger_span)
    for _ in range(MEASURE_ROUNDS):
        gap, point = touch_at(problem, step.obj, obj_pose, q0)
        gap -= CONTACT_GAP
        aside = 0.0
        if lateral and point is not None:
            aside = float((transforms.pose_inverse(obj_pose) @ np.append(point, 1.0))[:3]
                          @ tangent)
        if abs(gap) <= MEASURE_TOLERANCE and abs(aside) <= MEASURE_TOLERANCE:
            break
        reach = float(np.clip(reach - np.clip(gap, -MEASURE_LIMIT, MEASURE_LIMIT),
                              nominal - MEASURE_TOTAL, nominal + MEASURE_TOTAL))
        shift = float(np.clip(shift + np.clip(aside, -MEASURE_LIMIT, MEASURE_LIMIT),
                              start - MEASURE_TOTAL, start + MEASURE_TOTAL))
        choice = dataclasses.replace(choice, reach=reach, shift=shift if lateral else None)
        walk.choices[step.index] = choice
        walk.q_prev = q0
        q0, _ = walk.best_of([(obj_pose @ transforms.pose_inverse(
            walk.grip_of(step).matrix(0.0)), None)])
    walk.choices[step.index] = dataclasses.replace(choice, reach=reach)
    return q0


def _half_width(info, angle: float) -> float:
    """Half the width a pusher meets on the face at `angle`: a drum's radius."""
    return info.half[0] if info.disk else face_of(info, angle).width


def face_grip(problem, step, choice):
    """The grip of a push whose face is `choice.face` (planar: at choice.z, choice.yaw)."""
    info = problem.bodies[step.obj]
    face = face_of(info, choice.face if choice.face is not None else 0.0)
    if problem.planar:
        robot = problem.scene.robot
        z = choice.z if choice.z is not None else info.pose[2]
        yaw = choice.yaw if choice.yaw is not None else info.pose[3]
        return planar_face_grip(face, yaw, z - float(robot.base_pose[2, 3]), robot.radius)
    if choice.crosswise:
        span = problem.world.finger_span
        reach = choice.reach if choice.reach is not None else \
            face.depth + (span[1] if span else 0.0) + CONTACT_GAP
        return cross_face_grip(face, reach)
    shift = choice.shift if choice.shift is not None else finger_shift(
        choice.finger, problem.world.finger_span)
    if choice.level:
        lift = level_lift(info)
        if lift is None:
            raise ValueError(f"{step.name}: {step.obj} is too low for a level hand")
        return level_face_grip(face, lift, choice.reach,
                               problem.hand.depth, shift)
    return arm_face_grip(face, choice.reach, shift)


class Push(ModeKind):
    name = "push"
    required = ("object", "to")
    places = True
    holds = False
    planar_grip = True
    within_cone = True

    def lower(self, lo, index, op, mode):
        obj, _, to = lo.roles(op, mode)
        label = op.name
        lo.movable(label, obj)
        if lo.held is not None:
            raise LoweringError(f"{label}: cannot push while holding {lo.held}")
        if to is None or to not in lo.regions:
            raise LoweringError(f"{label}: the scene has no region {to!r}")
        lo.fits(label, op, obj, to, "to")
        below = lo.support.get(obj)
        if below is None or below != lo.regions[to].on:
            raise LoweringError(f"{label}: {obj} rests on {below}, region {to} is on "
                                f"{lo.regions[to].on}: a push slides on one support")
        if lo.stacked_on(obj):
            raise LoweringError(f"{label}: {obj} is under another object")
        # The pusher only touches the face (it stops CONTACT_GAP short). The object is
        # a contact the approach enters and the retreat leaves, as a grasped and a
        # placed one are: the margin from it but in the last (first) segment, where
        # the path is never nearer than at the keyframe (path.MotionMargins). As a
        # mere body near the keyframe it would be held only `tight_margin` clear the
        # whole way (robust-arm p09: 1 mm over five samples, 0.8 mm into its edge
        # between two; the replay's fingers struck it a segment before the touch).
        k0 = lo.motion(index, "free", None, None, {obj})
        lo.last_contact = frozenset({below})
        k1 = lo.motion(index, "push", obj, index, set(), {below}, own=True, pushes=True)
        lo.last_contact = frozenset({obj})
        lo.grip_params.append(index)
        return Step(index, op.name, self, obj, to, below, None, None, index, (k0, k1),
                    lo.rest_z[obj])

    def grip(self, problem, step, choice):
        return face_grip(problem, step, choice)

    def final_rows(self, walk, step):
        # The placement keeps the yaw the object has: a push does not turn it.
        before = walk.state[step.obj]
        walk.place(step)
        same_yaw(walk.rows.eq, step.name, before, walk.state[step.obj])

    def guess(self, walk, step):
        k0, k1 = step.keyframes
        problem = walk.problem
        info = problem.bodies[step.obj]
        obj_pose = walk.poses[step.obj]
        p = walk.placements[step.index]
        yaw = transforms.yaw_of(obj_pose)
        z = float(obj_pose[2, 3])
        u = obj_pose[:3, :3].T @ np.array([p.x - obj_pose[0, 3], p.y - obj_pose[1, 3], 0.0])
        if np.linalg.norm(u) < 1e-9:
            u = np.array([1.0, 0.0, 0.0])
        faces = candidate_faces(info, u / np.linalg.norm(u))
        end = pose_matrix(p.x, p.y, z, yaw)
        if walk.planar:
            face = faces[0]
            walk.choices[step.index] = GripChoice(z=z, yaw=yaw, face=face)
            grip = walk.grip_of(step)
            q0 = walk.planar_q(obj_pose[:3, 3], grip, 0.0)
            q1 = walk.planar_q(end[:3, 3], grip, 0.0)
        else:
            # Faces the push can go into first (the motion within their cone).
            cone = math.cos(math.atan(PUSH_FRICTION))
            aligned = [a for a in faces if math.cos(a) * u[0] + math.sin(a) * u[1]
                       >= cone * np.linalg.norm(u)] or faces[:1]
            # The hand down (its fingers' side on the face) first; level (its
            # fingertips on the face) where the object is tall enough for it.
            levels = (False, True) if level_lift(info) is not None else (False,)
            span = problem.world.finger_span
            fingers = {a: pushing_fingers(_half_width(info, a), span) for a in aligned}
            choices = [GripChoice(face=a, level=level, finger=finger)
                       for level in levels for a in aligned for finger in fingers[a]]
            # A face too narrow for both fingers may be pushed by the front finger, the
            # other behind it, the hand no wider than a finger across the face: the
            # one finger's twin stands beside the object, in a neighbour of a row
            # (blind23 p03: the middle of three cans 1.5 cm apart). Ranked after the
            # others where both are as clear: first by joint distance, it was 4 times
            # cheaper on that can (0.32 against 1.22) but ended 2 mm inside blind14
            # p08's can on its approach, and lost blind21 p06's cube to its kerb.
            choices += [GripChoice(face=a, crosswise=True) for a in aligned
                        if fingers[a] != (0,)]
            q0, choice = _clear_at_both_ends(walk, step, obj_pose, end, choices)
            q0 = _measured_touch(walk, step, obj_pose, choice, q0)
            G = transforms.pose_inverse(walk.grip_of(step).matrix(0.0))
            walk.q_prev = q0
            q1, _ = walk.best_of([(end @ G, None)])
        walk.grip[step.index] = 0.0
        walk.q[k0], walk.q[k1] = q0, q1
        walk.poses[step.obj] = end
        walk.q_prev = q1

    def reseed(self, walk, step, k):
        pass

    def relax(self, builder, step):
        builder.push(step)

    def relax_faces(self, problem, step):
        # A disk has a face in every direction: its pushes are relaxed without a cone.
        return () if problem.bodies[step.obj].disk else BOX_FACES

    def keyframe_rows(self, walk, step):
        k0, k1 = step.keyframes
        info = walk.problem.bodies[step.obj]
        frame, grip, t, t_block, H0 = walk.gripped(k0, step.index)
        C.same_pose(walk.rows.eq, walk.rows.ineq, step.name, H0, walk.state[step.obj],
                    walk.planar, yaw=not info.disk and not walk.planar)
        face = face_of(info, walk.choices[step.index].face)
        offset_rows(walk.rows.ineq, step.name, t, grip_block(step.index), face)
        walk.collide(k0, step, None, frame, {step.obj})
        frame, grip, t, t_block, H1 = walk.gripped(k1, step.index)
        if not walk.planar:
            C.upright(walk.rows.eq, step.name, H1, step.obj)
            C.rest_height(walk.rows.eq, step.name, H1, step.rest_z, step.support)
            if not info.disk:  # a cylinder's or sphere's yaw changes nothing
                same_yaw(walk.rows.eq, step.name, H0, H1)
        cone_rows(walk.rows.ineq, step.name, H0, H1, face.angle)
        walk.state.pop(step.obj)
        walk.placement_rows(step, H1)
        walk.collide(k1, step, held_of(step.obj, grip, t, t_block), frame, {step.support})
        walk.state[step.obj] = H1

    def path_rows(self, rows, label, problem, qs, held, kin) -> None:
        """Rows (stages.Rows) of the path NLP for the pushing motion through
        configurations qs (T + 1 of them, the fixed keyframes at both ends): the push
        rule at every step (push_contact.path_rows). `held`: collide.Held, the object
        on its FaceGrip; `kin`: grips.Kinematics. For path.py's phase_rows_fn."""
        T = len(qs) - 1
        poses = [held_pose(kin.frame(q), held.grip, held.t) for q in qs]
        blocks = [waypoint_block(i) if 0 < i < T else None for i in range(T + 1)]
        path_rows(rows.ineq, rows.eq, label, poses, blocks, held.grip, problem.planar,
                  turns=problem.bodies[held.name].disk)

    def switch(self, walk, step):
        walk.release(step.obj)

    def phases(self, walk, step):
        walk.release(step.obj)

    def check(self, walk, step):
        return check_push(walk, step, TOUCH_TOLERANCE) + walk.rest(step)
