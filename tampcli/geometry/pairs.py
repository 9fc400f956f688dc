"""Candidate pairs of a batched collision query and their narrow phase, all rows at once.

`collision.CollisionChecker` decides which pairs a query covers; this module
holds what a batch of rows needs: placed shapes per row (`Query`), the
oriented boxes, hulls and spheres of a set of parts in the world (`Boxes`),
the two vectorized screens (`broad_gaps`: world-aligned boxes and spheres;
`screen`: oriented boxes, then hull points), and `Batch`, which runs FCL on
each surviving pair, checks its answers and takes the joint gradients of a
whole group of pairs together.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from tampcli.geometry import obb, prism, transforms
from tampcli.geometry.narrow import (
    PRISMS,
    TOLERANCE,
    Placed,
    checked,
    fcl_distance,
    no_fcl,
    signed_distance,
)
from tampcli.geometry.parts import Part

SCALAR_PAIRS = 4  # groups of at most this many pairs skip the array set-up (measured)
HULL_SCREEN = 4  # the hull-point screen pays for itself from this many candidates on


@dataclass(frozen=True)
class Contact:
    a: str  # "link:NAME", "held:NAME" or "body:NAME"
    b: str
    distance: float  # signed, m; negative = penetration
    point_a: np.ndarray = field(repr=False)  # world witness point on a
    point_b: np.ndarray = field(repr=False)
    normal: np.ndarray = field(repr=False)  # unit, from a to b
    gradient: np.ndarray = field(repr=False)  # (n,) d distance / d q


class Query:
    """Per-configuration state: link frames, joint axes and placed link shapes.

    `shared` holds the placed shapes of scene bodies, which do not depend on
    the configuration: one dict for all samples of a batch.
    """

    __slots__ = ("frames", "chain", "_axes", "_placed", "_shared")

    def __init__(self, chain, frames, shared: dict):
        self.chain = chain
        self.frames = frames
        self._axes = None
        self._placed: dict = {}
        self._shared = shared

    def placed(self, key, part: Part, pose: np.ndarray | None) -> Placed:
        cache = self._shared if isinstance(key, tuple) and key[0] == "body" else self._placed
        found = cache.get(key)
        if found is None:
            if pose is None:
                pose = self.frames[part.link]
            t = pose if part.identity_local else pose @ part.shape.local
            found = Placed(part.shape, t)
            cache[key] = found
        return found

    def normal_gradient(self, link: int, point, normal) -> np.ndarray:
        """normal . d point / d q for a point attached to chain link `link`."""
        if self._axes is None:
            self._axes = self.chain.normal_gradient_basis(self.frames)
        p0, p1, p2 = point.tolist()
        n0, n1, n2 = normal.tolist()
        v = np.array([p1 * n2 - p2 * n1, p2 * n0 - p0 * n2, p0 * n1 - p1 * n0, n0, n1, n2])
        return (self._axes @ v) * self.chain.moved_mask[link]


class Boxes:
    """Oriented boxes and bounding spheres of a set of parts, in the world.

    Arrays have leading dimensions (..., k) for k parts: centres (3,), axes
    (3, 3), half extents (3,), world-aligned half extents (3,), sphere
    centres (3,) and radii.
    """

    __slots__ = ("frames", "c", "r", "h", "aabb", "s", "radius", "points")

    def __init__(self, frames, parts: list[Part], local=None):
        if local is None:
            local = local_boxes(parts)
        center, rot, half, sphere, radius, self.points = local
        self.frames = frames
        self.c, self.r = obb.world(frames, center, rot)
        self.h = half
        self.aabb = obb.aabb_half(self.r, half)
        rf = frames[..., :3, :3]
        self.s = np.einsum("...ij,...j->...i", rf, sphere) + frames[..., :3, 3]
        self.radius = radius


def local_boxes(parts: list[Part]):
    return (np.array([p.obb_center for p in parts]).reshape(-1, 3),
            np.array([p.obb_rot for p in parts]).reshape(-1, 3, 3),
            np.array([p.obb_half for p in parts]).reshape(-1, 3),
            np.array([p.shape.center for p in parts]).reshape(-1, 3),
            np.array([p.shape.radius for p in parts]),
            obb.padded([p.hull for p in parts]))


def screen(activation, a: Boxes, ia: tuple, pa, b: Boxes, ib: tuple, pb_) -> np.ndarray:
    """Which candidate pairs may be within `activation`: oriented boxes, then hulls.

    `ia`, `ib` index the boxes' arrays (sample and part indices, or part
    indices alone for unbatched sets); `pa`, `pb_` the part indices.
    """
    keep = obb.gaps(a.c[ia], a.r[ia], a.h[pa], b.c[ib], b.r[ib], b.h[pb_]) <= activation
    if keep.sum() < HULL_SCREEN:
        return keep
    sub_a = tuple(i[keep] for i in ia)
    sub_b = tuple(i[keep] for i in ib)
    keep[keep] = obb.hull_gaps(a.frames[sub_a], a.points[pa[keep]], a.r[sub_a],
                               b.frames[sub_b], b.points[pb_[keep]], b.r[sub_b],
                               a.c[sub_a], b.c[sub_b]) <= activation
    return keep


def masks(link_parts: list[Part], n_body_parts: int, parts_of: dict[str, list[int]],
          ignores, held_names):
    """(usable (S, link parts), columns (S, body parts)) from the names ignored and the
    object held at each row; `parts_of`: body name -> its columns."""
    n_samples = len(ignores)
    usable = np.ones((n_samples, len(link_parts)), dtype=bool)
    columns = np.ones((n_samples, n_body_parts), dtype=bool)
    for s, (ignore, held_name) in enumerate(zip(ignores, held_names, strict=True)):
        for j in parts_of.get(held_name, ()):
            columns[s, j] = False
        if not ignore:
            continue
        usable[s] = [p.owner not in ignore and p.owner.partition(":")[2] not in ignore
                     for p in link_parts]
        for name in ignore:
            bare = name.partition(":")[2] if name.startswith("body:") else name
            for j in parts_of.get(bare, ()):
                columns[s, j] = False
    return usable, columns


def broad_gaps(a_c, a_aabb, a_s, a_radius, b_c, b_aabb, b_s, b_radius) -> np.ndarray:
    """Lower bounds (broadcast shape) from world-aligned boxes and spheres: the larger."""
    apart = np.abs(a_c - b_c) - a_aabb - b_aabb
    box = np.sqrt((np.maximum(apart, 0.0) ** 2).sum(axis=-1))
    sphere = np.linalg.norm(a_s - b_s, axis=-1) - a_radius - b_radius
    return np.maximum(box, sphere)


class Batch:
    """The narrow phase of one `distances_many` call, run group by group of pairs.

    FCL answers each pair; the check of its answer (the gap of the two
    solids' projections on its normal, narrow.py) and the joint gradients are
    then computed for the whole group at once. Pairs whose check fails, or
    with a curved solid, take narrow.py's scalar path.
    """

    def __init__(self, checker, queries, frames, activation):
        self.checker = checker
        self.queries = queries
        self.frames = frames
        self.activation = activation
        self.out: list[list[Contact]] = [[] for _ in queries]
        self._basis = None

    def basis(self) -> np.ndarray:
        """(S, n, 6) gradient bases of all samples (chain.normal_gradient_basis)."""
        if self._basis is None:
            self._basis = self.checker.world.chain.normal_gradient_basis_batch(self.frames)
        return self._basis

    def narrow(self, samples, sides_a, sides_b, geom_a, geom_b) -> None:
        """Contacts of pairs (samples[t], sides_a[t], sides_b[t]) within activation.

        A side is (cache key, part, owner pose or None for a link); a geometry
        is (owner frames (k, 4, 4), hull points (k, V, 3), exact (k,), moving
        chain link (k,) or None when that side does not move with q).
        """
        k = len(sides_a)
        if k == 0:
            return
        if k <= SCALAR_PAIRS:
            self._scalar(samples.tolist(), sides_a, sides_b, geom_a[3], geom_b[3])
            return
        request = self.checker._request
        dist = np.empty(k)
        p1 = np.zeros((k, 3))
        p2 = np.zeros((k, 3))
        raws, placed = [], []
        closed = np.zeros(k, dtype=bool)  # answered exactly by prism.py
        samples = samples.tolist()
        for s, (key_a, pa, pose_a), (key_b, pb_, pose_b) in zip(samples, sides_a, sides_b,
                                                                strict=True):
            query = self.queries[s]
            placed.append((query.placed(key_a, pa, pose_a), query.placed(key_b, pb_, pose_b)))
        # Upright boxes apart in the plane, all at once (prism.upright_boxes).
        boxes = [t for t, (a, b) in enumerate(placed)
                 if a.shape.kind == "box" and b.shape.kind == "box"]
        upright = dict(zip(boxes, prism.upright_boxes([placed[t] for t in boxes]),
                           strict=True))
        for t, (a, b) in enumerate(placed):
            pa, pb_ = sides_a[t][1], sides_b[t][1]
            exact = upright.get(t)
            if exact is None and pa.shape.kind in PRISMS and pb_.shape.kind in PRISMS:
                exact = prism.distance(a, b)
            if exact is not None:
                raws.append(exact)
                closed[t] = True
                dist[t], p1[t], p2[t], _ = exact
                continue
            raw = None if no_fcl(a, b) else fcl_distance(request, a, pa.obj, b, pb_.obj)
            raws.append(raw)
            if raw is None:
                dist[t] = -math.inf
            else:
                dist[t], p1[t], p2[t] = raw
        diff = p2 - p1
        norm = np.linalg.norm(diff, axis=1)
        quick = (dist > TOLERANCE) & (norm > 1e-12) & geom_a[2] & geom_b[2] & ~closed
        normal = np.divide(diff, norm[:, None], out=np.zeros_like(diff),
                           where=norm[:, None] > 1e-12)
        for t in np.nonzero(closed)[0].tolist():
            normal[t] = raws[t][3]
        if quick.any():
            u = normal[quick][:, None, :]
            gap = obb.reach(geom_a[0][quick], geom_a[1][quick], u)[:, 0] + obb.reach(
                geom_b[0][quick], geom_b[1][quick], -u)[:, 0]
            quick[quick] = dist[quick] + gap <= TOLERANCE
        for t in np.nonzero(~quick & ~closed)[0].tolist():
            dist[t], p1[t], p2[t], normal[t] = checked(raws[t], *placed[t])
        margin_a = np.array([side[1].shape.margin for side in sides_a])
        margin_b = np.array([side[1].shape.margin for side in sides_b])
        dist -= margin_a + margin_b
        p1 += margin_a[:, None] * normal
        p2 -= margin_b[:, None] * normal
        within = dist <= self.activation
        if not within.any():
            return
        grad = np.zeros((k, self.checker.n))
        chain = self.checker.world.chain
        for sign, geom, point in ((-1.0, geom_a, p1), (1.0, geom_b, p2)):
            moves = geom[3]
            if moves is None:
                continue
            v = np.concatenate([transforms.cross(point, normal), normal], axis=1)
            g = np.einsum("kij,kj->ki", self.basis()[samples], v)
            grad += sign * g * chain.moved_mask[moves]
        for t in np.nonzero(within)[0].tolist():
            self.out[samples[t]].append(Contact(sides_a[t][1].owner, sides_b[t][1].owner,
                                                float(dist[t]), p1[t], p2[t], normal[t],
                                                grad[t]))

    def _scalar(self, samples, sides_a, sides_b, moves_a, moves_b) -> None:
        """`narrow` pair by pair: cheaper than array set-up for a handful of pairs."""
        checker = self.checker
        request = checker._request
        for t, (s, (key_a, pa, pose_a), (key_b, pb_, pose_b)) in enumerate(
                zip(samples, sides_a, sides_b, strict=True)):
            query = self.queries[s]
            a, b = query.placed(key_a, pa, pose_a), query.placed(key_b, pb_, pose_b)
            d, p1, p2, n = signed_distance(request, a, pa.obj, b, pb_.obj)
            if d > self.activation:
                continue
            grad = np.zeros(checker.n)
            if moves_a is not None:
                grad -= query.normal_gradient(int(moves_a[t]), p1, n)
            if moves_b is not None:
                grad += query.normal_gradient(int(moves_b[t]), p2, n)
            self.out[s].append(Contact(pa.owner, pb_.owner, d, p1, p2, n, grad))
