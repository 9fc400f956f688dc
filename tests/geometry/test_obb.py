"""Oriented boxes and hull points: tight around each solid, and the two vectorized
gaps are lower bounds on the certified distance (so the screen never drops a pair
that is within the activation distance)."""

import fcl
import numpy as np
import pytest

from tampcli.geometry import obb, transforms
from tampcli.geometry.narrow import Placed, signed_distance
from tampcli.geometry.parts import Part, fcl_object
from tampcli.geometry.shapes import Shape, primitive

REQUEST = fcl.DistanceRequest(enable_nearest_points=True, enable_signed_distance=True)


def _random_pose(rng, spread=0.3):
    rot = transforms.quat_to_matrix(rng.normal(size=4) / 1.0)
    return transforms.pose(rot, rng.uniform(-spread, spread, 3))


def _long_hull(rng) -> Shape:
    """A thin slanted convex solid: its frame-aligned box is loose, its principal one is not."""
    from tampcli.geometry.shapes import _hull

    axis = np.array([1.0, 1.0, 0.5]) / 1.5
    points = np.outer(rng.uniform(-0.15, 0.15, 60), axis) + rng.normal(scale=0.015, size=(60, 3))
    vertices, faces = _hull(points, "test")
    geom = fcl.Convex(vertices, len(faces) // 4, faces)
    mid = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    radius = float(np.max(np.linalg.norm(vertices - mid, axis=1)))
    return Shape(geom, np.eye(4), mid, radius, "convex", (), vertices)


def _shapes(rng):
    local = transforms.pose(transforms.rot_z(0.4), (0.02, -0.01, 0.03))
    return [primitive("box", (0.1, 0.2, 0.05)), primitive("cylinder", (0.04, 0.12)),
            primitive("sphere", (0.05,)), primitive("capsule", (0.03, 0.1)),
            primitive("box", (0.08, 0.03, 0.12), local), _long_hull(rng)]


def test_boxes_contain_their_solids():
    rng = np.random.default_rng(0)
    for shape in _shapes(rng):
        part = Part("body:x", shape, fcl_object(shape))
        for _ in range(50):
            u = rng.normal(size=3)
            u /= np.linalg.norm(u)
            # Support of the solid (owner frame) never exceeds its box's, nor its hull points'.
            local = shape.local[:3, :3].T @ u
            solid = shape.support(local) + u @ shape.local[:3, 3]
            box = u @ part.obb_center + np.abs(u @ part.obb_rot) @ part.obb_half
            assert solid <= box + 1e-9
            assert solid <= float(np.max(part.hull @ u)) + 1e-9


def test_principal_axes_make_a_long_solid_s_box_tight():
    part_shape = _long_hull(np.random.default_rng(1))
    _, _, half = obb.fit(part_shape)
    lo, hi = part_shape.vertices.min(axis=0), part_shape.vertices.max(axis=0)
    assert np.prod(2 * half) < 0.5 * np.prod(hi - lo)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_gaps_are_lower_bounds_on_the_distance(seed):
    rng = np.random.default_rng(seed)
    shapes = _shapes(rng)
    # One FCL object per side: FCL never returns when asked the distance of an object
    # to itself (as happens when a pair's two sides share one CollisionObject).
    sides = [[Part("body:x", s, fcl_object(s)) for s in shapes] for _ in range(2)]
    rows = []
    for _ in range(300):
        ia, ib = rng.integers(len(shapes), size=2)
        ta, tb = _random_pose(rng), _random_pose(rng)
        pa, pb = sides[0][ia], sides[1][ib]
        d = signed_distance(REQUEST, Placed(pa.shape, ta @ pa.shape.local), pa.obj,
                            Placed(pb.shape, tb @ pb.shape.local), pb.obj)[0]
        rows.append((ta, pa, tb, pb, d))
    ca, ra = obb.world(np.array([r[0] for r in rows]), np.array([r[1].obb_center for r in rows]),
                       np.array([r[1].obb_rot for r in rows]))
    cb, rb = obb.world(np.array([r[2] for r in rows]), np.array([r[3].obb_center for r in rows]),
                       np.array([r[3].obb_rot for r in rows]))
    ha = np.array([r[1].obb_half for r in rows])
    hb = np.array([r[3].obb_half for r in rows])
    box_gap = obb.gaps(ca, ra, ha, cb, rb, hb)
    hull_gap = obb.hull_gaps(np.array([r[0] for r in rows]), obb.padded([r[1].hull for r in rows]),
                             ra, np.array([r[2] for r in rows]),
                             obb.padded([r[3].hull for r in rows]), rb, ca, cb)
    dist = np.array([r[4] for r in rows])
    assert np.all(box_gap <= np.maximum(dist, 0.0) + 1e-9)
    assert np.all(hull_gap <= np.maximum(dist, 0.0) + 1e-9)
    # Not vacuous: separated pairs get positive bounds, and mostly close ones.
    apart = dist > 0.05
    assert apart.sum() > 50
    assert np.median(hull_gap[apart] / dist[apart]) > 0.5


def test_reach_is_the_support_of_the_points():
    rng = np.random.default_rng(4)
    frames = np.array([_random_pose(rng) for _ in range(5)])
    points = rng.normal(size=(5, 7, 3))
    axes = rng.normal(size=(5, 2, 3))
    got = obb.reach(frames, points, axes)
    for k in range(5):
        world = points[k] @ frames[k, :3, :3].T + frames[k, :3, 3]
        np.testing.assert_allclose(got[k], (world @ axes[k].T).max(axis=0))
