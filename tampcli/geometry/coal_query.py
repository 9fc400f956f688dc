"""A second opinion for the pairs whose FCL answer fails narrow.py's check: coal.

FCL 0.7's GJK stops early on curved solids (a cylinder's distance centimetres
off, fcl#508) and on meshes (micrometres off), so narrow.py checks every
answer against the support functions and, where the check fails, used to run
its own GJK (gjk.py, Python floats): on arm-sort that was 28,000 calls of
~210 us a solve, a third of its time, nearly all a Panda link against a
cylinder. Coal, the maintained fork of FCL (Pinocchio's collision library),
runs GJK until its duality gap is below a set tolerance: on 3,451 such pairs
recorded from arm-sort its distances agreed with gjk.py's certified ones
within 9e-9 m, at 14 us a pair from Python. Its answer is checked exactly as
FCL's (narrow.certified); gjk.py stays the last resort.

One `CoalDistance` per collision checker: the coal solids of the shapes it has
been asked about, built once each.
"""

from __future__ import annotations

import coal
import numpy as np
from scipy.spatial import ConvexHull, QhullError

from tampcli.geometry.shapes import Shape

GJK_TOLERANCE = 1e-9  # m: coal's duality-gap tolerance (narrow.TOLERANCE is 1e-8)


class CoalDistance:
    """Coal's signed distance between two placed shapes (narrow.Placed)."""

    def __init__(self):
        self._request = coal.DistanceRequest()
        self._request.gjk_tolerance = GJK_TOLERANCE
        self._request.enable_signed_distance = True
        self._result = coal.DistanceResult()
        # id(shape) -> (shape, its coal solid or None); the shape is kept so that
        # its id is not reused by another while the entry lives.
        self._solids: dict[int, tuple[Shape, object]] = {}

    def solid(self, shape: Shape):
        """The coal solid of `shape`'s core (None where coal cannot make one)."""
        found = self._solids.get(id(shape))
        if found is None:
            found = (shape, _solid(shape))
            self._solids[id(shape)] = found
        return found[1]

    def __call__(self, a, b):
        """(distance, world witness on a, world witness on b) of two narrow.Placed
        cores, FCL's convention (when penetrating, each witness lies inside the
        other solid); None where coal has no solid for one or throws."""
        sa, sb = self.solid(a.shape), self.solid(b.shape)
        if sa is None or sb is None:
            return None
        result = self._result
        result.clear()
        try:
            d = coal.distance(sa, coal.Transform3s(a.rot, a.pos), sb,
                              coal.Transform3s(b.rot, b.pos), self._request, result)
        except RuntimeError:
            return None
        return (float(d), np.array(result.getNearestPoint1()),
                np.array(result.getNearestPoint2()))


def _solid(shape: Shape):
    kind, size = shape.kind, shape.size
    if kind == "box":
        return coal.Box(*size)
    if kind == "cylinder":
        return coal.Cylinder(*size)
    if kind == "sphere":
        return coal.Sphere(size[0])
    if kind == "capsule":
        return coal.Capsule(*size)
    if shape.vertices is None or len(shape.vertices) < 4:
        return None
    try:
        hull = ConvexHull(shape.vertices)
    except QhullError:  # a flat hull: gjk.py answers it
        return None
    points = coal.StdVec_Vec3s()
    for p in np.asarray(shape.vertices, dtype=float):
        points.append(p)
    triangles = coal.StdVec_Triangle()
    for i, j, k in hull.simplices.tolist():
        triangles.append(coal.Triangle(i, j, k))
    return coal.Convex(points, triangles)
