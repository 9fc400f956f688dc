"""The certified narrow phase against closed-form distances, where FCL alone goes wrong."""

import fcl
import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.geometry.gjk import gjk_distance
from tampcli.geometry.narrow import Placed, signed_distance
from tampcli.geometry.parts import fcl_object
from tampcli.geometry.shapes import primitive

REQUEST = fcl.DistanceRequest(enable_nearest_points=True, enable_signed_distance=True)


def _query(sa, ta, sb, tb):
    return signed_distance(REQUEST, Placed(sa, ta), fcl_object(sa), Placed(sb, tb),
                           fcl_object(sb))


def _at(x, y, z, yaw=0.0):
    return transforms.pose(transforms.rot_z(yaw), (x, y, z))


def test_cylinder_beside_box_matches_closed_form():
    # Same heights: FCL 0.7 alone is off by up to ~2.5 cm here (fcl#508).
    cyl, box = primitive("cylinder", (0.05, 0.05)), primitive("box", (0.06, 0.06, 0.05))
    rng = np.random.default_rng(11)
    checked = 0
    for _ in range(300):
        x, y = rng.uniform(-0.6, 0.3, 2)
        dx, dy = max(abs(x + 0.2) - 0.03, 0.0), max(abs(y + 0.3) - 0.03, 0.0)
        true = np.hypot(dx, dy) - 0.05
        if true < 1e-4:
            continue
        d, pa, pb, n = _query(cyl, _at(x, y, 0.025), box, _at(-0.2, -0.3, 0.025))
        assert d == pytest.approx(true, abs=1e-7)
        assert np.linalg.norm(pb - pa) == pytest.approx(d, abs=1e-7)
        np.testing.assert_allclose(n, (pb - pa) / d, atol=1e-6)
        checked += 1
    assert checked > 200


@pytest.mark.parametrize("shape", ["box", "cylinder"])
def test_resting_contact_is_distance_zero_along_z(shape):
    # FCL's EPA reports decimetres of penetration towards a corner for these.
    floor = primitive("box", (2.0, 2.0, 0.02))
    obj = primitive(shape, (0.05, 0.05, 0.05) if shape == "box" else (0.05, 0.05))
    rng = np.random.default_rng(2)
    for _ in range(50):
        x, y, yaw = rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), rng.uniform(-3, 3)
        d, _, _, n = _query(obj, _at(x, y, 0.025, yaw), floor, _at(0, 0, -0.01))
        assert abs(d) < 1e-7
        np.testing.assert_allclose(np.abs(n), [0, 0, 1], atol=1e-6)


def test_box_penetration_depth_is_the_smallest_overlap():
    a, b = primitive("box", (0.2, 0.2, 0.2)), primitive("box", (0.1, 0.1, 0.1))
    d, _, _, n = _query(a, _at(0, 0, 0), b, _at(0.12, 0.0, 0.01))
    # Overlap along x: 0.1 + 0.05 - 0.12 = 0.03, the least of the three axes.
    assert d == pytest.approx(-0.03, abs=1e-6)
    np.testing.assert_allclose(n, [1, 0, 0], atol=1e-6)


def test_spheres():
    s = primitive("sphere", (0.1,))
    d, pa, pb, n = _query(s, _at(0, 0, 0), s, _at(0.3, 0.4, 0))
    assert d == pytest.approx(0.3, abs=1e-7)
    # On curved surfaces the distance converges faster than the witness points:
    # an error e in the normal changes the distance by ~e^2.
    np.testing.assert_allclose(n, [0.6, 0.8, 0], atol=1e-4)
    np.testing.assert_allclose(pa, [0.06, 0.08, 0], atol=1e-5)


def test_gjk_alone():
    a, b = primitive("box", (1, 1, 1)), primitive("box", (1, 1, 1))
    pa, pb = Placed(a, _at(0, 0, 0)), Placed(b, _at(0, 4, 0))
    dist, p1, p2 = gjk_distance(pa.support_point, pb.support_point, np.array([0, 1.0, 0]))
    assert dist == pytest.approx(3.0, abs=1e-9)  # FCL's libccd says 3.16 (fcl#508)
    assert p1[1] == pytest.approx(0.5) and p2[1] == pytest.approx(3.5)
    inside = Placed(b, _at(0.3, 0.2, 0.1))
    assert gjk_distance(pa.support_point, inside.support_point, np.array([1.0, 0, 0])) is None


def test_a_hull_is_rounded_by_pybullets_margin(tmp_path):
    """A mesh's hull is PyBullet's: grown by HULL_MARGIN, so 1 mm closer to a box
    than its core, separated or penetrating, witness points on the grown surface."""
    from tampcli.geometry.shapes import HULL_MARGIN, mesh_hulls

    path = tmp_path / "cube.obj"
    corners = [(x, y, z) for x in (-0.05, 0.05) for y in (-0.05, 0.05) for z in (-0.05, 0.05)]
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in corners) + "f 1 2 4\nf 5 6 8\n")
    (hull,) = mesh_hulls(str(path))
    assert hull.margin == HULL_MARGIN == 1e-3
    box = primitive("box", (0.1, 0.1, 0.1))
    for gap in (0.03, -0.004):
        d, pa, pb, n = _query(hull, _at(0.0, 0.0, 0.0), box, _at(0.1 + gap, 0.0, 0.0))
        assert d == pytest.approx(gap - HULL_MARGIN, abs=1e-7)
        np.testing.assert_allclose(n, [1.0, 0.0, 0.0], atol=1e-7)
        assert pa[0] == pytest.approx(0.05 + HULL_MARGIN, abs=1e-7)
        assert pb[0] == pytest.approx(0.05 + gap, abs=1e-7)
