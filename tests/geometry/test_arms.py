"""Arms beyond the Panda: built-in models, tool frames against PyBullet, fingers that
open and close (mimic joints following), and URDF files whose meshes are found or
reported where the scene names them."""

import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from tampcli.errors import SceneError
from tampcli.geometry import transforms
from tampcli.geometry.arms import ARMS
from tampcli.geometry.scene import RobotSpec, Scene
from tampcli.geometry.scene_parse import build_scene
from tampcli.geometry.tomlsrc import read_toml
from tampcli.geometry.urdf_file import pybullet_data_dir, read_urdf
from tampcli.geometry.world import World

from .worlds import box, simulator

DATA = pybullet_data_dir()
XARM = DATA / "xarm" / "xarm6_with_gripper.urdf"
XARM_FINGERS = ("drive_joint", "left_finger_joint", "left_inner_knuckle_joint",
                "right_outer_knuckle_joint", "right_finger_joint", "right_inner_knuckle_joint")


@pytest.fixture(scope="module", params=sorted(ARMS))
def arm(request):
    with World(Scene(None, RobotSpec(request.param))) as world:
        yield request.param, world


def _pybullet_frame(world, link_name: str) -> np.ndarray:
    sim = simulator(world)
    for j in range(sim.pb.getNumJoints(sim.robot, physicsClientId=sim.client)):
        info = sim.pb.getJointInfo(sim.robot, j, physicsClientId=sim.client)
        if info[12].decode() == link_name:
            s = sim.pb.getLinkState(sim.robot, j, computeForwardKinematics=True,
                                    physicsClientId=sim.client)
            return transforms.pose(transforms.quat_to_matrix(s[5]), s[4])
    raise KeyError(link_name)


def _joint_values(world, names) -> dict[str, float]:
    sim = simulator(world)
    out = {}
    for j in range(sim.pb.getNumJoints(sim.robot, physicsClientId=sim.client)):
        name = sim.pb.getJointInfo(sim.robot, j, physicsClientId=sim.client)[1].decode()
        if name in names:
            out[name] = sim.pb.getJointState(sim.robot, j, physicsClientId=sim.client)[0]
    return out


def test_tool_frame_is_pybullets_link_composed_with_the_offset(arm):
    name, world = arm
    spec = ARMS[name]
    offset = (transforms.pose_from_xyzquat(spec.tool_offset) if spec.tool_offset
              else np.eye(4))
    pybullet_link = spec.tool_frame or spec.tool_link
    rng = np.random.default_rng(3)
    try:
        for _ in range(10):
            q = rng.uniform(world.lower, world.upper)
            world.set_state(q)
            expected = _pybullet_frame(world, pybullet_link) @ offset
            np.testing.assert_allclose(world.tool_pose(q), expected, atol=2e-6)
            np.testing.assert_allclose(world.fk(q)[spec.tool_link] @ offset
                                       if spec.tool_frame is None else world.fk(q)[spec.tool_frame],
                                       expected, atol=2e-6)
    finally:
        world.set_state(world.start)


def test_tool_frame_follows_the_pandas_convention(arm):
    """Origin between the fingertips, 1 cm (+-0.5) above them; z out of the gripper
    (the flange behind the origin); fingers on either side along y."""
    name, world = arm
    assert 0.005 <= world.fingertip_depth <= 0.015, name
    assert 0.075 <= world.gripper_opening <= 0.095, name
    inner, outer = world.finger_span  # the open fingers' near and far sides from the axis
    assert inner == pytest.approx(world.gripper_opening / 2), name
    assert inner + 0.01 <= outer <= inner + 0.04, name  # fingers 1 to 4 cm thick
    tool = world.tool_pose(world.start)
    flange = transforms.pose_inverse(tool) @ world.fk(world.start)[ARMS[name].tool_link]
    assert flange[2, 3] <= 1e-9 and np.hypot(*flange[:2, 3]) < 1e-6, name
    # The ready pose points the tool down, within 5 degrees.
    assert tool[2, 2] < -0.996, name


def test_built_in_arms_name_their_joints_and_fingers(arm):
    name, world = arm
    assert world.n == len(ARMS[name].joints or world.joint_names)
    assert world.finger_names == ARMS[name].fingers.joints
    assert [r[0] for r in world.finger_range] == list(ARMS[name].fingers.open)
    assert [r[1] for r in world.finger_range] == list(ARMS[name].fingers.closed)


def test_xarm_joints_default_to_the_chain_and_mimic_joints_follow():
    world = World(Scene(None, RobotSpec("xarm6")))
    try:
        assert world.joint_names == tuple(f"joint{i}" for i in range(1, 7))
        assert world.tool_link == "tool_frame"
        assert set(_joint_values(world, XARM_FINGERS).values()) == {0.0}
        world.set_state(world.start, fingers_closed=True)
        closed = _joint_values(world, XARM_FINGERS)
        assert closed == pytest.approx(dict.fromkeys(XARM_FINGERS, 0.85))
        world.set_state(world.start)
        assert set(_joint_values(world, XARM_FINGERS).values()) == {0.0}
    finally:
        world.close()


@pytest.mark.parametrize("model", ["kuka_iiwa", "xarm6", "panda"])
def test_fingers_close_on_what_they_hold(model):
    """A cube between the open fingers: closing stops where the fingers touch it."""
    with World(Scene(None, RobotSpec(model))) as bare:
        tool = bare.tool_pose(bare.start)
    centre = tool[:3, 3] + tool[:3, 2] * 0.005
    cube = box("a", (0.05, 0.05, 0.05), centre, fixed=False,
               quat=tuple(transforms.matrix_to_quat(tool[:3, :3])))
    with World(Scene(None, RobotSpec(model), (cube,))) as world:
        sim = simulator(world)
        world.set_state(world.start, fingers_closed=True)
        points = sim.pb.getClosestPoints(sim.robot, sim.bodies["a"], 0.002,
                                         physicsClientId=sim.client)
        touching = [p for p in points if p[3] >= 0]
        assert touching, model
        assert min(p[8] for p in touching) > -0.002, model  # no finger deep inside
        values = _joint_values(world, world.finger_names)
        open_, closed = world.finger_range[0]
        for v in values.values():
            assert min(open_, closed) < v < max(open_, closed), (model, v)


# ------------------------------------------------------------ scene keys


def _scene(tmp_path, robot: str) -> Path:
    path = tmp_path / "s.scene.toml"
    path.write_text("[robot]\n" + robot)
    return path


def _robot(tmp_path, robot: str) -> RobotSpec:
    return build_scene(read_toml(str(_scene(tmp_path, robot)))).robot


def test_tool_offset_takes_every_pose_form_or_a_link_name(tmp_path):
    head = f'urdf = "{XARM}"\ntool_link = "xarm_gripper_base_link"\n'
    r = _robot(tmp_path, head + "tool_offset = [0, 0, 0.15]\n")
    assert r.model == "urdf" and r.tool_offset == (0, 0, 0.15, 0, 0, 0, 1)
    r = _robot(tmp_path, head + "tool_offset = [0, 0, 0.15, 1.5707963267948966]\n")
    assert r.tool_offset[5:] == pytest.approx((np.sqrt(0.5), np.sqrt(0.5)))
    r = _robot(tmp_path, head + "tool_offset = [0, 0, 0.15, 0, 0, 2, 0]\n")
    assert r.tool_offset[3:] == pytest.approx((0, 0, 1, 0))
    r = _robot(tmp_path, head + 'tool_offset = "left_finger"\n')
    assert r.tool_frame == "left_finger" and r.tool_offset is None
    r = _robot(tmp_path, head + 'fingers = { joints = ["drive_joint"], open = 0, closed = 0.85 }\n')
    assert r.fingers.joints == ("drive_joint",) and r.fingers.closed == (0.85,)
    assert r.joints is None


@pytest.mark.parametrize("robot, line, key, match", [
    ('model = "kuka_iiwa"\ntool_link = "x"\n', 3, "robot.tool_link", "only for model \"urdf\""),
    ('urdf = "{x}"\ntool_link = "l"\ntool_offset = [0, 0]\n', 4, "robot.tool_offset",
     "[x, y, z, qx, qy, qz, qw]"),
    ('urdf = "{x}"\ntool_link = "l"\ntool_offset = [0, 0, 0, 0, 0, 0, 0]\n', 4,
     "robot.tool_offset", "must not be zero"),
    ('urdf = "{x}"\ntool_link = "l"\nfingers = ["a"]\n', 4, "robot.fingers", "a table"),
    ('urdf = "{x}"\ntool_link = "l"\nfingers = {{ joints = ["a"], open = 0 }}\n', 4,
     "robot.fingers", "fingers.closed"),
    ('urdf = "{x}"\ntool_link = "l"\nfingers = {{ joints = ["a", "b"], open = [0], '
     'closed = 1 }}\n', 4, "robot.fingers", "one per finger joint (2)"),
    ('urdf = "{x}"\ntool_link = "l"\npackage_paths = ["nowhere"]\n', 4, "robot.package_paths",
     "no such folder"),
    ('model = "xarm6"\nstart = [0, 0, 0]\n', 3, "robot.start", "expected 6 joint values"),
])
def test_bad_arm_keys_are_located(tmp_path, robot, line, key, match):
    path = _scene(tmp_path, robot.format(x=XARM))
    with pytest.raises(SceneError) as info:
        build_scene(read_toml(str(path)))
    assert (info.value.line, info.value.key) == (line, key), info.value.render()
    assert match in info.value.message


@pytest.mark.parametrize("robot, key, match", [
    ('tool_link = "hand"\n', "robot.tool_link", "has no link 'hand'"),
    ('tool_link = "link6"\ntool_offset = "nowhere"\n', "robot.tool_offset", "no link 'nowhere'"),
    ('tool_link = "link6"\ntool_offset = "left_finger"\nfingers = { joints = ["drive_joint"], '
     'open = 0, closed = 0.85 }\n', "robot.tool_offset", "a joint moves it"),
    ('tool_link = "link6"\nfingers = { joints = ["joint6"], open = 0, closed = 1 }\n',
     "robot.fingers", "moves the tool link"),
    ('tool_link = "link6"\nfingers = { joints = ["grip"], open = 0, closed = 1 }\n',
     "robot.fingers", "'grip' is no movable joint"),
    ('tool_link = "link6"\nstart = [0, 0]\n', "robot.start", "expected 6 joint values"),
])
def test_urdf_names_are_checked_against_the_file(tmp_path, robot, key, match):
    path = _scene(tmp_path, f'urdf = "{XARM}"\n' + robot)
    scene = build_scene(read_toml(str(path)))
    with pytest.raises(SceneError) as info:
        World(scene)
    assert info.value.key == key and info.value.path == str(path), info.value.render()
    assert match in info.value.message


# ------------------------------------------------------------ URDF files and meshes


def _edited_xarm(folder: Path) -> Path:
    """What the issue's user did: a copy of the xArm URDF elsewhere, a TCP link added."""
    text = XARM.read_text()
    tcp = ('<joint name="tcp_joint" type="fixed"><parent link="xarm_gripper_base_link"/>'
           '<child link="tcp"/><origin rpy="0 0 0" xyz="0 0 0.152"/></joint>'
           '<link name="tcp"/></robot>')
    path = folder / "xarm_tcp.urdf"
    path.write_text(text.replace("</robot>", tcp))
    return path


def test_a_copied_urdf_finds_its_package_meshes_and_says_nothing(tmp_path, capfd):
    urdf = _edited_xarm(tmp_path)
    path = _scene(tmp_path, f'urdf = "{urdf.name}"\ntool_link = "xarm_gripper_base_link"\n'
                            'tool_offset = "tcp"\n'
                            'fingers = { joints = ["drive_joint"], open = 0, closed = 0.85 }\n')
    with World(build_scene(read_toml(str(path)))) as world:
        assert world.tool_link == "tcp"
        assert world.joint_names == tuple(f"joint{i}" for i in range(1, 7))
        with World(Scene(None, RobotSpec("xarm6"))) as builtin:
            q = builtin.start
            np.testing.assert_allclose(world.tool_pose(q), builtin.tool_pose(q), atol=1e-6)
    out, err = capfd.readouterr()
    assert "b3" not in out + err


def test_package_paths_find_a_package_elsewhere(tmp_path):
    package = tmp_path / "assets" / "mygripper" / "meshes"
    package.mkdir(parents=True)
    shutil.copy(DATA / "cube.obj", package / "palm.obj")
    urdf = tmp_path / "robots" / "arm.urdf"
    urdf.parent.mkdir()
    urdf.write_text(
        '<robot name="arm"><link name="base"/>'
        '<joint name="j1" type="revolute"><parent link="base"/><child link="hand"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<link name="hand"><collision><geometry>'
        '<mesh filename="package://mygripper/meshes/palm.obj" scale="0.05 0.05 0.05"/>'
        '</geometry></collision></link></robot>')
    robot = 'urdf = "robots/arm.urdf"\ntool_link = "hand"\n'
    with pytest.raises(SceneError) as info:
        World(build_scene(read_toml(str(_scene(tmp_path, robot)))))
    assert info.value.key == "robot.urdf" and info.value.line == 2
    assert "mesh 'package://mygripper/meshes/palm.obj' not found" in info.value.message
    assert re.search(r"arm\.urdf:1: ", info.value.message)
    robot += 'package_paths = ["assets"]\n'
    with World(build_scene(read_toml(str(_scene(tmp_path, robot))))) as world:
        assert world.joint_names == ("j1",) and world.tool_link == "hand"
        assert len(world.robot_link_shapes(world.chain.index["hand"])) == 1


def test_a_missing_mesh_is_located_and_nothing_raw_is_printed(cli, tmp_path):
    urdf = _edited_xarm(tmp_path)
    urdf.write_text(urdf.read_text().replace("left_finger.STL", "left_fingre.STL"))
    scene = tmp_path / "p.scene.toml"
    scene.write_text(f'[robot]\nurdf = "{urdf.name}"\ntool_link = "tcp"\n\n'
                     '[[objects]]\nname = "a"\nshape = "box"\nsize = [0.05, 0.05, 0.05]\n'
                     'pose = [0.4, 0, 0.025]\n')
    problem = tmp_path / "p.pddl"
    problem.write_text("(define (problem p) (:domain d) (:objects a - block) (:init) "
                       "(:goal (clear a)))")
    domain = tmp_path / "d.pddl"
    domain.write_text("(define (domain d) (:types block) (:predicates (clear ?b - block)))")
    run = cli("check", domain, problem)
    assert run.code == 2, run.out + run.err
    assert f"{scene}:2: robot.urdf: " in run.err
    assert "left_fingre.STL" in run.err and "b3" not in run.err + run.out


def test_urdf_tree_order_and_mimic_composition():
    urdf = read_urdf(str(XARM))
    assert urdf.arm_joints("tcp_missing") == ()
    assert urdf.arm_joints("xarm_gripper_base_link") == tuple(f"joint{i}" for i in range(1, 7))
    followers = urdf.followers(("drive_joint",))
    assert set(followers) == set(XARM_FINGERS[1:])
    assert all(v == ("drive_joint", 1.0, 0.0) for v in followers.values())


# ------------------------------------------------------------ docs/robots.md


ROBOTS_MD = Path(__file__).resolve().parents[2] / "docs" / "robots.md"


def test_robots_md_examples_are_real(tmp_path):
    """Every TOML example of docs/robots.md is a robot table tampcli reads; with the
    files it names put in place (a copy of the xArm URDF, edited as shown), each loads."""
    text = ROBOTS_MD.read_text()
    blocks = re.findall(r"```toml\n(.*?)```", text, re.DOTALL)
    (xml,) = re.findall(r"```xml\n(.*?)```", text, re.DOTALL)
    assert len(blocks) == 5
    (tmp_path / "arms").mkdir()
    shutil.copy(XARM, tmp_path / "arms" / XARM.name)
    (tmp_path / "xarm_tcp.urdf").write_text(XARM.read_text().replace("</robot>",
                                                                     xml + "</robot>"))
    tools = []
    for block in blocks:
        path = tmp_path / "example.scene.toml"
        path.write_text(block)
        with World(build_scene(read_toml(str(path)))) as world:
            tools.append(world.tool_pose(world.start if world.n == 7 else ARMS["xarm6"].ready))
    # The xArm three ways (built in, a URDF with an offset, a TCP link) has one tool frame.
    np.testing.assert_allclose(tools[1], tools[3], atol=1e-6)
    np.testing.assert_allclose(tools[3], tools[4], atol=1e-6)


def test_a_given_finger_opening_moves_the_mimic_joints_along():
    with World(Scene(None, RobotSpec("xarm6"))) as world:
        world.set_state(world.start, fingers_closed=True, finger_opening=0.4)
        assert _joint_values(world, XARM_FINGERS) == pytest.approx(dict.fromkeys(XARM_FINGERS,
                                                                                 0.4))
