"""The broad phase of a batched collision query: which candidate pairs reach FCL.

`collision.CollisionChecker` decides which pairs a query covers; this module
screens them, all rows at once: world-aligned boxes and spheres first
(`broad_gaps`), then oriented boxes and hull points (`screen`, obb.py). Each
screen bounds the distance from below, so a pair either puts beyond the
activation distance never reaches the narrow phase (pairs.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.geometry import obb
from tampcli.geometry.narrow import CURVED, PRISMS
from tampcli.geometry.parts import Part

HULL_SCREEN = 4  # the hull-point screen pays for itself from this many candidates on
# Relative error bound on a float32 projection u . p (a few roundings of 6e-8 each), with
# room to spare: the hull screen's products are float32 (measured 1.7 times faster
# than float64), and it widens its bound by this much per metre of the points' reach.
FLOAT32_ERROR = 1e-6


@dataclass(frozen=True, eq=False)
class PartTable:
    """A list of parts and what the batched phases need of each, as arrays over parts.

    Built once per list (the robot's links, the scene's body parts, a held
    object's parts): a batch then names parts by their index in the table.
    """

    parts: tuple[Part, ...]
    obb_center: np.ndarray  # (P, 3) oriented boxes around the solids, owner frames
    obb_rot: np.ndarray  # (P, 3, 3)
    obb_half: np.ndarray  # (P, 3)
    sphere: np.ndarray  # (P, 3) bounding-sphere centres, owner frames
    radius: np.ndarray  # (P,)
    hulls32: obb.PointSets  # owner-frame points whose hull holds each solid, float32
    slack: np.ndarray  # (P,) m, more than float32's error on a hull point's projection
    vertices: obb.PointSets  # each polytope's vertices in its shape frame (certify.py)
    local: np.ndarray  # (P, 4, 4) shape frames in the owner frames
    identity: bool  # every shape frame is its owner's frame
    polytope: np.ndarray  # (P,) the solid is the hull of `vertices`
    prism: np.ndarray  # (P,) a box or cylinder (prism.py answers them upright)
    box: np.ndarray  # (P,)
    curved: np.ndarray  # (P,) a cylinder or capsule: coal, not FCL, is asked (pairs.py)
    margin: np.ndarray  # (P,) m, the rounding of each shape (shapes.py)
    objs: tuple  # the FCL objects

    @classmethod
    def of(cls, parts) -> PartTable:
        parts = tuple(parts)
        shapes = [p.shape for p in parts]
        return cls(parts,
                   np.array([p.obb_center for p in parts]).reshape(-1, 3),
                   np.array([p.obb_rot for p in parts]).reshape(-1, 3, 3),
                   np.array([p.obb_half for p in parts]).reshape(-1, 3),
                   np.array([s.center for s in shapes]).reshape(-1, 3),
                   np.array([s.radius for s in shapes], dtype=float),
                   obb.PointSets([p.hull for p in parts], np.float32),
                   np.array([FLOAT32_ERROR * (1.0 + np.linalg.norm(p.hull, axis=1).max())
                             for p in parts]),
                   obb.PointSets([s.vertices for s in shapes]),
                   np.array([s.local for s in shapes]).reshape(-1, 4, 4),
                   all(p.identity_local for p in parts),
                   np.array([s.vertices is not None for s in shapes], dtype=bool),
                   np.array([s.kind in PRISMS for s in shapes], dtype=bool),
                   np.array([s.kind == "box" for s in shapes], dtype=bool),
                   np.array([s.kind in CURVED for s in shapes], dtype=bool),
                   np.array([s.margin for s in shapes], dtype=float),
                   tuple(p.obj for p in parts))


class Boxes:
    """Oriented boxes and bounding spheres of a table's parts, in the world.

    Arrays have leading dimensions (..., P) for the table's P parts: owner
    frames (4, 4), centres (3,), axes (3, 3), half extents (3,), world-aligned
    half extents (3,), sphere centres (3,) and radii.
    """

    __slots__ = ("table", "frames", "c", "r", "h", "aabb", "s", "radius")

    def __init__(self, frames, table: PartTable):
        self.table = table
        self.frames = frames
        self.c, self.r = obb.world(frames, table.obb_center, table.obb_rot)
        self.h = table.obb_half
        self.aabb = obb.aabb_half(self.r, self.h)
        rf = frames[..., :3, :3]
        self.s = np.matmul(rf, table.sphere[..., None])[..., 0] + frames[..., :3, 3]
        self.radius = table.radius


def screen(activation, a: Boxes, ia: tuple, pa, b: Boxes, ib: tuple, pb_) -> np.ndarray:
    """Which candidate pairs may be within `activation`: oriented boxes, then hulls.

    `ia`, `ib` index the boxes' arrays (sample and part indices, or part
    indices alone for unbatched sets); `pa`, `pb_` the part indices. Many
    candidates go straight to the hulls, whose bound is the tighter on the same
    directions and starts with the cheapest one (obb.hull_gaps' `beyond`): the
    boxes' screen would cost more than it saves them (measured on a Panda).
    """
    if len(pa) >= obb.GROUPED_FROM:
        keep = np.ones(len(pa), dtype=bool)
    else:
        keep = obb.gaps(a.c[ia], a.r[ia], a.h[pa], b.c[ib], b.r[ib], b.h[pb_]) <= activation
        if keep.sum() < HULL_SCREEN:
            return keep
    sub_a = tuple(i[keep] for i in ia)
    sub_b = tuple(i[keep] for i in ib)
    pa, pb_ = pa[keep], pb_[keep]
    beyond = activation + a.table.slack[pa] + b.table.slack[pb_]
    keep[keep] = obb.hull_gaps(a.table.hulls32, pa, a.frames[sub_a], a.r[sub_a], a.h[pa],
                               b.table.hulls32, pb_, b.frames[sub_b], b.r[sub_b], b.h[pb_],
                               a.c[sub_a], b.c[sub_b], beyond) <= beyond
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
    """Lower bounds (broadcast shape) from world-aligned boxes and spheres: the larger.

    Centres and half extents are (..., 3) arrays, radii (...). On many rows the
    arithmetic runs on the transposes (components first, rows last), so that
    numpy's innermost loops run along the rows rather than over 3 components (1.5
    times faster, measured on 200 configurations); the answer is transposed back.
    """
    if np.shape(a_c)[0] < TRANSPOSED_FROM:
        apart = np.abs(a_c - b_c) - a_aabb - b_aabb
        np.maximum(apart, 0.0, out=apart)
        between = a_s - b_s
        sphere = np.sqrt(np.einsum("...i,...i->...", between, between)) - a_radius - b_radius
        return np.maximum(np.sqrt(np.einsum("...i,...i->...", apart, apart)), sphere)
    ndim = max(np.ndim(a_c), np.ndim(b_c))

    def rev(x, extra=0):
        x = np.asarray(x)
        return x.reshape((1,) * (ndim - extra - x.ndim) + x.shape).T

    a_c, a_aabb, a_s, b_c, b_aabb, b_s = (rev(x) for x in (a_c, a_aabb, a_s, b_c, b_aabb, b_s))
    apart = np.abs(a_c - b_c)
    apart -= a_aabb
    apart -= b_aabb
    np.maximum(apart, 0.0, out=apart)
    apart *= apart
    between = a_s - b_s
    between *= between
    sphere = np.sqrt(between[0] + between[1] + between[2])
    sphere -= rev(a_radius, 1) + rev(b_radius, 1)
    return np.maximum(np.sqrt(apart[0] + apart[1] + apart[2]), sphere).T


TRANSPOSED_FROM = 8  # rows (a's leading dimension) from which broad_gaps transposes
