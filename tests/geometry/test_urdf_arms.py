"""A researcher's own URDF arm, as problems/blind28 brought two (written from the docs
alone): its file found beside the scene whatever the working folder, its cylinder
links in the collision model, and no reach ball where a track carries the arm."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.geometry.reach import reach_ball
from tampcli.geometry.scene_parse import build_scene
from tampcli.geometry.tomlsrc import read_toml
from tampcli.geometry.world import World

ROOT = Path(__file__).resolve().parents[2]
OWN_ARM = ROOT / "problems" / "blind28" / "p05"  # six revolute joints, boxes and cylinders
TRACK = ROOT / "problems" / "blind28" / "p06"  # the same kind of arm on a 1.5 m track


@pytest.mark.parametrize("where", ["root", "folder"])
def test_a_relative_urdf_is_read_beside_the_scene(monkeypatch, where):
    """Before: the scene's folder as the command line gave it, joined to the URDF's
    name, was looked for inside pybullet_data (`cannot read .../pybullet_data/problems/
    blind28/p05/b28arm.urdf`); tests had only used absolute paths."""
    if where == "root":
        monkeypatch.chdir(ROOT)
        scene = "problems/blind28/p05/p05.scene.toml"
    else:
        monkeypatch.chdir(OWN_ARM)
        scene = "p05.scene.toml"
    with World(build_scene(read_toml(scene))) as world:
        assert "hand" in world.chain.index  # the file's own links
        assert world.joint_names == tuple(f"joint{i}" for i in range(1, 7))


def test_cylinder_links_are_in_the_collision_model():
    """PyBullet turns a URDF <cylinder> into a mesh named 'unknown_file' unless asked
    not to, and that mesh was skipped: the base, link1 and link4 had no shape at all."""
    with World(build_scene(read_toml(str(OWN_ARM / "p05.scene.toml")))) as world:
        shapes = {name: world.robot_link_shapes(world.chain.index[name])
                  for name in ("base_link", "link1", "link4", "link2")}
        assert [s.kind for s in shapes["link2"]] == ["box"]
        for name, (radius, height, z) in {"base_link": (0.07, 0.10, 0.05),
                                          "link1": (0.055, 0.12, 0.06),
                                          "link4": (0.035, 0.04, 0.02)}.items():
            (shape,) = shapes[name]
            assert shape.kind == "cylinder"
            assert shape.size == pytest.approx((radius, height))
            assert shape.local[:3, 3] == pytest.approx((0.0, 0.0, z))


def test_an_arm_on_a_track_has_no_reach_ball():
    """The ball was centred on the arm's shoulder where the carriage starts (1.12 m),
    so a part 0.35 m from the shoulder with the carriage at the track's far end was
    'proved' out of reach and the task reported unsolvable."""
    with World(build_scene(read_toml(str(TRACK / "p06.scene.toml")))) as world:
        assert reach_ball(world) is None
        start = world.tool_pose(world.start)[:3, 3]
        moved = np.array(world.start, dtype=float)
        moved[0] = world.upper[0]  # the carriage at the far end of its track
        far = world.tool_pose(moved)[:3, 3]
        assert np.linalg.norm(far - start) > 1.0


def test_check_reports_the_grippers_opening_and_fingertip_depth():
    """robots.md names the two figures a new tool frame is checked by; blind28 found
    no command that printed them."""
    from tampcli.geometry.report import scene_summary
    from tampcli.pddl import parser

    domain = parser.parse_domain_file(OWN_ARM / "domain.pddl")
    problem = parser.parse_problem_file(OWN_ARM / "p05.pddl")
    robot = scene_summary(domain, problem, OWN_ARM / "p05.pddl")["robot"]
    assert robot["gripper_opening"] == pytest.approx(0.08, abs=0.002)
    assert 0.0 < robot["fingertip_depth"] < 0.03


def test_a_held_mesh_of_several_convex_parts_is_measured_as_where_it_rests():
    """blind29 p03: the SCARA (or the Panda) holding pybullet_data's duck, a mesh of
    several convex parts: the hull screen indexed the held boxes by part and crashed
    (IndexError, exit 70). Held, the duck keeps the distances it has set down at the
    same pose (the bodies' code path)."""
    from tampcli.geometry import transforms
    from tampcli.geometry.collision import CollisionChecker

    folder = ROOT / "problems" / "blind29" / "p03"
    with World(build_scene(read_toml(str(folder / "p03.scene.toml")))) as world:
        checker = CollisionChecker(world)
        assert len(checker._held("duck").parts) > 1
        rng = np.random.default_rng(3)
        compared = 0
        for _ in range(5):
            q = rng.uniform(world.lower, world.upper)
            tool = world.tool_pose(q)
            grasp = transforms.pose(None, (0.0, 0.0, -0.05))
            held = checker.distances(q, held=("duck", grasp), activation=0.5)
            rest = checker.distances(q, body_poses={"duck": tool @ grasp}, activation=0.5,
                                     static=True)
            by_held = {}
            for c in held:
                if c.a == "held:duck":
                    by_held[c.b] = min(by_held.get(c.b, np.inf), c.distance)
            by_rest = {}
            for c in rest:
                if "body:duck" in (c.a, c.b):
                    other = c.b if c.a == "body:duck" else c.a
                    by_rest[other] = min(by_rest.get(other, np.inf), c.distance)
            for other, d in by_held.items():
                if other in by_rest:
                    assert d == pytest.approx(by_rest[other], abs=1e-5), other
                    compared += 1
        assert compared >= 5


def test_check_shows_the_masses_a_scene_gives():
    """blind29 p05 (a seesaw whose balance the masses decide): `check` showed none."""
    from tampcli.geometry.report import scene_summary
    from tampcli.pddl import parser

    folder = ROOT / "problems" / "blind29" / "p05"
    domain = parser.parse_domain_file(folder / "domain.pddl")
    problem = parser.parse_problem_file(folder / "p05.pddl")
    bodies = {b["name"]: b for b in scene_summary(domain, problem, folder / "p05.pddl")["bodies"]}
    assert bodies["heavy"]["mass"] == pytest.approx(0.35)
    assert bodies["light"]["mass"] == pytest.approx(0.11)
    assert "mass" not in bodies["table"]
