"""Collision rows: one per (configuration sample, world body) plus one for self-collision.

Each row is min(distance over the robot's parts and the held object vs that
body, activation) - margin: a fixed-size vector per SLSQP call whatever the
contacts, constant (zero gradient) for pairs beyond `activation`.

The gradient of a contact distance is -n . (velocity of the witness point on
the moving side) + n . (velocity of the one on b): w.r.t. the joints from the
checker, w.r.t. a grip parameter and w.r.t. the pose of a body the skeleton
moved (a placed object) from the witness points here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.optimize.expr import Label, PoseX, RowSet
from tampcli.optimize.grips import Frame, Grip

# m: how much deeper than at its keyframe the optimizer lets a contact being entered
# or left go at a sample point (verify's limit, PENETRATION, is 1 mm; between sample
# points a contact can go deeper, which verify's 10x check catches).
TOUCH_SLACK = 1e-4


@dataclass(frozen=True)
class Held:
    name: str
    grip: Grip
    t: float
    t_block: str | None
    grasp: np.ndarray  # 4x4 object in tool frame at t


def held_of(name: str, grip: Grip, t: float, t_block: str | None) -> Held:
    return Held(name, grip, t, t_block, grip.matrix(t))


def row_keys(bodies, ignore, held: Held | None) -> list[str]:
    skip = set(ignore) | ({held.name} if held else set())
    return [b for b in bodies if b not in skip] + ["self"]


def contact_key(contact) -> str:
    """The row a contact belongs to: its body's name, or "self"."""
    kind, _, name = contact.b.partition(":")
    return name if kind == "body" else "self"


def _short(name: str) -> str:
    return name.partition(":")[2] or name


def body_matrices(poses: dict[str, PoseX]) -> dict[str, np.ndarray]:
    return {name: P.matrix() for name, P in poses.items()}


def held_spec(held: Held | None):
    """What the checker takes for a held object: (name, grasp) or None."""
    return (held.name, held.grasp) if held is not None else None


def contact_rows(rows: RowSet, step: str, contacts, q_weights, frame: Frame | None,
                 held: Held | None, poses: dict[str, PoseX], keys: list[str],
                 activation: float, margin: float, margins: dict[str, float] | None = None
                 ) -> None:
    """Add len(keys) rows for configuration q = sum of weights * blocks (see module doc),
    from the contacts the checker found at q.

    `q_weights`: [(block, weight)] whose weighted sum is q (one block at a keyframe;
    two at a point between waypoints). `poses`: bodies not at their start pose.
    `margins`: a key's own margin where it is not `margin` (about 0 for a contact
    being entered or left: touching).
    """
    best: dict[str, object] = {}
    for c in contacts:
        k = contact_key(c)
        if k in best and best[k].distance <= c.distance:
            continue
        best[k] = c
    own = margins or {}
    margins = np.array([own.get(k, margin) for k in keys])
    values = activation - margins
    labels = [Label(step, "clearance", "m")] * len(keys)
    jac: dict[str, np.ndarray] = {}
    for r, k in enumerate(keys):
        c = best.get(k)
        if c is None or c.distance >= activation:
            continue
        values[r] = c.distance - margins[r]
        labels[r] = Label(step, f"collision {_short(c.a)} vs {_short(c.b)} "
                          f"({_allowance(margins[r])})")
        for block, w in q_weights:
            _acc(jac, block, r, len(keys), w * c.gradient)
        if held is not None and held.t_block is not None and c.a == f"held:{held.name}":
            _acc(jac, held.t_block, r, len(keys),
                 np.array([-c.normal @ _witness_dt(frame, held, c.point_a)]))
        P = poses.get(k)
        if P is not None and P.jac:
            g = np.zeros((1, 12))
            n = c.normal
            rb = c.point_b - P.pos
            spin = n[0] * -rb[1] + n[1] * rb[0]
            ax = P.ax
            g[0, 0:3] = n
            # yaw = atan2(ax_y, ax_x): d yaw = ax_x d ax_y - ax_y d ax_x (unit ax)
            g[0, 3], g[0, 4] = -ax[1] * spin, ax[0] * spin
            for block, a in P.through(g).items():
                _acc(jac, block, r, len(keys), a[0])
    depends = {block for block, _ in q_weights}
    if held is not None and held.t_block is not None:
        depends.add(held.t_block)
    for k in keys:
        P = poses.get(k)
        if P is not None:
            depends.update(P.jac)
    rows.add(values, jac, labels, depends)


def _allowance(margin: float) -> str:
    if margin < 0:
        return f"touching: {1000 * -margin:.1f} mm deep at most"
    return f"margin {1000 * margin:.0f} mm"


def _acc(jac, block, row, m, grad) -> None:
    if block not in jac:
        jac[block] = np.zeros((m, len(grad)))
    jac[block][row] += grad


def _witness_dt(frame: Frame, held: Held, point) -> np.ndarray:
    """d point / d t for a point fixed on the held object."""
    c, G, dc, dG = held.grip.parts(held.t)
    local = G.T @ (frame.R.T @ (np.asarray(point) - frame.p) - c)
    return frame.R @ (dc + dG @ local)
