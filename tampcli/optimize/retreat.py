"""The empty hand's straight ends at a grasp or a place: it comes in to a grasp, and
backs off after letting go, along the tool's approach axis (its z), until its fingers
are the margin clear of the object.

Without them, the path NLP's free motion may turn towards its next keyframe at once,
its fingers sweeping sideways past the object they straddled, as close as the
motion's margins allow there (half the keyframe's distance: millimetres with a hand
narrowed to the grip). On a real arm, or in the physics replay (`validate
--physics`, whose joint tracking is off by about 0.01 rad: 4 to 7 mm at the tool),
that sweep knocks over what was just set down: blind31 p06's cube, left on an 11 cm
tower with a finger 6 mm from it, was swept off. Backing straight off first, a finger
that grazes the object slides along its face instead of pushing it over.

The ends are rungs `approach.RUNG` apart along the axis, each an IK solution seeded
by the one before, each (and `approach.CHECKS` points between two) no nearer to
anything than at the keyframe, less `approach.SLACK`, nor than the tight margin; the
NLP solves the motion between the outer rungs. Where IK or a collision stops them
before the fingers are clear, the rungs found so far are kept (a shorter straight
end is still straight); where the first rung fails, there is none (the NLP's own
path, as before). For an arm only (the planar robot has no fingers to straddle
with), only where the fingers close on the object (a grasp) or have just let go of
it (a place) (a push's tool comes to a face sideways, not along its axis), and only
where the object rests on another movable one (a stack), as a carry's straight ends
(approach.py): what a finger's graze topples, the one class the physics replay
has caught. (Tried on every grasp and place, the ends changed the library's arm
answers by 0.1 % at most, and arm-sort's complete search took 16.4 s against
16.3 s back to back: an open hand is mostly the margin clear of what it grasps
already. Not kept for want of a case that needs it.)
"""

from __future__ import annotations

import numpy as np

from tampcli.optimize.approach import (
    RUNG,
    SLACK,
    Approach,
    axis_rungs,
    lift,
    place_approach,
    stacked,
)
from tampcli.optimize.planar_approach import straight

REACH = 0.10  # m: the longest straight end along the axis


def straight_ends(problem, m, ctx, checker) -> tuple[Approach | None, Approach | None]:
    """(climb, descent): the straight ends motion m (its context `ctx`) starts and ends
    with, each None where it has none: a carry's vertical ones (approach.py), the
    planar disk's in the plane (planar_approach.py), else the empty hand's here."""
    climb = lift(problem, m, ctx.q_a, ctx.held, ctx.moved, checker) or straight(
        problem, m, ctx.q_a, ctx.q_b, ctx.held, ctx.moved, checker, m.leave_contact) \
        or departure(problem, m, ctx.q_a, ctx.moved, checker)
    descent = place_approach(problem, m, ctx.q_b, ctx.held, ctx.moved, checker) or \
        straight(problem, m, ctx.q_b, ctx.q_a, ctx.held, ctx.moved, checker,
                 m.enter_contact) or arrival(problem, m, ctx.q_b, ctx.moved, checker)
    return climb, descent


def departure(problem, m, q_a, moved: dict, checker) -> Approach | None:
    """The hand backing off what it let go of at q_a, where motion m starts: after a
    step whose fingers open there (a place; not a push, whose tool leaves the face it
    pushed as it likes)."""
    if m.index == 0 or problem.step_of_keyframe(m.index - 1).kind.fingers is not False:
        return None
    if not stacked(problem, problem.motions[m.index - 1].enter_contact):
        return None
    return backoff(problem, m, q_a, moved, checker, m.leave_contact)


def arrival(problem, m, q_b, moved: dict, checker) -> Approach | None:
    """The hand coming in to what it grasps at q_b, where motion m ends: before a step
    whose fingers close there (a grasp); its rungs listed from the keyframe out, as
    `departure`'s."""
    if problem.step_of_keyframe(m.index).kind.fingers is not True:
        return None
    after = m.index + 1
    if after >= len(problem.motions) or not stacked(problem, problem.motions[after].leave_contact):
        return None
    return backoff(problem, m, q_b, moved, checker, m.enter_contact)


def backoff(problem, m, q, moved: dict, checker, contacts) -> Approach | None:
    """Rungs from keyframe q back along the tool's approach axis until the robot is
    the margin clear of the movable objects among `contacts` (at most REACH); None
    where the motion is not an arm's empty hand leaving or entering such an object,
    where the fingers are already clear, or where not even one rung is possible."""
    if problem.planar or m.attached is not None or m.pushes or m.own:
        return None
    objects = {c for c in contacts if c in problem.bodies and not problem.bodies[c].fixed}
    if not objects:
        return None
    world, opts = problem.world, problem.options
    q = np.asarray(q, dtype=float)
    ignore = frozenset(m.sliding)
    near = checker.distances(q, moved, None, ignore, opts.margin, static=False)
    if not any(c.b == f"body:{name}" for c in near for name in objects):
        return None  # the fingers are clear already: nothing to back off from
    clear = min([opts.tight_margin, *(c.distance for c in near)]) - SLACK
    targets, qs = axis_rungs(
        problem, q, -world.tool_pose(q)[:3, 2], RUNG, int(np.ceil(REACH / RUNG - 1e-9)),
        None, moved, ignore, clear, checker,
        stop=lambda rung: _clear_of(checker, rung, moved, ignore, objects, opts.margin))
    return Approach(tuple(targets), tuple(qs)) if qs else None


def _clear_of(checker, q, moved, ignore, objects, margin: float) -> bool:
    """Whether the robot at q is at least `margin` from each of `objects`."""
    return not any(c.b == f"body:{name}" and c.distance < margin
                   for c in checker.distances(q, moved, None, ignore, margin, static=False)
                   for name in objects)
