"""What makes a placement stand: the rows and the cost of resting on a top face.

The rule (docs/formats.md, "Stacking"): an object placed on a support has its
whole footprint on the support's top face, and the combined centre of mass of
the object and of everything resting on it (directly or higher up) lies inside
that face, inset by STABLE_MARGIN of the smaller of the two bodies' half
extents along each axis of the face. A placement also loads every body under
its support, so the same row is written for each of them. Mass is uniform
density (DENSITY) unless the scene gives a body's `mass`.

Beyond standing, a stacked object lines up with the body below. The final NLP
(which only proposes placements) pulls it to that body's centre and faces
(`align_cost`). The keyframe NLP's objective is the motion's cost alone; there
rows keep the boxes of a tower (`tower_pair`) centred and square on the box
below, within ALIGN_SHIFT and ALIGN_TURN (`aligned`).
"""

from __future__ import annotations

import numpy as np

from tampcli.optimize.bodies import REST_TOLERANCE, BodyInfo
from tampcli.optimize.constraints import corners
from tampcli.optimize.expr import Jac, Label, PoseX, RowSet, add_jac

STABLE_MARGIN = 0.2  # the centre of mass stays this fraction of a half extent inside the face
OVERHANG = 5e-4  # m: how far a footprint may stick out of the face in the NLPs
# The pull of a stacked object to the body below, in the final NLP's objective (which
# only proposes placements): per m^2 of offset, per unit of sin^2(2 yaw difference).
ALIGN_OFFSET = 100.0
ALIGN_YAW = 1.0
# How far the keyframe NLP may turn a box of a tower from the faces of the box below
# (modulo a quarter turn) and move its centre from that box's centre (`tower_pair`
# says where).
ALIGN_TURN = np.radians(2.0)
ALIGN_SHIFT = 3e-3  # m


def point_rows(rows: RowSet, label: Label, c, c_jac: Jac, slack, S: PoseX,
               sinfo: BodyInfo) -> None:
    """The point c (xy, with d c / d blocks `c_jac`, each (2, size)) inside S's top face
    grown by `slack` (per axis of the face: (sx, sy); a disk face uses sx)."""
    d = c - S.pos[:2]
    if sinfo.disk:
        n = float(np.linalg.norm(d))
        u = d / n if n > 1e-12 else np.zeros(2)
        gs = np.zeros((1, 12))
        gs[0, 0:2] = u
        jac = add_jac(S.through(gs), {k: -u[None, :] @ j for k, j in c_jac.items()})
        rows.add(np.array([sinfo.half[0] + slack[0] - n]), jac, label)
        return
    vals, gs, gc = [], np.zeros((4, 12)), np.zeros((4, 2))
    row = 0
    for axis, col in ((0, 3), (1, 6)):
        e = S.v[col:col + 2]
        local = e @ d
        for sign in (1.0, -1.0):
            vals.append(sinfo.half[axis] + slack[axis] - sign * local)
            gc[row] = -sign * e
            gs[row, 0:2] = sign * e
            gs[row, col:col + 2] = -sign * d
            row += 1
    jac = add_jac(S.through(gs), {k: gc @ j for k, j in c_jac.items()})
    rows.add(np.array(vals), jac, label)


def footprint_on_face(rows: RowSet, step: str, P: PoseX, info: BodyInfo, S: PoseX,
                      sinfo: BodyInfo) -> None:
    """The whole footprint of P on S's top face (OVERHANG allowed)."""
    label = Label(step, f"footprint off the top of {sinfo.name}")
    if info.disk:
        r = info.half[0]
        g = np.zeros((2, 12))
        g[0, 0] = g[1, 1] = 1.0
        point_rows(rows, label, P.pos[:2].copy(), P.through(g), (OVERHANG - r,) * 2, S, sinfo)
        return
    for c, g in corners(P, info):
        point_rows(rows, label, c, P.through(g), (OVERHANG, OVERHANG), S, sinfo)


def margin(info: BodyInfo, sinfo: BodyInfo) -> tuple[float, float]:
    """The inset of the centre of mass of a load on `info`, resting on `sinfo`."""
    if sinfo.disk:
        return (STABLE_MARGIN * min(sinfo.half[0], min(info.half[:2])),) * 2
    return tuple(STABLE_MARGIN * min(sinfo.half[k], min(info.half[:2])) for k in (0, 1))


def com_on_face(rows: RowSet, step: str, load: list, base: BodyInfo, S: PoseX,
                sinfo: BodyInfo) -> None:
    """The centre of mass of `load` ([(PoseX, mass)], `base` the body at its bottom)
    inside S's top face, inset by `margin`."""
    total = sum(m for _, m in load)
    c = sum(m * P.pos[:2] for P, m in load) / total
    c_jac: Jac = {}
    for P, m in load:
        g = np.zeros((2, 12))
        g[0, 0] = g[1, 1] = m / total
        c_jac = add_jac(c_jac, P.through(g))
    inset = margin(base, sinfo)
    label = Label(step, f"centre of mass of {base.name} and its load too near the edge of "
                        f"{sinfo.name}")
    point_rows(rows, label, c, c_jac, (-inset[0], -inset[1]), S, sinfo)


def _sin_2turn(P: PoseX, S: PoseX):
    """(sin 2 (yaw_P - yaw_S), its gradient w.r.t. P.ax[:2], w.r.t. S.ax[:2]): zero
    when the faces are parallel, modulo a quarter turn."""
    a, b = P.ax[:2], S.ax[:2]
    s, c = b[0] * a[1] - b[1] * a[0], b @ a
    df_da = 2 * c * np.array([-b[1], b[0]]) + 2 * s * b
    df_db = 2 * c * np.array([a[1], -a[0]]) + 2 * s * a
    return 2 * s * c, df_da, df_db


def align_cost(P: PoseX, info: BodyInfo, S: PoseX, sinfo: BodyInfo) -> tuple[float, Jac]:
    """The final NLP's pull of a stacked object to its support's centre and faces:
    ALIGN_OFFSET |offset|^2 + ALIGN_YAW sin^2(2 yaw difference) (no yaw term for disks).
    Returns (cost, d cost / d blocks (size,))."""
    d = P.pos[:2] - S.pos[:2]
    gp, gs = np.zeros(12), np.zeros(12)
    cost = ALIGN_OFFSET * float(d @ d)
    gp[0:2], gs[0:2] = 2 * ALIGN_OFFSET * d, -2 * ALIGN_OFFSET * d
    if not (info.disk or sinfo.disk):
        f, df_da, df_db = _sin_2turn(P, S)
        cost += ALIGN_YAW * f * f
        gp[3:5] += 2 * ALIGN_YAW * f * df_da
        gs[3:5] += 2 * ALIGN_YAW * f * df_db
    grad = add_jac({k: gp @ j for k, j in P.jac.items()}, {k: gs @ j for k, j in S.jac.items()})
    return cost, grad


def tower_pair(info: BodyInfo, sinfo: BodyInfo) -> bool:
    """Whether `info` resting on `sinfo` is part of a tower, which the keyframe NLP keeps
    aligned (`aligned`): both are boxes and `info` does not fit on the face at every yaw,
    so its footprint rows alone would let it turn until its corners reach the edges.
    A box that fits at every yaw, and anything on or of a cylinder, is left to the
    footprint and centre-of-mass rows: it stands wherever they allow, and lining it up
    would cost motion."""
    if info.disk or sinfo.disk:
        return False
    return info.radius > min(sinfo.half[:2])


def aligned(rows: RowSet, step: str, P: PoseX, S: PoseX, sinfo: BodyInfo) -> None:
    """P's centre within ALIGN_SHIFT of S's: (ALIGN_SHIFT^2 - |offset|^2) / (2 ALIGN_SHIFT)
    >= 0, which reads in m near the limit and is smooth at the centre; and its faces
    within ALIGN_TURN of S's modulo a quarter turn: |sin 2 (yaw_P - yaw_S)| <=
    sin 2 ALIGN_TURN, as two rows halved so that they read in rad near zero."""
    d = P.pos[:2] - S.pos[:2]
    gp, gs = np.zeros((1, 12)), np.zeros((1, 12))
    gp[0, 0:2], gs[0, 0:2] = -d / ALIGN_SHIFT, d / ALIGN_SHIFT
    rows.add(np.array([(ALIGN_SHIFT ** 2 - float(d @ d)) / (2 * ALIGN_SHIFT)]),
             add_jac(P.through(gp), S.through(gs)),
             Label(step, f"centre off the centre of {sinfo.name}"))
    f, df_da, df_db = _sin_2turn(P, S)
    lim = np.sin(2 * ALIGN_TURN)
    gp, gs = np.zeros((2, 12)), np.zeros((2, 12))
    gp[0, 3:5], gs[0, 3:5] = -0.5 * df_da, -0.5 * df_db
    gp[1, 3:5], gs[1, 3:5] = 0.5 * df_da, 0.5 * df_db
    rows.add(np.array([0.5 * (lim - f), 0.5 * (lim + f)]), add_jac(P.through(gp), S.through(gs)),
             Label(step, f"turned from the faces of {sinfo.name}", "rad"))


# ---------------------------------------------------------------- verify

INSIDE = 1e-3  # m: what verify forgives of a footprint off its face or a centre of mass


def _face_excess(xy, rad: float, S: np.ndarray, sinfo: BodyInfo, inset) -> float:
    """How far (m) a disk of radius `rad` at xy reaches beyond S's top face shrunk by inset."""
    local = S[:3, :3].T @ np.array([xy[0] - S[0, 3], xy[1] - S[1, 3], 0.0])
    if sinfo.disk:
        return float(np.linalg.norm(local[:2]) + rad - (sinfo.half[0] - inset[0]))
    return float(max(abs(local[k]) + rad - (sinfo.half[k] - inset[k]) for k in (0, 1)))


def _rests_on(name: str, poses: dict, bodies: dict) -> str | None:
    """The body whose top face carries `name` (bottom on it, centre over it)."""
    info, P = bodies[name], poses[name]
    for other, oinfo in bodies.items():
        if other == name:
            continue
        S = poses[other]
        if abs(S[2, 3] + oinfo.half[2] - (P[2, 3] - info.half[2])) <= REST_TOLERANCE and \
                _face_excess(P[:2, 3], 0.0, S, oinfo, (0.0, 0.0)) <= 0.0:
            return other
    return None


def unstable(problem, step, poses: dict) -> list[str]:
    """What `verify` refuses of a placement: a footprint off the top face of the body it
    is stacked on, a load whose centre of mass leaves the inset face (module docstring).
    `poses`: name -> 4x4 world pose of every body once the step is done."""
    bodies = problem.bodies
    out = []
    regions = {r.name for r in problem.scene.regions}
    P, info = poses[step.obj], bodies[step.obj]
    if step.target is not None and step.target not in regions:
        S, sinfo = poses[step.target], bodies[step.target]
        pts = [(P[:2, 3], info.half[0])] if info.disk else [
            ((P[:3, :3] @ np.array([a * info.half[0], b * info.half[1], 0.0]) + P[:3, 3])[:2], 0.0)
            for a in (-1, 1) for b in (-1, 1)]
        over = max(_face_excess(xy, rad, S, sinfo, (0.0, 0.0)) for xy, rad in pts)
        if over > INSIDE:
            out.append(f"{step.name}: {step.obj}'s footprint sticks out of the top of "
                       f"{step.target} by {100 * over:.1f} cm")
    movable = [n for n, i in bodies.items() if not i.fixed]
    supports = {n: _rests_on(n, poses, bodies) for n in movable}
    supports[step.obj] = step.support
    base, support, seen = step.obj, step.support, set()
    while support is not None and base not in seen:
        seen.add(base)
        load = load_of(base, movable, supports)
        total = sum(bodies[n].mass for n in load)
        com = sum(bodies[n].mass * poses[n][:2, 3] for n in load) / total
        inset = margin(bodies[base], bodies[support])
        over = _face_excess(com, 0.0, poses[support], bodies[support], inset)
        if over > INSIDE:
            out.append(f"{step.name}: the centre of mass of {', '.join(sorted(load))} is "
                       f"{100 * over:.1f} cm beyond the stable part of {support}'s top face "
                       f"(inset {100 * min(inset):.1f} cm)")
        if bodies[support].fixed:
            break
        base, support = support, supports.get(support)
    return out


def load_of(name: str, movable, supports: dict) -> list[str]:
    """`name` and everything among `movable` resting on it, directly or higher up
    (what it carries)."""
    out, frontier = [name], [name]
    while frontier:
        below = frontier.pop()
        above = [o for o in movable if supports.get(o) == below and o not in out]
        out += above
        frontier += above
    return out
