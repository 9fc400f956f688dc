"""One signed-distance query between two convex solids, made robust.

FCL 0.7 answers fast but not always right, so every answer is checked:

- Separated: the projections of the solids on FCL's normal n leave a gap
  that bounds the true distance from below; FCL's witness points bound it
  from above. When the bounds disagree (FCL's GJK stopped on a wrong
  simplex: centimetres off for boxes and cylinders, fcl#508), our own GJK
  (gjk.py), warm-started on n, gives the certified distance.
- Touching or penetrating: our GJK first decides whether the solids are
  really apart. FCL's EPA returns nonsense for solids that touch face to
  face (a depth of decimetres towards a far corner; resting contacts do
  exactly that), so its depth is checked against an upper bound: for any
  unit direction u, the overlap of the projections on u bounds the depth.
  When EPA's depth exceeds the best overlap over a few candidate
  directions, that overlap and its direction are used instead.
"""

from __future__ import annotations

import math

import fcl
import numpy as np

from tampcli.geometry.gjk import gjk_distance
from tampcli.geometry.shapes import Shape

_TOL = 1e-7  # m: the accuracy we certify


def signed_distance(request, sa: Shape, oa, ta: np.ndarray, sb: Shape, ob, tb: np.ndarray):
    """(distance, point on a, point on b, unit normal from a to b), world frame.

    `oa`, `ob` are FCL objects already placed at `ta`, `tb` (4x4 world poses
    of the shapes themselves).
    """
    result = fcl.DistanceResult()  # keeps the smallest value seen: one per query
    d = float(fcl.distance(oa, ob, request, result))
    p1 = np.array(result.nearest_points[0])
    p2 = np.array(result.nearest_points[1])
    diff = p2 - p1
    norm = float(np.linalg.norm(diff))
    normal = None
    if norm > 1e-9:
        # When penetrating, FCL's witness points lie inside the other solid,
        # so p2 - p1 points from b to a: flip it.
        normal = diff / norm if d >= 0 else -diff / norm
    if d > _TOL and normal is not None:
        if -overlap(sa, ta, sb, tb, normal) >= d - _TOL:
            return d, p1, p2, normal
    guess = normal if normal is not None else tb[:3, 3] - ta[:3, 3]
    exact = gjk_distance(_support(sa, ta), _support(sb, tb), guess, _TOL)
    if exact is not None and exact[0] > _TOL:
        dist, pa, pb = exact
        return dist, pa, pb, (pb - pa) / dist
    return _checked_penetration(min(d, 0.0), p1, p2, normal if d <= 0 else None, sa, ta, sb, tb)


def _support(shape: Shape, t: np.ndarray):
    rot, pos = t[:3, :3], t[:3, 3]
    rot_t = rot.T

    def support(u):
        return rot @ shape.support_point(rot_t @ u) + pos

    return support


def overlap(sa: Shape, ta, sb: Shape, tb, u) -> float:
    """max over a of u.x - min over b of u.x: >= the penetration depth along u."""
    ha = float(u @ ta[:3, 3]) + sa.support(ta[:3, :3].T @ u)
    lb = float(u @ tb[:3, 3]) - sb.support(-(tb[:3, :3].T @ u))
    return ha - lb


def _candidates(sa: Shape, ta, sb: Shape, tb, normal):
    dirs = []
    if normal is not None:
        dirs.append(normal)
    axis = tb[:3, 3] - ta[:3, 3]
    if np.linalg.norm(axis) > 1e-12:
        dirs.append(axis / np.linalg.norm(axis))
    for s, t, sign in ((sa, ta, 1.0), (sb, tb, -1.0)):
        if s.kind in ("box",):
            for k in range(3):
                v = t[:3, k]
                dirs.append(v if sign * float(v @ axis) >= 0 else -v)
        elif s.kind in ("cylinder", "capsule"):
            v = t[:3, 2]
            dirs.append(v if sign * float(v @ axis) >= 0 else -v)
    dirs.extend(np.eye(3))
    dirs.extend(-np.eye(3))
    return dirs


def _checked_penetration(d, p1, p2, normal, sa, ta, sb, tb):
    best_u, best = None, math.inf
    for u in _candidates(sa, ta, sb, tb, normal):
        o = overlap(sa, ta, sb, tb, u)
        if o < best:
            best, best_u = o, u
    if normal is not None and -d <= best + 1e-6:
        return d, p1, p2, normal
    # EPA's answer is not credible: use the best projection direction.
    u = best_u
    pa = ta[:3, :3] @ sa.support_point(ta[:3, :3].T @ u) + ta[:3, 3]
    pb = pa - best * u
    if normal is None and best <= 0:
        # Touching: FCL gave coincident points, which stay the witnesses.
        return -best, p1, p2, u
    return -best, pa, pb, u
