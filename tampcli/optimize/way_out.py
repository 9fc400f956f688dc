"""The way out from under something: a keyframe with the hand under a body (a
side grasp in a shelf slot under its top board, a level hand under a low
ceiling) is left by backing out along the approach, not straight up.

The via-point start (path.via_points) leaves each keyframe straight up to a
height above everything near. Under a board that lift runs through the board,
and the path NLP from it could not get the hand out again (blind8 p03: every
carry out of a slot with 3.2 cm over the hand failed, `flask-a vs shelf-top by
4.9 cm`, and RRT-Connect found no path through the slot in 32,000 checks).
The hand came in along its approach, so it goes out that way: a small lift
(a held object off its support, within half the headroom), then back
horizontally, opposite the approach's horizontal part, its orientation kept,
until nothing above it is within `reach` of the tool, from where the lift is
clear.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize.collide import held_spec

EXIT_LIFT = 0.015  # m: the first lift, at most (and at most half the headroom)
EXIT_STEP = 0.02  # m between IK points along the way out: joint-space chords stay near it
MAX_JUMP = 0.5  # rad: a joint moving more than this between two of them left the branch
STEEP = 0.3  # an approach with less horizontal part than this points down: out is up
HEADROOM = 0.5  # m: a body's underside this far above the tool or more is not over it
MAX_EXIT = 0.4  # m: the way out goes this far back at most
HAND_REACH = 0.1  # m: how far the hand reaches around the tool origin (fingers, knuckles)
# m: the tool this close to under a body's footprint has the hand under it (the
# fingers reach past it); further out a lift is clear (a puck set down 15 cm in
# front of a shelf's board, 24 cm under it, is no hand in the shelf)
UNDER = 0.03
IK_TOLERANCE = 1e-3


@dataclass(frozen=True)
class WayOut:
    """Configurations backing out from a keyframe along the approach (nearest first),
    as far as the arm follows the line (a joint limit or a change of IK branch ends
    it: the xArm6's elbow at 8 cm back from a slot at 0.36 m), and `tool`: the pose
    from which the lift is clear, however far the configurations got."""

    configs: tuple[np.ndarray, ...]
    tool: np.ndarray


def way_out(problem, q, moved: dict, held) -> WayOut | None:
    """The way out from keyframe q from under what is above the hand, or None when
    nothing is or the hand points down."""
    world = problem.world
    tool = world.tool_pose(np.asarray(q, dtype=float))
    approach = tool[:3, 2]
    flat = math.hypot(approach[0], approach[1])
    if flat < STEEP:
        return None
    back = -approach[:2] / flat
    reach = HAND_REACH + problem.options.margin
    if held is not None:
        reach += 2 * problem.bodies[held.name].radius
    over = _over(problem, tool[:3, 3], back, moved, held, reach)
    if not over:
        return None
    distance = min(max(over.values()), MAX_EXIT)
    lift = min(EXIT_LIFT, 0.5 * _headroom(problem, q, moved, held, set(over)))

    def at(s):
        target = tool.copy()
        target[:3, 3] += np.array([s * back[0], s * back[1], lift])
        return target

    out, seed = [], np.asarray(q, dtype=float)
    for s in [0.0, *np.arange(EXIT_STEP, distance, EXIT_STEP), distance]:
        found, residual = world.ik(at(s), seed=seed, restarts=0)
        if residual > IK_TOLERANCE or np.max(np.abs(found - seed)) > MAX_JUMP:
            break
        out.append(found)
        seed = found
    return WayOut(tuple(out), at(distance))


def _over(problem, p: np.ndarray, back: np.ndarray, moved: dict, held, reach: float
          ) -> dict[str, float]:
    """name -> distance along `back` from the tool point p to where the body's footprint,
    grown by `reach`, is left, for each body above p whose footprint, grown by UNDER,
    holds p."""
    out = {}
    for name, info in problem.bodies.items():
        if held is not None and name == held.name:
            continue
        if name in moved:
            m = moved[name]
            centre, yaw = m[:3, 3], transforms.yaw_of(m)
        else:
            centre, yaw = np.array(info.pose[:3]), info.pose[3]
        underside = centre[2] - info.half[2]
        if not p[2] < underside < p[2] + HEADROOM:
            continue
        d = p[:2] - centre[:2]
        if info.disk:
            under = _disk_exit(d, back, info.half[0] + UNDER) is not None
            s = _disk_exit(d, back, info.half[0] + reach)
        else:
            c, sn = math.cos(yaw), math.sin(yaw)
            rot = np.array([[c, sn], [-sn, c]])  # world -> body frame
            half = np.array(info.half[:2])
            under = _box_exit(rot @ d, rot @ back, half + UNDER) is not None
            s = _box_exit(rot @ d, rot @ back, half + reach)
        if under:
            out[name] = s
    return out


def _box_exit(d: np.ndarray, u: np.ndarray, half: np.ndarray) -> float | None:
    """Where the ray d + s u (s >= 0) leaves the box |x| <= half; None if d is outside."""
    if np.any(np.abs(d) > half):
        return None
    exits = [(math.copysign(h, ui) - di) / ui for di, ui, h in zip(d, u, half, strict=True)
             if abs(ui) > 1e-9]
    return float(min(exits))


def _disk_exit(d: np.ndarray, u: np.ndarray, radius: float) -> float | None:
    """Where the ray d + s u leaves the disk |x| <= radius; None if d is outside."""
    if d @ d > radius * radius:
        return None
    b = float(d @ u)
    return -b + math.sqrt(b * b - float(d @ d) + radius * radius)


def _headroom(problem, q, moved: dict, held, names: set[str]) -> float:
    """The least distance at q from the hand (or what it holds) to the bodies `names`."""
    horizon = 2 * EXIT_LIFT
    found = problem.checker.distances(q, moved, held_spec(held), frozenset(), horizon)
    return min((c.distance for c in found if c.b.partition(":")[2] in names),
               default=horizon)
