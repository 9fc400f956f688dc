"""GJK distance between two convex solids given by support functions.

Used to check and, when needed, replace FCL's answer for separated solids:
FCL 0.7's GJK (both solvers) can stop on a wrong simplex and overestimate
the distance between boxes and cylinders by centimetres (a known upstream
bug, flexible-collision-library/fcl#508). This one stops only when the
duality gap |v| - v.w is below `tolerance`, so its distance is certified.
"""

from __future__ import annotations

import math

import numpy as np

MAX_ITERATIONS = 64


def gjk_distance(support_a, support_b, direction, tolerance: float = 1e-9):
    """(distance, point on a, point on b), or None when the solids intersect.

    `support_x(u)` returns the world point of x maximizing u . p. `direction`
    is a first guess of the direction from a to b.
    """
    d = np.asarray(direction, dtype=float)
    if not np.any(d):
        d = np.array([1.0, 0.0, 0.0])
    a, b = support_a(d), support_b(-d)
    simplex = [(a - b, a, b)]
    v = a - b
    for _ in range(MAX_ITERATIONS):
        vv = float(v @ v)
        if vv < 1e-24:
            return None
        a, b = support_a(-v), support_b(v)
        w = a - b
        norm = math.sqrt(vv)
        if norm - float(v @ w) / norm <= tolerance:
            break
        if any(np.array_equal(w, s[0]) for s in simplex):
            break  # no progress possible: v is the closest point to rounding
        simplex.append((w, a, b))
        v, simplex = _closest(simplex)
        if v is None:
            return None
    weights, simplex = _weights(simplex, v)
    pa = sum(lam * s[1] for lam, s in zip(weights, simplex, strict=True))
    pb = sum(lam * s[2] for lam, s in zip(weights, simplex, strict=True))
    return float(np.linalg.norm(v)), pa, pb


def _closest(simplex):
    """Closest point to the origin of the simplex hull, and the smallest sub-simplex holding it."""
    points = [s[0] for s in simplex]
    if len(points) == 4:
        return _tetrahedron(simplex)
    weights, keep = _barycentric(points)
    kept = [simplex[i] for i in keep]
    v = sum(lam * simplex[i][0] for lam, i in zip(weights, keep, strict=True))
    return v, kept


def _weights(simplex, v):
    points = [s[0] for s in simplex]
    if len(points) == 4:
        points = points[:3]
        simplex = simplex[:3]
    weights, keep = _barycentric(points)
    return weights, [simplex[i] for i in keep]


def _barycentric(points):
    """Weights and indices of the closest point to the origin on a point, segment or triangle."""
    if len(points) == 1:
        return [1.0], [0]
    if len(points) == 2:
        a, b = points
        ab = b - a
        denom = float(ab @ ab)
        t = 0.0 if denom <= 0.0 else min(1.0, max(0.0, -float(a @ ab) / denom))
        if t <= 0.0:
            return [1.0], [0]
        if t >= 1.0:
            return [1.0], [1]
        return [1.0 - t, t], [0, 1]
    return _triangle(*points)


def _triangle(a, b, c):
    # Ericson, Real-Time Collision Detection, 5.1.5, with p = origin.
    ab, ac = b - a, c - a
    ap = -a
    d1, d2 = float(ab @ ap), float(ac @ ap)
    if d1 <= 0 and d2 <= 0:
        return [1.0], [0]
    bp = -b
    d3, d4 = float(ab @ bp), float(ac @ bp)
    if d3 >= 0 and d4 <= d3:
        return [1.0], [1]
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        t = d1 / (d1 - d3)
        return [1 - t, t], [0, 1]
    cp = -c
    d5, d6 = float(ab @ cp), float(ac @ cp)
    if d6 >= 0 and d5 <= d6:
        return [1.0], [2]
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        t = d2 / (d2 - d6)
        return [1 - t, t], [0, 2]
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        t = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return [1 - t, t], [1, 2]
    denom = va + vb + vc
    if denom == 0.0:  # degenerate (collinear) triangle: best of its edges
        best = None
        for i, j in ((0, 1), (0, 2), (1, 2)):
            w, k = _barycentric([(a, b, c)[i], (a, b, c)[j]])
            idx = [(i, j)[m] for m in k]
            point = sum(lam * (a, b, c)[m] for lam, m in zip(w, idx, strict=True))
            if best is None or float(point @ point) < best[0]:
                best = (float(point @ point), w, idx)
        return best[1], best[2]
    v, w = vb / denom, vc / denom
    return [1 - v - w, v, w], [0, 1, 2]


def _tetrahedron(simplex):
    points = [s[0] for s in simplex]
    a, b, c, d = points
    best = None
    inside = True
    for face, opposite in (((0, 1, 2), 3), ((0, 1, 3), 2), ((0, 2, 3), 1), ((1, 2, 3), 0)):
        p, q, r = (points[i] for i in face)
        normal = np.cross(q - p, r - p)
        side_origin = float(normal @ (-p))
        side_opposite = float(normal @ (points[opposite] - p))
        if side_origin * side_opposite >= 0 and side_opposite != 0:
            continue  # the origin is on the inner side of this face
        inside = False
        weights, keep = _triangle(p, q, r)
        point = sum(lam * points[face[k]] for lam, k in zip(weights, keep, strict=True))
        dist = float(point @ point)
        if best is None or dist < best[0]:
            best = (dist, point, [simplex[face[k]] for k in keep])
    if inside:
        return None, simplex
    return best[1], best[2]
