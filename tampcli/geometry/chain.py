"""A kinematic tree in numpy: forward kinematics and point Jacobians.

Measured once by the World from the robot it loaded (any URDF or multibody),
then evaluated without touching the simulator: thousands of FK calls per NLP
would otherwise each pay resetJointState + getLinkState.

Link frames are URDF link frames (PyBullet's getLinkState[4:6]), not the
centre-of-mass frames. Joint types use PyBullet's codes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.geometry import transforms

REVOLUTE, PRISMATIC, FIXED = 0, 1, 4

# eps[i, j, k]: (o x a)_i = eps[i, j, k] o_j a_k, for a batched cross product in one call.
_LEVI_CIVITA = np.array([[[0, 0, 0], [0, 0, 1], [0, -1, 0]],
                         [[0, 0, -1], [0, 0, 0], [1, 0, 0]],
                         [[0, 1, 0], [-1, 0, 0], [0, 0, 0]]], dtype=float)
_LEVI_CIVITA.flags.writeable = False


@dataclass(frozen=True)
class ChainLink:
    name: str
    parent: int  # index into Chain.links, -1 for the base link itself
    origin: np.ndarray  # 4x4, child frame in parent frame at joint value 0
    joint_type: int  # REVOLUTE, PRISMATIC or FIXED
    axis: np.ndarray  # (3,) unit, in the child frame
    q_index: int  # index in q, or -1 when the joint is not an optimization variable
    fixed_value: float  # joint value used when q_index == -1
    pb_index: int  # PyBullet link index (-1: base)


class Chain:
    """Forward kinematics of a tree of links; link 0 is the base."""

    def __init__(self, links: list[ChainLink], base_pose: np.ndarray, n: int):
        self.links = tuple(links)
        self.names = tuple(link.name for link in links)
        self.index = {name: i for i, name in enumerate(self.names)}
        self.n = n
        self.base_pose = np.array(base_pose, dtype=float)
        # origin @ motion(q) = A + f1(q) B + f2(q) C, precomputed per link:
        # revolute (Rodrigues, K = [axis]x): A = O, B = O K, C = O K^2,
        # f1 = sin q, f2 = 1 - cos q; prismatic: B = O T(axis), f1 = q.
        self._plan = []
        for i, link in enumerate(links[1:], start=1):
            origin = link.origin.copy()
            # A joint that is not a variable is fixed at its value: fold it in.
            if link.q_index < 0 and link.joint_type != FIXED and link.fixed_value != 0.0:
                origin = origin @ _motion(link.joint_type, link.axis, link.fixed_value)
            kind = link.joint_type if link.q_index >= 0 else FIXED
            b = c = None
            if kind == REVOLUTE:
                k = np.zeros((4, 4))
                x, y, z = link.axis
                k[:3, :3] = [[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]]
                b, c = origin @ k, origin @ k @ k
            elif kind == PRISMATIC:
                t = np.zeros((4, 4))
                t[:3, 3] = link.axis
                b = origin @ t
            # [A; B; C] flattened: the local transform is (1, f1, f2) @ abc, one product.
            abc = None
            if kind == REVOLUTE:
                abc = np.stack([origin.ravel(), b.ravel(), c.ravel()])
            self._plan.append((i, link.parent, origin, b, c, kind, link.q_index, abc))
        # Which variables move each link: ancestors' joints in q.
        self.moved_by = np.zeros((len(links), n), dtype=bool)
        self.joint_link = np.full(n, -1)  # q index -> link whose joint it is
        self.joint_type = np.zeros(n, dtype=int)
        self.joint_axis = np.zeros((n, 3))
        for i, link in enumerate(links):
            if i > 0:
                self.moved_by[i] = self.moved_by[link.parent]
            if link.q_index >= 0:
                self.moved_by[i, link.q_index] = True
                self.joint_link[link.q_index] = i
                self.joint_type[link.q_index] = link.joint_type
                self.joint_axis[link.q_index] = link.axis
        self.revolute = self.joint_type == REVOLUTE
        self._has_prismatic = bool(np.any(~self.revolute))
        self.moved_mask = self.moved_by.astype(float)
        self._joint_links = [int(i) for i in self.joint_link]

    def fk_list(self, q) -> list[np.ndarray]:
        """World 4x4 frames of all links, in `names` order."""
        frames = [self.base_pose] * len(self.links)
        sin, cos = math.sin, math.cos
        coef = np.ones(3)
        for i, parent, a, b, _c, kind, qi, abc in self._plan:
            if kind == REVOLUTE:
                v = float(q[qi])
                coef[1], coef[2] = sin(v), 1.0 - cos(v)
                frames[i] = frames[parent] @ (coef @ abc).reshape(4, 4)
            elif kind == PRISMATIC:
                frames[i] = frames[parent] @ (a + float(q[qi]) * b)
            else:
                frames[i] = frames[parent] @ a
        return frames

    def fk_batch(self, qs) -> np.ndarray:
        """(T, L, 4, 4) frames of all links for T configurations (rows of qs).

        One batched product per link instead of T: for waypoint-wise work.
        """
        qs = np.atleast_2d(np.asarray(qs, dtype=float))
        out = np.empty((len(qs), len(self.links), 4, 4))
        out[:, 0] = self.base_pose
        # (1, sin q, 1 - cos q) of every joint and row at once: (T, n, 3).
        coef = np.stack([np.ones_like(qs), np.sin(qs), 1.0 - np.cos(qs)], axis=2)
        for i, parent, a, b, _c, kind, qi, abc in self._plan:
            if kind == REVOLUTE:
                local = (coef[:, qi] @ abc).reshape(-1, 4, 4)
            elif kind == PRISMATIC:
                local = a + qs[:, qi, None, None] * b
            else:
                local = a
            np.matmul(out[:, parent], local, out=out[:, i])
        return out

    def refixed(self, frames: np.ndarray, values: dict[int, np.ndarray]) -> np.ndarray:
        """fk_batch frames (S, L, 4, 4) with the joints of the links in `values` (not
        variables: fingers) at the given values (S,) per row instead of their fixed
        value; their descendants follow rigidly. Gradients w.r.t. q are unchanged:
        these joints are not in q."""
        out = frames.copy()
        moved = set()
        for i, parent, *_ in self._plan:
            if i in values:
                link = self.links[i]
                v = np.asarray(values[i], dtype=float)
                if np.all(v == v[0]):  # one value for every row (a hand held at one opening)
                    local = link.origin @ _motion(link.joint_type, link.axis, float(v[0]))
                else:
                    local = np.array([link.origin @ _motion(link.joint_type, link.axis, float(x))
                                      for x in v])
            elif parent in moved:
                local = np.linalg.solve(frames[:, parent], frames[:, i])
            else:
                continue
            out[:, i] = out[:, parent] @ local
            moved.add(i)
        return out

    def tool_jacobian_batch(self, frames: np.ndarray, link: int) -> np.ndarray:
        """(T, 6, n) [linear; angular] Jacobians of `link`'s origin from fk_batch frames."""
        joint_frames = frames[:, self.joint_link]  # (T, n, 4, 4)
        axes = np.einsum("tnij,nj->tni", joint_frames[:, :, :3, :3], self.joint_axis)
        lever = frames[:, link, None, :3, 3] - joint_frames[:, :, :3, 3]
        linear = np.where(self.revolute[None, :, None], transforms.cross(axes, lever), axes)
        angular = np.where(self.revolute[None, :, None], axes, 0.0)
        mask = self.moved_mask[link][None, :, None]
        return np.concatenate([(linear * mask).transpose(0, 2, 1),
                               (angular * mask).transpose(0, 2, 1)], axis=1)

    def joint_axes(self, frames) -> tuple[np.ndarray, np.ndarray]:
        """World axes (n, 3) and origins (n, 3) of the q joints, for a set of frames."""
        stacked = np.array([frames[i] for i in self._joint_links])
        axes = np.einsum("nij,nj->ni", stacked[:, :3, :3], self.joint_axis)
        return axes, stacked[:, :3, 3]

    def normal_gradient_basis(self, frames) -> np.ndarray:
        """(n, 6) B such that n . J(p) = B @ [p x n, n] for a point p on a moved link.

        Revolute: n . (a x (p - o)) = a . (p x n) + (o x a) . n; prismatic: a . n.
        """
        axes, origins = self.joint_axes(frames)
        basis = np.concatenate([axes, np.einsum("ijk,nj,nk->ni", _LEVI_CIVITA, origins, axes)],
                               axis=1)
        if self._has_prismatic:
            slide = ~self.revolute
            basis[slide, 3:] = axes[slide]
            basis[slide, :3] = 0.0
        return basis

    def normal_gradient_basis_batch(self, frames: np.ndarray) -> np.ndarray:
        """(S, n, 6) `normal_gradient_basis` of each of S sets of fk_batch frames."""
        joint_frames = frames[:, self.joint_link]  # (S, n, 4, 4)
        axes = np.einsum("snij,nj->sni", joint_frames[:, :, :3, :3], self.joint_axis)
        origins = joint_frames[:, :, :3, 3]
        basis = np.concatenate([axes, transforms.cross(origins, axes)], axis=2)
        if self._has_prismatic:
            slide = ~self.revolute
            basis[:, slide, 3:] = axes[:, slide]
            basis[:, slide, :3] = 0.0
        return basis

    def point_jacobian(self, axes, origins, link: int, point) -> np.ndarray:
        """(3, n) d point / d q for a world point rigidly attached to `link`.

        `axes`, `origins` from `joint_axes` of the same frames.
        """
        d = np.asarray(point, dtype=float) - origins
        ax, ay, az = axes[:, 0], axes[:, 1], axes[:, 2]
        dx, dy, dz = d[:, 0], d[:, 1], d[:, 2]
        jac = np.array([ay * dz - az * dy, az * dx - ax * dz, ax * dy - ay * dx])
        if self._has_prismatic:
            jac[:, ~self.revolute] = axes[~self.revolute].T
        jac[:, ~self.moved_by[link]] = 0.0
        return jac

    def jacobian_from_frames(self, frames, link: int, point) -> np.ndarray:
        """(3, n) d point / d q for a world point rigidly attached to `link`."""
        axes, origins = self.joint_axes(frames)
        return self.point_jacobian(axes, origins, link, point)

    def angular_jacobian_from_frames(self, frames, link: int) -> np.ndarray:
        """(3, n) angular velocity of `link` per joint velocity."""
        axes, _ = self.joint_axes(frames)
        jac = axes.T.copy()
        jac[:, ~(self.moved_by[link] & self.revolute)] = 0.0
        return jac


def _motion(kind: int, axis: np.ndarray, value: float) -> np.ndarray:
    t = np.eye(4)
    if kind == REVOLUTE:
        t[:3, :3] = _axis_angle(axis, value)
    elif kind == PRISMATIC:
        t[:3, 3] = axis * value
    return t


def _axis_angle(axis, angle: float) -> np.ndarray:
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    k = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    return np.eye(3) + s * k + (1.0 - c) * (k @ k)
