import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.geometry.world import World

from .worlds import kuka_scene, panda_scene, planar_scene, simulator


@pytest.fixture(scope="module")
def panda():
    with World(panda_scene()) as world:
        yield world


@pytest.fixture(scope="module")
def planar():
    with World(planar_scene()) as world:
        yield world


@pytest.fixture(scope="module")
def kuka():
    with World(kuka_scene()) as world:
        yield world


def _random_qs(world, count, seed=0):
    rng = np.random.default_rng(seed)
    return [rng.uniform(world.lower, world.upper) for _ in range(count)]


def _pybullet_link_frames(world):
    sim = simulator(world)
    out = {}
    for link in world.chain.links[1:]:
        s = sim.pb.getLinkState(sim.robot, link.pb_index, computeForwardKinematics=True,
                                physicsClientId=sim.client)
        out[link.name] = transforms.pose(transforms.quat_to_matrix(s[5]), s[4])
    return out


@pytest.mark.parametrize("name", ["panda", "planar", "kuka"])
def test_fk_matches_pybullet(name, request):
    world = request.getfixturevalue(name)
    try:
        for q in _random_qs(world, 25):
            world.set_state(q)
            expected = _pybullet_link_frames(world)
            mine = world.fk(q)
            for link, frame in expected.items():
                np.testing.assert_allclose(mine[link], frame, atol=2e-6, err_msg=link)
    finally:
        world.set_state(world.start)


def test_panda_names_limits_and_tool(panda):
    assert panda.joint_names == tuple(f"panda_joint{i}" for i in range(1, 8))
    assert panda.tool_link == "panda_grasptarget"
    assert panda.lower.shape == panda.upper.shape == panda.start.shape == (7,)
    assert np.all(panda.lower < panda.upper)
    assert np.all((panda.lower <= panda.start) & (panda.start <= panda.upper))
    # The grasp target sits 0.105 m along the hand's z axis from the hand frame.
    frames = panda.fk(panda.start)
    hand, tool = frames["panda_hand"], frames["panda_grasptarget"]
    np.testing.assert_allclose(tool[:3, 3], hand[:3, 3] + 0.105 * hand[:3, 2], atol=1e-9)
    # In the ready pose the tool points down.
    assert panda.tool_pose(panda.start)[2, 2] < -0.99


def test_planar_joints_hold_world_coordinates(planar):
    assert planar.joint_names == ("x", "y")
    pose = planar.tool_pose([0.2, -0.4])
    np.testing.assert_allclose(pose[:3, 3], [0.2, -0.4, 0.025], atol=1e-9)
    np.testing.assert_allclose(planar.lower, [-1.0, -1.0], atol=1e-3)
    np.testing.assert_allclose(planar.upper, [1.0, 1.0], atol=1e-3)


@pytest.mark.parametrize("name", ["panda", "planar", "kuka"])
def test_point_jacobian_matches_finite_differences(name, request):
    world = request.getfixturevalue(name)
    rng = np.random.default_rng(3)
    h = 1e-6
    for q in _random_qs(world, 10, seed=4):
        for link in world.link_names[1:]:
            frame = world.fk(q)[link]
            local = rng.normal(size=3) * 0.1
            point = frame[:3, :3] @ local + frame[:3, 3]
            jac = world.point_jacobian(q, link, point)
            numeric = np.zeros_like(jac)
            for i in range(world.n):
                dq = np.zeros(world.n)
                dq[i] = h
                fp, fm = world.fk(q + dq)[link], world.fk(q - dq)[link]
                numeric[:, i] = ((fp[:3, :3] @ local + fp[:3, 3])
                                 - (fm[:3, :3] @ local + fm[:3, 3])) / (2 * h)
            np.testing.assert_allclose(jac, numeric, atol=1e-7, err_msg=link)


def test_tool_jacobian_matches_finite_differences(panda):
    h = 1e-6
    for q in _random_qs(panda, 5, seed=5):
        jac = panda.tool_jacobian(q)
        base = panda.tool_pose(q)
        for i in range(panda.n):
            dq = np.zeros(panda.n)
            dq[i] = h
            plus, minus = panda.tool_pose(q + dq), panda.tool_pose(q - dq)
            np.testing.assert_allclose(jac[:3, i], (plus[:3, 3] - minus[:3, 3]) / (2 * h),
                                       atol=1e-7)
            # Angular velocity: the rotation vector of R(q+h) R(q)^T per h.
            omega = transforms.rotation_log(plus[:3, :3] @ base[:3, :3].T) / h
            np.testing.assert_allclose(jac[3:, i], omega, atol=1e-5)


def test_point_jacobian_matches_pybullet(panda):
    sim = simulator(panda)
    try:
        for q in _random_qs(panda, 5, seed=6):
            panda.set_state(q)
            link = panda.chain.links[panda.chain.index["panda_hand"]]
            local = [0.01, 0.02, 0.03]
            # PyBullet wants all movable joints (fingers too) and a URDF-link-frame position.
            full = list(q) + [0.04, 0.04]
            lin, _ = sim.pb.calculateJacobian(sim.robot, link.pb_index, local, full,
                                              [0.0] * 9, [0.0] * 9, physicsClientId=sim.client)
            frame = panda.fk(q)["panda_hand"]
            point = frame[:3, :3] @ local + frame[:3, 3]
            np.testing.assert_allclose(panda.point_jacobian(q, "panda_hand", point),
                                       np.array(lin)[:, :7], atol=1e-5)
    finally:
        panda.set_state(panda.start)


@pytest.mark.parametrize(("name", "count"), [("panda", 40), ("kuka", 15)])
def test_ik_reaches_reachable_targets(name, count, request):
    world = request.getfixturevalue(name)
    for k, q in enumerate(_random_qs(world, count, seed=7)):
        target = world.tool_pose(q)
        solution, residual = world.ik(target, rng_seed=k)
        assert residual < 1e-4, k
        np.testing.assert_allclose(world.tool_pose(solution), target, atol=1e-3)
        assert np.all(solution >= world.lower) and np.all(solution <= world.upper)


def test_ik_reports_unreachable_target(panda):
    target = transforms.pose(None, (2.0, 0.0, 0.5))
    _, residual = panda.ik(target, position_only=True, restarts=2)
    assert residual > 0.5


def test_ik_position_only(panda):
    target = transforms.pose(None, (0.4, 0.2, 0.3))
    q, residual = panda.ik(target, position_only=True)
    assert residual < 1e-4
    np.testing.assert_allclose(panda.tool_pose(q)[:3, 3], [0.4, 0.2, 0.3], atol=1e-4)


def _simulator_state(world):
    """Every joint value and every body pose in the World's client."""
    sim = simulator(world)
    joints = [sim.pb.getJointState(sim.robot, j, physicsClientId=sim.client)[0]
              for j in range(sim.pb.getNumJoints(sim.robot, physicsClientId=sim.client))]
    poses = {name: sim.pb.getBasePositionAndOrientation(uid, physicsClientId=sim.client)
             for name, uid in sim.bodies.items()}
    return joints, poses


@pytest.mark.parametrize("name", ["panda", "kuka"])
def test_queries_leave_simulator_unchanged(name, request):
    world = request.getfixturevalue(name)
    before = _simulator_state(world)
    q = world.upper - 0.1
    world.fk(q)
    world.point_jacobian(q, world.link_names[5], [0.1, 0.1, 0.5])
    world.ik(world.tool_pose(q))
    for body in world.body_names:
        world.aabb(body)
        world.aabb(body, base_only=True)
    for i in range(len(world.chain.links)):
        world.robot_link_shapes(i)
    for body in world.scene.bodies:
        if body.shape == "urdf":
            assert world.body_collision_shapes(body.name)
    world.part_boxes()
    world.bounds()
    world.camera_image(16, 12, eye=(1.5, 1.5, 1.5), target=(0.0, 0.0, 0.0))
    assert _simulator_state(world) == before


def test_body_pose_and_names(panda):
    assert "a" in panda.movable_names and "table" not in panda.movable_names
    assert set(panda.body_names) == {"pedestal", "table", "wall", "post", "ball", "a"}
    np.testing.assert_allclose(panda.body_pose("a")[:3, 3], [0.45, -0.1, 0.025])


def test_set_state_and_camera_image(planar):
    try:
        image = planar.camera_image(64, 48, eye=(0.0, -1.5, 1.5), target=(0.0, 0.0, 0.0))
        assert image.shape == (48, 64, 3) and image.dtype == np.uint8
        moved = transforms.pose(None, (0.0, 0.0, 0.025))
        planar.set_state([0.5, 0.5], {"a": moved})
        lo, hi = planar.bounds()
        np.testing.assert_allclose(lo[:2], [-1.0, -1.0], atol=0.01)
        image2 = planar.camera_image(64, 48, eye=(0.0, -1.5, 1.5), target=(0.0, 0.0, 0.0))
        assert np.abs(image2.astype(int) - image.astype(int)).sum() > 0
    finally:
        planar.set_state(planar.start, {"a": planar.body_pose("a")})


def test_close_releases_client():
    world = World(planar_scene())
    sim = simulator(world)
    world.close()
    assert not sim.pb.isConnected(physicsClientId=sim.client)
    world.close()


def test_any_urdf_arm(kuka):
    assert kuka.joint_names == tuple(f"lbr_iiwa_joint_{i}" for i in range(1, 8))
    assert kuka.tool_link == "lbr_iiwa_link_7"
    np.testing.assert_allclose(kuka.start, np.zeros(7))
    target = kuka.tool_pose(np.array([0.3, 0.5, 0.0, -1.2, 0.0, 0.8, 0.0]))
    q, residual = kuka.ik(target)
    assert residual < 1e-4


def test_urdf_robot_with_unknown_joint_is_a_scene_error():
    import dataclasses

    from tampcli.errors import SceneError

    scene = kuka_scene()
    bad = dataclasses.replace(scene, robot=dataclasses.replace(
        scene.robot, joints=("lbr_iiwa_joint_1", "elbow")))
    with pytest.raises(SceneError) as info:
        World(bad)
    assert info.value.key == "robot.joints" and "elbow" in info.value.message
    bad = dataclasses.replace(scene, robot=dataclasses.replace(scene.robot, tool_link="hand"))
    with pytest.raises(SceneError) as info:
        World(bad)
    assert info.value.key == "robot.tool_link"


def test_unloadable_files_are_scene_errors(tmp_path):
    import dataclasses

    from tampcli.errors import SceneError

    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='x'><link name='a'>")
    scene = planar_scene()
    broken = dataclasses.replace(scene, bodies=scene.bodies + (
        dataclasses.replace(scene.bodies[0], name="thing", shape="urdf", urdf=str(bad)),))
    with pytest.raises(SceneError) as info:
        World(broken)
    assert info.value.key == "objects.urdf"


@pytest.mark.parametrize("name", ["panda", "planar", "kuka"])
def test_batched_fk_and_jacobians_match_single(name, request):
    world = request.getfixturevalue(name)
    qs = np.array(_random_qs(world, 12, seed=9))
    frames = world.chain.fk_batch(qs)
    poses, jacs = world.tool_poses(qs), world.tool_jacobians(qs)
    for t, q in enumerate(qs):
        for k, frame in enumerate(world.chain.fk_list(q)):
            np.testing.assert_allclose(frames[t, k], frame, atol=1e-12)
        np.testing.assert_allclose(poses[t], world.tool_pose(q), atol=1e-12)
        np.testing.assert_allclose(jacs[t], world.tool_jacobian(q), atol=1e-12)


def test_fingers_open_and_close_for_replay(panda):
    sim = simulator(panda)

    def opening():
        return [sim.pb.getJointState(sim.robot, j, physicsClientId=sim.client)[0]
                for j in sim.fingers]

    try:
        assert opening() == pytest.approx([0.04, 0.04])
        panda.set_state(panda.start, fingers_closed=True)
        assert opening() == pytest.approx([0.0, 0.0])
        panda.set_state(panda.start, fingers_closed=True, finger_opening=0.025)
        assert opening() == pytest.approx([0.025, 0.025])
        # Kinematics (and collision geometry) keep the fingers open whatever replay does.
        frames = panda.fk(panda.start)
        gap = np.linalg.norm(frames["panda_leftfinger"][:3, 3]
                             - frames["panda_rightfinger"][:3, 3])
        assert gap == pytest.approx(0.08, abs=1e-6)
    finally:
        panda.set_state(panda.start)


def test_refixed_fingers_match_pybullet(panda):
    """Frames with the finger joints at given values (a solution file's finger
    columns) are where PyBullet puts the fingers at those values."""
    chain, links = panda.chain, panda.finger_links
    qs = _random_qs(panda, 5, seed=3)
    values = np.array([[0.0, 0.04], [0.01, 0.02], [0.025, 0.025], [0.04, 0.0], [0.03, 0.01]])
    frames = chain.refixed(chain.fk_batch(np.array(qs)), dict(zip(links, values.T, strict=True)))
    try:
        for row, (q, v) in enumerate(zip(qs, values, strict=True)):
            panda.set_state(q, fingers=v)
            expected = _pybullet_link_frames(panda)
            for i, link in enumerate(chain.links[1:], start=1):
                np.testing.assert_allclose(frames[row, i], expected[link.name], atol=2e-6,
                                           err_msg=link.name)
    finally:
        panda.set_state(panda.start)


def test_ik_answers_a_question_asked_again_the_same_way(panda):
    """ik.IkMemo: the same question, the same answer (a copy); an unreachable target
    is not tried again from another seed."""
    target = panda.tool_pose(_random_qs(panda, 1, seed=11)[0])
    seed = np.clip(panda.start + 0.3, panda.lower, panda.upper)
    q1, r1 = panda.ik(target, seed=seed, rng_seed=1)
    q1[:] = 0.0  # the caller's copy: the memo keeps its own
    q2, r2 = panda.ik(target, seed=seed, rng_seed=2)
    q3, r3 = panda.ik(target, seed=seed, rng_seed=2)
    assert r2 == r1 < 1e-4 and np.array_equal(q2, q3) and not np.array_equal(q2, q1)
    np.testing.assert_allclose(panda.tool_pose(q2), target, atol=1e-3)
    # out of reach: the second seed gets the first one's miss
    far = transforms.pose(None, (1.5, 0.3, 0.4))
    qa, ra = panda.ik(far, seed=panda.start, restarts=2)
    qb, rb = panda.ik(far, seed=np.clip(panda.start - 0.4, panda.lower, panda.upper),
                      restarts=2)
    assert ra == rb > 0.5 and np.array_equal(qa, qb)
    # another question is answered afresh
    q4, r4 = panda.ik(target, seed=panda.start, rng_seed=1)
    assert r4 < 1e-4


@pytest.mark.parametrize("rows", [slice(0, 6), slice(0, 3)])
def test_batched_ik_seeds_run_as_they_would_one_by_one(panda, rows):
    """ik._levenberg_marquardt_batch: each seed runs as it would alone (same steps,
    same stopping rules: the same outcome, and the same answer to rounding; a failing
    run may drift apart by rounding where it wanders), and the batch runs until the
    first seed in order that succeeds, as solve_ik one seed after another; targets
    reachable, reachable from some seeds only, and out of reach."""
    from tampcli.geometry import ik

    rng = np.random.default_rng(3)
    targets = [panda.tool_pose(q) for q in _random_qs(panda, 6, seed=5)]
    targets += [transforms.pose(None, (0.9, 0.1, 0.3)), transforms.pose(None, (1.4, 0.0, 0.5))]
    firsts = []
    for target in targets:
        seeds = np.array([rng.uniform(panda.lower, panda.upper) for _ in range(6)])
        one_by_one = [ik._levenberg_marquardt(panda, target, s, rows, 200, 1e-5)
                      for s in seeds]
        qs, res = ik._levenberg_marquardt_batch(panda, target, seeds, rows, 200, 1e-5)
        ok = [r <= 1e-5 for _, r in one_by_one]
        first = ok.index(True) if any(ok) else None
        last = first if first is not None else len(seeds) - 1
        assert [r <= 1e-5 for r in res[:last + 1]] == ok[:last + 1]
        if first is not None:
            np.testing.assert_allclose(qs[first], one_by_one[first][0], atol=1e-6)
        firsts.append(first)
    assert None in firsts and any(f not in (None, 0) for f in firsts)
