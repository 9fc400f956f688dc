"""place: the held object is released, resting on a region's body or on another body.

A carrying motion ends at the place keyframe (the object may touch its new
support in the last segment); where it rests is a block of the final NLP, and
in the keyframe NLP a function of the tool through the grip of its grasp.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize import constraints as C
from tampcli.optimize.bodies import REST_TOLERANCE, pose_matrix
from tampcli.optimize.collide import held_of
from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.skeleton import ImpossibleAction, LoweringError, Step
from tampcli.optimize.stability import OVERHANG, unstable


class Place(ModeKind):
    name = "place"
    required = ("object", "on")
    places = True
    fingers = False

    def lower(self, lo, index, op, mode):
        obj, target, _ = lo.roles(op, mode)
        label = op.name
        lo.movable(label, obj)
        if lo.held != obj:
            raise LoweringError(f"{label}: {obj} is not held"
                                + (f" (holding {lo.held})" if lo.held else ""))
        if target == obj:
            # A blocks-world `stack` lets a block onto itself (blind21 p05): refused with a
            # proof, every such ground action with it (bnb/lessons.py).
            raise ImpossibleAction(f"{label}: {obj} cannot be put on itself", op.action, obj,
                                   ("on", obj))
        if target in lo.regions:
            body = lo.regions[target].on
            lo.fits(label, op, obj, target, "on")
        elif target in lo.infos and target != obj:
            body = target
            if lo.holds_up(obj, target):
                raise LoweringError(f"{label}: {target} rests on {obj}")
            lo.fits_on(label, op, obj, target, OVERHANG)
        else:
            raise LoweringError(f"{label}: the scene has no region or body {target!r}")
        z = lo.rest_z[body] + lo.infos[body].half[2] + lo.infos[obj].half[2]
        if lo.planar and abs(z - lo.rest_z[obj]) > REST_TOLERANCE:
            raise LoweringError(f"{label}: the planar robot cannot lift {obj} onto {body} "
                                f"({100 * (z - lo.rest_z[obj]):+.1f} cm)")
        k = lo.motion(index, "carry", obj, lo.held_grip, {body})
        lo.last_contact = frozenset({obj})
        step = Step(index, op.name, self, obj, target, body, obj, None, lo.held_grip, (k,), z)
        lo.rest_z[obj] = z
        lo.support[obj] = body
        lo.held, lo.held_grip = None, None
        return step

    def grip(self, problem, step, choice):
        raise ValueError(f"{step.name}: a place holds by the grip of its grasp")

    def relax(self, builder, step):
        builder.place(step)

    def final_rows(self, walk, step):
        walk.place(step)

    def guess(self, walk, step):
        (k,) = step.keyframes
        p = walk.placements[step.index]
        x, y, yaw = p.x, p.y, p.yaw
        grasp = walk.problem.steps[step.grasp_step]
        grip = walk.grip_of(grasp)
        if walk.planar:
            q = self._planar_side(walk, step, grasp, grip, np.array([x, y, step.rest_z]))
            P = pose_matrix(x, y, step.rest_z, yaw)
        else:
            held = grip.matrix(walk.grip.get(grasp.index, 0.0))
            hold = transforms.pose_inverse(held)
            # A quarter turn changes an oblong footprint: only the placement's
            # own yaw and its half turn keep the final NLP's answer.
            info = walk.problem.bodies[step.obj]
            square = info.disk or abs(info.half[0] - info.half[1]) < REST_TOLERANCE
            targets = [(pose_matrix(x, y, step.rest_z, yaw + d) @ hold, yaw + d)
                       for d in (walk.QUARTERS if square else walk.QUARTERS[::2])]
            q, yaw_ = walk.best_of(targets, (step.obj, held), {step.support})
            P = pose_matrix(x, y, step.rest_z, yaw_)
        walk.poses[step.obj] = P
        walk.q[k] = q
        walk.q_prev = q

    @staticmethod
    def _planar_side(walk, step, grasp, grip, at: np.ndarray) -> np.ndarray:
        """The planar robot's configuration at the place; it may move the contact side
        its grasp chose.

        The grasp takes the side facing the robot's approach, which can leave the
        disk on the side of the placement that a neighbour occupies (measured: the
        second of two blocks put side by side in a walled bay, the disk between the
        two). When the disk at the place would touch something, every face of the
        object is tried for the contact, clear at the grasp first, then clear at the
        place, then nearest the grasp's choice; the grasp's keyframe follows.
        """
        phi0 = walk.grip[grasp.index]
        problem = walk.problem
        if problem.checker is None:
            return walk.planar_q(at, grip, phi0)
        start = walk.poses[step.obj]
        others = {n: t for n, t in walk.poses.items() if n != step.obj}
        horizon = problem.options.margin

        def clash(phi):
            q_place = walk.planar_q(at, grip, phi)
            q_pick = walk.planar_q(start[:3, 3], grip, phi)
            # The robot alone: where the held object ends does not depend on phi.
            place = problem.checker.min_distance(
                q_place, others, None, frozenset({step.support}), static=False,
                horizon=horizon)
            pick = problem.checker.min_distance(
                q_pick, others, None, frozenset({step.obj}), static=False,
                horizon=horizon)
            if walk.graded:
                # The keyframe stage's last try: how deep within the margin, to the
                # millimetre. Near walls every face may be within it, and the one 4 mm
                # in beats one 4 cm into a neighbour (blind27 p05: a box into a walled
                # pocket beside a slab). Not on the first tries: graded there, blind18
                # p04's corridor lost its answer.
                return (round(max(0.0, horizon - pick), 3), round(max(0.0, horizon - place), 3),
                        abs(math.remainder(phi - phi0, 2 * math.pi)))
            # Clear at the grasp first: the grasp's object stands where it stands, while
            # the keyframe NLP can still slide the placement within its region (pen-k4:
            # the top face, clear at the yard, put the disk into the rail at the pen).
            return pick < horizon, place < horizon, abs(math.remainder(phi - phi0, 2 * math.pi))

        best = min([phi0] + [transforms.yaw_of(start) + d for d in walk.QUARTERS], key=clash)
        if best != phi0:
            walk.grip[grasp.index] = float(best)
            (kg,) = grasp.keyframes
            walk.q[kg] = walk.planar_q(start[:3, 3], grip, best)
        return walk.planar_q(at, grip, best)

    def reseed(self, walk, step, k):
        pass

    def keyframe_rows(self, walk, step):
        (k,) = step.keyframes
        frame, grip, t, t_block, H = walk.gripped(k, step.grasp_step)
        if not walk.planar:
            C.upright(walk.rows.eq, step.name, H, step.obj)
            C.rest_height(walk.rows.eq, step.name, H, step.rest_z, step.support)
        walk.placement_rows(step, H)
        walk.collide(k, step, held_of(step.obj, grip, t, t_block), frame, {step.support})
        walk.state[step.obj] = H
        walk.heights[step.obj] = step.rest_z
        walk.held = None

    def switch(self, walk, step):
        walk.release(step.obj)
        walk.grasp = None

    def phases(self, walk, step):
        walk.release(step.obj)
        walk.instant(step)

    def check(self, walk, step):
        poses = {n: walk.after(n) if n in walk.poses else pose_matrix(*i.pose)
                 for n, i in walk.problem.bodies.items()}
        return walk.rest(step) + unstable(walk.problem, step, poses)
