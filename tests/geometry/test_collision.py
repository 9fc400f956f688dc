import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.world import World

from .worlds import kuka_scene, panda_scene, planar_scene, simulator

# PyBullet pads each convex mesh with a 1 mm collision margin, and so do our hulls
# (shapes.HULL_MARGIN): the distances agree as measured, to GJK's accuracy.
AGREE = 1e-3


@pytest.fixture(scope="module")
def panda():
    with World(panda_scene()) as world:
        yield world, CollisionChecker(world)


@pytest.fixture(scope="module")
def planar():
    with World(planar_scene()) as world:
        yield world, CollisionChecker(world)


@pytest.fixture(scope="module")
def kuka():
    with World(kuka_scene()) as world:
        yield world, CollisionChecker(world)


def _pybullet_ids(world, name):
    kind, _, bare = name.partition(":")
    if kind == "link":
        return simulator(world).robot, world.chain.links[world.chain.index[bare]].pb_index
    return simulator(world).bodies[bare], -1


def _compare_with_pybullet(world, checker, configurations, activation):
    """Closest distance per (link, body) pair vs PyBullet's getClosestPoints.

    A body made of several convex parts reports one contact per part: the
    smallest is PyBullet's answer for the body.
    """
    sim = simulator(world)
    pb, client = sim.pb, sim.client
    compared = 0
    try:
        for q in configurations:
            world.set_state(q)
            best: dict = {}
            for contact in checker.distances(q, activation=activation):
                key = (contact.a, contact.b)
                if key not in best or contact.distance < best[key].distance:
                    best[key] = contact
            for (a, b), contact in best.items():
                (ua, la), (ub, lb) = _pybullet_ids(world, a), _pybullet_ids(world, b)
                if lb == -1 and pb.getNumJoints(ub, physicsClientId=client) > 0:
                    points = pb.getClosestPoints(ua, ub, 0.5, linkIndexA=la,
                                                 physicsClientId=client)
                else:
                    points = pb.getClosestPoints(ua, ub, 0.5, la, lb, physicsClientId=client)
                assert points, (a, b)
                theirs = min(p[8] for p in points)
                if contact.distance > 0 and theirs > 0:
                    assert abs(theirs - contact.distance) < AGREE, (contact, theirs)
                elif contact.distance < -0.002:
                    assert theirs < 0, (contact, theirs)
                elif theirs < -0.002:
                    assert contact.distance < 0, (contact, theirs)
                compared += 1
    finally:
        world.set_state(world.start, {b.name: b.matrix for b in world.scene.bodies})
    return compared


def _random_qs(world, count, seed):
    rng = np.random.default_rng(seed)
    return [rng.uniform(world.lower, world.upper) for _ in range(count)]


@pytest.mark.parametrize(("name", "activation"), [("panda", 0.1), ("planar", 0.4),
                                                  ("kuka", 0.1)])
def test_signed_distances_match_pybullet(name, activation, request):
    world, checker = request.getfixturevalue(name)
    compared = _compare_with_pybullet(world, checker, _random_qs(world, 200, seed=11), activation)
    assert compared > 100


def test_penetration_sign_and_normal(planar):
    world, checker = planar
    # The disk (radius 0.05, 5 cm tall) 3.5 cm deep into the wall's face at x = 0.275;
    # lifting it out (5 cm) would take longer than backing out.
    q = np.array([0.26, 0.0])
    contact = checker.pair_distance(q, "link:planar_body", "body:wall")
    assert contact.distance == pytest.approx(-0.035, abs=1e-4)
    np.testing.assert_allclose(contact.normal, [1.0, 0.0, 0.0], atol=1e-3)
    np.testing.assert_allclose(contact.gradient, [-1.0, 0.0], atol=1e-3)
    q = np.array([0.2, 0.0])
    contact = checker.pair_distance(q, "link:planar_body", "body:wall")
    assert contact.distance == pytest.approx(0.025, abs=1e-5)
    np.testing.assert_allclose(contact.normal, [1.0, 0.0, 0.0], atol=1e-6)
    np.testing.assert_allclose(contact.point_a, [0.25, 0.0, contact.point_a[2]], atol=1e-5)


def _finite_difference(checker, q, contact, h=1e-4, **kw):
    """Central differences of the pair's distance, and whether they look smooth.

    Smooth: steps h and h/2 agree; a witness point switching features in
    between (a kink of the distance) makes them disagree.
    """
    def grad(step):
        out = np.zeros(len(q))
        for i in range(len(q)):
            dq = np.zeros(len(q))
            dq[i] = step
            plus = checker.pair_distance(q + dq, contact.a, contact.b, **kw).distance
            minus = checker.pair_distance(q - dq, contact.a, contact.b, **kw).distance
            out[i] = (plus - minus) / (2 * step)
        return out

    full, half = grad(h), grad(h / 2)
    return full, bool(np.max(np.abs(full - half)) < 1e-3)


@pytest.mark.parametrize(("name", "activation"), [("panda", 0.05), ("planar", 0.3),
                                                  ("kuka", 0.05)])
def test_distance_gradients_match_finite_differences(name, activation, request):
    world, checker = request.getfixturevalue(name)
    checked = skipped = 0
    for q in _random_qs(world, 30, seed=12):
        # pair_distance gives the closest part of a multi-part body: compare with that one.
        best: dict = {}
        for contact in checker.distances(q, activation=activation):
            key = (contact.a, contact.b)
            if key not in best or contact.distance < best[key].distance:
                best[key] = contact
        for contact in best.values():
            numeric, smooth = _finite_difference(checker, q, contact)
            if not smooth:
                skipped += 1
                continue
            # Separated: certified to 1e-8 m. Penetrating: FCL's EPA converges to ~1e-6 m.
            atol = 2e-4 if contact.distance > 0 else 1e-3
            np.testing.assert_allclose(contact.gradient, numeric, atol=atol,
                                       err_msg=f"{contact.a} {contact.b} {contact.distance}")
            checked += 1
    assert checked >= 10 and skipped <= checked / 4


def test_held_object_contacts_and_gradient(panda):
    world, checker = panda
    grasp = transforms.pose(None, (0.0, 0.0, 0.0))
    q = world.start.copy()
    q[1] += 0.6  # lean forward: the held cube nears the table
    contacts = checker.distances(q, held=("a", grasp), activation=0.5)
    held = [c for c in contacts if c.a == "held:a"]
    assert any(c.b == "body:table" for c in held)
    assert all(c.b != "body:a" for c in contacts)
    assert all(c.b not in ("link:panda_hand", "link:panda_leftfinger") for c in held)
    table = next(c for c in held if c.b == "body:table")
    numeric, smooth = _finite_difference(checker, q, table, held=("a", grasp))
    assert smooth
    np.testing.assert_allclose(table.gradient, numeric, atol=1e-4)
    # Tool pointing down, cube centred on the tool point: its bottom face is 2.5 cm lower.
    assert table.distance == pytest.approx(world.tool_pose(q)[2, 3] - 0.025, abs=0.01)


def test_self_collision_pairs_exclude_adjacent_links(panda):
    world, checker = panda
    names = set(checker.self_pair_names)
    assert len(names) == 39  # as documented in collision.py
    assert ("link:panda_link1", "link:panda_link2") not in names
    assert ("link:panda_link5", "link:panda_link6") not in names
    assert ("link:panda_hand", "link:panda_leftfinger") not in names
    assert ("link:panda_link1", "link:panda_hand") in names
    # Folding the arm onto itself is reported as self-collision.
    q = np.array([0.0, -1.7, 0.0, -3.0, 0.0, 0.0, 0.0])
    self_contacts = [c for c in checker.distances(q, activation=0.0)
                     if c.a.startswith("link:") and c.b.startswith("link:")]
    assert self_contacts


def test_support_and_ignore(planar):
    world, checker = planar
    assert checker.support == frozenset({"floor"})
    q = np.array([0.2, 0.0])
    names = {c.b for c in checker.distances(q, activation=0.2)}
    assert "body:wall" in names and "body:floor" not in names
    names = {c.b for c in checker.distances(q, activation=0.2, ignore=frozenset({"wall"}))}
    assert "body:wall" not in names


def test_body_poses_override_start_poses(planar):
    world, checker = planar
    q = np.array([-0.2, -0.15])
    far = transforms.pose(None, (0.9, 0.9, 0.025))
    assert any(c.b == "body:a" for c in checker.distances(q, activation=0.2))
    assert not any(c.b == "body:a"
                   for c in checker.distances(q, {"a": far}, activation=0.2))


def test_activation_prunes_far_pairs(planar):
    world, checker = planar
    q = np.array([0.0, 0.0])
    for contact in checker.distances(q, activation=0.1):
        assert contact.distance <= 0.1
    assert checker.min_distance(q) == pytest.approx(0.225, abs=1e-4)


def test_body_distance_and_planar_pose_gradient(planar):
    world, checker = planar
    rng = np.random.default_rng(5)
    for _ in range(20):
        xa, ya, yawa = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-3, 3)
        xb, yb, yawb = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-3, 3)

        def pose(x, y, yaw):
            return transforms.pose(transforms.rot_z(yaw), (x, y, 0.025))

        c = checker.body_distance("a", pose(xa, ya, yawa), "post", pose(xb, yb, yawb))
        h = 1e-4
        params = np.array([xa, ya, yawa, xb, yb, yawb])
        numeric = np.zeros(6)
        for i in range(6):
            d = np.zeros(6)
            d[i] = h
            p, m = params + d, params - d
            plus = checker.body_distance("a", pose(*p[:3]), "post", pose(*p[3:])).distance
            minus = checker.body_distance("a", pose(*m[:3]), "post", pose(*m[3:])).distance
            numeric[i] = (plus - minus) / (2 * h)
        np.testing.assert_allclose(c.gradient, numeric, atol=5e-4)


@pytest.mark.slow
@pytest.mark.parametrize(("name", "activation"), [("panda", 0.1), ("planar", 0.4),
                                                  ("kuka", 0.1)])
def test_signed_distances_match_pybullet_long_sweep(name, activation, request):
    world, checker = request.getfixturevalue(name)
    assert _compare_with_pybullet(world, checker, _random_qs(world, 2000, seed=21),
                                  activation) > 1000


@pytest.mark.slow
def test_held_object_gradients_long_sweep(panda):
    world, checker = panda
    rng = np.random.default_rng(22)
    checked = 0
    for q in _random_qs(world, 60, seed=23):
        grasp = transforms.pose(transforms.rot_z(rng.uniform(-3, 3)), (0.0, 0.0, 0.02))
        for contact in checker.distances(q, held=("a", grasp), activation=0.05):
            if not contact.a.startswith("held:"):
                continue
            numeric, smooth = _finite_difference(checker, q, contact, held=("a", grasp))
            if smooth:
                atol = 2e-4 if contact.distance > 0 else 1e-3
                np.testing.assert_allclose(contact.gradient, numeric, atol=atol)
                checked += 1
    assert checked >= 10


def _as_set(contacts):
    return sorted((c.a, c.b, round(c.distance, 9)) for c in contacts)


def test_batched_rows_equal_one_query_each(panda):
    """distances_many, with one world state and held object per row, gives each row
    exactly what `distances` gives it alone (contacts, distances and gradients)."""
    world, checker = panda
    rng = np.random.default_rng(5)
    movable = [b.name for b in world.scene.bodies if not b.fixed]
    qs, poses, helds, ignores = [], [], [], []
    for k in range(24):
        q = world.start + rng.normal(0.0, 0.4, world.n)
        q = np.clip(q, world.lower, world.upper)
        moved = {}
        if k % 3 and movable:
            name = movable[k % len(movable)]
            moved[name] = transforms.pose(transforms.rot_z(rng.uniform(-3, 3)),
                                          (*rng.uniform([0.3, -0.3], [0.6, 0.3]), 0.03))
        held = None
        if k % 4 == 1 and movable:
            held = (movable[0], transforms.pose(None, (0.0, 0.0, 0.03)))
        qs.append(q)
        poses.append(moved)
        helds.append(held)
        ignores.append(frozenset({"link:panda_hand"}) if k % 5 == 2 else frozenset())
    batched = checker.distances_many(np.array(qs), poses, helds, ignores, activation=0.1)
    found = 0
    for q, moved, held, ignore, rows in zip(qs, poses, helds, ignores, batched, strict=True):
        alone = checker.distances(q, moved, held, ignore, activation=0.1)
        assert _as_set(rows) == _as_set(alone)
        by_pair = {(c.a, c.b, round(c.distance, 9)): c for c in alone}
        for c in rows:
            np.testing.assert_allclose(c.gradient, by_pair[(c.a, c.b, round(c.distance, 9))]
                                       .gradient, atol=1e-9)
        found += len(rows)
    assert found > 20
