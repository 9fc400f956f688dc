"""Which faces of an upright box can push it from one set of centres into another:
the friction-cone rule of the planar robot's relaxation (relaxed.py), reduced to
the object's displacement alone.

In the relaxation a push keeps one offset w between the disk and the object, so
the disk's displacement d = q1 - q0 is the object's, c1 - c0, up to the drift
the relaxation allows (`drift`), and d must lie in the widened cone of the face
pushed: |d.e| <= mu' d.n + slack (relaxed.Builder._cone). With c0 in a box S
and c1 in a box T, d lies in the box T - S grown by the drift; no face whose
cone meets that box can be the push's face. That is a proof, at the cost of a
few evaluations of a convex piecewise-linear function (`cone_gap`), and it is
used twice:

- inside a relaxation (relaxed.py): the faces no cone of which leads from where
  the prefix leaves the object into the target are not enumerated (their QPs are
  infeasible anyway), so a prefix of four pushes costs one or two QPs per push
  rather than 4^4 assignments or, past 64, a bound without cones;
- before any skeleton (bnb/lessons.py, `first_push_proofs`): a push whose object
  has not been moved before it starts from the start pose, the same in every
  skeleton; when no face leads from there into the target, no skeleton in which
  that push moves its object first is feasible, wherever it stands in the skeleton.

A disk (cylinder, sphere) has a face in every direction: it has no cone here.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.optimize.kinds.push_check import SLACK
from tampcli.optimize.kinds.push_check import STILL as STILL_STEP
from tampcli.optimize.kinds.push_contact import BOX_FACES, PUSH_FRICTION
from tampcli.optimize.verify import INSIDE, RIGID
from tampcli.optimize.verify import STILL as STILL_OBJECT

# The widened cone validate's per-segment test implies for a whole push (relaxed.py).
MU = (PUSH_FRICTION + SLACK) / (1.0 - SLACK)
# Mode switches a proof made before any skeleton covers: a resting object may creep by
# validate's STILL at each (relaxed.Builder._centre), 1e-6 m; 1000 switches are 1 mm.
HORIZON = 1000


def rot(yaw: float) -> np.ndarray:
    """The 2x2 rotation by yaw."""
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[c, -s], [s, c]])


def footprint_extent(info) -> np.ndarray:
    """Half extents along the world axes of an upright body's footprint at its yaw."""
    if info.disk:
        return np.array([info.half[0]] * 2)
    return np.abs(rot(info.pose[3])) @ np.array(info.half[:2])


def centre_box(info, region) -> tuple[np.ndarray, np.ndarray]:
    """Where the centre of `info`'s footprint (at its start yaw: nothing turns it) may be
    with the footprint inside `region`, as validate measures (INSIDE); lo > hi on some
    axis when it fits nowhere."""
    ext = footprint_extent(info)
    return (np.asarray(region.lower, dtype=float) + ext - INSIDE,
            np.asarray(region.upper, dtype=float) - ext + INSIDE)


def cone_slack(waypoints: int) -> float:
    """The cone's additive slack (m): segments shorter than validate's STILL, any way."""
    return waypoints * STILL_STEP * (1.0 + MU)


def cone_gap(info, angle: float, src: tuple, dst: tuple, drift: float,
             slack: float) -> float:
    """min over d in (dst - src) grown by `drift` of |d.e| - mu' d.n, less `slack` (m):
    > 0 when no displacement from the box `src` (lo, hi) into the box `dst` lies in
    the cone of the face `angle` (inward normal, object frame). An empty `dst` is +inf.

    The function is convex and linear on either side of the line d.e = 0, so its
    least value on the box is at a corner or where that line crosses an edge."""
    dlo, dhi = np.asarray(dst[0], dtype=float), np.asarray(dst[1], dtype=float)
    if (dhi < dlo).any():
        return math.inf
    lo = dlo - np.asarray(src[1], dtype=float) - drift
    hi = dhi - np.asarray(src[0], dtype=float) + drift
    R = rot(info.pose[3])
    n = R @ np.array([math.cos(angle), math.sin(angle)])
    e = R @ np.array([-math.sin(angle), math.cos(angle)])
    points = [np.array([x, y]) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
    for axis in (0, 1):  # d.e = 0 on the edges where coordinate `axis` is fixed
        other = 1 - axis
        if abs(e[other]) < 1e-15:
            continue
        for fixed in (lo[axis], hi[axis]):
            t = -e[axis] * fixed / e[other]
            if lo[other] <= t <= hi[other]:
                p = np.zeros(2)
                p[axis], p[other] = fixed, t
                points.append(p)
    return min(abs(p @ e) - MU * (p @ n) for p in points) - slack


def open_faces(info, src: tuple, dst: tuple, drift: float, slack: float,
               faces=BOX_FACES) -> tuple[float, ...]:
    """The faces among `faces` whose cone leads from `src` into `dst` (all for a disk)."""
    if info.disk:
        return tuple(faces)
    return tuple(a for a in faces if cone_gap(info, a, src, dst, drift, slack) <= 0.0)


def first_push_blocked(info, region, waypoints: int) -> bool:
    """Proved: `info`'s object, pushed from its start pose (not moved before, in a
    skeleton of up to HORIZON mode switches), reaches `region` through no face."""
    if info.disk:
        return False
    start = np.array(info.pose[:2], dtype=float)
    drift = RIGID + 2 * STILL_OBJECT * HORIZON
    # A motion gets up to four times `waypoints` segments (motion.segments_for): the
    # slack of that many short ones, whatever this skeleton's push gets.
    return not open_faces(info, (start, start), centre_box(info, region), drift,
                          cone_slack(4 * waypoints))


def line_meets(start, region, obstacle, clearance: float, samples: int = 64) -> bool:
    """A guess, no proof: does the straight line from `start` (x, y) to the centre of
    `region`, swept by a disk of radius `clearance` (the pusher and the object beside
    it), meet the footprint of `obstacle` (a BodyInfo: an upright box or a disk)? A
    push that ran into that obstacle on its way to one region likely runs into it on
    the way to the others beyond it (bnb/lessons.py orders skeletons by this)."""
    a = np.asarray(start, dtype=float)
    b = np.asarray(region.center, dtype=float)
    points = a + np.linspace(0.0, 1.0, samples)[:, None] * (b - a)
    rel = points - np.array(obstacle.pose[:2])
    if obstacle.disk:
        gap = np.linalg.norm(rel, axis=1) - obstacle.half[0]
    else:
        local = rel @ rot(obstacle.pose[3])  # into the obstacle's frame
        out = np.maximum(np.abs(local) - np.array(obstacle.half[:2]), 0.0)
        gap = np.linalg.norm(out, axis=1)
    return bool((gap < clearance).any())
