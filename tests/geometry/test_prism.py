"""Upright prisms in closed form agree with the certified GJK/EPA path of narrow.py."""

import numpy as np
import pytest

from tampcli.geometry import prism, transforms
from tampcli.geometry.gjk import gjk_distance
from tampcli.geometry.narrow import TOLERANCE, Placed, _checked_penetration
from tampcli.geometry.shapes import primitive

SHAPES = [primitive("cylinder", (0.05, 0.05)), primitive("cylinder", (0.12, 0.3)),
          primitive("box", (0.3, 0.1, 0.04)), primitive("box", (0.06, 0.06, 0.2))]


def _upright(rng, shape, flip=False):
    rot = transforms.rot_z(rng.uniform(-3.2, 3.2))
    if flip:
        rot = rot @ np.diag([1.0, -1.0, -1.0])
    return Placed(shape, transforms.pose(rot, rng.uniform(-0.25, 0.25, 3)))


def _reference(a, b):
    """Certified distance by GJK when apart, projections (an upper bound on depth) when not."""
    exact = gjk_distance(a.support_point, b.support_point, b.pos - a.pos, 1e-12)
    if exact is not None and exact[0] > TOLERANCE:
        return exact[0]
    return None


@pytest.mark.parametrize("seed", range(4))
def test_closed_form_matches_gjk_and_projections(seed):
    rng = np.random.default_rng(seed)
    apart = inside = 0
    for _ in range(300):
        sa, sb = SHAPES[rng.integers(len(SHAPES))], SHAPES[rng.integers(len(SHAPES))]
        a, b = _upright(rng, sa, rng.random() < 0.2), _upright(rng, sb)
        d, pa, pb, n = prism.distance(a, b)
        assert np.linalg.norm(n) == pytest.approx(1.0)
        np.testing.assert_allclose(pb - pa, d * n, atol=1e-12)
        # Witnesses lie on their solids (support along n bounds them, and they reach it).
        assert n @ pa == pytest.approx(a.support(n), abs=1e-9)
        assert -n @ pb == pytest.approx(b.support(-n), abs=1e-9)
        reference = _reference(a, b)
        if reference is not None:
            assert d == pytest.approx(reference, abs=1e-8)
            apart += 1
        else:
            # Penetrating: the depth is the least overlap of projections, which the
            # certified path bounds from above; along n the overlap is exactly -d.
            assert d <= TOLERANCE
            assert a.support(n) + b.support(-n) == pytest.approx(-d, abs=1e-9)
            bound = _checked_penetration(d, pa, pb, n, a, b)[0]
            assert d >= bound - 1e-9
            inside += 1
    assert apart > 60 and inside > 20


def test_tilted_solids_are_left_to_the_general_path():
    cyl = primitive("cylinder", (0.05, 0.1))
    tilted = transforms.pose(transforms.quat_to_matrix([0.1, 0.0, 0.0, 1.0]), (0, 0, 0))
    box = Placed(primitive("box", (0.1, 0.1, 0.1)), transforms.pose(np.eye(3), (0.3, 0, 0)))
    assert prism.distance(Placed(cyl, tilted), box) is None
    assert prism.distance(Placed(primitive("sphere", (0.1,)), np.eye(4)), box) is None


def test_a_block_against_a_wall_that_aborts_fcl_is_answered():
    # robust-planar p01: FCL's signed distance (libccd's EPA) aborted the process on
    # this pair ("the origin is outside of the polytope"); the closed form answers it.
    block = Placed(primitive("box", (0.1, 0.05, 0.05)),
                   transforms.pose(np.eye(3), (0.63000000006247236, 0.20000000022528722, 0.025)))
    wall = Placed(primitive("box", (0.02, 0.3, 0.1)), transforms.pose(np.eye(3), (0.63, 0.05, 0.05)))
    d, pa, pb, n = prism.distance(block, wall)
    assert d == pytest.approx(-0.025, abs=1e-8)  # the block's 2.5 cm into the wall's end
    np.testing.assert_allclose(n, [0.0, -1.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(pb - pa, d * n, atol=1e-12)


def test_two_coincident_tilted_cubes_are_answered_without_fcl():
    # blind2 p02: FCL's signed distance aborted the process on a carried cube and its
    # copy at one tilted pose; box pairs take our own GJK and penetration path.
    import fcl

    from tampcli.geometry.narrow import no_fcl, signed_distance

    pose = transforms.pose(transforms.rot_z(0.4) @ np.array(
        [[1.0, 0.0, 0.0], [0.0, 0.6, -0.8], [0.0, 0.8, 0.6]]), (-0.175, -0.012, 0.413))
    cube = primitive("box", (0.05, 0.05, 0.05))
    a, b = Placed(cube, pose), Placed(cube, pose.copy())
    assert no_fcl(a, b)
    request = fcl.DistanceRequest(enable_nearest_points=True, enable_signed_distance=True)
    objects = [fcl.CollisionObject(fcl.Box(0.05, 0.05, 0.05)) for _ in range(2)]
    d, pa, pb, n = signed_distance(request, a, objects[0], b, objects[1])
    assert d == pytest.approx(-0.05, abs=1e-6)  # a full width deep, either way out
    np.testing.assert_allclose(np.linalg.norm(n), 1.0)


def test_tilted_boxes_apart_along_a_face_normal_take_fcl_and_agree_with_our_gjk():
    # A held box tilted in a carry, against a table or a basin: FCL's GJK answers
    # (no EPA runs for separated solids) and its checked answer is our GJK's.
    import fcl

    from tampcli.geometry.narrow import checked, no_fcl, signed_distance

    rng = np.random.default_rng(3)
    request = fcl.DistanceRequest(enable_nearest_points=True, enable_signed_distance=True)
    sent = 0
    for _ in range(300):
        sizes = [tuple(rng.uniform(0.02, 0.3, 3)) for _ in range(2)]
        poses = [transforms.pose(transforms.rot_z(rng.uniform(-3, 3)) @ transforms.rot_x(
            rng.uniform(-0.5, 0.5)), rng.uniform(-0.2, 0.2, 3)) for _ in range(2)]
        a, b = (Placed(primitive("box", s), p) for s, p in zip(sizes, poses, strict=True))
        objects = [fcl.CollisionObject(fcl.Box(*s)) for s in sizes]
        d, pa, pb, n = signed_distance(request, a, objects[0], b, objects[1])
        ours = checked(None, a, b)
        assert d == pytest.approx(ours[0], abs=1e-7)
        if not no_fcl(a, b):
            sent += 1
            assert d > 0
            np.testing.assert_allclose(pb - pa, d * n, atol=1e-7)
    assert 50 < sent < 300  # both paths were taken


def test_many_upright_box_pairs_at_once_are_the_pairs_one_by_one():
    rng = np.random.default_rng(11)
    pairs, answered = [], 0
    for _ in range(400):
        sizes = [tuple(rng.uniform(0.02, 0.3, 3)) for _ in range(2)]
        tilt = transforms.rot_x(0.2) if rng.uniform() < 0.1 else np.eye(3)
        poses = [transforms.pose(transforms.rot_z(rng.uniform(-3, 3)) @ (tilt if k else np.eye(3)),
                                 (*rng.uniform(-0.3, 0.3, 2), rng.uniform(0.0, 0.2)))
                 for k in range(2)]
        pairs.append(tuple(Placed(primitive("box", s), p)
                           for s, p in zip(sizes, poses, strict=True)))
    for (a, b), many in zip(pairs, prism.upright_boxes(pairs), strict=True):
        one = prism.distance(a, b)
        if many is None:
            continue
        answered += 1
        assert many[0] == pytest.approx(one[0], abs=1e-12)
        for x, y in zip(many[1:], one[1:], strict=True):
            np.testing.assert_allclose(x, y, atol=1e-12)
    assert 100 < answered < 400  # tilted and overlapping pairs are left to `distance`
