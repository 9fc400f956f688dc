"""Coal's second opinion (coal_query.py) against our certified GJK, on the pairs FCL
answers wrong: a Panda link's hull and a cylinder, boxes, spheres; and the certified
narrow phase with coal asked gives the same answers as without it."""

import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.geometry.coal_query import CoalDistance
from tampcli.geometry.gjk import gjk_distance
from tampcli.geometry.narrow import TOLERANCE, Placed, certified, fcl_distance
from tampcli.geometry.parts import fcl_object
from tampcli.geometry.shapes import primitive
from tampcli.geometry.world import World

from .worlds import panda_scene


def _random_pose(rng, spread=0.25):
    rot = transforms.quat_to_matrix(rng.normal(size=4) / 1.0)
    return transforms.pose(rot, rng.uniform(-spread, spread, 3))


@pytest.fixture(scope="module")
def hulls():
    """The Panda's convex link hulls (meshes: FCL is micrometres off on them)."""
    with World(panda_scene()) as world:
        shapes = [s for i in range(len(world.chain.links))
                  for s in world.robot_link_shapes(i) if s.kind == "convex"]
    assert len(shapes) >= 8
    return shapes


def test_coal_agrees_with_certified_gjk_on_separated_pairs(hulls):
    coal = CoalDistance()
    rng = np.random.default_rng(5)
    others = [primitive("cylinder", (0.03, 0.12)), primitive("box", (0.05, 0.07, 0.2)),
              primitive("sphere", (0.04,)), primitive("capsule", (0.02, 0.1))]
    compared = 0
    for _ in range(400):
        sa = hulls[rng.integers(len(hulls))]
        sb = others[rng.integers(len(others))]
        a, b = Placed(sa, _random_pose(rng)), Placed(sb, _random_pose(rng))
        exact = gjk_distance(a.support_point, b.support_point, b.pos - a.pos, 1e-10)
        if exact is None or exact[0] < 1e-4:
            continue
        d, pa, pb = coal(a, b)
        assert d == pytest.approx(exact[0], abs=1e-8)
        assert np.linalg.norm(pb - pa) == pytest.approx(d, abs=1e-8)
        # The witness points lie on the solids: no support beyond them along the normal.
        n = (pb - pa) / d
        assert a.support(n) == pytest.approx(float(n @ pa), abs=1e-7)
        assert b.support(-n) == pytest.approx(float(-n @ pb), abs=1e-7)
        compared += 1
    assert compared > 150


def test_coal_penetration_follows_fcls_convention():
    """Penetrating, each witness point lies inside the other solid: p2 - p1 points
    from b to a, as narrow.fcl_normal expects."""
    coal = CoalDistance()
    cyl, box = primitive("cylinder", (0.03, 0.1)), primitive("box", (0.1, 0.1, 0.1))
    a = Placed(cyl, transforms.pose(np.eye(3), (0.07, 0.0, 0.0)))
    b = Placed(box, np.eye(4))
    d, pa, pb = coal(a, b)
    assert d == pytest.approx(-0.01, abs=1e-7)
    assert pa[0] == pytest.approx(0.04, abs=1e-7)  # the cylinder's side, inside the box
    assert pb[0] == pytest.approx(0.05, abs=1e-7)  # the box's face, inside the cylinder


def test_certified_answers_are_the_same_with_coal_asked(hulls):
    """The second opinion only saves time: with or without it, the certified narrow
    phase gives the same distances, and with it our GJK is seldom needed."""
    import fcl

    request = fcl.DistanceRequest(enable_nearest_points=True, enable_signed_distance=True)
    coal = CoalDistance()
    asked = []

    def second(a, b):
        asked.append(1)
        return coal(a, b)

    rng = np.random.default_rng(9)
    cyl = primitive("cylinder", (0.035, 0.15))
    for _ in range(300):
        sa = hulls[rng.integers(len(hulls))]
        a, b = Placed(sa, _random_pose(rng, 0.15)), Placed(cyl, _random_pose(rng, 0.15))
        raw = fcl_distance(request, a, fcl_object(sa), b, fcl_object(cyl))
        plain = certified(raw, a, b)
        with_coal = certified(raw, a, b, second)
        assert with_coal[0] == pytest.approx(plain[0], abs=max(2 * TOLERANCE, 1e-7))
        if plain[0] > 1e-4:
            np.testing.assert_allclose(with_coal[3], plain[3], atol=1e-3)
    assert len(asked) > 50  # FCL's answer failed the check that often: coal was asked
