"""One signed-distance query between two convex solids, made robust.

FCL 0.7 answers fast but not always right, so every answer is checked:

- Separated: the projections of the solids on FCL's normal n leave a gap
  that bounds the true distance from below; FCL's witness points bound it
  from above. When the bounds disagree by more than TOLERANCE (FCL's GJK
  stopped early or on a wrong simplex: micrometres off for meshes,
  centimetres off for boxes and cylinders, fcl#508), our own GJK (gjk.py),
  warm-started on n, gives the certified distance.
- Touching or penetrating: for any unit direction u, the overlap of the
  two solids' projections on u bounds the penetration depth from above,
  and a negative overlap proves separation. Over a few candidate
  directions (FCL's normal, the centre line, the boxes' and cylinders'
  axes, the world axes): a negative best overlap sends the pair to our
  GJK; a zero one is a resting contact (distance 0); otherwise EPA's depth
  is kept unless it exceeds the bound. FCL's EPA returns nonsense for
  solids that touch face to face (a depth of decimetres towards a far
  corner; resting contacts do exactly that): the bound catches it.

All of this is on the shapes' cores; `rounded` then grows each by its
margin (shapes.py: PyBullet's rounding of a hull).
"""

from __future__ import annotations

import math

import fcl
import numpy as np

from tampcli.geometry import prism
from tampcli.geometry.gjk import gjk_distance
from tampcli.geometry.shapes import Shape

TOLERANCE = 1e-8  # m: the accuracy we certify (finite differences at 1e-4 stay clean)


class Placed:
    """A shape at a world pose, with its support function in world coordinates.

    Vertices stay in the shape's frame: directions are rotated instead, which
    costs 3 x k products rather than transforming every vertex.
    """

    __slots__ = ("shape", "t", "rot", "pos", "vertices", "_fcl")

    def __init__(self, shape: Shape, t: np.ndarray):
        self.shape, self.t = shape, t
        self.rot, self.pos = t[:3, :3], t[:3, 3]
        self.vertices = shape.vertices
        self._fcl = None

    def fcl_transform(self) -> fcl.Transform:
        if self._fcl is None:
            self._fcl = fcl.Transform(self.rot, self.pos)
        return self._fcl

    def support_point(self, u: np.ndarray) -> np.ndarray:
        """A world point of the solid maximizing u . p."""
        local = self.rot.T @ u
        if self.vertices is not None:
            return self.rot @ self.vertices[int((self.vertices @ local).argmax())] + self.pos
        return self.rot @ self.shape.support_point(local) + self.pos

    def support(self, u: np.ndarray) -> float:
        """max over the solid of u . p."""
        local = self.rot.T @ u
        if self.vertices is not None:
            return float((self.vertices @ local).max() + u @ self.pos)
        return float(u @ self.pos) + self.shape.support(local)

    def supports(self, dirs: np.ndarray) -> np.ndarray:
        """support(u) for each row u of dirs (k, 3)."""
        local = dirs @ self.rot
        base = dirs @ self.pos
        if self.vertices is not None:
            return (self.vertices @ local.T).max(axis=0) + base
        kind, size = self.shape.kind, self.shape.size
        if kind == "sphere":
            return base + size[0] * np.linalg.norm(dirs, axis=1)
        r, h = size
        ends = 0.5 * h * np.abs(local[:, 2])
        if kind == "cylinder":
            return base + r * np.hypot(local[:, 0], local[:, 1]) + ends
        return base + r * np.linalg.norm(local, axis=1) + ends


def signed_distance(request, a: Placed, oa, b: Placed, ob, second=None):
    """(distance, point on a, point on b, unit normal from a to b), world frame,
    of the two solids (each shape grown by its margin).

    `oa`, `ob` are the FCL objects of the two shapes; they are moved to the
    placed poses here. `second`: as in `certified`.
    """
    return rounded(*_core_distance(request, a, oa, b, ob, second), a.shape.margin,
                   b.shape.margin)


def rounded(d, p1, p2, normal, margin_a: float, margin_b: float):
    """The answer for the cores grown by their margins: distance less both, witness
    points moved out along the normal (which stays; so do the gradients, since
    d/dq of n . p is the same for p and p + r n on one link)."""
    if not margin_a and not margin_b:
        return d, p1, p2, normal
    return d - margin_a - margin_b, p1 + margin_a * normal, p2 - margin_b * normal, normal


PRISMS = ("box", "cylinder")  # kinds prism.py answers when upright
# Kinds on which FCL 0.7's GJK mostly stops early (arm-sort: 96 % of a Panda link's
# pairs with a cylinder failed the check): the second engine is asked first for them.
CURVED = ("cylinder", "capsule")


def second_first(a: Shape, b: Shape, second) -> bool:
    """Whether the pair of shapes `a`, `b` is asked of `second` (coal) instead of FCL."""
    return second is not None and (a.kind in CURVED or b.kind in CURVED)


def _core_distance(request, a: Placed, oa, b: Placed, ob, second=None):
    if a.shape.kind in PRISMS and b.shape.kind in PRISMS:
        exact = prism.distance(a, b)
        if exact is not None:
            return exact
    asked = not (second_first(a.shape, b.shape, second) or no_fcl(a, b))
    return certified_pair(fcl_distance(request, a, oa, b, ob) if asked else None, a, b,
                          second)


def certified_pair(raw, a: Placed, b: Placed, second=None):
    """`certified` of FCL's answer, or of `second`'s for a pair FCL was not asked
    because `second_first` sends it there."""
    if raw is None and second_first(a.shape, b.shape, second):
        return certified(second(a, b), a, b)
    return certified(raw, a, b, second)


def certified(raw, a: Placed, b: Placed, second=None):
    """The certified answer from FCL's raw one (distance, witness on a, witness on b;
    None if FCL was not asked or threw): kept when the quick check (the gap on its
    normal) passes, otherwise `checked`.

    `second`, when given, is another engine's query (coal_query.CoalDistance: a
    callable of (a, b) giving a raw answer or None), asked once a separated answer
    fails the check, before our GJK: FCL 0.7's GJK stops early on cylinders and
    meshes, coal's runs to its tolerance at ~14 us a pair against ~210 us for
    `checked`'s GJK (coal_query.py). Its answer is checked the same way.
    """
    if raw is not None:
        d, p1, p2 = raw
        normal = fcl_normal(d, p1, p2)
        if d > TOLERANCE and normal is not None:
            if d + overlap(a, b, normal) <= TOLERANCE:
                return d, p1, p2, normal
            if second is not None:
                return certified(second(a, b), a, b)
    return checked(raw, a, b)


FCL_BOX_GAP = 1e-4  # m: boxes this far apart along a face normal are safe for FCL's GJK


def no_fcl(a: Placed, b: Placed) -> bool:
    """Two tilted boxes (upright ones are prism.py's) not separated along a face normal
    of either by FCL_BOX_GAP go to our own GJK and penetration path (`checked`), not to
    FCL: its signed distance (libccd's EPA, which runs only when its GJK finds contact)
    aborted the process on two coincident tilted cubes ("the origin is outside of the
    polytope", a C++ error Python cannot catch; blind2 p02). Separated ones go to FCL,
    whose answer is checked as any other: a held box tilted in a carry is such a pair
    (arm-kitchen: 8,144 of 8,146 box pairs; FCL's answer failed the check on 29)."""
    if a.shape.kind != "box" or b.shape.kind != "box":
        return False
    dirs = np.concatenate([a.rot.T, b.rot.T])
    ahead = a.supports(dirs) + b.supports(-dirs)  # minus the gap of b beyond a along u
    behind = a.supports(-dirs) + b.supports(dirs)
    return not (min(ahead.min(), behind.min()) < -FCL_BOX_GAP)


def fcl_distance(request, a: Placed, oa, b: Placed, ob):
    """FCL's answer (distance, witness on a, witness on b), unchecked; None if it throws."""
    oa.setTransform(a.fcl_transform())
    ob.setTransform(b.fcl_transform())
    result = fcl.DistanceResult()  # keeps the smallest value seen: one per query
    try:
        d = float(fcl.distance(oa, ob, request, result))
    except RuntimeError:  # FCL's EPA can throw on degenerate contacts (fcl#319)
        return None
    return d, np.array(result.nearest_points[0]), np.array(result.nearest_points[1])


def fcl_normal(d: float, p1, p2):
    """The unit normal from a to b of FCL's witness points (None when they coincide).

    When penetrating, FCL's witness points lie inside the other solid, so
    p2 - p1 points from b to a: flipped.
    """
    diff = p2 - p1
    norm = math.sqrt(float(diff @ diff))
    if norm <= 1e-12:
        return None
    return diff / norm if d >= 0 else -diff / norm


def checked(raw, a: Placed, b: Placed):
    """The certified answer from FCL's raw one (or None) when the quick check failed."""
    if raw is None:
        exact = gjk_distance(a.support_point, b.support_point, b.pos - a.pos, TOLERANCE)
        if exact is not None and exact[0] > TOLERANCE:
            dist, pa, pb = exact
            return dist, pa, pb, (pb - pa) / dist
        return _checked_penetration(0.0, None, None, None, a, b)
    d, p1, p2 = raw
    normal = fcl_normal(d, p1, p2)
    if d > TOLERANCE and normal is not None:
        if d + overlap(a, b, normal) <= TOLERANCE:
            return d, p1, p2, normal
        return _gjk(a, b, normal)
    return _checked_penetration(min(d, 0.0), p1, p2, normal if d <= 0 else None, a, b)


def _gjk(a: Placed, b: Placed, guess):
    exact = gjk_distance(a.support_point, b.support_point, guess, TOLERANCE)
    if exact is None:  # intersecting after all: FCL's separation was within its tolerance
        u = guess / max(np.linalg.norm(guess), 1e-12)
        depth = overlap(a, b, u)
        pa = a.support_point(u)
        return -depth, pa, pa - depth * u, u
    dist, pa, pb = exact
    if dist <= TOLERANCE:
        u = guess / max(np.linalg.norm(guess), 1e-12)
        return dist, pa, pb, u
    return dist, pa, pb, (pb - pa) / dist


def overlap(a: Placed, b: Placed, u: np.ndarray) -> float:
    """max over a of u.x - min over b of u.x: >= the penetration depth along u,
    and minus it is a lower bound on the distance."""
    return a.support(u) + b.support(-u)


_WORLD_AXES = np.vstack([np.eye(3), -np.eye(3)])


def _candidates(a: Placed, b: Placed, normal) -> np.ndarray:
    """Directions (k, 3) on which to bound the penetration depth."""
    rows = [_WORLD_AXES]
    if normal is not None:
        rows.append(normal.reshape(1, 3))
    axis = b.pos - a.pos
    norm = math.sqrt(float(axis @ axis))
    if norm > 1e-12:
        rows.append((axis / norm).reshape(1, 3))
    for placed in (a, b):
        kind = placed.shape.kind
        if kind == "box":
            rows.append(placed.rot.T)
            rows.append(-placed.rot.T)
        elif kind in ("cylinder", "capsule"):
            z = placed.rot[:, 2].reshape(1, 3)
            rows.append(z)
            rows.append(-z)
    return np.concatenate(rows)


def _checked_penetration(d, p1, p2, normal, a: Placed, b: Placed):
    dirs = _candidates(a, b, normal)
    overlaps = a.supports(dirs) + b.supports(-dirs)
    k = int(overlaps.argmin())
    best, u = float(overlaps[k]), dirs[k]
    if best < -TOLERANCE:
        # A separating direction: FCL's intersection was wrong; measure the gap.
        return _gjk(a, b, u)
    if best <= TOLERANCE:
        # Touching (resting contact): distance 0 along the separating direction.
        pa = a.support_point(u)
        return -best, pa, pa - best * u, u
    if normal is not None and -d <= best + 1e-6:
        return d, p1, p2, normal
    # EPA's depth exceeds a certified bound: use the best projection direction.
    pa = a.support_point(u)
    return -best, pa, pa - best * u, u
