"""The batched narrow phase (pairs.Batch: FCL on each pair in its relative placement,
then certify.py's checks over all pairs at once) against the pair-by-pair one
(narrow.signed_distance): the same certified answers on hundreds of pairs, no pair
within the activation distance screened out, and joint gradients that match finite
differences."""

import fcl
import numpy as np
import pytest

from tampcli.geometry import certify, obb, transforms
from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.narrow import (
    TOLERANCE,
    Placed,
    checked,
    fcl_distance,
    fcl_normal,
    overlap,
)
from tampcli.geometry.parts import fcl_object, rigid_groups
from tampcli.geometry.shapes import mesh_hulls, primitive
from tampcli.geometry.world import World

from .worlds import panda_scene

ACTIVATION = 0.05
REQUEST = fcl.DistanceRequest(enable_nearest_points=True, enable_signed_distance=True)


@pytest.fixture(scope="module")
def panda():
    with World(panda_scene()) as world:
        checker = CollisionChecker(world)
        rng = np.random.default_rng(0)
        # Anywhere within the joint limits: many self-collisions and penetrations.
        qs = np.array([rng.uniform(world.lower, world.upper) for _ in range(150)])
        yield world, checker, qs, checker.distances_many(qs, activation=ACTIVATION,
                                                         static=True)


def _closest(contacts):
    """The closest contact per (a, b): pair_distance answers a body of several parts so."""
    best: dict = {}
    for c in contacts:
        if (c.a, c.b) not in best or c.distance < best[(c.a, c.b)].distance:
            best[(c.a, c.b)] = c
    return best


def test_batched_answers_equal_pair_by_pair(panda):
    world, checker, qs, rows = panda
    apart = inside = 0
    for q, contacts in zip(qs, rows, strict=True):
        for (a, b), c in _closest(contacts).items():
            alone = checker.pair_distance(q, a, b)
            assert c.distance == pytest.approx(alone.distance, abs=1e-8), (a, b)
            # Witness points and normal agree with the distance.
            assert float(c.normal @ c.normal) == pytest.approx(1.0, abs=1e-9)
            assert float(c.normal @ (c.point_b - c.point_a)) == pytest.approx(c.distance,
                                                                             abs=1e-7)
            if c.distance > 1e-6:
                np.testing.assert_allclose(c.point_b - c.point_a, c.distance * c.normal,
                                           atol=1e-7)
                np.testing.assert_allclose(c.normal, alone.normal, atol=1e-3)
                apart += 1
            else:
                inside += 1
    assert apart >= 200 and inside >= 50


def test_no_pair_within_activation_is_screened_out(panda):
    world, checker, qs, rows = panda
    group = rigid_groups(world.chain)
    moving = sorted({p.owner for p in checker.link_parts if group[p.link] != 0})
    pairs = [(a, f"body:{b}") for a in moving for b in checker.body_parts]
    pairs += list(checker.self_pair_names)
    close = 0
    for q, contacts in zip(qs[:60], rows[:60], strict=True):
        found = {(c.a, c.b) for c in contacts}
        for a, b in pairs:
            if checker.pair_distance(q, a, b).distance <= ACTIVATION - 1e-9:
                assert (a, b) in found
                close += 1
    assert close >= 150


def test_batched_gradients_match_finite_differences(panda):
    world, checker, qs, rows = panda
    compared = 0
    for q, contacts in zip(qs[:40], rows[:40], strict=True):
        for (a, b), c in _closest(contacts).items():
            numeric = []
            for h in (1e-4, 5e-5):
                g = np.zeros(world.n)
                for i in range(world.n):
                    dq = np.zeros(world.n)
                    dq[i] = h
                    g[i] = (checker.pair_distance(q + dq, a, b).distance
                            - checker.pair_distance(q - dq, a, b).distance) / (2 * h)
                numeric.append(g)
            if np.max(np.abs(numeric[0] - numeric[1])) > 1e-3:
                continue  # a witness point switches features within the step: a kink
            np.testing.assert_allclose(c.gradient, numeric[0], atol=2e-4 if c.distance > 0
                                       else 1e-3, err_msg=f"{a} {b} {c.distance}")
            compared += 1
    assert compared >= 40


def _polytopes():
    """Boxes and convex hulls, as certify.py takes them (polytopes only)."""
    import pybullet_data

    hull = mesh_hulls(f"{pybullet_data.getDataPath()}/duck_vhacd.obj", (0.1, 0.1, 0.1))[0]
    return [primitive("box", (0.1, 0.2, 0.05)), primitive("box", (0.04, 0.04, 0.3)), hull]


def _solids(shapes, index, frames):
    return certify.Solids(obb.PointSets([s.vertices for s in shapes]), np.array(index),
                          frames[:, :3, :3], frames[:, :3, 3],
                          np.array([shapes[i].kind == "box" for i in index]))


def test_certify_decides_as_narrow_checked_pair_by_pair():
    """certify.separated and certify.penetration, on random pairs of polytopes near
    each other, give what narrow.checked gives the same FCL answers one at a time."""
    rng = np.random.default_rng(7)
    shapes = _polytopes()
    objs = [[fcl_object(s) for s in shapes] for _ in range(2)]
    ia, ib, fa, fb, raws = [], [], [], [], []
    while len(raws) < 400:
        i, j = rng.integers(len(shapes), size=2)
        ta = transforms.pose(transforms.quat_to_matrix(rng.normal(size=4)),
                             rng.uniform(-0.08, 0.08, 3))
        tb = transforms.pose(transforms.quat_to_matrix(rng.normal(size=4)),
                             rng.uniform(-0.08, 0.08, 3))
        # Some resting on a's top face, flat: the touching contacts EPA gets wrong.
        if len(raws) % 5 == 0:
            ta = transforms.pose(None, (0.0, 0.0, 0.0))
            tb = transforms.pose(transforms.rot_z(rng.uniform(-3, 3)),
                                 (*rng.uniform(-0.03, 0.03, 2), 0.5 * (
                                     shapes[i].size[2] if shapes[i].kind == "box" else 0.0)
                                  + 0.5 * (shapes[j].size[2] if shapes[j].kind == "box"
                                           else 0.0)))
            if shapes[i].kind != "box" or shapes[j].kind != "box":
                continue
        raw = fcl_distance(REQUEST, Placed(shapes[i], ta), objs[0][i], Placed(shapes[j], tb),
                           objs[1][j])
        if raw is None:
            continue
        ia.append(i), ib.append(j), fa.append(ta), fb.append(tb), raws.append(raw)
    fa, fb = np.array(fa), np.array(fb)
    a, b = _solids(shapes, ia, fa), _solids(shapes, ib, fb)
    dist = np.array([r[0] for r in raws])
    p1, p2 = np.array([r[1] for r in raws]), np.array([r[2] for r in raws])
    unit = np.array([fcl_normal(1.0, r[1], r[2]) if fcl_normal(1.0, r[1], r[2]) is not None
                     else np.zeros(3) for r in raws])
    has = np.linalg.norm(unit, axis=1) > 0
    apart = (dist > TOLERANCE) & has
    rows = np.flatnonzero(apart)
    passed = certify.separated(dist[rows], unit[rows], a.rows(rows), b.rows(rows))
    # FCL's answers made too long by 1 um: both checks must refuse them.
    longer = certify.separated(dist[rows] + 1e-6, unit[rows], a.rows(rows), b.rows(rows))
    for t, ok, wrong in zip(rows.tolist(), passed.tolist(), longer.tolist(), strict=True):
        pa, pb = Placed(shapes[ia[t]], fa[t]), Placed(shapes[ib[t]], fb[t])
        assert ok == (dist[t] + overlap(pa, pb, unit[t]) <= TOLERANCE)
        assert not wrong and not dist[t] + 1e-6 + overlap(pa, pb, unit[t]) <= TOLERANCE
    assert len(rows) >= 100 and passed.all()
    # Separated pairs as if FCL had called them touching: where one of the candidate
    # directions separates them, both see it (and narrow.checked measures the gap).
    far = rows[dist[rows] > 1e-3]
    *_, separating = certify.penetration(np.zeros(len(far)), p1[far], p1[far],
                                         np.zeros((len(far), 3)), np.zeros(len(far), bool),
                                         a.rows(far), b.rows(far))
    for t, found in zip(far.tolist(), separating.tolist(), strict=True):
        pa, pb = Placed(shapes[ia[t]], fa[t]), Placed(shapes[ib[t]], fb[t])
        assert found == (checked((0.0, p1[t], p1[t]), pa, pb)[0] > 0)
    assert len(far) >= 50 and separating.sum() >= 50
    rows = np.flatnonzero(~apart)
    inside = dist[rows] <= 0
    out_d, out_p1, out_p2, out_n, separating = certify.penetration(
        np.minimum(dist[rows], 0.0), p1[rows], p2[rows], -unit[rows], inside & has[rows],
        a.rows(rows), b.rows(rows))
    touching = 0
    for r, t in enumerate(rows.tolist()):
        pa, pb = Placed(shapes[ia[t]], fa[t]), Placed(shapes[ib[t]], fb[t])
        d, q1, q2, n = checked(raws[t], pa, pb)
        if separating[r]:
            assert d > 0  # narrow.checked found the gap that certify sends to GJK
            continue
        assert out_d[r] == pytest.approx(d, abs=1e-12)
        np.testing.assert_allclose(out_n[r], n, atol=1e-12)
        # On a tie (a face along the direction) the witness may be another point of it.
        assert out_n[r] @ out_p1[r] == pytest.approx(n @ q1, abs=1e-9)
        np.testing.assert_allclose(out_p2[r] - out_p1[r], q2 - q1, atol=1e-9)
        touching += abs(d) <= TOLERANCE
    assert len(rows) >= 100 and touching >= 20
