"""move: a motion of its own, free or carrying what is held; the hand may have to
end above a region or a body (`to`).

Its keyframe only asks the tool to be over the target, so its guess is
revised backwards from the keyframe that follows (see `reseed`).
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.optimize import constraints as C
from tampcli.optimize.expr import Label, PoseX
from tampcli.optimize.kinds.base import ModeKind
from tampcli.optimize.layout import keyframe_block
from tampcli.optimize.skeleton import LoweringError, Step

MOVE_HOVER = 0.08  # m: a move's keyframe starts this far above its target
HELD_TILT = math.radians(3.0)  # rad: the most what is carried may lean where a move ends


def target_rect(problem, target, at=None):
    """(lo, hi) corners of a region, or of the rectangle inside a body's top face, the
    body's centre at `at` (x, y) when given (where the skeleton has moved it), else
    where the scene puts it."""
    for r in problem.scene.regions:
        if r.name == target:
            return np.asarray(r.lower), np.asarray(r.upper)
    c = np.asarray(problem.bodies[target].pose[:2] if at is None else at[:2], dtype=float)
    h = _half(problem, target)
    return c - h, c + h


def _half(problem, body) -> np.ndarray:
    """Half extents, along the world axes, of the rectangle a move over `body` ends in."""
    info = problem.bodies[body]
    return np.array(info.half[:2]) if not info.disk else np.array([info.half[0]] * 2) / np.sqrt(2)


def _moved_body(walk, target) -> bool:
    """Whether `target` is a movable body (the move aims where it stands by then)."""
    return target in walk.problem.bodies and not walk.problem.bodies[target].fixed


def _top_under(problem, target) -> float:
    body = next((r.on for r in problem.scene.regions if r.name == target), target)
    return problem.bodies[body].top


def _held_height(problem, step) -> float:
    return 2 * problem.bodies[step.held_before].half[2] if step.held_before else 0.0


class Move(ModeKind):
    name = "move"
    optional = ("to",)

    def lower(self, lo, index, op, mode):
        _, _, to = lo.roles(op, mode)
        if to is not None and to not in lo.regions and to not in lo.infos:
            raise LoweringError(f"{op.name}: the scene has no region or body {to!r}")
        k = lo.motion(index, "carry" if lo.held else "free", lo.held, lo.held_grip, set(),
                      own=True)
        lo.last_contact = frozenset()
        return Step(index, op.name, self, None, to, None, lo.held, lo.held, lo.held_grip, (k,))

    def grip(self, problem, step, choice):
        raise ValueError(f"{step.name}: a move holds by the grip of its grasp")

    def final_rows(self, walk, step):
        pass

    def guess(self, walk, step):
        (k,) = step.keyframes
        problem = walk.problem
        T = walk.world.tool_pose(walk.q_prev).copy()
        if step.target is not None:
            at = walk.poses[step.target][:3, 3] if step.target in walk.poses else None
            lo, hi = target_rect(problem, step.target, at)
            T[:2, 3] = 0.5 * (np.asarray(lo) + np.asarray(hi))
            if not walk.planar:
                # Above the target, with what is held clear of it (resting contact
                # has no useful distance gradient).
                T[2, 3] = max(T[2, 3], _top_under(problem, step.target)
                              + _held_height(problem, step) + MOVE_HOVER)
        q = T[:2, 3].copy() if walk.planar else walk.best_of([(T, None)])[0]
        walk.q[k] = np.clip(q, walk.world.lower, walk.world.upper)
        walk.q_prev = walk.q[k]

    def reseed(self, walk, step, k):
        """Re-seed the keyframe from the one after it, lifted clear above the target.

        The forward guess (the previous hand pose slid over the target) can sit
        in another IK branch than the grasp or place that follows, and the
        keyframe NLP then stays in a local optimum several times the cost
        (measured on arm-kitchen: 1.28 vs 0.41).
        """
        q_next = walk.q.get(k + 1)
        if step.target is None or q_next is None:
            return
        problem, world = walk.problem, walk.world
        t = world.tool_pose(q_next).copy()
        at = walk.poses[step.target][:3, 3] if step.target in walk.poses else None
        lo, hi = target_rect(problem, step.target, at)
        t[:2, 3] = np.clip(t[:2, 3], lo, hi)
        t[2, 3] = max(t[2, 3], _top_under(problem, step.target)
                      + _held_height(problem, step)) + MOVE_HOVER
        q, res = world.ik(t, seed=q_next, rng_seed=int(walk.rng.integers(1 << 30)))
        if res < walk.IK_TOLERANCE:
            walk.q[k] = np.clip(q, world.lower, world.upper)

    def keyframe_rows(self, walk, step):
        (k,) = step.keyframes
        frame = walk.tool_frames[k]
        if step.target is not None:
            n = walk.problem.n
            tool = PoseX(np.concatenate([frame.p, np.zeros(9)]),
                         {keyframe_block(k): np.vstack([frame.Jp, np.zeros((9, n))])})
            if _moved_body(walk, step.target) and step.target in walk.state:
                # Over the body where the skeleton has put it by then, a placement the
                # NLP may still slide (blind28 p03: a cup held over a bowl's start
                # spot, 26 cm from the bowl moved to the mat).
                body = walk.state[step.target]
                jac = dict(tool.jac)
                for block, J in body.jac.items():
                    jac[block] = jac.get(block, 0.0) - J
                rel = PoseX(tool.v - body.v, jac)
                h = _half(walk.problem, step.target)
                C.point_in_rect(walk.rows.ineq, step.name, rel, -h, h,
                                f"tool outside {step.target}")
            else:
                lo, hi = target_rect(walk.problem, step.target)
                C.point_in_rect(walk.rows.ineq, step.name, tool, lo, hi,
                                f"tool outside {step.target}")
            if not walk.planar:
                self._above(walk, step, k, tool)
        if walk.held is not None and not walk.planar:
            # What is carried stays nearly upright where a move ends: a pinch grip
            # tilted about its fingers lets the object swing back under gravity
            # (blind6 p04: held 9 deg over a scanner, 9 deg off in the physics replay).
            name, grip_step = walk.held
            H = walk.gripped(k, grip_step)[4]
            C.tilt_within(walk.rows.ineq, step.name, H, name, HELD_TILT)
        # What the planar robot carries slides on the surfaces at its bottom's height
        # (skeleton.motion's `sliding`): resting on them where the move ends too
        # (blind24 p05: a parcel carried to a checkpoint, refused at `parcel vs bench`).
        walk.collide(k, step, walk.held_now(), frame, set(walk.problem.motions[k].sliding))

    def _above(self, walk, step, k, tool) -> None:
        """Over its target, the hand (or what it carries) is above the face the target
        lies on: implied by the collision rows, and the one that keeps the `reach`
        relaxation (no collision rows) from sinking the hand into the table, a start
        the keyframe NLP took 30 SLSQP iterations to climb out of (arm-kitchen)."""
        problem = walk.problem
        floor = _top_under(problem, step.target) + problem.options.tight_margin
        if walk.held is not None:
            name, grip_step = walk.held
            low = walk.gripped(k, grip_step)[4]
            depth = problem.bodies[name].half[2]
        else:
            low, depth = tool, problem.hand.depth
        g = np.zeros((1, 12))
        g[0, 2] = 1.0
        walk.rows.ineq.add(np.array([low.pos[2] - depth - floor]), low.through(g),
                           Label(step.name, f"hand below the top of what {step.target} lies on"))

    def switch(self, walk, step):
        pass

    def phases(self, walk, step):
        pass

    def check(self, walk, step):
        return []
