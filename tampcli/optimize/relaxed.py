"""A proved lower bound on the trajectory cost of a skeleton, or of every
completion of a prefix: the seed's V(d_0:k) with the rest relaxed (§5).

For the planar robot (q = the disk's x, y; it never turns, nor does what it
carries or pushes) the trajectory problem without collisions in motion is a
convex QP (but for objects kept apart: a disjunction of QPs):

- cost: each motion phase has T segments from keyframe q_{k-1} to q_k, so its
  cost sum |dq|^2 >= |q_k - q_{k-1}|^2 / T (Cauchy-Schwarz), q_{-1} the start;
- a grasp: the object's centre = q + v, v one offset for the whole hold, in
  the footprint grown by the rim (a rounded rectangle or a disk), relaxed to
  16 of its supporting half-planes (the held object may drift from v by
  validate's RIGID per motion phase);
- a place: the centre = q + v inside its region, the footprint's axis-aligned
  half extents inward (the yaw is the start's: nothing turns it); on a body,
  the centre over the body's top face;
- a push: the object moves with the disk (up to validate's RIGID drift), its
  offset behind one face of a box (each assignment of faces is a QP of its
  own; the bound is their minimum), the displacement within that face's
  friction cone; a disk's push keeps its offset on a circle (relaxed as a
  grasp's) and drops the cone;
- joint limits on every keyframe;
- a box put down apart from every upright box resting beside it: a
  disjunction over separating axes, branched on (relaxed_apart.py).

Everything else (collisions in motion, disks and meshes kept apart,
stability, a move's target, a symbolic action) is dropped, which only
lowers the value: it is a lower
bound on the cost of every trajectory `validate` accepts (its tolerances are
the relaxation's slack), and so, for a prefix, on every completion (what is
added costs >= 0). Each QP is solved with a certificate (convex_qp), so the
bound is `proved`; on any other robot there is no such relaxation (None).
Each step's kind adds its rows (ModeKind.relax), so a kind that adds none
(a move, a symbolic action) is relaxed to its motion alone.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from tampcli.optimize.bodies import TOUCH_TOLERANCE
from tampcli.optimize.convex_qp import ConvexQP
from tampcli.optimize.kinds.push_check import PENETRATION, SLACK, STILL
from tampcli.optimize.kinds.push_contact import PUSH_FRICTION, face_of
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.push_reach import cone_slack, footprint_extent, open_faces, rot
from tampcli.optimize.relaxed_apart import Apart, apart, solve_apart
from tampcli.optimize.relaxed_why import cone_why, why_infeasible
from tampcli.optimize.verify import INSIDE, LIMIT, RIGID
from tampcli.optimize.verify import STILL as STILL_OBJECT

DIRECTIONS = 16  # supporting half-planes of a grip's offset set (a polygon around it)
MAX_FACE_ASSIGNMENTS = 64  # past this, pushes are relaxed to their offset hull, no cone
MAX_QPS = 24  # per bound, shared by the face assignments' branch and bound on apart rows


@dataclass(frozen=True)
class RelaxedBound:
    """value: lower bound on the trajectory cost (m^2); inf when no trajectory
    satisfies even the relaxation. kind: "proved" or "heuristic"."""

    value: float
    kind: str
    qps: int = 0  # QPs solved
    why: str | None = None  # what makes it infeasible, in words


def relaxed_bound(problem: TrajectoryProblem) -> RelaxedBound | None:
    """The bound of `problem` (a lowered skeleton or prefix); None off the planar robot."""
    if not problem.planar:
        return None
    if problem.error is not None:
        return RelaxedBound(math.inf, "proved", why=problem.error)
    hull = Builder(problem, {})  # no face chosen: no friction cone
    choices = [(s.index, s.kind.relax_faces(problem, s)) for s in problem.steps]
    choices = [(i, faces) for i, faces in choices if faces]
    pushes = [problem.steps[i].name for i, _ in choices]
    # Only the faces whose cone can lead from where the object is into the target
    # (push_reach.py): the others' QPs are infeasible, proved without solving them.
    choices = [(i, hull.open_faces(problem.steps[i], faces)) for i, faces in choices]
    closed = next((i for i, faces in choices if not faces), None)
    if closed is not None:
        return RelaxedBound(math.inf, "proved", 0, cone_why(problem, closed))
    assignments = [{}]
    if math.prod(len(faces) for _, faces in choices) <= MAX_FACE_ASSIGNMENTS:
        assignments = [dict(zip([i for i, _ in choices], pick, strict=True))
                       for pick in itertools.product(*[faces for _, faces in choices])]
    budget = max(5, MAX_QPS // len(assignments))
    best, proved, qps = math.inf, True, 0
    for faces in assignments:
        builder = hull if not faces else Builder(problem, faces)
        out, solved, _ = solve_apart(builder.qp(), builder.aparts, budget)
        best, proved, qps = min(best, out.value), proved and out.proved, qps + solved
    kind = "proved" if proved else "heuristic"
    why = why_infeasible(problem, hull, budget, pushes,
                         lambda faces: Builder(problem, faces)) if math.isinf(best) else None
    return RelaxedBound(float(max(best, 0.0)), kind, qps, why)


def _polygon(support) -> list[tuple[np.ndarray, float]]:
    """Half-planes d'v <= h(d) around a convex set given by its support function."""
    out = []
    for j in range(DIRECTIONS):
        d = np.array([math.cos(2 * math.pi * j / DIRECTIONS),
                      math.sin(2 * math.pi * j / DIRECTIONS)])
        out.append((d, support(d)))
    return out


class Builder:
    """The QP of one skeleton for one assignment of pushed faces: variables are
    2-vectors (keyframes, grip offsets, placements) with boxes; rows in lists. Each
    step's kind adds its rows (ModeKind.relax) through `grasp`, `place`, `push`."""

    def __init__(self, problem: TrajectoryProblem, faces: dict[int, float]):
        self.problem, self.faces = problem, faces
        self.lo: list[float] = []
        self.hi: list[float] = []
        self.ineq: list[tuple[dict[int, np.ndarray], float]] = []  # sum a_v'x_v <= b
        world = problem.world
        self.qlo = np.asarray(world.lower, dtype=float) - LIMIT
        self.qhi = np.asarray(world.upper, dtype=float) + LIMIT
        self.keyframes = [self.var(self.qlo, self.qhi) for _ in range(problem.n_keyframes)]
        # Where each movable object's centre is: a constant (x, y) or a variable.
        self.pos: dict[str, np.ndarray | int] = {
            n: np.array(i.pose[:2]) for n, i in problem.bodies.items() if not i.fixed}
        self.offsets: dict[int, tuple[int, int]] = {}  # grasp step -> (offset var, keyframe)
        self.aparts: list[Apart] = []
        self.push_boxes: dict[int, tuple] = {}  # push step -> (centre box before, after)
        self.regions = {r.name: r for r in problem.scene.regions}
        for step in problem.steps:
            step.kind.relax(self, step)

    def forget(self, step) -> None:
        """The step moves its object where the relaxation does not follow."""
        self.pos.pop(step.obj, None)

    def var(self, lo, hi) -> int:
        i = len(self.lo)
        self.lo.extend(float(v) for v in lo)
        self.hi.extend(float(v) for v in hi)
        return i

    def box(self, i: int) -> tuple[np.ndarray, np.ndarray]:
        return np.array(self.lo[i:i + 2]), np.array(self.hi[i:i + 2])

    def near(self, terms: dict[int, float], const: np.ndarray, slack: float) -> None:
        """|sum coef * x_v + const| <= slack, both coordinates."""
        for sign in (1.0, -1.0):
            for axis in (0, 1):
                e = sign * np.eye(2)[axis]
                self.ineq.append(({v: c * e for v, c in terms.items()},
                                  slack - sign * float(const[axis])))

    def _centre(self, obj: str, q: int, offset: int) -> None:
        """obj's centre is q + offset (it may have crept by validate's STILL at each
        mode switch since it was last put down)."""
        at = self.pos.get(obj)
        slack = STILL_OBJECT * len(self.problem.steps)
        if isinstance(at, np.ndarray):
            self.near({q: 1.0, offset: 1.0}, -at, slack)
        else:
            self.near({q: 1.0, offset: 1.0, at: -1.0}, np.zeros(2), slack)

    def _offset(self, support, reach: float) -> int:
        v = self.var([-reach] * 2, [reach] * 2)
        for d, h in _polygon(support):
            self.ineq.append(({v: d}, h))
        return v

    def grasp(self, step) -> None:
        """The object's centre is the keyframe plus an offset in the grown footprint."""
        info = self.problem.bodies[step.obj]
        rim = self.problem.scene.robot.radius + TOUCH_TOLERANCE
        if info.disk:
            def support(d):
                return rim + info.half[0]
            reach = rim + info.half[0]
        else:
            half, R = np.array(info.half[:2]), rot(info.pose[3])

            def support(d):
                return float(np.abs(R.T @ d) @ half) + rim
            reach = float(footprint_extent(info).max()) + rim
        v = self._offset(support, reach)
        (k,) = step.keyframes
        if step.obj in self.pos:
            self._centre(step.obj, self.keyframes[k], v)
        self.offsets[step.index] = (v, k)
        self.pos.pop(step.obj, None)  # held: where it is follows the disk

    def _placement(self, step, q: int, offset: int, phases: int) -> int:
        """A variable for obj's centre after the step = q + offset, inside its target;
        up to `phases` motion phases' drift (validate's RIGID each) away from it."""
        info = self.problem.bodies[step.obj]
        drift = RIGID * phases + STILL_OBJECT * len(self.problem.steps)
        qlo, qhi = self.box(q)
        olo, ohi = self.box(offset)
        lo, hi = qlo + olo - drift, qhi + ohi + drift
        ext, regions = footprint_extent(info), self.regions
        if step.target in regions:
            r = regions[step.target]
            lo = np.maximum(lo, np.asarray(r.lower) + ext - INSIDE)
            hi = np.minimum(hi, np.asarray(r.upper) - ext + INSIDE)
        c = self.var(lo, np.maximum(hi, lo))
        self.near({c: 1.0, q: -1.0, offset: -1.0}, np.zeros(2), drift)
        if step.target not in regions and step.support is not None:
            self._over(c, step.support)
        if (hi < lo).any():  # an empty box: infeasible, as a row says
            self.ineq.append(({c: np.zeros(2)}, -1.0))
        beside = [(n, at) for n, at in self.pos.items() if n != step.obj]
        beside += [(n, np.array(i.pose[:2])) for n, i in self.problem.bodies.items()
                   if i.fixed and n != step.support]
        self.aparts += [a for n, at in beside
                        if (a := apart(self.problem, step, c, n, at, self.box)) is not None]
        self.pos[step.obj] = c
        return c

    def _over(self, c: int, support: str) -> None:
        """The centre over the support's top face (in its frame), as verify measures."""
        sinfo = self.problem.bodies[support]
        at = self.pos.get(support) if not sinfo.fixed else np.array(sinfo.pose[:2])
        if at is None:
            return
        R = rot(sinfo.pose[3])
        half = np.array(sinfo.half[:2]) + INSIDE
        for axis in (0, 1):
            for sign in (1.0, -1.0):
                a = sign * R[:, axis]
                if isinstance(at, np.ndarray):
                    self.ineq.append(({c: a}, half[axis] + float(a @ at)))
                else:
                    self.ineq.append(({c: a, at: -a}, half[axis]))

    def place(self, step) -> None:
        """Released where the keyframe plus the grasp's offset puts it, inside its target."""
        (k,) = step.keyframes
        held = self.offsets.get(step.grasp_step)
        if held is not None:
            v, since = held
            self._placement(step, self.keyframes[k], v, k - since)

    def push(self, step) -> None:
        """Behind a face at the first keyframe, moved with the disk to the second, within
        the face's cone, into the target."""
        k0, k1 = step.keyframes
        info = self.problem.bodies[step.obj]
        rim = self.problem.scene.robot.radius
        angle = self.faces.get(step.index)
        w = self._face_offset(info, rim, angle)  # the object's centre minus the disk's
        q0, q1 = self.keyframes[k0], self.keyframes[k1]
        at = self.pos.get(step.obj)
        if at is not None:
            self._centre(step.obj, q0, w)
        c = self._placement(step, q1, w, 1)  # the same offset all along the push
        if at is not None:  # where the centre starts and ends: boxes (push_reach.py)
            src = (at, at) if isinstance(at, np.ndarray) else self.box(at)
            self.push_boxes[step.index] = (src, self.box(c))
        if angle is not None:
            self._cone(info, angle, q0, q1)

    def _face_offset(self, info, rim: float, angle: float | None) -> int:
        """The pusher beyond the face `angle` (inward normal, object frame) of a box,
        as validate attributes a contact to a face: its centre further out along that
        normal than along the other axis, the rim touching (TOUCH_TOLERANCE away at
        most, PENETRATION in at most, a corner's diagonal included). With no face (a
        disk, or too many pushes), around the whole footprint."""
        R = rot(info.pose[3])
        out = rim + TOUCH_TOLERANCE
        if angle is None:
            half = np.array(info.half[:2]) if not info.disk else None

            def support(d):
                return out + (info.half[0] if half is None else float(np.abs(R.T @ d) @ half))
            return self._offset(support, float(footprint_extent(info).max()) + out)
        face = face_of(info, angle)
        n = R @ np.array([math.cos(angle), math.sin(angle)])
        e = R @ np.array([-math.sin(angle), math.cos(angle)])
        reach = float(footprint_extent(info).max()) + 2 * out  # holds at any yaw
        w = self.var([-reach] * 2, [reach] * 2)
        near = (rim - PENETRATION) / math.sqrt(2)  # at a corner, on its diagonal
        self.ineq += [({w: n}, face.depth + out), ({w: -n}, -face.depth - near),
                      ({w: e}, face.width + out), ({w: -e}, face.width + out)]
        return w

    def open_faces(self, step, faces) -> tuple[float, ...]:
        """The faces among `faces` of a push whose cone can lead from where this
        skeleton leaves its object into the target: the others' QPs are infeasible
        (push_reach.cone_gap, with this relaxation's drift: the centre's creep at
        both ends and a push phase's RIGID). All of them where the object's place
        before the push is not followed (a kind without relaxation moved it)."""
        boxes = self.push_boxes.get(step.index)
        if boxes is None:
            return tuple(faces)
        drift = RIGID + 2 * STILL_OBJECT * len(self.problem.steps)
        return open_faces(self.problem.bodies[step.obj], *boxes, drift,
                          cone_slack(self.problem.options.waypoints), faces)

    def _cone(self, info, angle: float, q0: int, q1: int) -> None:
        """|d.e| <= mu' d.n + slack for d = q1 - q0 (the object moves with the disk)."""
        R = rot(info.pose[3])
        n = R @ np.array([math.cos(angle), math.sin(angle)])
        e = R @ np.array([-math.sin(angle), math.cos(angle)])
        # validate's test per segment, |d.e| <= mu d.n + SLACK |d|, implies this
        # wider cone for each segment longer than STILL, so for their sum; the
        # shorter ones add at most STILL each, in any direction.
        mu = (PUSH_FRICTION + SLACK) / (1.0 - SLACK)
        slack = self.problem.options.waypoints * STILL * (1.0 + mu)
        for sign in (1.0, -1.0):
            a = sign * e - mu * n
            self.ineq.append(({q1: a, q0: -a}, slack))

    def qp(self) -> ConvexQP:
        n = len(self.lo)
        T = self.problem.options.waypoints
        P, c, r = np.zeros((n, n)), np.zeros(n), 0.0
        prev = np.asarray(self.problem.world.start, dtype=float)[:2]
        prev_i = None
        for k in self.keyframes:
            # |q_k - q_prev|^2 / T, q_prev a constant (the start) or a variable.
            for a in (0, 1):
                P[k + a, k + a] += 2.0 / T
                if prev_i is None:
                    c[k + a] -= 2.0 * prev[a] / T
                    r += prev[a] ** 2 / T
                else:
                    P[prev_i + a, prev_i + a] += 2.0 / T
                    P[k + a, prev_i + a] -= 2.0 / T
                    P[prev_i + a, k + a] -= 2.0 / T
            prev_i = k
        # Every equality holds up to validate's tolerances: rows of A, none in E.
        return ConvexQP(P, c, r, *_matrix(self.ineq, n), np.zeros((0, n)), np.zeros(0),
                        np.array(self.lo), np.array(self.hi))


def _matrix(rows, n: int) -> tuple[np.ndarray, np.ndarray]:
    M, rhs = np.zeros((len(rows), n)), np.zeros(len(rows))
    for i, (terms, bound) in enumerate(rows):
        for v, a in terms.items():
            M[i, v:v + 2] += a
        rhs[i] = bound
    return M, rhs
