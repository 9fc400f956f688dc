"""Oriented boxes and hull points: tight around each solid, and the two vectorized
gaps are lower bounds on the certified distance (so the screen never drops a pair
that is within the activation distance)."""

import fcl
import numpy as np
import pytest

from tampcli.geometry import obb, transforms
from tampcli.geometry.broad import FLOAT32_ERROR
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


def _rows(seed):
    """300 random pairs of parts (one FCL object per side: FCL never returns when asked
    the distance of an object to itself) with their certified distances."""
    rng = np.random.default_rng(seed)
    shapes = _shapes(rng)
    sides = [[Part("body:x", s, fcl_object(s)) for s in shapes] for _ in range(2)]
    rows = []
    for _ in range(300):
        ia, ib = rng.integers(len(shapes), size=2)
        ta, tb = _random_pose(rng), _random_pose(rng)
        pa, pb = sides[0][ia], sides[1][ib]
        d = signed_distance(REQUEST, Placed(pa.shape, ta @ pa.shape.local), pa.obj,
                            Placed(pb.shape, tb @ pb.shape.local), pb.obj)[0]
        rows.append((ta, ia, tb, ib, d))
    return sides, rows


def _hull_gaps(sides, rows, float32=False, beyond=None):
    """obb.gaps and obb.hull_gaps of the rows, as broad.screen calls them."""
    ta = np.array([r[0] for r in rows])
    tb = np.array([r[2] for r in rows])
    ia = np.array([r[1] for r in rows])
    ib = np.array([r[3] for r in rows])
    parts_a, parts_b = sides
    ca, ra = obb.world(ta, np.array([parts_a[i].obb_center for i in ia]),
                       np.array([parts_a[i].obb_rot for i in ia]))
    cb, rb = obb.world(tb, np.array([parts_b[i].obb_center for i in ib]),
                       np.array([parts_b[i].obb_rot for i in ib]))
    ha = np.array([parts_a[i].obb_half for i in ia])
    hb = np.array([parts_b[i].obb_half for i in ib])
    dtype = np.float32 if float32 else float
    hull = obb.hull_gaps(obb.PointSets([p.hull for p in parts_a], dtype), ia, ta, ra, ha,
                         obb.PointSets([p.hull for p in parts_b], dtype), ib, tb, rb, hb, ca, cb,
                         beyond)
    return obb.gaps(ca, ra, ha, cb, rb, hb), hull, (ta, ia, ra, ca, tb, ib, rb, cb)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_gaps_are_lower_bounds_on_the_distance(seed):
    sides, rows = _rows(seed)
    box_gap, hull_gap, _ = _hull_gaps(sides, rows)
    dist = np.array([r[4] for r in rows])
    assert np.all(box_gap <= np.maximum(dist, 0.0) + 1e-9)
    assert np.all(hull_gap <= np.maximum(dist, 0.0) + 1e-9)
    # Not vacuous: separated pairs get positive bounds, and mostly close ones.
    apart = dist > 0.05
    assert apart.sum() > 50
    assert np.median(hull_gap[apart] / dist[apart]) > 0.5


def test_hull_gaps_equal_every_point_on_all_seven_axes():
    """hull_gaps takes a solid's support on its own box axes from the box (tight on its
    points) for many pairs: the same bound as projecting all points on all 7
    directions (what it does for a few pairs); and in float32 (the screen's) it
    stays within broad.FLOAT32_ERROR of it."""
    sides, rows = _rows(3)
    assert len(rows) >= obb.GROUPED_FROM
    _, hull, (ta, ia, ra, ca, tb, ib, rb, cb) = _hull_gaps(sides, rows)
    _, hull32, _ = _hull_gaps(sides, rows, float32=True)
    _, few, _ = _hull_gaps(sides, rows[:10])
    np.testing.assert_allclose(few, hull[:10], atol=1e-12)
    # With a threshold, the bound decides every pair as the full one does.
    for beyond in (0.0, 0.05):
        cut = _hull_gaps(sides, rows, beyond=np.full(len(rows), beyond))[1]
        np.testing.assert_array_equal(cut <= beyond, hull <= beyond)
        assert np.all(cut <= hull + 1e-12)
        assert 0 < (hull <= beyond).sum() < len(rows)
    for t in range(len(rows)):
        d = cb[t] - ca[t]
        line = d / np.linalg.norm(d)
        axes = np.vstack([ra[t].T, rb[t].T, line])
        axes *= np.where(axes @ d < 0, -1.0, 1.0)[:, None]
        pa = sides[0][ia[t]].hull @ ta[t][:3, :3].T + ta[t][:3, 3]
        pb = sides[1][ib[t]].hull @ tb[t][:3, :3].T + tb[t][:3, 3]
        full = ((pb @ axes.T).min(axis=0) - (pa @ axes.T).max(axis=0)).max()
        assert hull[t] == pytest.approx(full, abs=1e-12)
        assert abs(hull32[t] - full) <= 2 * FLOAT32_ERROR * (1.0 + 0.5)


@pytest.mark.parametrize("n", [6, obb.PADDED_POINTS // 12 + 5])
def test_reach_and_support_points_of_point_sets_of_several_sizes(n):
    """Both ways `reach` takes the solids (padded for a few, set by set for many)."""
    rng = np.random.default_rng(4)
    sets = [rng.normal(size=(v, 3)) for v in (7, 3, 12)]
    points = obb.PointSets(sets)
    assert points.gathered(n) == (n < 100)
    index = rng.integers(len(sets), size=n)
    frames = np.array([_random_pose(rng) for _ in index])
    axes = rng.normal(size=(n, 2, 3))
    got = obb.reach(points, index, frames[:, :3, :3], frames[:, :3, 3], axes)
    best = obb.support_points(points, index, frames[:, :3, :3], frames[:, :3, 3], axes[:, 0])
    for k, i in enumerate(index):
        world = sets[i] @ frames[k, :3, :3].T + frames[k, :3, 3]
        np.testing.assert_allclose(got[k], (world @ axes[k].T).max(axis=0))
        np.testing.assert_allclose(best[k], world[(world @ axes[k, 0]).argmax()])
