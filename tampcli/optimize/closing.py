"""The closing sweep: fingers that close on what they grasp (or open off what they
let go of) through nothing else.

A grasp's fingers go from the hand's opening to the object's width; something
between an open finger and the object's face (a rail, a wall) would be crushed or
would stop them, whatever the open hand clears (blind28 p04). `sweep_contact`
asks the collision checker for one configuration with the fingers at each opening
between, SWEEP_STEP apart; the keyframe stage refuses keyframes whose sweep is
blocked (`closing_blocked`), and `verify` judges a trajectory so (`validate` too).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from tampcli.optimize import grasp_families as F
from tampcli.optimize.assemble import walk
from tampcli.optimize.hand import _cached

SWEEP_STEP = 0.003  # m of opening between two finger positions the closing sweep checks
SWEEP_TOLERANCE = 1e-3  # m: a finger this deep in something at a sweep position is blocked
CLOSING = "the fingers close through"  # closing_blocked's words
# Halvings of the fingers' travel to where they touch the object: a tenth of a
# millimetre on the Panda's 8 cm, ample for 3 mm steps (30 for the hand a plan keeps).
SWEEP_BISECTIONS = 10


def closing_blocked(problem, keyframes, choices, start) -> str | None:
    """Why the fingers cannot close on what a grasp takes (or open off what a place
    lets go of) at the keyframes, or None (`sweep_contact`; blind28 p04: the KUKA's
    open fingers came down outside 1 cm rails 3 mm from the part, 1 mm from them, and
    the part was gripped with a rail between each finger and its face)."""
    if not sweeps(problem):
        return None
    opened = opened_hand(problem)
    for ctx in walk(problem, keyframes, choices, start):
        step = problem.step_of_keyframe(ctx.index)
        if step is None or step.kind.fingers is None or step.obj is None:
            continue
        grasp = step if step.kind.fingers is True else problem.steps[step.grasp_step]
        choice = choices.get(grasp.index)
        if choice is None:
            continue
        width = F.closing_width(problem.bodies[step.obj], choice.psi or 0.0)
        deep = sweep_contact(problem, ctx.q_b, ctx.moved, step.obj, opened, width)
        if deep is not None:
            return closing_words(step.name, deep)
    return None


def sweeps(problem) -> bool:
    """Whether the closing sweep applies: an arm with fingers (a URDF arm's too)."""
    return not problem.planar and problem.world.gripper_opening is not None \
        and problem.checker is not None


def opened_hand(problem) -> tuple[float, ...]:
    """The finger joints' values of the hand the plan keeps (open, or narrowed)."""
    hand = problem.hand.values
    return hand if hand is not None else problem.world.gripper_at(0.0)[0]


def sweep_contact(problem, q, others: dict, obj: str, opened, width: float):
    """The deepest contact (pairs.Contact), deeper than SWEEP_TOLERANCE, of a finger link
    with anything but `obj` as the fingers go from `opened` (finger joint values) to
    touching a width `width` at configuration q, at most SWEEP_STEP of opening apart;
    None when the sweep is clear. `others`: name -> 4x4 of bodies off their start."""
    world = problem.world
    touching = _cached(problem, width, 0.0, SWEEP_BISECTIONS)
    if touching.values is None:
        return None
    fingers = {f"link:{world.chain.links[i].name}" for i in world.finger_links}
    opening = world.gripper_opening
    n = max(2, int(np.ceil(max(opening - width, 0.0) / SWEEP_STEP)) + 1)
    sweep = np.linspace(np.asarray(opened, dtype=float), np.asarray(touching.values), n)
    rows = np.tile(np.asarray(q, dtype=float), (n, 1))
    found = problem.checker.distances_many(rows, others, None, [frozenset({obj})] * n, 0.0,
                                           static=False, fingers=sweep)
    deep = min((c for contacts in found for c in contacts
                if (c.a in fingers) != (c.b in fingers)), key=lambda c: c.distance, default=None)
    if deep is None or deep.distance >= -SWEEP_TOLERANCE:
        return None
    return deep if deep.a in fingers else dataclasses.replace(deep, a=deep.b, b=deep.a)


def closing_words(action: str, deep) -> str:
    """The violation `sweep_contact` found, in words (its finger first)."""
    return (f"{action}: {CLOSING} {deep.b.split(':', 1)[-1]} "
            f"({deep.a.split(':', 1)[-1]} {100 * -deep.distance:.1f} cm into it)")
