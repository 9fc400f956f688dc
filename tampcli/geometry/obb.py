"""Oriented bounding boxes and hull vertices of the collision parts, and two
vectorized lower bounds on the distance between many pairs at once.

The broad phase of `collision.py` screens every (sample, part, body) triple
with world-aligned boxes and spheres; the pairs that survive are screened
again here, all together: first by the separating-axis gap of their
oriented boxes (`gaps`), then by the gap between the projections of their
hull vertices on the same axes (`hull_gaps`, tighter for long links whose
box is loose). Each bounds the distance between the solids from below, so a
pair either puts beyond the activation distance is dropped without a
narrow-phase query: a few numpy expressions for all pairs of a batch
instead of a Python call per pair.
"""

from __future__ import annotations

import numpy as np


def fit(shape) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(centre (3,), axes (3, 3) as columns, half extents (3,)) of a box around the
    solid, in the frame of the shape's owner (the shape's `local` applied)."""
    rot = np.eye(3)
    center = np.zeros(3)
    if shape.kind == "box":
        half = 0.5 * np.asarray(shape.size, dtype=float)
    elif shape.kind == "sphere":
        half = np.full(3, shape.size[0])
    elif shape.kind in ("cylinder", "capsule"):
        r, h = shape.size
        half = np.array([r, r, 0.5 * h + (r if shape.kind == "capsule" else 0.0)])
    else:
        center, rot, half = _fit_points(np.asarray(shape.vertices, dtype=float))
    local_rot, local_pos = shape.local[:3, :3], shape.local[:3, 3]
    return local_rot @ center + local_pos, local_rot @ rot, half


def _fit_points(points: np.ndarray):
    """The smaller of the frame-aligned box and the box on the principal axes."""
    best = None
    candidates = [np.eye(3)]
    if len(points) >= 4:
        spread = np.cov((points - points.mean(axis=0)).T)
        _, vectors = np.linalg.eigh(spread)
        if np.linalg.det(vectors) < 0:
            vectors[:, 0] = -vectors[:, 0]
        candidates.append(vectors)
    for rot in candidates:
        local = points @ rot
        lo, hi = local.min(axis=0), local.max(axis=0)
        half = 0.5 * (hi - lo)
        volume = float(np.prod(2 * half))
        if best is None or volume < best[0]:
            best = (volume, rot @ (0.5 * (lo + hi)), rot, half)
    return best[1], best[2], best[3]


def world(frames: np.ndarray, center: np.ndarray, rot: np.ndarray):
    """World centres (..., 3) and axes (..., 3, 3) of boxes given in owner frames.

    frames (..., 4, 4); center (..., 3) and rot (..., 3, 3) broadcast against them.
    """
    r = frames[..., :3, :3]
    # matmul, not einsum: 4x faster on broadcast stacks of 3-vectors (measured)
    return np.matmul(r, center[..., None])[..., 0] + frames[..., :3, 3], np.matmul(r, rot)


def aabb_half(rot: np.ndarray, half: np.ndarray) -> np.ndarray:
    """Half extents (..., 3) of the world-aligned box around oriented boxes."""
    return np.matmul(np.abs(rot), half[..., None])[..., 0]


def gaps(ca, ra, ha, cb, rb, hb) -> np.ndarray:
    """(k,) lower bounds on the distances between k pairs of oriented boxes.

    Centres (k, 3), axes (k, 3, 3) (columns), half extents (k, 3). The widest
    gap between the boxes' projections on the 7 axes tried; negative when they
    overlap on all of them.
    """
    d = cb - ca
    norm = np.linalg.norm(d, axis=1, keepdims=True)
    line = np.divide(d, norm, out=np.zeros_like(d), where=norm > 1e-12)
    axes = np.concatenate([ra.transpose(0, 2, 1), rb.transpose(0, 2, 1), line[:, None, :]],
                          axis=1)  # (k, 7, 3): unit directions as rows
    reach_a = np.einsum("kam,km->ka", np.abs(np.matmul(axes, ra)), ha)
    reach_b = np.einsum("kam,km->ka", np.abs(np.matmul(axes, rb)), hb)
    apart = np.abs(np.einsum("kai,ki->ka", axes, d))
    return (apart - reach_a - reach_b).max(axis=1)


def hull_points(shape, center, rot, half) -> np.ndarray:
    """(V, 3) points, in the owner frame, whose convex hull contains the solid.

    A convex solid's own vertices (a box's 8 corners); for curved solids the
    corners of their oriented box (a superset, so projections still bound).
    """
    if shape.vertices is not None:
        return shape.vertices @ shape.local[:3, :3].T + shape.local[:3, 3]
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)],
                       dtype=float) * half
    return corners @ rot.T + center


GROUPED_FROM = 128  # pairs from which `hull_gaps` saves products at the cost of calls
# Points `reach` gathers padded at most; beyond, it takes the solids set by set (the
# measured crossover on a Panda's links, 11 sets of up to 260 points: ~130 solids).
PADDED_POINTS = 32768


class PointSets:
    """The point sets (V_i, 3) of several solids, each in its own frame, as `reach`
    takes them: one array per set, and all of them padded to one size by repeating
    their first point (which changes no maximum). A solid given no points (None: a
    curved one, never to be asked) gets the origin."""

    __slots__ = ("sets", "padded")

    def __init__(self, sets, dtype=float):
        self.sets = tuple(np.zeros((1, 3), dtype=dtype) if p is None
                          else np.asarray(p, dtype=dtype) for p in sets)
        size = max((len(p) for p in self.sets), default=1)
        self.padded = np.empty((len(self.sets), size, 3), dtype=dtype)
        for i, p in enumerate(self.sets):
            self.padded[i, :len(p)] = p
            self.padded[i, len(p):] = p[0]

    def gathered(self, k: int) -> bool:
        """Whether k solids are taken padded, gathered in one array (else set by set)."""
        return k * self.padded.shape[1] <= PADDED_POINTS


def groups(index: np.ndarray) -> list[np.ndarray]:
    """The positions of equal values of `index`, one array per value (ascending).

    Sliced by hand: np.split costs ~70 us a call in its Python-level axis swaps.
    """
    order = np.argsort(index, kind="stable")
    cuts = [0, *(np.flatnonzero(np.diff(index[order])) + 1).tolist(), len(order)]
    return [order[lo:hi] for lo, hi in zip(cuts[:-1], cuts[1:], strict=True) if hi > lo]


def hull_gaps(table_a, index_a, frames_a, ra, ha, table_b, index_b, frames_b, rb, hb, ca,
              cb, beyond=None) -> np.ndarray:
    """(k,) lower bounds on the distances between k pairs of solids given by points.

    Side a of pair t is the hull of the point set index_a[t] of table_a
    (`PointSets`, owner frames) placed by frames_a[t] (4, 4), with the oriented box (`fit`)
    of centre ca[t], axes ra[t] (3, 3) and half extents ha[t]; likewise b. The
    directions tried are those of `gaps`.

    `beyond` (k,), when given: a pair whose gap along the centre line alone
    exceeds it keeps that gap (a lower bound too) without the other 6 directions.
    On a Panda's self pairs the centre line drops 566 of the 577 pairs all 7
    directions drop, for a quarter of the work.
    """
    d = cb - ca
    norm = np.linalg.norm(d, axis=1, keepdims=True)
    line = np.divide(d, norm, out=np.zeros_like(d), where=norm > 1e-12)
    if beyond is not None and len(d) >= GROUPED_FROM:
        u = line[:, None, :]
        gap = -(reach(table_a, index_a, frames_a[:, :3, :3], frames_a[:, :3, 3], u)
                + reach(table_b, index_b, frames_b[:, :3, :3], frames_b[:, :3, 3], -u))[:, 0]
        todo = np.flatnonzero(gap <= beyond)
        gap[todo] = hull_gaps(table_a, index_a[todo], frames_a[todo], ra[todo], ha[todo],
                              table_b, index_b[todo], frames_b[todo], rb[todo], hb[todo],
                              ca[todo], cb[todo])
        return gap
    axes = np.concatenate([ra.transpose(0, 2, 1), rb.transpose(0, 2, 1), line[:, None, :]],
                          axis=1)  # (k, 7, 3)
    axes = axes * np.where(np.einsum("kai,ki->ka", axes, d) < 0, -1.0, 1.0)[:, :, None]
    if len(d) < GROUPED_FROM:  # few pairs: fewer calls, all directions through the points
        top_a = reach(table_a, index_a, frames_a[:, :3, :3], frames_a[:, :3, 3], axes)
        top_b = reach(table_b, index_b, frames_b[:, :3, :3], frames_b[:, :3, 3], -axes)
        return (-(top_a + top_b)).max(axis=1)
    # A box from `fit` touches its points on each face: on its own axes a solid's
    # support is its box's, and only the other 4 directions need its points.
    top_a = np.empty(axes.shape[:2])
    top_a[:, :3] = np.einsum("kai,ki->ka", axes[:, :3], ca) + ha
    top_a[:, 3:] = reach(table_a, index_a, frames_a[:, :3, :3], frames_a[:, :3, 3], axes[:, 3:])
    top_b = np.empty(axes.shape[:2])
    top_b[:, 3:6] = hb - np.einsum("kai,ki->ka", axes[:, 3:6], cb)
    top_b[:, _OTHER_B] = reach(table_b, index_b, frames_b[:, :3, :3], frames_b[:, :3, 3],
                               -axes[:, _OTHER_B])
    return (-(top_a + top_b)).max(axis=1)


_OTHER_B = [0, 1, 2, 6]  # the directions of `hull_gaps` that are not b's own axes


def reach(points: PointSets, index, rot, pos, axes) -> np.ndarray:
    """(k, m): max over solid t's points of u . x, for its m world directions u.

    Solid t is point set index[t] of `points` at rotation rot[t] (3, 3) and
    position pos[t] (3,); axes (k, m, 3). The products are in the points' dtype.
    Many solids of large sets are taken set by set, one matrix product per set:
    sets differ in size (a Panda link has 102 to 260 hull points), and gathering a
    padded copy per solid then costs more than the products; otherwise they are
    gathered padded, which saves the grouping's calls (`PointSets.gathered`).
    """
    k, m = axes.shape[:2]
    # (k, m, 3): directions in the solids' frames
    local = np.matmul(axes, rot).astype(points.padded.dtype, copy=False)
    if points.gathered(k):
        top = np.matmul(local, points.padded[index].transpose(0, 2, 1)).max(axis=2)
    else:
        top = np.empty((k, m))
        for rows in groups(index):
            top[rows] = (local[rows].reshape(-1, 3) @ points.sets[index[rows[0]]].T).max(
                axis=1).reshape(-1, m)
    return top + np.einsum("kai,ki->ka", axes, pos)


def support_points(points: PointSets, index, rot, pos, u) -> np.ndarray:
    """(k, 3): a world point of solid t (as in `reach`) maximizing u[t] . x; u (k, 3)."""
    local = np.einsum("ki,kij->kj", u, rot)
    if points.gathered(len(u)):
        sets = points.padded[index]
        best = np.einsum("kvi,ki->kv", sets, local).argmax(axis=1)
        out = sets[np.arange(len(u)), best]
    else:
        out = np.empty((len(u), 3))
        for rows in groups(index):
            p = points.sets[index[rows[0]]]
            out[rows] = p[(local[rows] @ p.T).argmax(axis=1)]
    return np.einsum("kij,kj->ki", rot, out) + pos
