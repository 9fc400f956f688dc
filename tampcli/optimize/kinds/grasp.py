"""grasp: the object moves with the hand from here on.

A free motion ends at the grasp keyframe (the fingers may touch the object in
its last segment). The arm holds it in one of the grasp families the action
allows and the gripper can do on that shape (grasp_families.py: from the top,
from the side at a pitch); the planar robot by suction on its side (at a
contact angle, a grip parameter).
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize import constraints as C
from tampcli.optimize import grasp_families as F
from tampcli.optimize.bodies import TOUCH_TOLERANCE, pose_matrix
from tampcli.optimize.grips import touch_distance
from tampcli.optimize.hand import closing_depth
from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.skeleton import ImpossibleAction, LoweringError, Step
from tampcli.optimize.values import GripChoice


def _clear_contact_angle(walk, step, obj_pose, grip) -> float:
    """The planar robot's contact angle to start from: facing where the robot comes
    from, unless the robot there would stand in something (a wall beside the
    object, a neighbour in a pen); then the clear face middle nearest that
    direction (eight directions round a disk)."""
    toward = walk.angle(obj_pose[:2, 3] - walk.world.tool_pose(walk.q_prev)[:2, 3])
    checker = walk.problem.checker
    if checker is None:
        return toward
    half = getattr(grip, "half", None)
    spokes = 4 if half is not None else 8
    base = getattr(grip, "yaw", 0.0)
    candidates = [toward] + [base + j * 2 * math.pi / spokes for j in range(spokes)]
    others = {n: p for n, p in walk.poses.items() if n != step.obj}
    margin = walk.problem.options.tight_margin

    def score(phi):
        q = walk.planar_q(obj_pose[:3, 3], grip, phi)
        d = checker.min_distance(q, others, None, frozenset({step.obj}), static=False,
                                 horizon=margin)
        turn = abs((phi - toward + math.pi) % (2 * math.pi) - math.pi)
        return (d < margin, turn)

    return min(candidates, key=score)


class Grasp(ModeKind):
    """`families`: the grasp families (grasp_families.FAMILIES) a lowered step may
    use; the registered kind allows every one, a step's kind those its action
    allows that fit its object."""

    name = "grasp"
    required = ("object",)
    fingers = True
    takes_grasps = True  # modes.toml may restrict the families (`grasps = [...]`)

    def __init__(self, families: tuple[str, ...] = tuple(F.FAMILIES)):
        self.families = families

    def __eq__(self, other) -> bool:
        return type(other) is type(self) and other.families == self.families

    def __hash__(self) -> int:
        return hash((self.name, self.families))

    def lower(self, lo, index, op, mode):
        obj, _, _ = lo.roles(op, mode)
        label = op.name
        lo.movable(label, obj)
        if lo.held is not None:
            raise LoweringError(f"{label}: already holding {lo.held}")
        if lo.stacked_on(obj):
            raise LoweringError(f"{label}: {obj} is under another object")
        kind = self
        if not lo.planar:
            families, why = F.possible(getattr(mode, "grasps", None), lo.infos[obj],
                                       lo.gripper_opening)
            if not families:
                message = f"{label}: no grasp of {obj} fits ({'; '.join(why)})"
                if not lo.infos[obj].exact:  # its bounding box's width: no proof
                    raise LoweringError(message + " (as its bounding box)", proved=False)
                raise ImpossibleAction(message, op.action, obj)
            kind = Grasp(families)
        k = lo.motion(index, "free", None, None, {obj})
        lo.last_contact = frozenset({lo.support.get(obj)} - {None})
        step = Step(index, op.name, kind, obj, held_before=None, held_after=obj,
                    grasp_step=index, keyframes=(k,))
        lo.held, lo.held_grip = obj, index
        if lo.planar or any(F.FAMILIES[f].has_param for f in kind.families):
            lo.grip_params.append(index)
        lo.support[obj] = None
        return step

    def grip(self, problem, step, choice):
        body = problem.bodies[step.obj]
        closed = closing_depth(problem, F.closing_width(body, choice.psi or 0.0))
        return F.family_of(choice).grip(body, choice, problem.hand.depth,
                                        problem.options.margin, closed)

    def final_rows(self, walk, step):
        walk.state.pop(step.obj, None)

    def guess(self, walk, step):
        (k,) = step.keyframes
        obj_pose = walk.poses[step.obj]
        if walk.planar:
            walk.choices[step.index] = GripChoice(z=float(obj_pose[2, 3]),
                                                  yaw=transforms.yaw_of(obj_pose))
            grip = walk.grip_of(step)
            phi = _clear_contact_angle(walk, step, obj_pose, grip) + (
                walk.rng.normal(0.0, 4 * walk.jitter) if walk.jitter else 0.0)
            walk.grip[step.index] = float(phi)
            q = walk.planar_q(obj_pose[:3, 3], grip, phi)
        else:
            choice, t, q = _choose(walk, step, obj_pose)
            walk.choices[step.index] = choice
            if step.index in walk.problem.grip_params:
                walk.grip[step.index] = t
        walk.q[k] = q
        walk.q_prev = q

    def reseed(self, walk, step, k):
        pass

    def relax(self, builder, step):
        builder.grasp(step)

    def keyframe_rows(self, walk, step):
        (k,) = step.keyframes
        frame, _, t, t_block, H = walk.gripped(k, step.index)
        info = walk.problem.bodies[step.obj]
        C.same_pose(walk.rows.eq, walk.rows.ineq, step.name, H, walk.state[step.obj],
                    walk.planar, yaw=not info.disk and not walk.planar)
        if not walk.planar:
            F.family_of(walk.choices.get(step.index, GripChoice())).rows(
                walk.rows.ineq, step.name, t, t_block)
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
        # Or the point the fingertips close at, where they swing down as they close
        # (hand.closing_depth: the xArm6's hold a thin object with the tool origin
        # above its top).
        gain = max(closing_depth(problem, _across(info, obj, tool)) - problem.hand.depth, 0.0)
        half = np.array(info.half) + TOUCH_TOLERANCE
        if all(np.any(np.abs(obj[:3, :3].T @ (d + shift * tool[:3, 2])) > half)
               for shift in dict.fromkeys((0.0, gain))):
            return [f"{step.name}: the grasp point is outside {step.obj}"]
        families = step.kind.families
        if not any(F.FAMILIES[f].holds(tool, obj) for f in families):
            return [f"{step.name}: the gripper holds {step.obj} in no grasp family it may use "
                    f"({', '.join(families)})"]
        return []


def _across(info, obj: np.ndarray, tool: np.ndarray) -> float:
    """The object's width along the tool's y axis, the fingers' closing axis."""
    if info.disk:
        return 2 * info.half[0]
    axis = obj[:3, :3].T @ tool[:3, 1]
    return float(2 * np.abs(axis) @ np.array(info.half))


def _choose(walk, step, obj_pose) -> tuple[GripChoice, float, np.ndarray]:
    """The discrete grip of a grasp, its starting parameter and the IK keyframe.

    Every fitting grip of every family the step allows is tried by IK; the
    reachable ones first, then the least penetrating (so a hand that only fits
    under a shelf from the side is taken from the side), then the family's rank
    (a top grasp where it is clear: what the library's problems were built
    with), then the joint distance. A retry (jitter) also tries each grip at the
    place that ends the hold and ranks by reachability and penetration at both
    ends, then distance, so it may try another family, and fingers that would
    close into a neighbour at a tightly packed place close across the other
    pair of faces (blind3 p05). Not the first try: the keyframe NLP can slide a
    placement clear where its region has room, and the pick's own choice is then
    the cheaper one (arm-pick-place p04: 0.44 against 0.67). Families are tried
    in rank order and the search stops at the first that has a reachable, clear
    grip.
    """
    problem = walk.problem
    info = problem.bodies[step.obj]
    moved = {n: p for n, p in walk.poses.items() if n != step.obj}
    place = _place_of(walk, step) if walk.jitter else None
    best = None
    for rank, name in enumerate(step.kind.families):
        family = F.FAMILIES[name]
        # Each grip's IK target, then its place's (both turns), asked as one batch.
        grips, targets = [], []
        for choice, t in itertools.product(family.choices(info, problem.world.gripper_opening),
                                           family.starts):
            walk.choices[step.index] = choice
            grip = walk.grip_of(step)
            at_place = _place_targets(place, grip, t)
            grips.append((choice, t, len(at_place)))
            targets += [obj_pose @ transforms.pose_inverse(grip.matrix(t)), *at_place]
        answers = iter(walk.solve_ik_many(targets))
        found = []  # (choice, t, q, residual, [(q, residual) at the place, both turns])
        for choice, t, n_place in grips:
            q, res = next(answers)
            found.append((choice, t, q, res, [next(answers) for _ in range(n_place)]))
        # The family's clashes in one batched query: the grips, then their places.
        at_place = [q for *_, tries in found for q, _ in tries]
        beside = {place[0].obj, place[0].support} if place is not None else set()
        clashes = walk.clashes([q for _, _, q, _, _ in found] + at_place, moved,
                               [{step.obj}] * len(found) + [beside] * len(at_place))
        of_place = iter(clashes[len(found):])
        for (choice, t, q, res, tries), clash in zip(found, clashes, strict=False):
            far, clash_place = False, 0.0
            if tries:
                # The better turn at the place (the place's own choice, kinds/place.py).
                far, clash_place = min([(r > walk.IK_TOLERANCE, next(of_place))
                                        for _, r in tries])
            score = (res > walk.IK_TOLERANCE, far, round(clash + clash_place, 3),
                     0 if walk.jitter else rank, float(np.linalg.norm(q - walk.q_prev)))
            if best is None or score < best[0]:
                best = (score, choice, t, q)
        if best is not None and not any(best[0][:2]) and best[0][2] == 0.0 and not walk.jitter:
            break
    _, choice, t, q = best
    return choice, t, q


def _place_of(walk, step):
    """(the placing step that ends this hold, its placement) when the walk has it."""
    for later in walk.problem.steps[step.index + 1:]:
        if later.kind.places and later.grasp_step == step.index:
            p = walk.placements.get(later.index)
            return None if p is None else (later, p)
    return None


def _place_targets(place, grip, t: float) -> list:
    """The tool poses holding by `grip` at the placement, at its yaw and the half turn
    (the place's own choice, kinds/place.py); [] without a placement."""
    if place is None:
        return []
    later, p = place
    hold = transforms.pose_inverse(grip.matrix(t))
    return [pose_matrix(p.x, p.y, later.rest_z, p.yaw + turn) @ hold for turn in (0.0, math.pi)]
