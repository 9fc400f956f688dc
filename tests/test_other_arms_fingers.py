"""The KUKA iiwa's and the xArm6's hands narrowed to the plan's grips, as the
Panda's is (optimize/hand.py), and their finger columns through the file.

blind12 p01 with the robot swapped: a 2.2 cm slab 5.6 cm from a wall, gripped
only across its thickness, at the wall. Fully open, each arm's fingers stand
in the wall (the KUKA's by 0.5 cm, the xArm's by 1.0 cm, measured before the
hand model covered them: no skeleton solved); narrowed, both plans solve, and
`validate`, its physics replay included, accepts the files they write. The
xArm names one finger joint (`drive_joint`) and five more mimic it: the file
gives the named one, the World adds the others.
"""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tests.conftest import ROOT

SOURCE = ROOT / "problems" / "blind12" / "p01"


def _swapped(folder, model: str):
    for name in ("domain.pddl", "modes.toml", "p01.pddl"):
        shutil.copy(SOURCE / name, folder / name)
    scene = (SOURCE / "p01.scene.toml").read_text()
    assert 'model = "panda"' in scene
    (folder / "p01.scene.toml").write_text(scene.replace('model = "panda"', f'model = "{model}"'))
    return folder / "domain.pddl", folder / "p01.pddl"


@pytest.fixture(scope="module", params=["kuka_iiwa", "xarm6"])
def solved(request, tmp_path_factory):
    from tests.test_cli_validate_shapes import solve

    folder = tmp_path_factory.mktemp(request.param)
    domain, problem = _swapped(folder, request.param)
    data = solve(domain, problem, folder / "solution.json")
    return request.param, domain, problem, folder / "solution.json", data


def test_the_plan_writes_the_named_finger_joint(solved):
    model, _, problem, _, data = solved
    with World(load_scene(problem.with_suffix(".scene.toml"), geometric=False)) as world:
        names, ((open_, closed),) = world.finger_names, world.finger_range
        assert len(names) == 1
        assert data["robot"]["joints"] == [*world.joint_names, names[0]]
        fingers = np.array([q[-1] for q in data["trajectory"]])
        grasp, place = (p["end"] for p in data["phases"] if p["action"] is not None)
        # Narrower than open before the grasp, closer still on the slab while held.
        free, held = fingers[0], fingers[grasp]
        assert np.allclose(fingers[:grasp], free) and np.allclose(fingers[grasp:place + 1], held)
        assert 0.0 < (free - open_) / (closed - open_) < (held - open_) / (closed - open_) < 1.0
        # Closed on the slab: the fingers' gap there is its 2.2 cm.
        assert world.gripper_at((held - open_) / (closed - open_))[1] == pytest.approx(
            0.022, abs=2e-3)
    (entry,) = data["grasps"]
    assert entry["faces"] == "±x" and entry["hand_opening"] < 0.08


def test_validate_and_its_physics_replay_accept_it(cli, solved):
    _, domain, problem, path, _ = solved
    run = cli("validate", "--json", "--physics", domain, problem, path)
    data = json.loads(run.out)
    assert run.code == 0, data["violations"]
    assert data["physics"]["max_distance"] < 0.01


def test_the_mimicking_joints_follow_the_named_one(tmp_path):
    _, problem = _swapped(tmp_path, "xarm6")
    with World(load_scene(problem.with_suffix(".scene.toml"), geometric=False)) as world:
        assert len(world.finger_links) == 6
        for t in (0.0, 0.3, 1.0):
            values, _, _ = world.gripper_at(t)
            assert world.finger_values(values[:1]) == pytest.approx(values, abs=1e-12)
        with pytest.raises(ValueError, match="finger values"):
            world.finger_values(values)
