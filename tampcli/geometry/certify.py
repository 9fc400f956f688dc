"""narrow.py's checks of FCL's answers, for many pairs of polytopes at once.

The same bounds as `narrow.checked`, in array operations over all pairs of a
batch whose two solids are polytopes (convex hulls and boxes, whose support
is exact over their vertices): a separated answer is kept when the gap of the
solids' projections on its normal meets its distance (`separated`); a
touching or penetrating one is bounded by the least overlap of the solids'
projections over the same candidate directions as `narrow._candidates`
(`penetration`). What these leave undecided (a separating direction found
where FCL saw contact, or a separated answer off by more than TOLERANCE) goes
pair by pair to `narrow.certified` (FCL asked once more, then our GJK).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.geometry import obb
from tampcli.geometry.narrow import TOLERANCE

_WORLD_AXES = np.vstack([np.eye(3), -np.eye(3)])


@dataclass(frozen=True, eq=False)
class Solids:
    """One side of k pairs of polytopes in the world.

    Solid t is the hull of point set index[t] of `vertices` (obb.PointSets, in
    its shape frame) at rotation rot[t] and position pos[t]; box[t] says it is a
    box (whose face normals are candidate directions).
    """

    vertices: obb.PointSets
    index: np.ndarray  # (k,)
    rot: np.ndarray  # (k, 3, 3)
    pos: np.ndarray  # (k, 3)
    box: np.ndarray  # (k,) bool

    def rows(self, rows) -> Solids:
        return Solids(self.vertices, self.index[rows], self.rot[rows], self.pos[rows],
                      self.box[rows])

    def supports(self, dirs: np.ndarray) -> np.ndarray:
        """(k, m): max over solid t of u . x for its m directions dirs[t] (m, 3)."""
        return obb.reach(self.vertices, self.index, self.rot, self.pos, dirs)

    def support_points(self, u: np.ndarray) -> np.ndarray:
        """(k, 3): a world point of solid t maximizing u[t] . x."""
        return obb.support_points(self.vertices, self.index, self.rot, self.pos, u)


def separated(dist: np.ndarray, normal: np.ndarray, a: Solids, b: Solids) -> np.ndarray:
    """(k,) which separated answers (distance, unit normal from a to b) are certified:
    minus the overlap of the projections on the normal bounds the distance from
    below, and the answer is kept when it is within TOLERANCE of that bound."""
    u = normal[:, None, :]
    gap = a.supports(u)[:, 0] + b.supports(-u)[:, 0]
    return dist + gap <= TOLERANCE


def penetration(dist, p1, p2, normal, has_normal, a: Solids, b: Solids):
    """`narrow._checked_penetration` of k pairs FCL found touching or penetrating.

    dist (k,) FCL's distance (at most 0 here), p1, p2 (k, 3) its witness points,
    normal (k, 3) its unit normal from a to b where has_normal (k,). Returns
    (dist, p1, p2, normal, separating): the certified answers, and which pairs
    have a separating direction (FCL's contact was wrong: they need GJK, and
    their rows in the answers are meaningless).
    """
    k = len(dist)
    filler = np.broadcast_to(_WORLD_AXES[0], (k, 3))
    line = b.pos - a.pos
    norm = np.linalg.norm(line, axis=1)
    line = np.divide(line, norm[:, None], out=np.zeros_like(line),
                     where=norm[:, None] > 1e-12)
    # Fixed slots in narrow._candidates' order; an absent candidate repeats the first
    # direction, which argmin (first of equals) never prefers to it. A side with no box
    # among its solids has no face slots.
    rows = [np.broadcast_to(_WORLD_AXES, (k, 6, 3)),
            np.where(has_normal[:, None], normal, filler)[:, None],
            np.where(norm[:, None] > 1e-12, line, filler)[:, None]]
    for solids in (a, b):
        if not solids.box.any():
            continue
        faces, is_box = solids.rot.transpose(0, 2, 1), solids.box[:, None, None]
        rows += [np.where(is_box, faces, filler[:, None]),
                 np.where(is_box, -faces, filler[:, None])]
    dirs = np.concatenate(rows, axis=1)  # (k, 8 to 20, 3)
    overlaps = a.supports(dirs) + b.supports(-dirs)
    pick = overlaps.argmin(axis=1)
    at = np.arange(k)
    best, u = overlaps[at, pick], dirs[at, pick]
    separating = best < -TOLERANCE
    keep = ~separating & (best > TOLERANCE) & has_normal & (-dist <= best + 1e-6)
    out = (dist.copy(), p1.copy(), p2.copy(), normal.copy())
    bound = ~separating & ~keep  # touching, or EPA's depth beyond the bound
    if bound.any():
        pa = a.rows(bound).support_points(u[bound])
        depth = best[bound]
        out[0][bound] = -depth
        out[1][bound] = pa
        out[2][bound] = pa - depth[:, None] * u[bound]
        out[3][bound] = u[bound]
    return (*out, separating)
