"""Constraint values and exact Jacobians, written on PoseX (see expr.py).

Inequalities are `>= 0`, equalities `= 0`; each row carries a Label so the
worst violation can be said in words.
"""

from __future__ import annotations

import numpy as np

from tampcli.optimize.bodies import BodyInfo
from tampcli.optimize.expr import Label, PoseX, RowSet

DOWN = 0.9  # cos of the largest tilt of an upright held object at grasp/push keyframes


def _g(m: int) -> np.ndarray:
    return np.zeros((m, 12))


def inside_region(rows: RowSet, step: str, P: PoseX, info: BodyInfo, region) -> None:
    """Whole footprint inside the (axis-aligned) region rectangle."""
    lo, hi = np.asarray(region.lower), np.asarray(region.upper)
    if info.disk:
        r = info.half[0]
        vals = np.array([P.pos[0] - lo[0] - r, hi[0] - r - P.pos[0],
                         P.pos[1] - lo[1] - r, hi[1] - r - P.pos[1]])
        g = _g(4)
        g[0, 0], g[1, 0], g[2, 1], g[3, 1] = 1, -1, 1, -1
    else:
        hx, hy = info.half[0], info.half[1]
        vals, g = [], _g(16)
        row = 0
        for a in (-1.0, 1.0):
            for b in (-1.0, 1.0):
                corner = P.pos[:2] + a * hx * P.ax[:2] + b * hy * P.ay[:2]
                for axis in (0, 1):
                    for sign, bound in ((1.0, lo[axis]), (-1.0, hi[axis])):
                        vals.append(sign * (corner[axis] - bound))
                        g[row, axis] = sign
                        g[row, 3 + axis] = sign * a * hx
                        g[row, 6 + axis] = sign * b * hy
                        row += 1
        vals = np.array(vals)
    rows.add(vals, P.through(g), Label(step, f"footprint outside region {region.name}"))


def rest_height(rows: RowSet, step: str, P: PoseX, z: float, support: str) -> None:
    g = _g(1)
    g[0, 2] = 1.0
    rows.add(np.array([P.pos[2] - z]), P.through(g), Label(step, f"not resting on {support}"))


def upright(rows: RowSet, step: str, P: PoseX, what: str) -> None:
    g = _g(2)
    g[0, 9], g[1, 10] = 1.0, 1.0
    rows.add(P.az[:2].copy(), P.through(g), Label(step, f"{what} tilted", "rad"))


def tilt_within(rows: RowSet, step: str, P: PoseX, what: str, tilt: float) -> None:
    """P's z axis within `tilt` (rad) of the vertical: az_z >= cos(tilt)."""
    g = _g(1)
    g[0, 11] = 1.0
    rows.add(np.array([P.az[2] - np.cos(tilt)]), P.through(g),
             Label(step, f"{what} tilted", ""))


def stays_up(rows: RowSet, step: str, P: PoseX) -> None:
    """az_z >= DOWN: excludes the upside-down branch of the upright equations."""
    g = _g(1)
    g[0, 11] = 1.0
    rows.add(np.array([P.az[2] - DOWN]), P.through(g), Label(step, "upside down", ""))


GAP = 1e-3  # m: footprints of two resting objects kept this far apart (touching is allowed)


def corner_jac(a: float, b: float, hx: float, hy: float) -> np.ndarray:
    """d corner / d v (2, 12) of the footprint corner pos + a hx ax + b hy ay."""
    g = np.zeros((2, 12))
    g[0, 0] = g[1, 1] = 1.0
    g[0, 3] = g[1, 4] = a * hx
    g[0, 6] = g[1, 7] = b * hy
    return g


def corners(P: PoseX, info: BodyInfo) -> list[tuple[np.ndarray, np.ndarray]]:
    """The footprint corners of a box: (xy, d xy / d v)."""
    hx, hy = info.half[0], info.half[1]
    return [(P.pos[:2] + a * hx * P.ax[:2] + b * hy * P.ay[:2], corner_jac(a, b, hx, hy))
            for a in (-1.0, 1.0) for b in (-1.0, 1.0)]


def _pair_jac(P: PoseX, gp: np.ndarray, Q: PoseX, gq: np.ndarray):
    jac = P.through(gp)
    for k, v in Q.through(gq).items():
        jac[k] = jac[k] + v if k in jac else v
    return jac


def _sat(P: PoseX, pinfo: BodyInfo, Q: PoseX, qinfo: BodyInfo):
    """Separation of two box footprints: the largest gap along an edge normal of either.

    Positive: apart by at least that much along that axis; negative: minus the
    penetration depth (separating axis theorem, exact for convex polygons).
    Returns (value, d/d v_P (12,), d/d v_Q (12,)).

    In Python floats: it runs for every pair of placed boxes at every evaluation of
    every NLP with placements, and numpy's per-call cost on 4 x 2 arrays was most of
    its time (arm-sort: 51,000 calls per three skeletons).
    """
    vp, vq = P.v.tolist(), Q.v.tolist()
    cp = _corners(vp, pinfo.half[0], pinfo.half[1])
    cq = _corners(vq, qinfo.half[0], qinfo.half[1])
    axes = ((vp[3], vp[4]), (vp[6], vp[7]), (vq[3], vq[4]), (vq[6], vq[7]))
    proj_p = [[x * ux + y * uy for x, y in cp] for ux, uy in axes]
    proj_q = [[x * ux + y * uy for x, y in cq] for ux, uy in axes]
    # Along -u first: on a tie (coincident footprints, as at the centred start) P
    # moves along +x, the way the centre-distance rows it replaced pushed it.
    vals = [min(a) - max(b) for a, b in zip(proj_p, proj_q, strict=True)]
    vals += [min(b) - max(a) for a, b in zip(proj_p, proj_q, strict=True)]
    best = max(range(8), key=vals.__getitem__)  # the first of equal ones, as argmax
    sign = -1.0 if best < 4 else 1.0
    i = best % 4
    nx, ny = sign * axes[i][0], sign * axes[i][1]
    along_p = [x * nx + y * ny for x, y in cp]
    along_q = [x * nx + y * ny for x, y in cq]
    ia = max(range(4), key=along_p.__getitem__)
    ib = min(range(4), key=along_q.__getitem__)
    gp, gq = np.zeros(12), np.zeros(12)
    for g, (a, b), half, scale in ((gp, _SIGN_PAIRS[ia], pinfo.half, -1.0),
                                   (gq, _SIGN_PAIRS[ib], qinfo.half, 1.0)):
        g[0], g[1] = scale * nx, scale * ny
        g[3], g[4] = scale * nx * a * half[0], scale * ny * a * half[0]
        g[6], g[7] = scale * nx * b * half[1], scale * ny * b * half[1]
    col = 3 if i % 2 == 0 else 6
    g = gp if i < 2 else gq
    g[col] += sign * (cq[ib][0] - cp[ia][0])
    g[col + 1] += sign * (cq[ib][1] - cp[ia][1])
    return float(vals[best]), gp, gq


_SIGN_PAIRS = tuple((a, b) for a in (-1.0, 1.0) for b in (-1.0, 1.0))  # corner order


def _corners(v: list, hx: float, hy: float) -> list[tuple[float, float]]:
    """The footprint corners (x, y) of pose v (PoseX.v as a list), in _SIGN_PAIRS' order."""
    return [(v[0] + a * hx * v[3] + b * hy * v[6], v[1] + a * hx * v[4] + b * hy * v[7])
            for a, b in _SIGN_PAIRS]


def _rect_point(R: PoseX, rinfo: BodyInfo, c: np.ndarray):
    """Signed distance of point c (xy) from a rectangle or disk footprint, and its
    gradients w.r.t. v_R (12,) and c (2,)."""
    d = c - R.pos[:2]
    ex, ey = R.ax[:2], R.ay[:2]
    local = np.array([ex @ d, ey @ d])
    half = np.asarray(rinfo.half[:2])
    if rinfo.disk:
        n = float(np.linalg.norm(local))
        sd, gl = n - half[0], (local / n if n > 1e-12 else np.array([1.0, 0.0]))
    else:
        q = np.abs(local) - half
        sgn = np.sign(local) + (local == 0)
        if np.all(q <= 0):
            i = int(np.argmax(q))
            sd, gl = float(q[i]), np.zeros(2)
            gl[i] = sgn[i]
        else:
            out = np.maximum(q, 0.0)
            sd = float(np.linalg.norm(out))
            gl = out / sd * sgn
    gc = gl[0] * ex + gl[1] * ey
    gr = np.zeros(12)
    gr[0:2] = -gc
    gr[3:5] = gl[0] * d
    gr[6:8] = gl[1] * d
    return float(sd), gr, gc


def apart(rows: RowSet, step: str, P: PoseX, pinfo: BodyInfo, Q: PoseX, qinfo: BodyInfo,
          other: str, gap: float = GAP) -> None:
    """Footprints apart by `gap`, exactly: disks by their centres, a disk and a box by
    the centre's distance from the box, two boxes by the separating axis theorem."""
    gp, gq = np.zeros((1, 12)), np.zeros((1, 12))
    if pinfo.disk and qinfo.disk:
        d = P.pos[:2] - Q.pos[:2]
        n = float(np.linalg.norm(d))
        u = d / n if n > 1e-12 else np.array([1.0, 0.0])
        val = n - pinfo.half[0] - qinfo.half[0]
        gp[0, 0:2], gq[0, 0:2] = u, -u
    elif pinfo.disk or qinfo.disk:
        (D, dinfo, gd), (R, rinfo, gr) = ((P, pinfo, gp), (Q, qinfo, gq)) if pinfo.disk \
            else ((Q, qinfo, gq), (P, pinfo, gp))
        sd, g_r, g_c = _rect_point(R, rinfo, D.pos[:2])
        val = sd - dinfo.half[0]
        gr[0] = g_r
        gd[0, 0:2] = g_c
    else:
        val, gp[0], gq[0] = _sat(P, pinfo, Q, qinfo)
    rows.add(np.array([val - gap]), _pair_jac(P, gp, Q, gq), Label(step, f"overlaps {other}"))


def within_reach(rows: RowSet, step: str, P: PoseX, centre, reach: float) -> None:
    d = P.pos - np.asarray(centre)
    n = float(np.linalg.norm(d))
    g = _g(1)
    g[0, 0:3] = -d / max(n, 1e-12)
    rows.add(np.array([reach - n]), P.through(g), Label(step, "out of the robot's reach"))


def near(rows: RowSet, step: str, P: PoseX, centre_xy, radius: float) -> None:
    """P's (x, y) within `radius` of centre_xy (squared: smooth at the centre)."""
    d = P.pos[:2] - np.asarray(centre_xy, dtype=float)
    g = _g(1)
    g[0, 0:2] = -2.0 * d
    rows.add(np.array([radius * radius - float(d @ d)]), P.through(g),
             Label(step, "off the spot clear of a later motion"))


def same_pose(rows: RowSet, ineq: RowSet, step: str, H: PoseX, target: PoseX, planar: bool,
              yaw: bool) -> None:
    """The gripped object's pose (from the tool) matches where the object is."""
    k = 2 if planar else 3
    g = _g(k)
    for i in range(k):
        g[i, i] = 1.0
    jac = H.through(g)
    for name, v in target.through(-g).items():
        jac[name] = jac[name] + v if name in jac else v
    rows.add(H.pos[:k] - target.pos[:k], jac, Label(step, "tool off the contact pose"))
    if planar:
        return
    upright(rows, step, H, "tool")
    stays_up(ineq, step, H)
    if yaw:
        # Tool yaw equal to the object's modulo pi: the gripper is symmetric.
        val = H.ax[0] * target.ax[1] - H.ax[1] * target.ax[0]
        gh, go = _g(1), _g(1)
        gh[0, 3], gh[0, 4] = target.ax[1], -target.ax[0]
        go[0, 3], go[0, 4] = -H.ax[1], H.ax[0]
        jac = H.through(gh)
        for name, v in target.through(go).items():
            jac[name] = jac[name] + v if name in jac else v
        rows.add(np.array([val]), jac, Label(step, "gripper not aligned with the faces", "rad"))


def same_yaw(rows: RowSet, step: str, P: PoseX, Q: PoseX) -> None:
    """P turned as Q: sin(yaw_P - yaw_Q) = 0 (both upright; starts on the right branch)."""
    val = Q.ax[0] * P.ax[1] - Q.ax[1] * P.ax[0]
    gp, gq = _g(1), _g(1)
    gp[0, 3], gp[0, 4] = -Q.ax[1], Q.ax[0]
    gq[0, 3], gq[0, 4] = P.ax[1], -P.ax[0]
    rows.add(np.array([val]), _pair_jac(P, gp, Q, gq), Label(step, "turned", "rad"))


def point_in_rect(rows: RowSet, step: str, P: PoseX, lo, hi, what: str) -> None:
    vals = np.array([P.pos[0] - lo[0], hi[0] - P.pos[0], P.pos[1] - lo[1], hi[1] - P.pos[1]])
    g = _g(4)
    g[0, 0], g[1, 0], g[2, 1], g[3, 1] = 1, -1, 1, -1
    rows.add(vals, P.through(g), Label(step, what))
