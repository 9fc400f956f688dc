"""The tool frame with its Jacobians, and how a held or pushed object hangs from it.

A grip is the object's frame in the tool frame: centre `c` and axes gx, gy, gz
(columns of a rotation), possibly depending on one continuous parameter (the
contact angle of the planar robot; the yaw offset of a push). A world vector
R u attached to the tool moves with the joints as d(R u)/dq_j = w_j x (R u),
so every held quantity has an exact Jacobian from the tool's (6, n) one.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Frame:
    """Tool pose at one configuration and its Jacobians (linear, angular)."""

    p: np.ndarray  # (3,)
    R: np.ndarray  # (3, 3)
    Jp: np.ndarray  # (3, n)
    Jw: np.ndarray  # (3, n)

    @property
    def matrix(self) -> np.ndarray:
        t = np.eye(4)
        t[:3, :3] = self.R
        t[:3, 3] = self.p
        return t


class Kinematics:
    """Tool frames of a World's robot, with a one-entry cache (SLSQP asks twice)."""

    def __init__(self, world):
        self.world = world
        self.chain = world.chain
        self.tool = world.chain.index[world.tool_link]
        self._last_q = None
        self._last = None

    def frame(self, q) -> Frame:
        q = np.asarray(q, dtype=float)
        if self._last_q is not None and np.array_equal(q, self._last_q):
            return self._last
        frames = self.chain.fk_list(q)
        t = frames[self.tool]
        f = Frame(t[:3, 3].copy(), t[:3, :3].copy(),
                  self.chain.jacobian_from_frames(frames, self.tool, t[:3, 3]),
                  self.chain.angular_jacobian_from_frames(frames, self.tool))
        self._last_q, self._last = q.copy(), f
        return f

    def frames(self, qs) -> list[Frame]:
        """`frame` of each row of qs, from one batched forward kinematics."""
        qs = np.atleast_2d(np.asarray(qs, dtype=float))
        if len(qs) == 0:
            return []
        frames = self.chain.fk_batch(qs)
        jac = self.chain.tool_jacobian_batch(frames, self.tool)
        tool = frames[:, self.tool]
        return [Frame(tool[i, :3, 3].copy(), tool[i, :3, :3].copy(), jac[i, :3], jac[i, 3:])
                for i in range(len(qs))]


def skew(v) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


@dataclass(frozen=True)
class Grip(ABC):
    """Object frame in the tool frame as a function of an optional parameter t.

    One subclass per way of holding: TopGrip (arm, fixed yaw offset),
    PitchGrip (arm from the side, t = pitch), SideGrip (planar suction, t =
    contact angle); a push's FaceGrip (kinds/push_contact.py, t = the contact's
    offset along the face).
    """

    c0: tuple[float, float, float]  # centre when it does not depend on t
    has_param = False  # t is a variable of the keyframe NLP

    @abstractmethod
    def parts(self, t: float):
        """c, G (3x3 columns gx gy gz), dc/dt, dG/dt."""

    def matrix(self, t: float) -> np.ndarray:
        c, G, _, _ = self.parts(t)
        out = np.eye(4)
        out[:3, :3] = G
        out[:3, 3] = c
        return out


def _down(psi: float):
    """Tool z points down, the object stays upright: its axes in the tool frame, and d/dpsi."""
    cp, sp = math.cos(psi), math.sin(psi)
    G = np.array([[cp, -sp, 0.0], [-sp, -cp, 0.0], [0.0, 0.0, -1.0]])
    dG = np.array([[-sp, -cp, 0.0], [-cp, sp, 0.0], [0.0, 0.0, 0.0]])
    return G, dG


@dataclass(frozen=True)
class TopGrip(Grip):
    """The arm's fingers from above, at a fixed yaw offset psi (object yaw minus tool yaw)."""

    psi: float = 0.0

    def parts(self, t: float):
        G, _ = _down(self.psi)
        return np.array(self.c0), G, np.zeros(3), np.zeros((3, 3))


def touch_distance(a: float, half: tuple[float, float] | None, rim: float,
                   radius: float = 0.0) -> tuple[float, float]:
    """(s, ds/da): how far from an object's centre a disk of radius `rim` touches it,
    in direction `a` of the object's frame. `half`: the half extents of a box's
    footprint; None for an upright cylinder of `radius`.

    The disk's centre lies on the footprint grown by `rim` (a rounded
    rectangle): on a flat side, or on the arc round a corner, where a constant
    distance (rim plus the larger half extent) would put the disk inside the box.
    """
    if half is None:
        return rim + radius, 0.0
    hx, hy = half
    ca, sa = math.cos(a), math.sin(a)
    cx, sy = abs(ca), abs(sa)
    if cx > 1e-12 and (hx + rim) / cx * sy <= hy:
        s = (hx + rim) / cx
        return s, s * sa / ca
    if sy > 1e-12 and (hy + rim) / sy * cx <= hx:
        s = (hy + rim) / sy
        return s, -s * ca / sa
    b = cx * hx + sy * hy
    root = math.sqrt(max(rim * rim - hx * hx - hy * hy + b * b, 0.0))
    db = -sa * math.copysign(1.0, ca) * hx + ca * math.copysign(1.0, sa) * hy
    return b + root, db * (1.0 + b / root if root > 0 else 1.0)


@dataclass(frozen=True)
class SideGrip(Grip):
    """The planar robot's rim on the object's side: t is the contact angle.

    The centre is where the rim touches the object's side in direction t
    (`touch_distance`); `rho` stands for it when `half` is None (a disk).
    """

    rho: float = 0.0  # centre distance from the robot axis (a disk: the same at every t)
    yaw: float = 0.0  # object yaw (the planar robot does not turn)
    half: tuple[float, float] | None = None  # a box's footprint half extents
    rim: float = 0.0  # the robot's radius (with `half`)
    has_param = True

    def distance(self, t: float) -> tuple[float, float]:
        """(centre distance, its derivative in t)."""
        if self.half is None:
            return self.rho, 0.0
        return touch_distance(t - self.yaw, self.half, self.rim)

    def parts(self, t: float):
        ct, st = math.cos(t), math.sin(t)
        rho, drho = self.distance(t)
        c = np.array([rho * ct, rho * st, self.c0[2]])
        dc = np.array([drho * ct - rho * st, drho * st + rho * ct, 0.0])
        cy, sy = math.cos(self.yaw), math.sin(self.yaw)
        G = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]])
        return c, G, dc, np.zeros((3, 3))


@dataclass(frozen=True)
class HeldPose:
    """World pose of a gripped object (centre, axes) with d/dq (3, n) and d/dt (3,)."""

    pos: np.ndarray
    axes: np.ndarray  # (3, 3) columns ax ay az
    dpos_dq: np.ndarray
    daxes_dq: np.ndarray  # (3, 3, n): [:, i, :] is d axis_i / dq
    dpos_dt: np.ndarray
    daxes_dt: np.ndarray  # (3, 3)


def held_pose(frame: Frame, grip: Grip, t: float) -> HeldPose:
    c, G, dc, dG = grip.parts(t)
    rc = frame.R @ c
    pos = frame.p + rc
    dpos_dq = frame.Jp - skew(rc) @ frame.Jw
    axes = frame.R @ G
    daxes = np.stack([-skew(axes[:, i]) @ frame.Jw for i in range(3)], axis=1)
    return HeldPose(pos, axes, dpos_dq, daxes, frame.R @ dc, frame.R @ dG)


def _rz(psi: float) -> np.ndarray:
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


@dataclass(frozen=True)
class PitchGrip(Grip):
    """The arm's fingers from the side: the approach along direction psi of the
    object's frame, pitched down by t from horizontal (t = pi/2 would come from
    above), the fingers closing across it with the tool's y axis horizontal;
    `roll` = -1 turns the hand over about its approach.

    Here c0 is the grasp point (the tool origin) in the object's frame: the
    hand turns about it as t changes, so the fingers keep straddling the same
    part of the object.
    """

    psi: float = 0.0
    roll: float = 1.0
    has_param = True

    def tool_axes(self, t: float):
        """Tool axes (columns x y z) in the object's frame, and d/dt."""
        ct, st, s = math.cos(t), math.sin(t), self.roll
        a = np.array([[-s * st, 0.0, ct], [0.0, s, 0.0], [-s * ct, 0.0, -st]])
        da = np.array([[-s * ct, 0.0, -st], [0.0, 0.0, 0.0], [s * st, 0.0, -ct]])
        z = _rz(self.psi)
        return z @ a, z @ da

    def parts(self, t: float):
        R, dR = self.tool_axes(t)
        p = np.array(self.c0)
        return -R.T @ p, R.T, -dR.T @ p, dR.T
