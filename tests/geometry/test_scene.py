from pathlib import Path

import numpy as np
import pytest

from tampcli.errors import SceneError
from tampcli.geometry.scene import find_modes, find_scene, load_scene
from tampcli.optimize.modes import load_modes
from tampcli.pddl import parser

from .loading import load_checked

DATA = Path(__file__).parent / "data"


@pytest.fixture(scope="module")
def domain():
    return parser.parse_domain_file(str(DATA / "domain.pddl"))


@pytest.fixture(scope="module")
def problem():
    return parser.parse_problem_file(str(DATA / "p01.pddl"))


def test_find_scene_and_modes():
    assert find_scene(DATA / "p01.pddl") == DATA / "p01.scene.toml"
    assert find_modes(DATA / "domain.pddl") == DATA / "modes.toml"
    assert find_scene(DATA / "nothing.pddl") is None


def test_load_scene(domain, problem):
    modes = load_modes(DATA / "modes.toml", domain)
    scene = load_scene(DATA / "p01.scene.toml", domain, problem, modes=modes)
    assert scene.robot.model == "panda"
    assert [b.name for b in scene.bodies] == ["table", "a", "b", "wall"]
    a = scene.body("a")
    assert not a.fixed and not a.obstacle and a.color[0] > 0.5
    np.testing.assert_allclose(a.matrix[:3, 3], [0.45, -0.2, 0.025])
    assert a.matrix[1, 0] == pytest.approx(np.sin(0.3))
    assert scene.body("wall").obstacle and scene.body("wall").fixed
    assert scene.body("b").color == (0.2, 0.4, 0.9, 1.0)
    assert scene.region("goal").on == "table"
    assert scene.camera.eye == (1.3, 0.9, 0.9)
    assert scene.movable_names == ("a", "b")


def test_load_modes(domain):
    modes = load_modes(DATA / "modes.toml", domain)
    assert modes["pick"].kind == "grasp" and modes["pick"].object == "?b"
    assert modes["place"].bind(("a", "goal")) == {"object": "a", "on": "goal", "to": None}
    assert modes["wait"].kind == "none"
    assert set(modes) == {"pick", "place", "wait"}
    assert modes.missing == ()


def test_scene_errors_are_scene_errors(tmp_path, domain, problem):
    bad = tmp_path / "bad.scene.toml"
    bad.write_text("[robot]\nmodel = 'panda'\n[[objects]]\nname = 'a'\nshape = 'box'\n"
                   "size = [0.05, -0.05, 0.05]\npose = [0, 0, 0]\n")
    with pytest.raises(SceneError) as info:
        load_scene(bad, domain, problem)
    assert info.value.line == 6 and info.value.key == "objects.size"


@pytest.mark.parametrize(("sink", "refused"), [(0.0, False), (0.002, False), (0.006, True)])
def test_resting_contact_is_not_overlap(tmp_path, domain, problem, sink, refused):
    """Cube `a` rests on the table, sunk by `sink` metres: a few mm of slack are allowed."""
    text = (DATA / "p01.scene.toml").read_text().replace(
        "pose = [0.45, -0.2, 0.025, 0.3]", f"pose = [0.45, -0.2, {0.025 - sink}, 0.3]")
    path = tmp_path / "p01.scene.toml"
    path.write_text(text)
    if not refused:
        load_checked(path, domain, problem)
        return
    with pytest.raises(SceneError) as info:
        load_checked(path, domain, problem)
    assert info.value.key == "objects.pose" and "overlaps 'table'" in info.value.message
    assert info.value.line == text.splitlines().index(
        f"pose = [0.45, -0.2, {0.025 - sink}, 0.3]") + 1


def test_planar_robot_scene(tmp_path, domain, problem):
    path = tmp_path / "planar.scene.toml"
    path.write_text(
        '[robot]\nmodel = "planar"\nbase = [0.0, 0.0, 0.025]\nradius = 0.04\n'
        '[[objects]]\nname = "table"\nshape = "box"\nsize = [2.0, 2.0, 0.02]\n'
        'pose = [0.0, 0.0, -0.01]\nfixed = true\n'
        '[[objects]]\nname = "a"\nshape = "cylinder"\nsize = [0.03, 0.05]\n'
        'pose = [0.3, 0.3, 0.025]\n'
        '[[objects]]\nname = "b"\nshape = "sphere"\nsize = [0.025]\npose = [-0.3, 0.3, 0.025]\n'
        '[[regions]]\nname = "goal"\non = "table"\ncenter = [0.5, -0.5]\nsize = [0.2, 0.2]\n')
    scene = load_checked(path, domain, problem)
    assert scene.robot.model == "planar" and scene.robot.radius == 0.04
    # Starting inside the cylinder is a collision at the start.
    path.write_text(path.read_text().replace("base = [0.0, 0.0, 0.025]",
                                             "base = [0.3, 0.3, 0.025]"))
    with pytest.raises(SceneError) as info:
        load_checked(path, domain, problem)
    assert info.value.key == "robot.start" and "planar_body" in info.value.message
    assert info.value.source_line == "base = [0.3, 0.3, 0.025]"


@pytest.mark.parametrize(("after", "mass", "error"), [
    ('color = "red"', "0.2", None),
    ('color = "red"', "-1", "must be positive, got -1"),
    ('color = "red"', '"heavy"', "expected a number, got 'heavy'"),
    ("fixed = true\ncolor = [0.55, 0.4, 0.3, 1.0]", "3.0", "a fixed object does not move"),
])
def test_object_mass(tmp_path, domain, problem, after, mass, error):
    """`mass` (kg, for the physics replay): a positive number, only on a movable object."""
    text = (DATA / "p01.scene.toml").read_text()
    assert after in text
    text = text.replace(after, f"{after}\nmass = {mass}", 1)
    path = tmp_path / "p01.scene.toml"
    path.write_text(text)
    if error is None:
        scene = load_scene(path, domain, problem)
        assert scene.body("a").mass == pytest.approx(0.2) and scene.body("b").mass is None
        return
    with pytest.raises(SceneError) as info:
        load_scene(path, domain, problem)
    assert info.value.key == "objects.mass" and error in info.value.message
    assert info.value.line == text.splitlines().index(f"mass = {mass}") + 1


@pytest.mark.parametrize(("pose", "error"), [
    ("[0.45, -0.2, 0.025, 0.3]", None),  # turned about z only
    ("[0.45, -0.2, 0.025, 1.5708, 0.0, 0.0]", "'a' is tilted 90.0 deg"),  # lying on its side
    ("[0.45, -0.2, 0.025, 3.1416, 0.0, 0.0]", "'a' is tilted 180.0 deg"),  # upside down
])
def test_a_movable_object_must_start_upright(tmp_path, domain, problem, pose, error):
    """Grips are built in the object's frame and every placement is upright: a lying
    movable body was gripped through itself, or refused as too wide (a false proof)."""
    text = (DATA / "p01.scene.toml").read_text()
    old = "pose = [0.45, -0.2, 0.025, 0.3]"
    assert old in text
    text = text.replace(old, f"pose = {pose}", 1)
    path = tmp_path / "p01.scene.toml"
    path.write_text(text)
    if error is None:
        load_scene(path, domain, problem)
        return
    with pytest.raises(SceneError) as info:
        load_scene(path, domain, problem)
    assert info.value.key == "objects.pose" and error in info.value.message
    assert "must start upright" in info.value.message
