"""GJK distance between two convex solids given by support functions.

Used to check and, when needed, replace FCL's answer for separated solids:
FCL 0.7's GJK can stop on a wrong simplex, a few micrometres off for
meshes and centimetres off for boxes and cylinders (a known upstream bug,
flexible-collision-library/fcl#508). This one stops only when the duality
gap |v| - v.w / |v| is below `tolerance`, so its distance is certified.

The simplex arithmetic runs on Python floats: at 3 components, numpy's
per-call overhead would dominate.
"""

from __future__ import annotations

import math

import numpy as np

MAX_ITERATIONS = 64


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def gjk_distance(support_a, support_b, direction, tolerance: float = 1e-9):
    """(distance, point on a, point on b), or None when the solids intersect.

    `support_x(u)` returns the world point (numpy (3,)) of x maximizing u . p.
    `direction` is a first guess of the direction from a to b.
    """
    d = np.asarray(direction, dtype=float)
    if not np.any(d):
        d = np.array([1.0, 0.0, 0.0])
    a, b = support_a(d), support_b(-d)
    simplex = [(tuple(a - b), a, b)]
    v = simplex[0][0]
    for _ in range(MAX_ITERATIONS):
        vv = _dot(v, v)
        if vv < 1e-24:
            return None
        nv = np.array(v)
        a, b = support_a(-nv), support_b(nv)
        w = (a[0] - b[0], a[1] - b[1], a[2] - b[2])
        norm = math.sqrt(vv)
        if norm - _dot(v, w) / norm <= tolerance:
            break
        if any(w == s[0] for s in simplex):
            break  # no progress possible: v is the closest point to rounding
        simplex.append((w, a, b))
        v, simplex, weights = _closest(simplex)
        if v is None:
            return None
    weights, simplex = _weights(simplex)
    pa = sum(lam * s[1] for lam, s in zip(weights, simplex, strict=True))
    pb = sum(lam * s[2] for lam, s in zip(weights, simplex, strict=True))
    return math.sqrt(_dot(v, v)), pa, pb


def _closest(simplex):
    """Closest point to the origin, the smallest sub-simplex holding it, its weights."""
    if len(simplex) == 4:
        return _tetrahedron(simplex)
    weights, keep = _barycentric([s[0] for s in simplex])
    kept = [simplex[i] for i in keep]
    return _combine(weights, kept), kept, weights


def _combine(weights, simplex):
    x = y = z = 0.0
    for lam, s in zip(weights, simplex, strict=True):
        x += lam * s[0][0]
        y += lam * s[0][1]
        z += lam * s[0][2]
    return (x, y, z)


def _weights(simplex):
    if len(simplex) == 4:  # only when the loop stopped right after a tetrahedron step
        simplex = simplex[:3]
    weights, keep = _barycentric([s[0] for s in simplex])
    return weights, [simplex[i] for i in keep]


def _barycentric(points):
    """Weights and indices of the closest point to the origin on a point, segment or triangle."""
    if len(points) == 1:
        return [1.0], [0]
    if len(points) == 2:
        a, b = points
        ab = _sub(b, a)
        denom = _dot(ab, ab)
        t = 0.0 if denom <= 0.0 else min(1.0, max(0.0, -_dot(a, ab) / denom))
        if t <= 0.0:
            return [1.0], [0]
        if t >= 1.0:
            return [1.0], [1]
        return [1.0 - t, t], [0, 1]
    return _triangle(*points)


def _triangle(a, b, c):
    # Ericson, Real-Time Collision Detection, 5.1.5, with the query point at the origin.
    ab, ac = _sub(b, a), _sub(c, a)
    d1, d2 = -_dot(ab, a), -_dot(ac, a)
    if d1 <= 0 and d2 <= 0:
        return [1.0], [0]
    d3, d4 = -_dot(ab, b), -_dot(ac, b)
    if d3 >= 0 and d4 <= d3:
        return [1.0], [1]
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        t = d1 / (d1 - d3)
        return [1 - t, t], [0, 1]
    d5, d6 = -_dot(ab, c), -_dot(ac, c)
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
    if denom == 0.0:  # degenerate (collinear) triangle: the best of its edges
        best = None
        pts = (a, b, c)
        for i, j in ((0, 1), (0, 2), (1, 2)):
            w, k = _barycentric([pts[i], pts[j]])
            idx = [(i, j)[m] for m in k]
            p = [0.0, 0.0, 0.0]
            for lam, m in zip(w, idx, strict=True):
                for axis in range(3):
                    p[axis] += lam * pts[m][axis]
            dist = _dot(p, p)
            if best is None or dist < best[0]:
                best = (dist, w, idx)
        return best[1], best[2]
    v, w = vb / denom, vc / denom
    return [1 - v - w, v, w], [0, 1, 2]


_FACES = (((0, 1, 2), 3), ((0, 1, 3), 2), ((0, 2, 3), 1), ((1, 2, 3), 0))


def _tetrahedron(simplex):
    points = [s[0] for s in simplex]
    best = None
    inside = True
    for face, opposite in _FACES:
        p, q, r = (points[i] for i in face)
        normal = _cross(_sub(q, p), _sub(r, p))
        side_origin = -_dot(normal, p)
        side_opposite = _dot(normal, _sub(points[opposite], p))
        if side_origin * side_opposite >= 0 and side_opposite != 0:
            continue  # the origin is on the inner side of this face
        inside = False
        weights, keep = _triangle(p, q, r)
        sub = [simplex[face[k]] for k in keep]
        point = _combine(weights, sub)
        dist = _dot(point, point)
        if best is None or dist < best[0]:
            best = (dist, point, sub, weights)
    if inside:
        return None, simplex, None
    return best[1], best[2], best[3]
