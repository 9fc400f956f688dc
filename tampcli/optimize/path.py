"""The "path" NLP of one motion phase: its interior waypoints, keyframes fixed.

Per-phase NLPs (T-1 waypoints each) instead of one joint NLP: with the
keyframes fixed the phases are independent, each NLP is small (SLSQP's work
grows with the cube of the variables), and a failing phase is named. The
cost is the seed's smoothness term, sum |q_{i+1} - q_i|^2 over the phase.
Collision rows are taken at every interior waypoint and at
`interpolation_checks` points inside every segment (the first and last
segments too: they move with the first and last interior waypoints).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.optimize import constraints as C
from tampcli.optimize.bodies import REST_TOLERANCE
from tampcli.optimize.collide import (
    TOUCH_SLACK,
    Held,
    body_matrices,
    contact_key,
    contact_rows,
    held_spec,
    row_keys,
)
from tampcli.optimize.expr import Label, PoseX, held_posex
from tampcli.optimize.grips import held_pose
from tampcli.optimize.layout import Layout, waypoint_block
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.skeleton import MotionPhase
from tampcli.optimize.stages import Rows
from tampcli.optimize.way_out import way_out

STEP_RATIO = 2.0  # longest segment of a motion over its root-mean-square step


def pose_of_matrix(t) -> PoseX:
    t = np.asarray(t, dtype=float)
    return PoseX(np.concatenate([t[:3, 3], t[:3, 0], t[:3, 1], t[:3, 2]]))


def phase_layout(problem: TrajectoryProblem, T: int) -> Layout:
    return Layout(tuple((waypoint_block(i), problem.n) for i in range(1, T)))


def samples(T: int, checks: int):
    """(tau, i, s): position tau = i + s along the phase, between waypoints i and i+1."""
    out = []
    for i in range(T):
        for j in range(checks + 1):
            s = j / (checks + 1)
            if i == 0 and j == 0:
                continue
            out.append((i + s, i, s))
    return out


def phase_rows_fn(problem: TrajectoryProblem, m: MotionPhase, q_a, q_b, held: Held | None,
                  moved: dict, kin, checker, T: int, checks: int, rest_z: float | None,
                  label: str, keep=None, margin: float | None = None,
                  own: MotionMargins | None = None):
    """evaluate(x) -> Rows for motion `m` from q_a to q_b (both fixed), over T segments.

    Its cost is (T / waypoints) * sum |dq|^2: a motion given more segments than the
    options' `waypoints` (a sampled path with many corners) is weighed as if it had
    that many, so a motion's cost approximates the same integral of squared joint
    speed whatever its segments (a straight line costs |q_b - q_a|^2 / waypoints).

    `keep(tau) -> bool` selects the sample points that get collision rows
    (all when None). `rest_z`: the height a pushed object keeps (None: nothing
    is pushed). `margin`: the clearance kept (the options' when None); `own`:
    the motion's margins for some keys (`motion_margins`; None: the contacts
    entered or left touch, TOUCH_SLACK deep at most).
    """
    opts = problem.options
    margin = opts.margin if margin is None else margin
    layout = phase_layout(problem, T)
    poses = {name: pose_of_matrix(t) for name, t in moved.items()}
    keys = row_keys(list(problem.bodies), m.sliding, held)
    pts = [p for p in samples(T, checks) if keep is None or keep(p[0])]
    n = problem.n

    def block(i):
        return waypoint_block(i) if 0 < i < T else None

    ignores = [allowed_contacts(m)] * len(pts)
    own = own or MotionMargins.touching(m)
    margins = [own.at(tau, T) for tau, _, _ in pts]
    weights = [[(b, wgt) for b, wgt in ((block(i), 1 - s), (block(i + 1), s))
                if b is not None and wgt > 0] for _, i, s in pts]
    where = np.array([i for _, i, _ in pts], dtype=int)
    frac = np.array([s for _, _, s in pts])[:, None]
    matrices = body_matrices(poses)
    spec = held_spec(held)
    scale = T / opts.waypoints
    hess = {key: scale * block for key, block in smoothness_hessian(T, n).items()}

    def evaluate(x):
        w = x.reshape(T - 1, n)
        qs = np.vstack([q_a, w, q_b])
        rows = Rows()
        d = np.diff(qs, axis=0)
        rows.cost = scale * float(np.sum(d * d))
        for i in range(1, T):
            rows.cost_grad[waypoint_block(i)] = 2.0 * scale * (d[i - 1] - d[i])
        rows.cost_hess = hess
        _step_rows(rows, d, T, label)
        samples_q = (1 - frac) * qs[where] + frac * qs[where + 1]
        contacts = checker.distances_many(samples_q, matrices, spec, ignores, opts.activation)
        for q, found, wts, keyed in zip(samples_q, contacts, weights, margins, strict=True):
            frame = kin.frame(q) if held is not None and held.t_block else None
            contact_rows(rows.ineq, label, found, wts, frame, held, poses, keys,
                         opts.activation, margin, keyed)
        if m.own:
            problem.step_of_keyframe(m.index).kind.path_rows(rows, label, problem, qs, held,
                                                             kin)
        if rest_z is not None and not problem.planar:
            for i in range(1, T):
                frame = kin.frame(qs[i])
                H = held_posex(held_pose(frame, held.grip, held.t), waypoint_block(i), None)
                C.upright(rows.eq, label, H, held.name)
                C.rest_height(rows.eq, label, H, rest_z, "its support")
        return rows

    return evaluate, layout


def smoothness_hessian(T: int, n: int) -> dict:
    """The cost's second derivatives (constant): 4 I at each interior waypoint, -2 I
    between neighbours. Ipopt steps with it; SLSQP builds its own from gradients."""
    eye = np.eye(n)
    out = {(waypoint_block(i), waypoint_block(i)): 4.0 * eye for i in range(1, T)}
    out.update({(waypoint_block(i), waypoint_block(i + 1)): -2.0 * eye for i in range(1, T - 1)})
    return out


def _step_rows(rows: Rows, d: np.ndarray, T: int, label: str) -> None:
    """|d_i|^2 <= STEP_RATIO^2 * mean |d_j|^2 for each of the T segments.

    Collision rows hold at sample points only: without these rows the NLP
    makes the segment that crosses a wall as long as it takes for its sample
    points to land on either side (measured: a Panda's last segment 8 times
    the others, through a slot's wall between every 16th point).
    """
    sq = np.sum(d * d, axis=1)
    c = STEP_RATIO ** 2 / T
    values = c * np.sum(sq) - sq
    dS = {i: 2.0 * (d[i - 1] - d[i]) for i in range(1, T)}  # d sum |d|^2 / d q_i
    jac = {}
    for i in range(1, T):
        J = np.outer(np.full(T, c), dS[i])
        J[i - 1] -= 2.0 * d[i - 1]  # d |d_{i-1}|^2 / d q_i
        J[i] += 2.0 * d[i]  # d |d_i|^2 / d q_i
        jac[waypoint_block(i)] = J
    rows.ineq.add(values, jac, Label(label, f"a segment longer than {STEP_RATIO:g} times "
                                     "the mean step", ""))


def allowed_contacts(m: MotionPhase) -> frozenset[str]:
    """What motion m may go into: only what it slides along (resting contact)."""
    return frozenset(m.sliding)


@dataclass(frozen=True)
class MotionMargins:
    """Per-key margins of one motion where they are not its margin.

    near: for what is closer than the margin at either keyframe (other than the
    contacts the motion enters or leaves), half its least distance there, at
    least `tight`: a slot the keyframe NLP could only fill with a smaller
    margin. Held to the margin there, the samples near the keyframe could not
    be feasible, and the NLP would make the last segment as long as it takes for
    them to land outside the slot. Not `tight` throughout: the NLP holds its
    samples at the margin, and between two of them a corner dips ~2 mm closer
    (a cube carried down beside another, placed 1 cm away: 0.8 mm into it, and
    the physics replay knocked the other over).
    entering / leaving: the contacts the motion ends or starts in, in its last
    or first segment: never closer than at the keyframe (nor than the margin),
    so touching where the keyframe touches; fingers that straddle what they
    grasp with millimetres to spare keep them on the way down.
    """

    near: dict[str, float]
    entering: dict[str, float]
    leaving: dict[str, float]

    @classmethod
    def touching(cls, m: MotionPhase) -> MotionMargins:
        return cls({}, dict.fromkeys(m.enter_contact, -TOUCH_SLACK),
                   dict.fromkeys(m.leave_contact, -TOUCH_SLACK))

    def at(self, tau: float, T: int) -> dict[str, float]:
        out = dict(self.near)
        if tau < 1:
            out.update(self.leaving)
        if tau > T - 1:
            out.update(self.entering)
        return out


def motion_margins(checker, m: MotionPhase, q_a, q_b, held, moved, margin: float,
                   tight: float, straddle: bool = False) -> MotionMargins:
    """`straddle`: the half-distance rule below for what the motion enters or leaves
    (the hand narrowed to its grips, optimize/hand.py)."""
    ends = m.enter_contact | m.leave_contact
    found = checker.distances_many(np.array([q_a, q_b]), moved, held_spec(held),
                                   [allowed_contacts(m)] * 2, margin)
    least = [{}, {}]
    for side, cs in zip(least, found, strict=True):
        for c in cs:
            k = contact_key(c)
            side[k] = min(side.get(k, np.inf), c.distance)
    near = {k: max(tight, min(least[0].get(k, margin), least[1].get(k, margin)) / 2)
            for side in least for k, d in side.items() if d < margin and k not in ends}
    # With the hand narrowed, what the motion enters or leaves without touching it there,
    # nearer than the margin at that keyframe (fingers straddling an object with
    # millimetres to spare), keeps half that distance outside the end segment too: held
    # to the margin there, the hand could only come down on it in one long last segment
    # (arm-kitchen with the hand opened 6 mm a side: a detour costing 7 times the
    # straight line, 47 NLPs against 23). What it touches there (an object set down on
    # another) keeps the margin until the end segment, which alone may come that close.
    for keys, side in ((m.enter_contact, least[1]), (m.leave_contact, least[0])):
        if straddle:
            near.update({k: side[k] / 2 for k in keys
                         if k in side and 2 * tight < side[k] < margin and k not in near})

    def touch(keys, side):
        return {k: min(margin, side.get(k, margin)) - TOUCH_SLACK for k in keys}

    return MotionMargins(near, touch(m.enter_contact, least[1]), touch(m.leave_contact, least[0]))


def sample_clearance(problem, m: MotionPhase, q_a, q_b, x, held, moved, checker, T, checks,
                     margin: float, horizon: float, own: MotionMargins
                     ) -> dict[float, float]:
    """tau -> least slack over the sample's contacts (distance less the margin the rows
    keep for that contact), capped at `horizon`."""
    w = np.asarray(x).reshape(T - 1, problem.n)
    qs = np.vstack([q_a, w, q_b])
    pts = samples(T, checks)
    samples_q = np.array([(1 - s) * qs[i] + s * qs[i + 1] for _, i, s in pts])
    contacts = checker.distances_many(samples_q, moved, held_spec(held),
                                      [allowed_contacts(m)] * len(pts), horizon + margin)
    out = {}
    for (tau, _, _), found in zip(pts, contacts, strict=True):
        at = own.at(tau, T)
        out[tau] = min((c.distance - at.get(contact_key(c), margin) for c in found),
                       default=horizon)
    return out


def via_points(problem: TrajectoryProblem, q_a, q_b, T: int, held_height: float, moved: dict,
               rng, held: Held | None = None) -> np.ndarray:
    """(T-1, n) initial interior waypoints: lift, cross above the obstacles, descend.

    A keyframe with the hand under something is left (or reached) first along its
    approach, backing out from under it (way_out): straight up would run through it.
    `held`: what the hand carries (its size decides how far out is clear)."""
    world = problem.world
    q_a, q_b = np.asarray(q_a, float), np.asarray(q_b, float)
    if problem.planar:
        return _planar_detour(problem, q_a, q_b, T, moved)
    ends = []
    for q in (q_a, q_b):
        out = way_out(problem, q, moved, held)
        ends.append((world.tool_pose(q), (q,)) if out is None
                    else (out.tool, (q, *out.configs)))
    (ta, out_a), (tb, out_b) = ends
    near = [world.tool_pose(q)[:2, 3] for q in (q_a, q_b)] + [ta[:2, 3], tb[:2, 3]]
    lo = np.min(near, axis=0) - 0.1
    hi = np.max(near, axis=0) + 0.1
    top = max(ta[2, 3], tb[2, 3])
    for name, info in problem.bodies.items():
        x, y = (moved[name][:2, 3] if name in moved else info.pose[:2])
        r = info.radius
        if x + r >= lo[0] and x - r <= hi[0] and y + r >= lo[1] and y - r <= hi[1]:
            z = (moved[name][2, 3] if name in moved else info.pose[2]) + info.half[2]
            if z < top + 0.6:
                top = max(top, z + held_height + 0.08)
    ups = []
    for t, out in ((ta, out_a), (tb, out_b)):
        up = t.copy()
        up[2, 3] = top
        ups.append(_lifted(world, up, out, int(rng.integers(1 << 30))))
    path = np.array([*out_a, *ups[0], *ups[1], *out_b[::-1]])
    seg = np.linalg.norm(np.diff(path, axis=0), axis=1) + 1e-9
    cum = np.concatenate([[0.0], np.cumsum(seg)]) / np.sum(seg)
    taus = np.arange(1, T) / T
    return np.array([[np.interp(t, cum, path[:, j]) for j in range(path.shape[1])]
                     for t in taus])


def _lifted(world, up: np.ndarray, out: tuple, rng_seed: int) -> list[np.ndarray]:
    """[IK of the lifted pose `up`] ([] where none is found) from the last of `out`
    (the keyframe, then its way out). After a way out, the arm near a joint limit,
    the pose or else the position alone from there, before random seeds: their
    answer can swing the first joint round (blind8 p03: 5 rad, through the arm's
    own links on the way)."""
    tries = [dict(restarts=0), dict(restarts=0, position_only=True)] if len(out) > 1 else []
    for kwargs in [*tries, dict(rng_seed=rng_seed)]:
        q, res = world.ik(up, seed=out[-1], **kwargs)
        if res < 1e-3:
            return [q]
    return []


def _planar_detour(problem, q_a, q_b, T, moved) -> np.ndarray:
    """Straight line, bent around the first body it would cross (side chosen by clearance).

    Only where motion.py's grid route (geometry/planar_route.py) finds nothing: a
    passage narrower than the grid's step. Round a second wall it runs through it."""
    radius = problem.scene.robot.radius
    taus = np.arange(1, T) / T
    line = q_a + np.outer(taus, q_b - q_a)
    d = q_b - q_a
    length = np.linalg.norm(d)
    if length < 1e-9:
        return line
    u = d / length
    normal = np.array([-u[1], u[0]])
    base_z = float(problem.scene.robot.base_pose[2, 3])
    h = problem.scene.robot.height / 2
    for name, info in problem.bodies.items():
        centre = moved[name][:3, 3] if name in moved else np.array(info.pose[:3])
        if (centre[2] + info.half[2] < base_z - h + REST_TOLERANCE
                or centre[2] - info.half[2] > base_z + h):
            continue
        rel = centre[:2] - q_a
        along = rel @ u
        across = rel @ normal
        clear = info.radius + radius + 0.03
        if 0 < along < length and abs(across) < clear:
            side = -1.0 if across > 0 else 1.0
            offset = side * (clear - abs(across)) + side * 0.02
            bump = np.sin(np.pi * taus) * offset
            line = line + np.outer(bump, normal)
            break
    return line
