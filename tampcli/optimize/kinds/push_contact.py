"""The contact of a push: which side face the pusher touches, where along it, and
the rule that makes the motion a push rather than a drag.

The model (quasi-static, sticking contact): the object slides on its support,
upright, at its resting height, and does not turn (its yaw is fixed for the
whole push; rotation is not modelled). The pusher touches one side face with
its contact point at offset s along the face, |s| <= OFFSET_FRACTION of the
face's half width, so that the line of the push passes near the centre. Every
displacement d of the object satisfies

    |d . e| <= mu (d . n)        (n: the face's inward normal, e: its tangent)

that is, the object moves into the contacted face, within the friction cone of
half-angle atan(mu) around n, mu = PUSH_FRICTION. A face is named by the angle
of its inward normal in the object's frame (0: the -x face, pi/2: the -y face);
a disk has a face in every direction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.optimize.expr import Label, PoseX, RowSet, add_jac
from tampcli.optimize.grips import Grip

PUSH_FRICTION = 0.5  # pusher on object; half-angle of the cone atan(0.5) = 26.6 deg
# The NLPs' cone, a little inside the one verify judges by (25.3 against 26.6 deg): an
# NLP's step on the cone's edge passes its own tolerance and failed verify's 0.1 %
# (blind14 p08: a can's first step 27 deg off its touch).
NLP_FRICTION = 0.95 * PUSH_FRICTION
OFFSET_FRACTION = 0.5  # the contact point stays in the middle half of the face
CONTACT_GAP = 5e-4  # m: pusher to face when touching (verify allows 1 mm in, 2 mm out)
PANDA_FINGER_HALF = 0.0131  # m: tool origin to the open fingers' outer side (collision mesh)
PANDA_FINGERTIP_HALF = 0.01  # m: a fingertip's half width, across the tool's y axis
PANDA_WRIST_HALF = 0.045  # m: the wrist (panda_link7) either side of a level hand's axis
# A level hand's axis above the support: its wrist clear of the support by the 1 cm margin
# and 1 mm where the object is tall enough; else as high as the fingertips allow, its wrist
# clear by the 1 mm tight margin. At 4.5 cm (half the hand and the margin, before) the
# wrist met the support (blind2 p07).
LEVEL_CLEARANCE = PANDA_WRIST_HALF + 0.011
LEVEL_TIGHT = PANDA_WRIST_HALF + 0.0015
BOX_FACES = (0.0, 0.5 * math.pi, math.pi, -0.5 * math.pi)
# Both open fingers push a face only where it reaches this far past their near sides at
# the face's middle; a narrower face (or a thinner drum) would pass between them (blind21
# p06: a 4 cm cube straddled by the KUKA's fingers 8 cm apart, its push 1 cm short).
FINGER_OVERLAP = 0.005
FINGER_HALF = 0.01  # m: half a fingertip's width along the tool's y axis, at most


@dataclass(frozen=True)
class Face:
    """One side face of an upright object, in the object's frame."""

    angle: float  # of the inward normal
    depth: float  # half extent along the normal: centre to face
    width: float  # half extent along the face

    @property
    def normal(self) -> np.ndarray:
        return np.array([math.cos(self.angle), math.sin(self.angle), 0.0])

    @property
    def tangent(self) -> np.ndarray:
        return np.array([-math.sin(self.angle), math.cos(self.angle), 0.0])

    @property
    def offset_limit(self) -> float:
        return OFFSET_FRACTION * self.width


def face_of(info, angle: float) -> Face:
    if info.disk:
        return Face(angle, info.half[0], 0.0)
    c, s = abs(math.cos(angle)), abs(math.sin(angle))
    return Face(angle, c * info.half[0] + s * info.half[1], s * info.half[0] + c * info.half[1])


def candidate_faces(info, direction_local) -> list[float]:
    """Face angles, best aligned with the wanted motion (object frame) first."""
    if info.disk:
        return [math.atan2(direction_local[1], direction_local[0])]
    return sorted(BOX_FACES, key=lambda a: -(math.cos(a) * direction_local[0]
                                              + math.sin(a) * direction_local[1]))


def contacted_face(info, rel) -> Face:
    """The face a pusher at `rel` (object frame, xy) is beyond: the one it touches."""
    if info.disk:
        return face_of(info, math.atan2(-rel[1], -rel[0]))
    axis = max((0, 1), key=lambda k: abs(rel[k]) - info.half[k])
    return face_of(info, (0.0 if axis == 0 else 0.5 * math.pi) + (rel[axis] > 0) * math.pi)


@dataclass(frozen=True)
class FaceGrip(Grip):
    """The object in the tool frame while the tool pushes one face; t = the offset s.

    `axes` are the object's axes in the tool frame (rows of a rotation),
    `normal` / `tangent` the face's in the tool frame, `reach` the distance
    from the tool origin to the object's centre along the normal.
    """

    axes: tuple = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    normal: tuple = (1.0, 0.0, 0.0)
    tangent: tuple = (0.0, 1.0, 0.0)
    reach: float = 0.0
    has_param = True

    def parts(self, t: float):
        n, e = np.array(self.normal), np.array(self.tangent)
        c = np.array(self.c0) + self.reach * n - t * e
        return c, np.array(self.axes), -e, np.zeros((3, 3))


def planar_face_grip(face: Face, yaw: float, dz: float, radius: float) -> FaceGrip:
    """The planar disk (which does not turn) behind `face` of an object at `yaw`."""
    c, s = math.cos(yaw), math.sin(yaw)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return FaceGrip((0.0, 0.0, dz), tuple(map(tuple, R)), tuple(R @ face.normal),
                    tuple(R @ face.tangent), face.depth + radius + CONTACT_GAP)


def pushing_fingers(half_width: float, span: tuple[float, float] | None) -> tuple[int, ...]:
    """GripChoice.finger values for a face (or drum) of this half width, the open
    fingers' near and far sides `span` from the tool's axis (World.finger_span): both
    (0) where the face reaches past their near sides, else either one alone (+1, -1)."""
    if span is None or half_width >= span[0] + FINGER_OVERLAP:
        return (0,)
    return (1, -1)


def finger_shift(finger: int, span: tuple[float, float] | None) -> float:
    """How far along the tool's y axis the contact lies from the tool's axis: 0 for
    both fingers, else the middle of the one finger's tip (at most FINGER_HALF
    past its near side: a finger's collision hull widens above its tip)."""
    if not finger or span is None:
        return 0.0
    inner, outer = span
    return finger * (inner + min(FINGER_HALF, 0.5 * (outer - inner)))


def arm_face_grip(face: Face, reach: float | None = None, shift: float = 0.0) -> FaceGrip:
    """The arm's tool pointing down, its x axis out of the face: the open fingers'
    side (spread along the tool's y, along the face) against it, at the centre's height.

    `reach`: tool origin to the object's centre as measured on the arm's own
    collision shapes (see push.py's guess); by default the Panda's fingers.
    `shift`: the contact's place along the tool's y axis (finger_shift): one finger
    alone centred on a narrow face.
    """
    tool_in_obj = np.column_stack([-face.normal, face.tangent, [0.0, 0.0, -1.0]])
    G = tool_in_obj.T
    if reach is None:
        reach = face.depth + PANDA_FINGER_HALF + CONTACT_GAP
    return FaceGrip((0.0, shift, 0.0), tuple(map(tuple, G)), tuple(G @ face.normal),
                    tuple(G @ face.tangent), reach)


def cross_face_grip(face: Face, reach: float) -> FaceGrip:
    """The arm's tool pointing down, its y axis (the closing axis) into the face: the
    open fingers one behind the other, the front one's outer side against the face
    at the centre's height, its width across it. `reach`: tool origin to the object's
    centre (the front finger's far side and CONTACT_GAP beyond the face, measured as
    arm_face_grip's)."""
    tool_in_obj = np.column_stack([face.tangent, face.normal, [0.0, 0.0, -1.0]])
    G = tool_in_obj.T
    return FaceGrip((0.0, 0.0, 0.0), tuple(map(tuple, G)), tuple(G @ face.normal),
                    tuple(G @ face.tangent), reach)


def level_lift(info) -> float | None:
    """How far above the object's centre a level hand's axis runs: high enough for the
    hand to clear the support, low enough for the fingertips to meet the face; None
    when the object is too low for both."""
    need = LEVEL_CLEARANCE - info.half[2]
    most = info.half[2] - PANDA_FINGERTIP_HALF
    if need <= most:
        return max(need, 0.0)
    return most if LEVEL_TIGHT - info.half[2] <= most else None


def level_face_grip(face: Face, lift: float, reach: float | None = None,
                    fingertip: float = 0.0, shift: float = 0.0) -> FaceGrip:
    """The arm's hand level, its tool z axis into the face and the fingers spread along
    it: the fingertips push (under a low ceiling). The tool's x axis points down.
    `fingertip`: how far the fingertips reach beyond the tool origin (the World's);
    `shift` as arm_face_grip's."""
    tool_in_obj = np.column_stack([[0.0, 0.0, -1.0], face.tangent, face.normal])
    G = tool_in_obj.T
    if reach is None:
        reach = face.depth + fingertip + CONTACT_GAP
    return FaceGrip(tuple(G @ np.array([0.0, 0.0, -lift]) + (0.0, shift, 0.0)),
                    tuple(map(tuple, G)), tuple(G @ face.normal), tuple(G @ face.tangent),
                    reach)


# ---------------------------------------------------------------- rows


def _face_axes(P: PoseX, angle: float):
    """The face's inward normal and tangent in the world, from P's axes, with d/d(ax, ay)."""
    c, s = math.cos(angle), math.sin(angle)
    return c * P.ax + s * P.ay, -s * P.ax + c * P.ay, (c, s), (-s, c)


def cone_rows(rows: RowSet, step: str, H0: PoseX, H1: PoseX, angle: float,
              mu: float = NLP_FRICTION) -> None:
    """mu (d . n) -+ d . e >= 0 for d = H1 - H0 (the object's displacement), n and e
    the face's normal and tangent at H0: the motion lies in the friction cone."""
    d = H1.pos - H0.pos
    n, e, (nx, ny), (ex, ey) = _face_axes(H0, angle)
    vals, g1, g0 = [], np.zeros((2, 12)), np.zeros((2, 12))
    for r, sign in enumerate((-1.0, 1.0)):
        w = mu * n + sign * e
        vals.append(float(w @ d))
        g1[r, 0:3] = w
        g0[r, 0:3] = -w
        g0[r, 3:6] = d * (mu * nx + sign * ex)
        g0[r, 6:9] = d * (mu * ny + sign * ey)
    rows.add(np.array(vals), add_jac(H1.through(g1), H0.through(g0)),
             Label(step, "motion not into the pushed face (a drag)"))


def same_yaw(rows: RowSet, step: str, H0: PoseX, H1: PoseX) -> None:
    """sin(yaw1 - yaw0) = 0: the pushed object does not turn."""
    a0, a1 = H0.ax, H1.ax
    g0, g1 = np.zeros((1, 12)), np.zeros((1, 12))
    g0[0, 3], g0[0, 4] = a1[1], -a1[0]
    g1[0, 3], g1[0, 4] = -a0[1], a0[0]
    rows.add(np.array([a0[0] * a1[1] - a0[1] * a1[0]]),
             add_jac(H0.through(g0), H1.through(g1)), Label(step, "pushed object turns", "rad"))


def offset_rows(rows: RowSet, step: str, t: float, t_block: str, face: Face) -> None:
    """|s| <= the face's offset limit: the contact stays in the middle of the face."""
    lim = face.offset_limit
    rows.add(np.array([lim - t, lim + t]), {t_block: np.array([[-1.0], [1.0]])},
             Label(step, "contact off the middle of the pushed face"))


def path_rows(ineq: RowSet, eq: RowSet, step: str, poses, blocks, grip: FaceGrip,
              planar: bool, mu: float = NLP_FRICTION, turns: bool = False) -> None:
    """The push rule between consecutive waypoints of the pushing motion.

    `poses[i]`: the object's grips.HeldPose at waypoint i (all of them, the
    fixed keyframes at both ends included); `blocks[i]`: that waypoint's block
    (None: fixed). Cone rows for every step, with the face's normal and
    tangent where the push starts (the object does not turn); for the arm,
    the yaw of every waypoint equal to the first's, unless the object `turns`
    (a cylinder or sphere, whose footprint a turn leaves as it was).
    """
    # The tool's axes in the world at the start: the object's (R_tool @ G) times G^T;
    # the face's normal and tangent are given in the tool's frame.
    R0 = poses[0].axes @ np.array(grip.axes).T
    n, e = R0 @ np.array(grip.normal), R0 @ np.array(grip.tangent)
    label = Label(step, "motion not into the pushed face (a drag)")
    for i in range(len(poses) - 1):
        d = poses[i + 1].pos - poses[i].pos
        for sign in (-1.0, 1.0):
            w = mu * n + sign * e
            jac = {}
            for b, h, side in ((blocks[i + 1], poses[i + 1], 1.0), (blocks[i], poses[i], -1.0)):
                if b is not None:
                    jac = add_jac(jac, {b: side * (w @ h.dpos_dq)[None, :]})
            ineq.add(np.array([float(w @ d)]), jac, label)
    if planar or turns:
        return
    a0 = poses[0].axes[:, 0]
    for h, b in zip(poses, blocks, strict=True):
        if b is None:
            continue
        a, da = h.axes[:, 0], h.daxes_dq[:, 0, :]
        eq.add(np.array([a0[0] * a[1] - a0[1] * a[0]]),
               {b: (a0[0] * da[1] - a0[1] * da[0])[None, :]},
               Label(step, "pushed object turns", "rad"))
