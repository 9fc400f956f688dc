"""`validate` on real `solve` output reshaped into the other shapes solution.json
allows: the verdict stays that of the trajectory, not of its layout."""

import json
import subprocess
import sys

import numpy as np
import pytest

from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tests.conftest import ROOT
from tests.solution_shapes import add_fingers, add_retreat, arm_only, split_motion

ARM = ROOT / "domains" / "arm-pick-place" / "domain.pddl"
ARM1 = ROOT / "problems" / "arm-pick-place" / "p01.pddl"
TAMP = ROOT / "domains" / "planar-tamp" / "domain.pddl"
TAMP3 = ROOT / "problems" / "planar-tamp" / "p03.pddl"


def solve(domain, problem, out) -> dict:
    subprocess.run([sys.executable, "-m", "tampcli", "solve", str(domain), str(problem),
                    "--out", str(out), "--time-limit", "120", "--quiet"],
                   check=True, capture_output=True, timeout=300, cwd=ROOT)
    data = json.loads(out.read_text())
    assert data["status"] == "solved"
    for key in ("domain", "problem", "scene", "modes"):
        if data[key] is not None:
            data[key] = str((ROOT / data[key]).resolve())
    return data


@pytest.fixture(scope="module")
def written(tmp_path_factory) -> dict:
    """pick a, place a, as solve writes it (the hand open: optimize/hand.py)."""
    data = solve(ARM, ARM1, tmp_path_factory.mktemp("arm") / "p01.json")
    assert [(p["action"], p["start"], p["end"]) for p in data["phases"]] == [
        (None, 0, 10), ("(pick a start)", 10, 10), (None, 10, 20), ("(place a goal)", 20, 20)]
    return data


@pytest.fixture(scope="module")
def arm(written):
    """motion 0-10, pick, carry 10-20, place, without finger columns (the fingers
    then open, closed on a from the pick to the place)."""
    with World(load_scene(written["scene"], geometric=False)) as world:
        yield arm_only(written), world


@pytest.fixture
def validate(cli, tmp_path):
    def run(data, domain=ARM, problem=ARM1):
        path = tmp_path / "solution.json"
        path.write_text(json.dumps(data))
        return path, cli("validate", domain, problem, path)

    return run


def valid(run) -> None:
    path, result = run
    assert result.code == 0, result.out + result.err
    assert result.out.startswith("valid, cost 2")


def test_as_solved(arm, validate):
    valid(validate(arm[0]))


def test_a_motion_split_in_two_at_a_waypoint(arm, validate):
    data, world = arm
    valid(validate(split_motion(data, 0, 5, world)))


def test_three_motions_carrying_between_pick_and_place(arm, validate):
    data, world = arm
    three = split_motion(split_motion(data, 2, 13, world), 3, 16, world)
    assert [p["action"] for p in three["phases"]].count(None) == 4
    valid(validate(three))


def test_inside_a_split_motion_the_held_object_keeps_its_grasp(arm, validate):
    data, world = arm
    split = split_motion(data, 2, 13, world)
    split["objects"]["a"][3][2] += 0.05  # the boundary at waypoint 13: 5 cm off the tool
    _, run = validate(split)
    assert run.code == 1
    assert "phases[2] (waypoint 13): a moves relative to the tool (5.0 cm)" in run.out


def test_inside_a_split_motion_what_is_not_held_stays(arm, validate):
    data, world = arm
    split = split_motion(data, 0, 5, world)
    split["objects"]["a"][1][0] += 0.02
    _, run = validate(split)
    assert run.code == 1
    assert "phases[0] (waypoint 5): a moves but is not attached (2.0 cm)" in run.out


def starting_at_the_grasp(data) -> dict:
    """No motion before the pick: the trajectory starts where the robot grasps."""
    out = dict(data, trajectory=data["trajectory"][10:],
               phases=[{"action": "(pick a start)", "start": 0, "end": 0, "attached": "a"},
                       {"action": None, "start": 0, "end": 10, "attached": "a"},
                       {"action": "(place a goal)", "start": 10, "end": 10, "attached": None}],
               objects={"a": data["objects"]["a"][1:]})
    return json.loads(json.dumps(out))


def test_zero_motions_before_an_action(arm, validate):
    valid(validate(starting_at_the_grasp(arm[0])))


def test_zero_motions_keep_the_files_waypoint_numbers(arm, validate):
    data = starting_at_the_grasp(arm[0])
    data["trajectory"][4][3] = 0.5  # panda_joint4's upper limit is 0
    _, run = validate(data)
    assert run.code == 1
    assert "waypoint 4: joint panda_joint4 = 0.5000 outside" in run.out


def lift(data, world, heights) -> list:
    """Waypoints moving the tool straight up (or down) from the last one."""
    q = np.array(data["trajectory"][-1])
    top, out = world.tool_pose(q), []
    for dz in heights:
        target = top.copy()
        target[2, 3] += dz
        q, residual = world.ik(target, q)
        assert residual < 1e-4
        out.append(q)
    return out


def test_a_retreat_after_the_last_action(arm, validate):
    data, world = arm
    valid(validate(add_retreat(data, lift(data, world, (0.03, 0.06, 0.1)))))


def test_a_retreat_is_checked_for_collisions(arm, validate):
    data, world = arm
    _, run = validate(add_retreat(data, lift(data, world, (-0.05, -0.1))))
    assert run.code == 1
    assert "the motion after (place a goal): collision panda_hand vs a" in run.out


def opening(i: int) -> float:
    # Closed on the 5 cm cube while carrying; open at waypoint 10, which ends the
    # motion down to the cube too (the fingers close after it: closed there, they
    # would touch the cube before it is held).
    return 0.025 if 10 < i < 20 else 0.04


def test_the_open_hand_leaves_the_finger_columns_out(written):
    """The open hand solves pick-place p01: the file leaves the fingers out (open
    unless closed on what is held), as it did before hands were narrowed."""
    assert not any("finger" in name for name in written["robot"]["joints"])


def test_as_solved_with_its_finger_columns(tmp_path, validate):
    """blind12 p01: a 2.2 cm slab 5.6 cm from a wall, which the open hand cannot pick;
    narrowed to it and 6 mm a side, solve writes the Panda's two finger columns."""
    domain = ROOT / "problems" / "blind12" / "p01" / "domain.pddl"
    problem = domain.with_name("p01.pddl")
    data = solve(domain, problem, tmp_path / "p01.json")
    joints = data["robot"]["joints"]
    assert joints[-2:] == ["panda_finger_joint1", "panda_finger_joint2"]
    fingers = np.array([q[-2:] for q in data["trajectory"]])
    grasp, place = (p["end"] for p in data["phases"] if p["action"] is not None)
    # Opened 3.4 cm (1.7 cm a finger and the pads' 1.1 mm), not fully (4 cm); closed
    # on the slab (1.1 cm a finger and the pads) from the pick's waypoint to the place's.
    assert np.allclose(fingers[:grasp], fingers[0]) and 0.017 < fingers[0, 0] < 0.019
    assert np.allclose(fingers[grasp:place + 1], fingers[grasp])
    assert 0.011 < fingers[grasp, 0] < 0.013
    valid(validate(data, domain, problem))


def test_finger_columns(arm, validate):
    data, _ = arm
    order = ("panda_finger_joint2",) + tuple(data["robot"]["joints"]) + ("panda_finger_joint1",)
    valid(validate(add_fingers(data, opening, order)))


def test_finger_columns_beyond_the_fingers_travel(arm, validate):
    data, _ = arm
    _, run = validate(add_fingers(data, lambda i: 0.05 if i == 3 else opening(i)))
    assert run.code == 1
    assert "waypoint 3: finger joint panda_finger_joint1 = 0.0500 outside [0, 0.04]" in run.out


def test_finger_columns_are_where_the_collision_check_puts_the_fingers(arm, validate):
    """Closed on nothing on the way down to a (the fingers meet where the 5 cm cube
    will be), they go into it at the grasp: open, the same trajectory is valid."""
    data, _ = arm
    _, run = validate(add_fingers(data, lambda i: 0.0 if i <= 10 else opening(i)))
    assert run.code == 1
    assert "motion 0 before (pick a start): collision panda_" in run.out
    assert "finger vs a" in run.out


def test_an_unknown_joint_is_bad_input(arm, validate):
    data = json.loads(json.dumps(arm[0]))
    data["robot"]["joints"][6] = "panda_joint8"
    path, run = validate(data)
    assert run.code == 2
    assert f"{path}: robot.joints: unknown joint 'panda_joint8'" in run.err
    assert "panda_finger_joint1" in run.err  # the names it could have used


def test_phases_that_do_not_meet_are_bad_input(arm, validate):
    data, world = arm
    split = split_motion(data, 0, 5, world)
    split["phases"][1]["start"] = 6
    path, run = validate(split)
    assert run.code == 2
    assert f"{path}: phases[1].start: starts at 6, expected 5" in run.err
    assert "Traceback" not in run.err


def test_wrong_pose_count_is_bad_input(arm, validate):
    data, world = arm
    split = split_motion(data, 0, 5, world)
    split["objects"]["a"].pop()
    path, run = validate(split)
    assert run.code == 2
    assert f"{path}: objects.a: expected 6 poses" in run.err and "found 5" in run.err


def test_a_symbolic_action_between_two_motions(tmp_path, validate):
    """planar-tamp p03: place a stove, cook a, pick a; here the robot moves before
    and after the cook, two motions where the plan has one."""
    data = solve(TAMP, TAMP3, tmp_path / "p03.json")
    actions = [(p["action"], p["start"], p["end"]) for p in data["phases"]]
    assert actions[3:6] == [("(place a stove)", 20, 20), ("(cook a stove)", 20, 20),
                            (None, 20, 30)]
    with World(load_scene(data["scene"], geometric=False)) as world:
        split = split_motion(data, 5, 25, world)
    cook, first = split["phases"][4], split["phases"][5]
    split["phases"][4] = dict(first, start=20, end=25)
    split["phases"][5] = dict(cook, start=25, end=25)
    path, run = validate(split, TAMP, TAMP3)
    assert run.code == 0, run.out + run.err
    assert run.out.startswith("valid, cost 5")
