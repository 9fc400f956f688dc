import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tampcli.geometry import transforms as tf

angles = st.floats(-math.pi, math.pi, allow_nan=False)
coords = st.floats(-10, 10, allow_nan=False)
quats = st.tuples(*[st.floats(-1, 1, allow_nan=False)] * 4).filter(
    lambda q: 0.1 < math.sqrt(sum(v * v for v in q)))


@given(quats)
def test_quaternion_matrix_round_trip(q):
    q = np.array(q) / np.linalg.norm(q)
    back = tf.matrix_to_quat(tf.quat_to_matrix(q))
    assert back[3] >= 0
    assert np.allclose(back, q, atol=1e-9) or np.allclose(back, -q, atol=1e-9)
    m = tf.quat_to_matrix(q)
    np.testing.assert_allclose(m @ m.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(m) == pytest.approx(1.0)


@given(quats, quats)
def test_quaternion_product_composes_rotations(a, b):
    a, b = np.array(a), np.array(b)
    np.testing.assert_allclose(tf.quat_to_matrix(tf.quat_multiply(a, b)),
                               tf.quat_to_matrix(a) @ tf.quat_to_matrix(b), atol=1e-9)


def test_known_rotations():
    np.testing.assert_allclose(tf.rot_z(math.pi / 2) @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(tf.rot_x(math.pi / 2) @ [0, 1, 0], [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(tf.rot_y(math.pi / 2) @ [0, 0, 1], [1, 0, 0], atol=1e-15)
    # PyBullet's getQuaternionFromEuler([0, 0, pi/2]).
    np.testing.assert_allclose(tf.matrix_to_quat(tf.rpy_to_matrix(0, 0, math.pi / 2)),
                               [0, 0, math.sqrt(0.5), math.sqrt(0.5)], atol=1e-12)


def test_rpy_matches_pybullet():
    import pybullet

    rng = np.random.default_rng(0)
    for _ in range(20):
        rpy = rng.uniform(-3, 3, 3)
        q = pybullet.getQuaternionFromEuler(rpy)
        np.testing.assert_allclose(tf.rpy_to_matrix(*rpy), tf.quat_to_matrix(q), atol=1e-6)


@settings(max_examples=50)
@given(coords, coords, coords, angles, angles, angles)
def test_pose_from_list_forms(x, y, z, r, p, yw):
    assert np.array_equal(tf.pose_from_list([x, y, z])[:3, 3], [x, y, z])
    four = tf.pose_from_list([x, y, z, yw])
    assert tf.yaw_of(four) == pytest.approx(yw, abs=1e-9) or abs(abs(yw) - math.pi) < 1e-9
    six = tf.pose_from_list([x, y, z, r, p, yw])
    np.testing.assert_allclose(six[:3, :3], tf.rpy_to_matrix(r, p, yw))
    seven = tf.pose_from_list(tf.xyzquat_from_pose(six))
    np.testing.assert_allclose(seven, six, atol=1e-9)
    np.testing.assert_allclose(tf.pose_inverse(six) @ six, np.eye(4), atol=1e-9)


def test_pose_from_list_rejects_other_lengths():
    with pytest.raises(ValueError):
        tf.pose_from_list([1, 2])
    with pytest.raises(ValueError):
        tf.pose_from_xyzquat([0, 0, 0, 0, 0, 0])
    with pytest.raises(ValueError):
        tf.quat_to_matrix([0, 0, 0, 0])


@given(quats)
def test_rotation_log_inverts_axis_angle(q):
    m = tf.quat_to_matrix(q)
    w = tf.rotation_log(m)
    angle = np.linalg.norm(w)
    assert angle <= math.pi + 1e-9
    if angle > 1e-9:
        k = w / angle
        skew = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        rebuilt = np.eye(3) + math.sin(angle) * skew + (1 - math.cos(angle)) * skew @ skew
        np.testing.assert_allclose(rebuilt, m, atol=1e-6)


def test_rotation_log_near_pi():
    for axis in ([1, 0, 0], [0, 1, 1], [1, -2, 0.5]):
        k = np.array(axis, dtype=float) / np.linalg.norm(axis)
        for angle in (math.pi, math.pi - 1e-6):
            q = np.append(k * math.sin(angle / 2), math.cos(angle / 2))
            w = tf.rotation_log(tf.quat_to_matrix(q))
            assert np.linalg.norm(w) == pytest.approx(angle, abs=1e-5)
            assert abs(abs(w @ k) - angle) < 1e-5
