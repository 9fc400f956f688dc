"""The narrow phase of a batched collision query: candidate pairs answered, all rows at once.

`broad.py` screens the candidate pairs of a `collision.CollisionChecker`
query; `Batch` answers the pairs that remain: upright boxes and cylinders in
closed form (prism.py), the rest by FCL pair by pair, whose answers are then
checked (certify.py for two polytopes, narrow.py otherwise) and whose joint
gradients are taken for the whole group at once. `Query` holds the placed
shapes of one configuration, for the queries of one pair at a time.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field

import fcl
import numpy as np

from tampcli.geometry import certify, prism, transforms
from tampcli.geometry.broad import PartTable
from tampcli.geometry.certify import Solids
from tampcli.geometry.narrow import (
    TOLERANCE,
    Placed,
    certified_pair,
    no_fcl,
    rounded,
    second_first,
)
from tampcli.geometry.parts import Part

SCALAR_PAIRS = 8  # groups of at most this many pairs skip the array set-up (measured)


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
        return (self._axes @ moment(point, normal)) * self.chain.moved_mask[link]


def moment(point, normal) -> np.ndarray:
    """[p x n, n]: a gradient basis row (chain.normal_gradient_basis) times this is
    n . d p / d q_i. In Python floats: np.cross costs ~20 us a call on 3-vectors."""
    p0, p1, p2 = point.tolist()
    n0, n1, n2 = normal.tolist()
    return np.array([p1 * n2 - p2 * n1, p2 * n0 - p0 * n2, p0 * n1 - p1 * n0, n0, n1, n2])


@dataclass(frozen=True, eq=False)
class Side:
    """One side of k candidate pairs: part index[t] of `table`, its owner at frames[t]."""

    table: PartTable
    index: np.ndarray  # (k,)
    frames: np.ndarray  # (k, 4, 4) owner frames in the world
    moves: np.ndarray | None  # (k,) the chain link that carries the owner; None: fixed

    def shape_frames(self) -> np.ndarray:
        """(k, 4, 4) world frames of the shapes."""
        if self.table.identity:
            return self.frames
        return np.matmul(self.frames, self.table.local[self.index])


_IDENTITY = fcl.Transform()
_FAR = sys.float_info.max


def fcl_distance(request, oa, ob, rot, pos, result):
    """FCL's signed distance of object oa at rotation rot, position pos in the frame of
    ob (which is put at the identity); None if FCL throws. The witness points, in ob's
    frame, are left in `result`.

    One relative placement per pair instead of two world ones: the answer depends on
    it alone, and setting a rotation and a translation costs less than building the
    fcl.Transform objects of both sides (measured: 0.7 against 1.5 us a pair).
    """
    ob.setTransform(_IDENTITY)
    oa.setRotation(rot)
    oa.setTranslation(pos)
    result.min_distance = _FAR  # a result keeps the least distance it has seen
    try:
        return fcl.distance(oa, ob, request, result)
    except RuntimeError:  # FCL's EPA can throw on degenerate contacts (fcl#319)
        return None


class Batch:
    """The narrow phase of one `distances_many` call, run group by group of pairs.

    Each group is a set of pairs (row, side a, side b); `narrow` answers them
    all and adds those within `activation` to the rows' contacts (`out`).
    """

    def __init__(self, checker, frames, activation):
        self.checker = checker
        self.frames = frames
        self.activation = activation
        self.out: list[list[Contact]] = [[] for _ in range(len(frames))]
        self._basis = None

    def basis(self) -> np.ndarray:
        """(S, n, 6) gradient bases of all samples (chain.normal_gradient_basis)."""
        if self._basis is None:
            self._basis = self.checker.world.chain.normal_gradient_basis_batch(self.frames)
        return self._basis

    def narrow(self, samples: np.ndarray, a: Side, b: Side) -> None:
        """Contacts of the pairs (samples[t], a's part t, b's part t) within activation."""
        k = len(samples)
        if k == 0:
            return
        wa, wb = a.shape_frames(), b.shape_frames()
        if k <= SCALAR_PAIRS:
            self._scalar(samples, a, wa, b, wb)
            return
        ra, xa, rb, xb = wa[:, :3, :3], wa[:, :3, 3], wb[:, :3, :3], wb[:, :3, 3]
        ta, tb, ia, ib = a.table, b.table, a.index, b.index
        dist = np.zeros(k)
        p1 = np.zeros((k, 3))
        p2 = np.zeros((k, 3))
        normal = np.zeros((k, 3))
        done = np.zeros(k, dtype=bool)  # certified answers
        asked = self._closed_forms(wa, a, wb, b, dist, p1, p2, normal, done)
        if self.checker.coal is not None:  # coal answers them (`_certified`)
            asked &= ~(ta.curved[ia] | tb.curved[ib])
        found = self._fcl(asked, ra, xa, rb, xb, a, b, dist, p1, p2)
        diff = p2 - p1
        norm = np.linalg.norm(diff, axis=1)
        unit = np.divide(diff, norm[:, None], out=np.zeros_like(diff),
                         where=norm[:, None] > 1e-12)
        apart = found & (dist > TOLERANCE) & (norm > 1e-12)
        polytopes = found & ta.polytope[ia] & tb.polytope[ib]
        solids_a = Solids(ta.vertices, ia, ra, xa, ta.box[ia])
        solids_b = Solids(tb.vertices, ib, rb, xb, tb.box[ib])
        rows = np.flatnonzero(apart & polytopes)
        if len(rows):
            rows = rows[certify.separated(dist[rows], unit[rows], solids_a.rows(rows),
                                          solids_b.rows(rows))]
            normal[rows] = unit[rows]
            done[rows] = True
        rows = np.flatnonzero(polytopes & ~apart)
        if len(rows):
            inside = dist[rows] <= 0.0
            # Penetrating, FCL's witness points lie inside the other solid: b to a.
            *answer, separating = certify.penetration(
                np.minimum(dist[rows], 0.0), p1[rows], p2[rows], -unit[rows],
                inside & (norm[rows] > 1e-12), solids_a.rows(rows), solids_b.rows(rows))
            ok = ~separating
            for array, value in zip((dist, p1, p2, normal), answer, strict=True):
                array[rows[ok]] = value[ok]
            done[rows[ok]] = True
        for t in np.flatnonzero(~done).tolist():
            raw = (float(dist[t]), p1[t].copy(), p2[t].copy()) if found[t] else None
            dist[t], p1[t], p2[t], normal[t] = self._certified(
                raw, ta.parts[int(ia[t])], wa[t], tb.parts[int(ib[t])], wb[t])
        margin_a, margin_b = ta.margin[ia], tb.margin[ib]
        dist -= margin_a + margin_b
        p1 += margin_a[:, None] * normal
        p2 -= margin_b[:, None] * normal
        self._contacts(samples, a, b, dist, p1, p2, normal)

    def _closed_forms(self, wa, a: Side, wb, b: Side, dist, p1, p2, normal, done):
        """Answer the pairs of upright boxes and cylinders (prism.py) in place; returns
        which pairs FCL is to answer (not those two tilted boxes in contact, narrow.no_fcl)."""
        asked = np.ones(len(wa), dtype=bool)
        rows = np.flatnonzero(a.table.prism[a.index] & b.table.prism[b.index]).tolist()
        if not rows:
            return asked
        placed = [(Placed(a.table.parts[a.index[t]].shape, wa[t]),
                   Placed(b.table.parts[b.index[t]].shape, wb[t])) for t in rows]
        boxes = [i for i, t in enumerate(rows) if a.table.box[a.index[t]]
                 and b.table.box[b.index[t]]]
        upright = dict(zip(boxes, prism.upright_boxes([placed[i] for i in boxes]), strict=True))
        for i, t in enumerate(rows):
            exact = upright.get(i)
            if exact is None:
                exact = prism.distance(*placed[i])
            if exact is not None:
                dist[t], p1[t], p2[t], normal[t] = exact
                done[t] = True
                asked[t] = False
            elif no_fcl(*placed[i]):
                asked[t] = False
        return asked

    def _fcl(self, asked, ra, xa, rb, xb, a: Side, b: Side, dist, p1, p2) -> np.ndarray:
        """FCL's answers of the pairs asked, in place (world witness points); returns
        which pairs it answered."""
        rows = np.flatnonzero(asked)
        found = np.zeros(len(asked), dtype=bool)
        if not len(rows):
            return found
        rot, pos = _relative(ra[rows], xa[rows], rb[rows], xb[rows])
        near = np.zeros((len(rows), 2, 3))
        request = self.checker._request
        result = fcl.DistanceResult()
        objs_a, objs_b = a.table.objs, b.table.objs
        answered = np.zeros(len(rows), dtype=bool)
        for i, (t, ja, jb) in enumerate(zip(rows.tolist(), a.index[rows].tolist(),
                                           b.index[rows].tolist(), strict=True)):
            d = fcl_distance(request, objs_a[ja], objs_b[jb], rot[i], pos[i], result)
            if d is not None:
                dist[t] = d
                near[i] = result.nearest_points
                answered[i] = True
        rows = rows[answered]
        near = near[answered]
        world = np.matmul(near, rb[rows].transpose(0, 2, 1)) + xb[rows][:, None]
        p1[rows], p2[rows] = world[:, 0], world[:, 1]
        found[rows] = True
        return found

    def _contacts(self, samples, a: Side, b: Side, dist, p1, p2, normal) -> None:
        """The contacts within activation, with their joint gradients."""
        within = np.flatnonzero(dist <= self.activation)
        if not len(within):
            return
        grad = np.zeros((len(within), self.checker.n))
        rows = samples[within]
        chain = self.checker.world.chain
        n = normal[within]
        basis = self.basis()[rows]
        for sign, side, point in ((-1.0, a, p1), (1.0, b, p2)):
            if side.moves is None:
                continue
            v = np.concatenate([transforms.cross(point[within], n), n], axis=1)
            g = np.matmul(basis, v[:, :, None])[:, :, 0]
            g *= chain.moved_mask[side.moves[within]]
            if sign > 0:
                grad += g
            else:
                grad -= g
        parts_a, parts_b = a.table.parts, b.table.parts
        out = self.out
        for s, ja, jb, d, pa, pb_, u, g in zip(
                rows.tolist(), a.index[within].tolist(), b.index[within].tolist(),
                dist[within].tolist(), p1[within], p2[within], normal[within], grad,
                strict=True):
            out[s].append(Contact(parts_a[ja].owner, parts_b[jb].owner, d, pa, pb_, u, g))

    def _scalar(self, samples, a: Side, wa, b: Side, wb) -> None:
        """`narrow` pair by pair (narrow.py's checks): cheaper than the arrays' set-up
        for a handful of pairs. FCL is asked as in `_fcl`, so both paths get the
        same answers from it."""
        ra, xa, rb, xb = wa[:, :3, :3], wa[:, :3, 3], wb[:, :3, :3], wb[:, :3, 3]
        rot, pos = _relative(ra, xa, rb, xb)
        request = self.checker._request
        result = fcl.DistanceResult()
        mask = self.checker.world.chain.moved_mask
        ta, tb = a.table, b.table
        for t, (s, ja, jb) in enumerate(zip(samples.tolist(), a.index.tolist(),
                                            b.index.tolist(), strict=True)):
            pa, pb_ = ta.parts[ja], tb.parts[jb]
            answer = None
            if ta.prism[ja] and tb.prism[jb]:
                answer = prism.distance(Placed(pa.shape, wa[t]), Placed(pb_.shape, wb[t]))
            if answer is None:
                raw = None
                if not second_first(pa.shape, pb_.shape, self.checker.coal) and not (
                        ta.box[ja] and tb.box[jb]
                        and no_fcl(Placed(pa.shape, wa[t]), Placed(pb_.shape, wb[t]))):
                    d = fcl_distance(request, pa.obj, pb_.obj, rot[t], pos[t], result)
                    if d is not None:
                        near_a, near_b = result.nearest_points
                        raw = (d, rb[t] @ near_a + xb[t], rb[t] @ near_b + xb[t])
                answer = self._certified(raw, pa, wa[t], pb_, wb[t])
            d, p1, p2, n = rounded(*answer, pa.shape.margin, pb_.shape.margin)
            if d > self.activation:
                continue
            grad = np.zeros(self.checker.n)
            basis = self.basis()[s]
            if a.moves is not None:
                grad -= (basis @ moment(p1, n)) * mask[a.moves[t]]
            if b.moves is not None:
                grad += (basis @ moment(p2, n)) * mask[b.moves[t]]
            self.out[s].append(Contact(pa.owner, pb_.owner, float(d), p1, p2, n, grad))

    def _certified(self, raw, pa: Part, wa, pb_: Part, wb):
        """narrow.certified_pair of FCL's answer (in the world) for one pair: coal
        (coal_query.py) asked when it fails the check, or first (narrow.second_first)."""
        return certified_pair(raw, Placed(pa.shape, wa), Placed(pb_.shape, wb),
                              self.checker.coal)


def _relative(ra, xa, rb, xb):
    """(rotations (k, 3, 3), positions (k, 3)) of frames a in frames b."""
    return np.matmul(rb.transpose(0, 2, 1), ra), np.einsum("kji,kj->ki", rb, xa - xb)
