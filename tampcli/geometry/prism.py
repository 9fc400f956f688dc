"""Exact signed distance between upright prisms: boxes and cylinders whose axis is vertical.

An upright prism is a Cartesian product: a 2D base (a rectangle or a disk) in
x, y times a height interval in z. For two products the squared distance is
the sum of the squared distances of the factors, and the penetration depth
(least translation that separates them) is the smaller of the factors'
depths. So the 3D query reduces to a rectangle/disk query in the plane and
an interval query, both closed form.

This is the common case of the planar robot (a vertical cylinder) and of
blocks on tables, where FCL's cylinder answers are centimetres off (fcl#508)
and the iterative GJK that would otherwise certify them costs a millisecond
in Python. Two upright boxes are answered here too: FCL's signed distance
(libccd's EPA) aborts the process on some touching rectangles ("the origin is
outside of the polytope", a C++ error Python cannot catch), measured on a
block set down against a wall.
"""

from __future__ import annotations

import math

import numpy as np

UPRIGHT = 1e-9  # |1 - R_zz| under which a solid's z axis counts as vertical


def base(placed):
    """(kind, centre (2,), x axis (2,), half extents or radius, z low, z high), or None."""
    kind = placed.shape.kind
    if kind not in ("box", "cylinder"):
        return None
    rot, pos = placed.rot, placed.pos
    if abs(abs(rot[2, 2]) - 1.0) > UPRIGHT:
        return None
    if kind == "box":
        hx, hy, hz = (0.5 * s for s in placed.shape.size)
        axis = rot[:2, 0] / max(math.hypot(rot[0, 0], rot[1, 0]), 1e-300)
        return "box", pos[:2], axis, (hx, hy), pos[2] - hz, pos[2] + hz
    r, h = placed.shape.size
    return "disk", pos[:2], None, r, pos[2] - 0.5 * h, pos[2] + 0.5 * h


def distance(a, b):
    """(distance, point on a, point on b, unit normal from a to b), or None when either
    solid is not an upright prism."""
    fa, fb = base(a), base(b)
    if fa is None or fb is None:
        return None
    # The planar factor, as (signed distance, point on a, point on b, unit normal a -> b).
    if fa[0] == "box" and fb[0] == "box":
        planar = _boxes(fa, fb)
    elif fa[0] == "disk" and fb[0] == "disk":
        planar = _disks(fa, fb)
    elif fa[0] == "disk":
        planar = _disk_box(fa, fb)
    else:
        d, pb, pa, n, common = _disk_box(fb, fa)
        planar = (d, pa, pb, (-n[0], -n[1]), common)
    d_xy, pa_xy, pb_xy, n_xy, common = planar
    # The vertical factor: the gap between the height intervals (negative: overlap).
    below = fb[4] - fa[5]  # b above a
    above = fa[4] - fb[5]  # b below a
    if below >= above:
        d_z, za, zb, n_z = below, fa[5], fb[4], 1.0
    else:
        d_z, za, zb, n_z = above, fa[4], fb[5], -1.0
    if d_xy > 0 and d_z > 0:
        dist = math.hypot(d_xy, d_z)
        pa = np.array([pa_xy[0], pa_xy[1], za])
        pb = np.array([pb_xy[0], pb_xy[1], zb])
        return dist, pa, pb, (pb - pa) / dist
    if d_xy >= d_z:
        # Separated (or least deep) in the plane: witnesses at a common height.
        z = _shared_height(fa, fb)
        pa = np.array([pa_xy[0], pa_xy[1], z])
        pb = np.array([pb_xy[0], pb_xy[1], z])
        return d_xy, pa, pb, np.array([n_xy[0], n_xy[1], 0.0])
    # Separated (or least deep) in height: the bases overlap; witnesses above a
    # point of both.
    x, y = common
    return d_z, np.array([x, y, za]), np.array([x, y, zb]), np.array([0.0, 0.0, n_z])


def _shared_height(fa, fb) -> float:
    lo, hi = max(fa[4], fb[4]), min(fa[5], fb[5])
    return 0.5 * (lo + hi)


def _disks(fa, fb):
    ca, ra = fa[1], fa[3]
    cb, rb = fb[1], fb[3]
    dx, dy = cb[0] - ca[0], cb[1] - ca[1]
    norm = math.hypot(dx, dy)
    n = (dx / norm, dy / norm) if norm > 1e-12 else (1.0, 0.0)
    pa = (ca[0] + ra * n[0], ca[1] + ra * n[1])
    pb = (cb[0] - rb * n[0], cb[1] - rb * n[1])
    # Along the centre line, the middle of the stretch both disks cover.
    t = 0.5 * (max(-ra, norm - rb) + min(ra, norm + rb))
    return norm - ra - rb, pa, pb, n, (ca[0] + t * n[0], ca[1] + t * n[1])


def _disk_box(disk, box):
    """Disk a vs rectangle b in the plane: (signed distance, point on a, point on b,
    normal a -> b, a point of both when they overlap)."""
    c, r = disk[1], disk[3]
    centre, (ux, uy), (hx, hy) = box[1], box[2], box[3]
    # The disk centre in the rectangle's frame.
    rx, ry = c[0] - centre[0], c[1] - centre[1]
    px, py = ux * rx + uy * ry, -uy * rx + ux * ry
    qx, qy = min(max(px, -hx), hx), min(max(py, -hy), hy)
    outside = (qx, qy) != (px, py)
    if outside:
        gx, gy = px - qx, py - qy
        gap = math.hypot(gx, gy)
        nx, ny = -gx / gap, -gy / gap  # from the disk towards the rectangle
        d = gap - r
    else:
        # Centre inside: leave through the nearest side.
        if hx - abs(px) <= hy - abs(py):
            side = 1.0 if px >= 0 else -1.0
            qx, qy = side * hx, py
            nx, ny = -side, 0.0
            inside = hx - abs(px)
        else:
            side = 1.0 if py >= 0 else -1.0
            qx, qy = px, side * hy
            nx, ny = 0.0, -side
            inside = hy - abs(py)
        d = -inside - r
    # Back to the world: the point on the rectangle and the normal.
    wx, wy = centre[0] + ux * qx - uy * qy, centre[1] + uy * qx + ux * qy
    n = (ux * nx - uy * ny, uy * nx + ux * ny)
    pa = (c[0] + r * n[0], c[1] + r * n[1])
    # Overlapping: the rectangle's point nearest the centre is in the disk, and the
    # centre itself when it is inside the rectangle.
    common = (wx, wy) if outside else (c[0], c[1])
    return d, pa, (wx, wy), n, common


def _corners(box) -> np.ndarray:
    """The rectangle's corners (4, 2), counter-clockwise."""
    centre, (ux, uy), (hx, hy) = box[1], box[2], box[3]
    ex, ey = (hx * ux, hx * uy), (-hy * uy, hy * ux)  # half extents along u and v
    cx, cy = centre[0], centre[1]
    return np.array([(cx + sx * ex[0] + sy * ey[0], cy + sx * ex[1] + sy * ey[1])
                     for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1))])


def _nearest_corner_side(P, Q):
    """(distance, corner of P, its nearest point on a side of Q) over P's 4 corners and
    Q's 4 sides, in one pass over all 16 pairs (corner-major: the first least one)."""
    a = Q
    ab = np.roll(Q, -1, axis=0) - Q  # side i runs from corner i to corner i + 1
    ap = P[:, None, :] - a[None, :, :]  # (corner, side, 2)
    t = np.clip((ap * ab).sum(axis=2) / np.maximum((ab * ab).sum(axis=1), 1e-300), 0.0, 1.0)
    q = a[None, :, :] + t[:, :, None] * ab[None, :, :]
    d = np.sqrt(((q - P[:, None, :]) ** 2).sum(axis=2))
    i, j = divmod(int(d.argmin()), 4)
    return float(d[i, j]), P[i], q[i, j]


def _boxes(fa, fb):
    """Rectangle a vs rectangle b in the plane: (signed distance, point on a, point on
    b, normal a -> b, a point of both when they overlap). Apart: the nearest pair of
    a corner and a side. Overlapping: the separating-axis depth (the least
    translation that separates two convex polygons is along one of their sides'
    normals), the witnesses the deepest corner of a and its shift out of b."""
    A, B = _corners(fa), _corners(fb)
    (ax, ay), (bx, by) = fa[2], fb[2]
    axes = np.array([[ax, ay], [-ay, ax], [bx, by], [-by, bx]])
    pa, pb = A @ axes.T, B @ axes.T  # (corner, axis)
    ahead = pb.min(axis=0) - pa.max(axis=0)  # b on the + side of a along the axis
    behind = pa.min(axis=0) - pb.max(axis=0)
    plus = pa.max(axis=0) - pb.min(axis=0) <= pb.max(axis=0) - pa.min(axis=0)
    gaps = np.where(plus, ahead, behind)
    k = int(gaps.argmax())
    gap, n = float(gaps[k]), axes[k] if plus[k] else -axes[k]
    if gap > 0:
        d, p, q = _nearest_corner_side(A, B)
        d_b, p_b, q_b = _nearest_corner_side(B, A)
        if d_b < d:
            d, p, q = d_b, q_b, p_b
        normal = (q - p) / d if d > 1e-12 else n
        return d, tuple(p), tuple(q), (float(normal[0]), float(normal[1])), None
    # Overlapping: depth -gap along n; a's deepest corner into b, and where it leaves b.
    proj = A @ n
    deep = A[np.isclose(proj, proj.max(), rtol=0.0, atol=1e-12)].mean(axis=0)
    pa, pb = deep, deep + gap * n
    return gap, tuple(pa), tuple(pb), (float(n[0]), float(n[1])), tuple(_overlap_point(A, B))


def _overlap_point(A, B) -> np.ndarray:
    """A point of both convex polygons (they overlap): the mean of a clipped by b."""
    poly = list(A)
    for i in range(4):
        a, b = B[i], B[(i + 1) % 4]
        edge = b - a

        def inside(p, a=a, edge=edge):
            return edge[0] * (p[1] - a[1]) - edge[1] * (p[0] - a[0]) >= -1e-12

        out = []
        for j, p in enumerate(poly):
            q = poly[(j + 1) % len(poly)]
            if inside(p):
                out.append(p)
            if inside(p) != inside(q):
                den = edge[0] * (q[1] - p[1]) - edge[1] * (q[0] - p[0])
                t = (edge[0] * (a[1] - p[1]) - edge[1] * (a[0] - p[0])) / den
                out.append(p + t * (q - p))
        poly = out or poly
    return np.mean(poly, axis=0)


def upright_boxes(pairs: list) -> list:
    """`distance` of many pairs of boxes at once, each answer or None.

    The same geometry as `_boxes`, in arrays over the pairs. `_boxes` keeps its own
    small-array form: this one called with a single pair costs 1.6 times as much
    (measured: 98 against 62 us), and single pairs are what the scalar path asks
    for. tests/geometry/test_prism.py checks the two agree.

    The pairs answered are those of two upright boxes whose bases are apart in the
    plane (what an optimizer's iterates mostly are); the rest (None) take
    `distance` one by one. Same answers as `distance`, in array operations over
    all pairs: one pair by `distance` costs ~50 us of numpy calls on 2 x 4
    corners (robust-planar p04's plank: 220,000 of them in one path stage).
    """
    out = [None] * len(pairs)
    bases = [(base(a), base(b)) for a, b in pairs]
    idx = [i for i, (fa, fb) in enumerate(bases)
           if fa is not None and fb is not None and fa[0] == "box" and fb[0] == "box"]
    if not idx:
        return out
    fa = [bases[i][0] for i in idx]
    fb = [bases[i][1] for i in idx]
    A, ua = _corners_many(fa)
    B, ub = _corners_many(fb)
    axes = np.concatenate([ua, _perp(ua), ub, _perp(ub)], axis=1)  # (k, 4, 2)
    pa = np.einsum("kci,kai->kca", A, axes)  # (k, corner, axis)
    pb = np.einsum("kci,kai->kca", B, axes)
    plus = pa.max(axis=1) - pb.min(axis=1) <= pb.max(axis=1) - pa.min(axis=1)
    gaps = np.where(plus, pb.min(axis=1) - pa.max(axis=1), pa.min(axis=1) - pb.max(axis=1))
    apart = gaps.max(axis=1) > 0
    if not apart.any():
        return out
    A, B = A[apart], B[apart]
    d, p, q = _nearest_corner_side_many(A, B)
    d_b, p_b, q_b = _nearest_corner_side_many(B, A)
    swap = d_b < d
    d = np.where(swap, d_b, d)
    p, q = np.where(swap[:, None], q_b, p), np.where(swap[:, None], p_b, q)
    n_xy = (q - p) / d[:, None]  # apart: d > 0
    z = np.array([(f[4], f[5]) for f in fa])[apart]
    zb = np.array([(f[4], f[5]) for f in fb])[apart]
    below, above = zb[:, 0] - z[:, 1], z[:, 0] - zb[:, 1]
    up = below >= above
    d_z = np.where(up, below, above)
    za, zbb = np.where(up, z[:, 1], z[:, 0]), np.where(up, zb[:, 0], zb[:, 1])
    shared = 0.5 * (np.maximum(z[:, 0], zb[:, 0]) + np.minimum(z[:, 1], zb[:, 1]))
    corner = d_z > 0  # apart in height too: the nearest points are on both rims
    dist = np.where(corner, np.hypot(d, d_z), d)
    wa = np.column_stack([p, np.where(corner, za, shared)])
    wb = np.column_stack([q, np.where(corner, zbb, shared)])
    normal = np.where(corner[:, None], (wb - wa) / dist[:, None],
                      np.column_stack([n_xy, np.zeros(len(d))]))
    for row, i in enumerate(np.asarray(idx)[apart].tolist()):
        out[i] = (float(dist[row]), wa[row], wb[row], normal[row])
    return out


def _perp(u: np.ndarray) -> np.ndarray:
    return np.stack([-u[..., 1], u[..., 0]], axis=-1)


_SIGNS = np.array([(1, 1), (-1, 1), (-1, -1), (1, -1)], dtype=float)  # as _corners


def _corners_many(bases) -> tuple[np.ndarray, np.ndarray]:
    """(corners (k, 4, 2) counter-clockwise as `_corners`, x axes (k, 1, 2))."""
    centre = np.array([f[1] for f in bases], dtype=float)
    u = np.array([f[2] for f in bases], dtype=float)
    half = np.array([f[3] for f in bases], dtype=float)
    v = _perp(u)
    corners = (centre[:, None, :] + (_SIGNS[None, :, 0:1] * half[:, None, 0:1]) * u[:, None, :]
               + (_SIGNS[None, :, 1:2] * half[:, None, 1:2]) * v[:, None, :])
    return corners, u[:, None, :]


def _nearest_corner_side_many(P, Q):
    """`_nearest_corner_side` of k polygon pairs: (distances (k,), corners (k, 2),
    points on sides (k, 2))."""
    ab = np.roll(Q, -1, axis=1) - Q  # (k, side, 2)
    ap = P[:, :, None, :] - Q[:, None, :, :]  # (k, corner, side, 2)
    t = np.clip((ap * ab[:, None]).sum(axis=3)
                / np.maximum((ab * ab).sum(axis=2), 1e-300)[:, None, :], 0.0, 1.0)
    q = Q[:, None, :, :] + t[..., None] * ab[:, None, :, :]
    d = np.sqrt(((q - P[:, :, None, :]) ** 2).sum(axis=3)).reshape(len(P), 16)
    best = d.argmin(axis=1)
    rows = np.arange(len(P))
    i, j = best // 4, best % 4
    return d[rows, best], P[rows, i], q[rows, i, j]
