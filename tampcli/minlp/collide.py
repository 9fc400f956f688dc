"""Collision avoidance valid between waypoints, not only at them.

A footprint A moves in a straight line from a0 to a1 (a waypoint segment;
what the robot carries translates with it) while B stays at b. If both ends
lie beyond the same face of the Minkowski sum A + B,

    n . (a0 - b) >= offset  and  n . (a1 - b) >= offset,

then so does every point of the segment (a half-plane is convex), so A never
meets B during the motion. One binary per face picks it; big-M switches off
the faces not picked. Faces no point of the variables' box can reach are not
created; a pair some face always separates needs no constraint.
"""

from __future__ import annotations

from collections.abc import Sequence

from pyscipopt import quicksum

from tampcli.minlp.bigm import implies_le, linear_sup
from tampcli.minlp.footprint import Footprint, separating_faces


def _terms(n, point, sign: float):
    """(terms over variables, constant) of sign * n . point."""
    terms, constant = [], 0.0
    for c, x in zip(n, point, strict=True):
        if isinstance(x, float | int):
            constant += sign * c * float(x)
        elif abs(c) > 1e-12:
            terms.append((sign * c, x))
    return terms, constant


def _face_reach(n, a, b) -> tuple[list, float, float]:
    """Terms and constant of -n . (a - b), and the sup of n . (a - b) over the box."""
    ta, ca = _terms(n, a, -1.0)
    tb, cb = _terms(n, b, 1.0)
    terms, constant = ta + tb, ca + cb
    sup = linear_sup([(-c, v) for c, v in terms], -constant)
    return terms, constant, sup


def separate(model, ends: Sequence[Sequence], b: Sequence, a_shape: Footprint,
             b_shape: Footprint, demand, name: str) -> int:
    """When the 0/1 expression `demand` is 1, every point in `ends` (the ends of a segment
    of A's centre, or one point) lies beyond one common face of A + B centred at b.
    Returns the number of binaries created."""
    faces = []
    for n, offset in separating_faces(a_shape, b_shape):
        rows = [_face_reach(n, a, b) for a in ends]
        if any(sup < offset for _, _, sup in rows):
            continue  # no point of the box is beyond this face
        if all(linear_sup(terms, constant) <= -offset for terms, constant, _ in rows):
            return 0  # this face always separates: nothing to enforce
        faces.append((offset, rows))
    if not faces:
        never = model.addVar(f"{name}_never", vtype="B", ub=0.0)
        model.addCons(never >= demand, name=f"{name}_never")
        return 0
    picks = [model.addVar(f"{name}_f{j}", vtype="B") for j in range(len(faces))]
    model.addCons(quicksum(picks) >= demand, name=f"{name}_one")
    for j, (offset, rows) in enumerate(faces):
        for e, (terms, constant, _) in enumerate(rows):
            # n . (a - b) >= offset  <=>  -n . (a - b) <= -offset
            implies_le(model, picks[j], terms, -offset - constant, f"{name}_f{j}_e{e}")
    return len(picks)
