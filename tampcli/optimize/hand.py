"""The hand's opening for one skeleton: the fingers opened only as wide as the
widest object it grasps needs, not fully.

The optimizer takes an arm's fingers at one opening at every keyframe and
along every motion: the collision rows and the grasp's depth use it, and
the solution's finger columns give it (closed on what is held from each
grasp to its place). Fully open, a Panda's fingers reach 6.6 cm from the
tool's axis; a 2.4 cm bar 6 cm from a bin's rim could not be picked across
that axis (blind10 p05), and a finger beside a box packed among others
starts inside its neighbour. So a skeleton's hand opens to the widest
closing width among its grasps, as the keyframe guess chose their faces
(grasp_families.closing_width of each choice), plus CLEARANCE on either
side, measured on the arm's own finger shapes (World.gripper_at). The
keyframe NLP and the path stage take the hand so where they fail with it
fully open (keyframe_stage.keyframes: open first, which found the better local
optima on the library's problems); the guess, choosing, takes it open (a grip
it scores as clashing there is only tried later).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from tampcli.optimize import grasp_families as F
from tampcli.solution_read import FINGERED_MODELS

# m, between each finger and the object at a grasp: twice GRIPPER_SLACK's 2.5 mm a
# side, which the widest objects the open hand takes already leave and the physics
# replay closes from.
CLEARANCE = 0.006
_BISECTIONS = 30
# Fractions of the fingers' travel at which a linkage's fingertip reach is measured
# (`_closing_table`).
CLOSING_SAMPLES = 17


@dataclass(frozen=True)
class Hand:
    """The fingers as one skeleton keeps them."""

    values: tuple[float, ...] | None  # finger joint values (World.finger_links); None: open
    opening: float | None  # World.gripper_opening's measure at `values`; None: no fingers
    depth: float  # how far the fingertips reach beyond the tool origin (m)


def narrowed(hand: Hand | None) -> bool:
    """Whether `hand` is opened less than fully (a problem's hand narrowed to its grips)."""
    return hand is not None and hand.values is not None


def open_hand(world) -> Hand:
    """The hand fully open (as loaded): the arm without a narrower need, or no fingers."""
    return Hand(None, world.gripper_opening, world.fingertip_depth or 0.0)


def grasp_width(problem, choices: dict) -> float | None:
    """The widest closing width among the skeleton's grasps as `choices` (step ->
    values.GripChoice) grip them; None when it grasps nothing (or no choice is made)."""
    widths = [F.closing_width(problem.bodies[step.obj], choice.psi or 0.0)
              for step in problem.steps if step.kind.fingers is True
              and (choice := choices.get(step.index)) is not None]
    return max(widths) if widths else None


def hand_for(world, width: float | None, clearance: float = CLEARANCE,
             bisections: int = _BISECTIONS) -> Hand:
    """The hand opened to `width` + 2 `clearance` (the most closed fraction whose
    measured opening is at least that, found by `bisections` halvings of the fingers'
    travel), fully open when that is as wide as it goes or `width` is None."""
    full = open_hand(world)
    if width is None or full.opening is None or width + 2 * clearance >= full.opening:
        return full
    values, opening, depth = world.gripper_at(_fraction(world, width + 2 * clearance,
                                                        bisections))
    return Hand(values, opening, depth)


def _fraction(world, need: float, bisections: int) -> float:
    """The most closed fraction of the fingers' travel (World.gripper_at) whose opening
    is at least `need`, by `bisections` halvings."""
    lo, hi = 0.0, 1.0  # opening(lo) >= need > opening(hi)
    if world.gripper_at(hi)[1] >= need:
        return hi
    for _ in range(bisections):
        mid = 0.5 * (lo + hi)
        if world.gripper_at(mid)[1] >= need:
            lo = mid
        else:
            hi = mid
    return lo


def closing_depth(problem, width: float) -> float:
    """How far beyond the tool origin the fingertips reach at their deepest as they
    close onto an object `width` wide (from fully open: at least as deep as from the
    hand the plan keeps). Fingers that slide (the Panda's, the KUKA's) reach as far as
    open; a linkage's fingertips swing down as they close (the xArm6's: 1.1 cm open,
    2.4 cm closed on a 2.4 cm coin), and a top grasp of a thin object must keep them
    clear of its support (blind32 p04: the coin's support met 1 cm deep by the closing
    sweep on every grasp tried). From `_closing_table`, one step of it past the touching
    fraction (a conservative millimetre on the xArm6)."""
    hand = problem.hand
    table = _closing_table(problem.world)
    if table is None:
        return hand.depth
    openings, depths = table
    wide = np.flatnonzero(openings >= width)
    last = min((int(wide[-1]) if len(wide) else 0) + 1, len(depths) - 1)
    return max(hand.depth, float(np.max(depths[:last + 1])))


def _closing_table(world):
    """(openings, fingertip depths) at CLOSING_SAMPLES fractions of the fingers' travel,
    from open to closed; None for fingers whose depth does not change as they close
    (within 0.5 mm at open, half and closed), or none. Kept in the World's
    `measures`: measured once per World (about 2 ms a fraction)."""
    key = ("closing table",)
    if key not in world.measures:
        table = None
        if world.gripper_opening is not None:
            ends = [world.gripper_at(t)[2] for t in (0.0, 0.5, 1.0)]
            if max(ends) - min(ends) > 5e-4:
                rows = [world.gripper_at(t)[1:] for t in np.linspace(0.0, 1.0, CLOSING_SAMPLES)]
                table = (np.array([r[0] for r in rows]), np.array([r[1] for r in rows]))
        world.measures[key] = table
    return world.measures[key]


def hand_of(problem, choices: dict) -> Hand:
    """The hand for a skeleton whose grasps grip as `choices` say: open for the
    planar robot, for an arm whose finger joints a solution file cannot give (a
    URDF arm, solution_read.FINGERS_OF: there the fingers are open unless closed
    on what they hold) and for a skeleton with a push."""
    world = problem.world
    if problem.planar or world.gripper_opening is None \
            or world.scene.robot.model not in FINGERED_MODELS \
            or any(m.pushes for m in problem.motions):
        # A push's contact is modelled on the open fingers (kinds/push_contact.py), and
        # `validate` checks it so (blind10 p08: narrowed, the pusher ended 1 mm inside
        # its crate by validate's open-handed check).
        return problem.hand
    return _cached(problem, grasp_width(problem, choices), CLEARANCE)


def narrows(problem, choices: dict) -> bool:
    """Whether `hand_of` is narrower than the problem's hand for these choices."""
    return hand_of(problem, choices) != problem.hand


def _cached(problem, width: float | None, clearance: float,
            bisections: int = _BISECTIONS) -> Hand:
    """hand_for, kept in the World's `measures` for every skeleton (a bisection of World
    measurements: 0.06 s on the xArm6, paid per skeleton when kept per problem)."""
    key = ("hand", None if width is None else round(width, 6), clearance, bisections)
    measures = problem.world.measures
    if key not in measures:
        measures[key] = hand_for(problem.world, width, clearance, bisections)
    return measures[key]


def with_hand(problem, choices: dict):
    """`problem` with its hand (and its checker's fingers) as `hand_of` says."""
    hand = hand_of(problem, choices)
    if hand == problem.hand:
        return problem
    return dataclasses.replace(problem, hand=hand, checker=problem.checker.with_fingers(
        hand.values))


def finger_columns(problem, events, choices: dict, n: int) -> np.ndarray | None:
    """(n, k) every finger joint's value (World.finger_links' order: the solution's
    finger columns, World.finger_names, come first) at each of its n waypoints: the
    hand's opening, closed on a grasped object (touching it: its closing width) from
    its grasp's waypoint to its place's. `events`: (waypoint
    where a step ends, step) in order (assemble.assemble). None with the hand open
    as loaded: the file then leaves the fingers out, which means the same."""
    hand = problem.hand
    if not narrowed(hand):
        return None
    opened = np.asarray(hand.values, dtype=float)
    out = np.tile(opened, (n, 1))
    for at, step in events:
        if step.kind.fingers is True:
            choice = choices.get(step.index)
            psi = choice.psi if choice is not None and choice.psi is not None else 0.0
            width = F.closing_width(problem.bodies[step.obj], psi)
            out[at:] = _cached(problem, width, 0.0).values
        elif step.kind.fingers is False:
            out[at + 1:] = opened
    return out

