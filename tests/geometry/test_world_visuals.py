"""A World loaded without its visual shapes (what solve, validate and the physics
replay load) measures the robot and the scene as the one that renders does."""

import dataclasses
from xml.etree import ElementTree

import numpy as np
import pytest

from tampcli.errors import SceneError
from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.urdf_file import without_visuals
from tampcli.geometry.world import World

from .worlds import kuka_scene, panda_scene, planar_scene


@pytest.mark.parametrize("make", [panda_scene, kuka_scene], ids=["panda", "kuka"])
def test_a_world_without_visuals_has_the_same_robot_bodies_and_distances(make):
    scene = make()
    with World(scene) as full, World(scene, visuals=False) as bare:
        assert full.visuals and not bare.visuals
        assert bare.joint_names == full.joint_names
        assert bare.link_names == full.link_names
        for name in ("lower", "upper", "start"):
            np.testing.assert_array_equal(getattr(bare, name), getattr(full, name))
        np.testing.assert_allclose(bare.bounds(), full.bounds(), atol=1e-9)
        qs = np.random.default_rng(3).uniform(full.lower, full.upper, (20, full.n))
        np.testing.assert_allclose(bare.chain.fk_batch(qs), full.chain.fk_batch(qs), atol=1e-12)
        found = [CollisionChecker(w).distances_many(qs, activation=0.2) for w in (full, bare)]
        pairs = [[sorted((c.a, c.b, round(c.distance, 9)) for c in row) for row in f]
                 for f in found]
        assert pairs[0] == pairs[1]
        assert sum(len(row) for row in pairs[0]) > 20  # the arms come near something


def test_without_visuals_keeps_links_joints_and_collisions():
    import pybullet_data

    text = open(f"{pybullet_data.getDataPath()}/franka_panda/panda.urdf").read()
    before, after = ElementTree.fromstring(text), ElementTree.fromstring(without_visuals(text))
    assert len(before.findall("link/visual")) > 5 and not after.findall("link/visual")
    for tag in ("link", "joint", "link/collision", "link/inertial"):
        assert len(after.findall(tag)) == len(before.findall(tag)) > 0


def test_a_missing_visual_mesh_is_refused_with_or_without_visuals(tmp_path):
    urdf = tmp_path / "thing.urdf"
    urdf.write_text(
        "<robot name='thing'>\n<link name='base'>\n"
        "<visual><geometry><mesh filename='nowhere.obj'/></geometry></visual>\n"
        "<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>\n"
        "</link></robot>")
    scene = planar_scene()
    thing = dataclasses.replace(scene.bodies[0], name="thing", shape="urdf", urdf=str(urdf))
    scene = dataclasses.replace(scene, bodies=scene.bodies + (thing,))
    messages = []
    for visuals in (True, False):
        with pytest.raises(SceneError) as info:
            World(scene, visuals=visuals)
        assert info.value.key == "objects.urdf" and "nowhere.obj" in info.value.message
        messages.append(info.value.message)
    assert messages[0] == messages[1]  # the same line of the file, however it is loaded
