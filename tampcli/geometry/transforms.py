"""Pose helpers: 4x4 homogeneous matrices <-> [x, y, z, qx, qy, qz, qw].

Quaternions are (x, y, z, w) everywhere in tampcli, as in PyBullet. FCL,
whose quaternions are (w, x, y, z), is only ever given rotation matrices.
"""

from __future__ import annotations

import math

import numpy as np


def quat_to_matrix(quat) -> np.ndarray:
    """3x3 rotation of the unit quaternion (x, y, z, w) (normalized first)."""
    x, y, z, w = (float(v) for v in quat)
    n = math.sqrt(x * x + y * y + z * z + w * w)
    if n == 0.0:
        raise ValueError("zero quaternion")
    x, y, z, w = x / n, y / n, z / n, w / n
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def matrix_to_quat(rot) -> np.ndarray:
    """(x, y, z, w) of a 3x3 rotation, with w >= 0 (Shepperd's method)."""
    m = np.asarray(rot, dtype=float)
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = [(m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, s / 4]
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = [s / 4, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s]
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = [(m[0, 1] + m[1, 0]) / s, s / 4, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s]
    else:
        s = 2.0 * math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = [(m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, s / 4, (m[1, 0] - m[0, 1]) / s]
    q = np.array(q)
    q /= np.linalg.norm(q)
    return -q if q[3] < 0 else q


def quat_multiply(a, b) -> np.ndarray:
    """The Hamilton product a * b of (x, y, z, w) quaternions (apply b, then a)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    ])


def rpy_to_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """3x3 rotation Rz(yaw) Ry(pitch) Rx(roll): URDF's and PyBullet's convention."""
    return rot_z(yaw) @ rot_y(pitch) @ rot_x(roll)


def rot_x(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_y(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def pose(rot=None, pos=(0.0, 0.0, 0.0)) -> np.ndarray:
    """4x4 pose from a 3x3 rotation (identity when None) and a position."""
    t = np.eye(4)
    if rot is not None:
        t[:3, :3] = rot
    t[:3, 3] = pos
    return t


def pose_from_xyzquat(xyzquat) -> np.ndarray:
    """4x4 pose from [x, y, z, qx, qy, qz, qw]."""
    v = [float(x) for x in xyzquat]
    if len(v) != 7:
        raise ValueError(f"expected 7 numbers [x, y, z, qx, qy, qz, qw], got {len(v)}")
    return pose(quat_to_matrix(v[3:]), v[:3])


def xyzquat_from_pose(t) -> list[float]:
    """[x, y, z, qx, qy, qz, qw] of a 4x4 pose."""
    t = np.asarray(t, dtype=float)
    return [float(v) for v in t[:3, 3]] + [float(v) for v in matrix_to_quat(t[:3, :3])]


def pose_from_list(values) -> np.ndarray:
    """4x4 pose from [x, y, z], [x, y, z, yaw], [x, y, z, roll, pitch, yaw] or xyz+quat."""
    v = [float(x) for x in values]
    if len(v) == 3:
        return pose(None, v)
    if len(v) == 4:
        return pose(rot_z(v[3]), v[:3])
    if len(v) == 6:
        return pose(rpy_to_matrix(*v[3:]), v[:3])
    if len(v) == 7:
        return pose_from_xyzquat(v)
    raise ValueError(f"a pose has 3, 4, 6 or 7 numbers, got {len(v)}")


def pose_inverse(t) -> np.ndarray:
    """Inverse of a rigid 4x4 pose (transpose the rotation; no general inverse)."""
    t = np.asarray(t, dtype=float)
    out = np.eye(4)
    rt = t[:3, :3].T
    out[:3, :3] = rt
    out[:3, 3] = -rt @ t[:3, 3]
    return out


def yaw_of(t) -> float:
    """Yaw (rotation about world z) of a pose's rotation, rpy convention."""
    t = np.asarray(t, dtype=float)
    return math.atan2(t[1, 0], t[0, 0])


def rotation_log(rot) -> np.ndarray:
    """Axis * angle (3,) of a 3x3 rotation; robust near 0 and pi."""
    m = np.asarray(rot, dtype=float)
    cos = max(-1.0, min(1.0, (m[0, 0] + m[1, 1] + m[2, 2] - 1.0) / 2.0))
    angle = math.acos(cos)
    w = np.array([m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1]])
    if angle < 1e-6:
        return 0.5 * w
    if math.pi - angle < 1e-4:
        # sin(angle) ~ 0: recover the axis from the symmetric part instead.
        diag = np.clip((np.diag(m) - cos) / (1.0 - cos), 0.0, None)
        axis = np.sqrt(diag)
        k = int(np.argmax(axis))
        for i in range(3):
            if i != k and (m[k, i] + m[i, k]) < 0:
                axis[i] = -axis[i]
        if w @ axis < 0:
            axis = -axis
        return angle * axis / np.linalg.norm(axis)
    return angle / (2.0 * math.sin(angle)) * w


def rotation_logs(rots: np.ndarray) -> np.ndarray:
    """`rotation_log` of each of (S, 3, 3) rotations: (S, 3). Rows near 0 or pi take
    `rotation_log`'s own branches."""
    m = np.asarray(rots, dtype=float)
    cos = np.clip((np.trace(m, axis1=1, axis2=2) - 1.0) / 2.0, -1.0, 1.0)
    angle = np.arccos(cos)
    w = np.stack([m[:, 2, 1] - m[:, 1, 2], m[:, 0, 2] - m[:, 2, 0], m[:, 1, 0] - m[:, 0, 1]],
                 axis=1)
    plain = (angle >= 1e-6) & (math.pi - angle >= 1e-4)
    out = np.empty((len(m), 3))
    out[plain] = (angle[plain] / (2.0 * np.sin(angle[plain])))[:, None] * w[plain]
    for i in np.flatnonzero(~plain).tolist():
        out[i] = rotation_log(m[i])
    return out


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise cross product of (..., 3) arrays (np.cross costs several times more)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)

