"""The arm's grasp families: the ways its fingers may hold an object (docs/formats.md, "Grasp").

A family is a type here, registered by its name in FAMILIES (the names
modes.toml's `grasps` takes, in the order the initial guess prefers them).
Its discrete part (which faces the fingers close on, which way the hand is
turned) the initial guess enumerates (`choices`, tried by IK and kept); its
continuous part is the keyframe NLP's: the tool's pose itself (so the yaw
about the vertical is free) and, for a side grasp, the approach's pitch, a
grip parameter kept in its range by `rows`.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod

import numpy as np

from tampcli.optimize.bodies import REST_TOLERANCE
from tampcli.optimize.expr import Label
from tampcli.optimize.grips import Grip, PitchGrip, TopGrip
from tampcli.optimize.units import cm
from tampcli.optimize.values import GripChoice

GRIPPER_SLACK = 0.005  # m: an object this much narrower than the opening fits between
FINGER_DEPTH = 0.015  # m, at most this far below the object's top is a top grasp's point
MIN_DEPTH = 0.002  # m, the grasp point at least this far inside the object
SIDE_PITCH = math.pi / 3  # rad, the steepest a side approach comes down
# A side grasp's point this far inside the face it approaches (the Panda's hand
# is 3.9 cm behind it: the fingertips hold 2.2 cm of the object, the hand
# keeps clear of what stands right behind that face) ...
SIDE_REACH = 0.012  # m
SIDE_BELOW_TOP = 0.01  # m, ... and this far below its top (half a fingertip's width)
SIDE_MIN_HEIGHT = 0.03  # m: a flatter object leaves a side grasp's fingers the support
TILT = math.acos(0.99)  # rad (8.1 deg), how far verify lets a grasp stray from its family
QUARTERS = (0.0, 0.5 * math.pi, math.pi, -0.5 * math.pi)


def closing_width(info, psi: float) -> float:
    """The object's width along the fingers' closing axis when they close across
    direction psi + 90 degrees of its frame (both families close along tool y)."""
    if info.disk:
        return 2 * info.half[0]
    return 2 * (info.half[1] if abs(math.cos(psi)) > 0.5 else info.half[0])


def fits(width: float, opening: float | None) -> bool:
    """`opening` None: no fingers, nothing too wide."""
    return opening is None or width <= opening - GRIPPER_SLACK


class GraspFamily(ABC):
    """One way of holding; subclasses are registered in FAMILIES by `name`."""

    name: str
    has_param: bool = False  # the keyframe NLP has a grip parameter for it

    def choices(self, info, opening: float | None) -> list[GripChoice]:
        """The discrete grips of this family whose closing width fits the opening."""
        return [GripChoice(psi=psi, family=self.name, roll=roll) for psi in QUARTERS
                for roll in self.rolls if fits(closing_width(info, psi), opening)]

    rolls: tuple[float, ...] = (1.0,)

    def why_not(self, info, opening: float | None) -> str | None:
        """Why the gripper cannot hold this shape this way (None: it can)."""
        if not self.choices(info, opening):
            narrow = min(closing_width(info, psi) for psi in QUARTERS)
            return (f"{cm(narrow)} cm wide; the gripper opens "
                    f"{cm(opening)} cm and takes at most "
                    f"{cm(opening - GRIPPER_SLACK)} cm")
        return None

    @abstractmethod
    def grip(self, info, choice: GripChoice, fingertip: float, clearance: float,
             closed: float | None = None) -> Grip:
        """The grip of `choice` on an object (`info`: bodies.BodyInfo); `fingertip`:
        how far the fingertips reach beyond the tool origin; `clearance`: what they
        keep from the support; `closed`: how far at their deepest as they close on it
        (hand.closing_depth; None: as far as `fingertip`)."""

    starts: tuple[float, ...] = (0.0,)  # grip parameters the initial guess tries

    def rows(self, ineq, step: str, t: float, t_block: str | None) -> None:
        """Rows keeping the grip parameter in the family's range (none without one)."""
        return None

    @abstractmethod
    def holds(self, tool: np.ndarray, obj: np.ndarray) -> bool:
        """A tool pose (4x4) at a grasp belongs to this family (verify)."""


class Top(GraspFamily):
    """From above: the tool's z axis points down, at a yaw offset (a quarter turn
    for a box, so the fingers close on two faces; any yaw for a disk)."""

    name = "top"

    def grip(self, info, choice, fingertip, clearance, closed=None):
        # Deep enough to hold, shallow enough that the fingertips stay clear of
        # whatever the object stands on (thin discs, trays with rims) as they close.
        # Fingertips that swing down as they close (the xArm6's) hold lower than the
        # tool origin by what they gain: the grasp point may be that much higher.
        gain = 0.0 if closed is None else max(closed - fingertip, 0.0)
        clear = 2 * info.half[2] - fingertip - gain - clearance - REST_TOLERANCE
        depth = float(np.clip(min(FINGER_DEPTH, clear), MIN_DEPTH - gain, info.half[2]))
        return TopGrip((0.0, 0.0, info.half[2] - depth),
                       psi=choice.psi if choice.psi is not None else 0.0)

    def holds(self, tool, obj):
        return tool[2, 2] <= -math.cos(TILT)


class Side(GraspFamily):
    """From the side: the hand horizontal (fingers closing along a horizontal
    axis across two faces), approaching along the object's other horizontal
    axis, pitched down by t in [0, SIDE_PITCH]; either way up (`roll`)."""

    name = "side"
    has_param = True
    rolls = (1.0, -1.0)
    # Level first; pitched a little lifts the wrist, whose housing is wider than
    # the hand, off the surface the object stands on.
    starts = (0.0, math.pi / 24, math.pi / 12, math.pi / 6)

    def why_not(self, info, opening):
        if 2 * info.half[2] < SIDE_MIN_HEIGHT:
            return (f"{100 * 2 * info.half[2]:.1f} cm tall: too flat for the fingers "
                    f"from the side (at least {100 * SIDE_MIN_HEIGHT:.0f} cm)")
        return super().why_not(info, opening)

    def grip(self, info, choice, fingertip, clearance, closed=None):
        psi = choice.psi if choice.psi is not None else 0.0
        along = info.half[0] if info.disk else (
            info.half[0] if abs(math.cos(psi)) > 0.5 else info.half[1])
        reach = min(SIDE_REACH, along - MIN_DEPTH)
        z = max(info.half[2] - SIDE_BELOW_TOP, 0.0)
        point = (-along + reach) * np.array([math.cos(psi), math.sin(psi)])
        return PitchGrip((float(point[0]), float(point[1]), z), psi=psi, roll=choice.roll)

    def rows(self, ineq, step, t, t_block):
        if t_block is not None:
            ineq.add(np.array([t, SIDE_PITCH - t]), {t_block: np.array([[1.0], [-1.0]])},
                     [Label(step, "side grasp pitched up", "rad"),
                      Label(step, f"side grasp pitched down more than "
                            f"{math.degrees(SIDE_PITCH):.0f} deg", "rad")])

    def holds(self, tool, obj):
        pitch = math.asin(float(np.clip(-tool[2, 2], -1.0, 1.0)))
        return abs(tool[2, 1]) <= math.sin(TILT) and -TILT <= pitch <= SIDE_PITCH + TILT


FAMILIES: dict[str, GraspFamily] = {f.name: f for f in (Top(), Side())}
TOP = FAMILIES[Top.name]


def family_of(choice: GripChoice) -> GraspFamily:
    return FAMILIES[choice.family] if choice.family is not None else TOP


def possible(requested, info, opening: float | None) -> tuple[tuple[str, ...], list[str]]:
    """(the families of `requested` the gripper can do on this shape, why each other
    cannot); `requested` None: every family."""
    names = tuple(requested) if requested else tuple(FAMILIES)
    ok, why = [], []
    for name in names:
        reason = FAMILIES[name].why_not(info, opening)
        if reason is None:
            ok.append(name)
        else:
            why.append(f"{name}: {reason}")
    return tuple(ok), why
