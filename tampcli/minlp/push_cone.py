"""A push in the MINLP is the quasi-static push of `optimize/kinds/push.py`.

The disk touches one side face of the pushed object (a binary per face of its
footprint, one face for the whole push) and every step of the push goes into
that face within the friction cone: with u the face's outward normal and e
its tangent, a step d of the object keeps d.u <= 0 and |d.e| <= mu (-d.u),
mu = `PUSH_FRICTION`. While pushing, the disk's centre stands `depth + radius
+ CONTACT_GAP` beyond the face (within `TOUCH_SLACK`) and within the face's
length. The object does not turn (the MINLP keeps every yaw). All of it is
linear once the face and the pushing steps are fixed: big-M rows switched by
push[o][k] + face[j] - 1.
"""

from __future__ import annotations

import numpy as np
from pyscipopt import quicksum

from tampcli.minlp.bigm import implies_le
from tampcli.optimize.kinds.push_contact import CONTACT_GAP, PUSH_FRICTION

TOUCH_SLACK = 1e-3  # m: verify lets the pusher be 1 mm in or 2 mm out of touch


def encode_push_cones(model, r, objects, carry, robot_radius: float, shapes, steps: int) -> None:
    for name, o in objects.items():
        pushes = [(k, carry.push[name][k]) for k in range(steps)
                  if not isinstance(carry.push[name][k], float)]  # none before the first step
        if all(p.getUbOriginal() == 0.0 for _, p in pushes):
            continue
        faces = _faces(shapes[name])
        face = [model.addVar(f"face_{name}_{j}", vtype="B") for j in range(len(faces))]
        model.addCons(quicksum(face) <= 1, name=f"one_face_{name}")
        for k, p in pushes:
            model.addCons(quicksum(face) >= p, name=f"a_face_{name}_{k}")
            for j, (u, e, depth, half_length) in enumerate(faces):
                switch = p + face[j] - 1
                tag = f"{name}_{k}_{j}"
                stand = depth + robot_radius + CONTACT_GAP
                rel_u, c_u = _dot(u, r[k], o[k])
                implies_le(model, switch, [(-c, v) for c, v in rel_u],
                           -(stand - TOUCH_SLACK) + c_u, f"touch_in_{tag}")
                implies_le(model, switch, rel_u, stand + TOUCH_SLACK - c_u, f"touch_out_{tag}")
                rel_e, c_e = _dot(e, r[k], o[k])
                implies_le(model, switch, rel_e, half_length - c_e, f"on_face_hi_{tag}")
                implies_le(model, switch, [(-c, v) for c, v in rel_e], half_length + c_e,
                           f"on_face_lo_{tag}")
                d_u, k_u = _dot(u, o[k + 1], o[k])
                d_e, k_e = _dot(e, o[k + 1], o[k])
                implies_le(model, switch, d_u, -k_u, f"into_{tag}")
                for sign in (1.0, -1.0):
                    terms = [(sign * c, v) for c, v in d_e] + \
                        [(PUSH_FRICTION * c, v) for c, v in d_u]
                    implies_le(model, switch, terms, -(sign * k_e + PUSH_FRICTION * k_u),
                               f"cone_{'+' if sign > 0 else '-'}_{tag}")


def _faces(shape) -> list[tuple[np.ndarray, np.ndarray, float, float]]:
    """(outward normal, tangent, depth from the centre, half length) of each edge."""
    v = np.asarray(shape.vertices, dtype=float)
    out = []
    for a, b in zip(v, np.roll(v, -1, axis=0), strict=True):
        edge = b - a
        length = float(np.linalg.norm(edge))
        e = edge / length
        u = np.array([e[1], -e[0]])  # counter-clockwise vertices: the right of an edge is out
        out.append((u, e, float(a @ u), 0.5 * length))
    return out


def _dot(w, a, b):
    """(terms, constant) of w . (a - b) for 2-D points of variables or floats."""
    terms, constant = [], 0.0
    for coef_sign, point in ((1.0, a), (-1.0, b)):
        for axis in range(2):
            c = coef_sign * float(w[axis])
            if c == 0.0:
                continue
            if isinstance(point[axis], float):
                constant += c * point[axis]
            else:
                terms.append((c, point[axis]))
    return terms, constant
