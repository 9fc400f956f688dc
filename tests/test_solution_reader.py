"""solution_read: every shape the format allows is read, and comes out in one
canonical form; structural errors are located (file: key, expected, found)."""

import copy
import json

import pytest

from tampcli import solution
from tampcli.errors import SolutionFileError
from tampcli.solution import Phase, Solution
from tampcli.solution_read import FINGERS_OF, check_solution, read_solution

FINGER_JOINTS = FINGERS_OF["panda"]

A0 = [0.3, 0.0, 0.025, 0.0, 0.0, 0.0, 1.0]  # cube a on the table
A1 = [0.3, 0.1, 0.025, 0.0, 0.0, 0.0, 1.0]  # ... carried part way
A2 = [0.3, 0.3, 0.025, 0.0, 0.0, 0.0, 1.0]  # ... in the goal region
PLAN = ["(pick a table)", "(place a goal)"]


def planar(trajectory, phases, poses) -> dict:
    """A hand-written planar solution: `phases` as (action, start, end, attached)."""
    return {
        "version": 1, "domain": "d.pddl", "problem": "p.pddl", "scene": "p.scene.toml",
        "modes": None, "status": "solved", "reason": None, "plan": list(PLAN),
        "symbolic_cost": 2.0, "cost": 1.0, "objective": 3.0, "symbolic_weight": 1.0,
        "lower_bound": 1.0, "gap": (3.0 - 1.0) / 3.0,
        "robot": {"model": "planar", "joints": ["x", "y"], "tool_link": "planar_body"},
        "trajectory": [list(map(float, q)) for q in trajectory],
        "phases": [{"action": a, "start": s, "end": e, "attached": h} for a, s, e, h in phases],
        "objects": {"a": [list(p) for p in poses]},
        "skeletons": [], "stats": {}, "kkt": {},
        "grasps": [{"action": PLAN[0], "object": "a", "family": "suction",
                    "contact_angle": 0.5}],
    }


def line(n: int, x0: float = 0.0) -> list[list[float]]:
    return [[x0 + 0.1 * i, 0.0] for i in range(n)]


SOLVE_SHAPE = planar(line(5), [(None, 0, 2, None), (PLAN[0], 2, 2, "a"), (None, 2, 4, "a"),
                               (PLAN[1], 4, 4, None)], [A0, A0, A0, A2, A2])


def read(tmp_path, data) -> object:
    path = tmp_path / "solution.json"
    path.write_text(json.dumps(data))
    return read_solution(path)


def fails(tmp_path, data, key, *words) -> str:
    path = tmp_path / "solution.json"
    path.write_text(json.dumps(data))
    with pytest.raises(SolutionFileError) as info:
        read_solution(path)
    text = info.value.render()
    assert text.startswith(f"{path}: {key}: "), text
    for word in words:
        assert word in text, text
    return text


def test_what_solve_writes_round_trips_and_is_already_canonical(tmp_path):
    written = read(tmp_path, SOLVE_SHAPE).raw
    path = tmp_path / "again.json"
    solution.write(written, path)
    assert json.loads(path.read_text()) == SOLVE_SHAPE
    checked = read_solution(path)
    assert checked.raw == written and checked.canonical == written
    assert checked.boundaries == (0, 1, 2, 3, 4) and checked.fingers is None
    assert checked.retreat is None


def test_grasps_are_optional_and_a_list_of_objects(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    assert read(tmp_path, data).raw.grasps[0]["contact_angle"] == 0.5
    del data["grasps"]  # a file another planner wrote
    assert read(tmp_path, data).raw.grasps == ()
    data["grasps"] = {"(pick a)": "top"}
    fails(tmp_path, data, "grasps", "expected a list of objects")


def test_three_motions_between_two_actions_are_one(tmp_path):
    data = planar(line(7), [(None, 0, 2, None), (PLAN[0], 2, 2, "a"), (None, 2, 3, "a"),
                            (None, 3, 5, "a"), (None, 5, 6, "a"), (PLAN[1], 6, 6, None)],
                  [A0, A0, A0, A1, A1, A2, A2])
    checked = read(tmp_path, data)
    assert checked.canonical.phases == (Phase(None, 0, 2), Phase(PLAN[0], 2, 2, "a"),
                                        Phase(None, 2, 6, "a"), Phase(PLAN[1], 6, 6))
    assert checked.boundaries == (0, 1, 2, 5, 6)
    assert checked.canonical.objects == {"a": [A0, A0, A0, A2, A2]}
    assert checked.canonical.trajectory == checked.raw.trajectory
    assert checked.raw.phases[3] == Phase(None, 3, 5, "a")  # the file as written stays


def test_zero_motions_between_two_actions(tmp_path):
    data = planar(line(3), [(PLAN[0], 0, 0, "a"), (PLAN[1], 0, 0, None),
                            (None, 0, 2, None)], [A0, A0, A0, A0])
    checked = read(tmp_path, data)
    assert [p.action for p in checked.canonical.phases] == [PLAN[0], PLAN[1], None]
    assert checked.retreat == Phase(None, 0, 2)


def test_motions_after_the_last_action_are_one_retreat(tmp_path):
    data = planar(line(6), [(None, 0, 1, None), (PLAN[0], 1, 1, "a"), (None, 1, 2, "a"),
                            (PLAN[1], 2, 2, None), (None, 2, 4, None), (None, 4, 5, None)],
                  [A0, A0, A0, A2, A2, A2, A2])
    checked = read(tmp_path, data)
    assert checked.retreat == Phase(None, 2, 5)
    assert checked.canonical.phases[-1] is checked.retreat
    assert checked.boundaries == (0, 1, 2, 3, 4, 6)


def test_a_motion_before_the_first_action_is_no_retreat(tmp_path):
    data = planar(line(2), [(None, 0, 1, None), (PLAN[0], 1, 1, "a"), (PLAN[1], 1, 1, None)],
                  [A0] * 4)
    assert read(tmp_path, data).retreat is None


def panda_with_fingers(order) -> dict:
    """A Panda solution whose waypoints hold the arm and both fingers, in `order`."""
    arm = [f"panda_joint{i}" for i in range(1, 8)]
    rows = []
    for i in range(5):
        value = {name: 0.1 * k + 0.01 * i for k, name in enumerate(arm)}
        value.update({FINGER_JOINTS[0]: 0.04 - 0.005 * i, FINGER_JOINTS[1]: 0.03})
        rows.append([value[name] for name in order])
    data = copy.deepcopy(SOLVE_SHAPE)
    data["robot"] = {"model": "panda", "joints": list(order), "tool_link": "panda_grasptarget"}
    data["trajectory"] = rows
    return data


@pytest.mark.parametrize("order", [
    tuple(f"panda_joint{i}" for i in range(1, 8)) + FINGER_JOINTS,
    (FINGER_JOINTS[1],) + tuple(f"panda_joint{i}" for i in range(1, 8)) + (FINGER_JOINTS[0],),
])
def test_finger_columns_are_the_finger_opening(tmp_path, order):
    checked = read(tmp_path, panda_with_fingers(order))
    assert checked.canonical.robot["joints"] == [f"panda_joint{i}" for i in range(1, 8)]
    assert checked.canonical.trajectory[2] == tuple(0.1 * k + 0.02 for k in range(7))
    assert checked.fingers == tuple((0.04 - 0.005 * i, 0.03) for i in range(5))
    assert checked.raw.robot["joints"] == list(order)
    assert len(checked.raw.trajectory[0]) == 9


def test_one_finger_column_stands_for_both(tmp_path):
    data = panda_with_fingers(tuple(f"panda_joint{i}" for i in range(1, 8)) + FINGER_JOINTS)
    data["robot"]["joints"].pop()
    data["trajectory"] = [q[:8] for q in data["trajectory"]]
    checked = read(tmp_path, data)
    assert checked.fingers[1] == (0.035, 0.035)
    assert len(checked.canonical.trajectory[0]) == 7


def test_the_finger_names_are_the_worlds():
    from tampcli.geometry.world import PANDA_FINGERS

    assert FINGER_JOINTS == PANDA_FINGERS
    assert FINGERS_OF["kuka_iiwa"] == ("gripper_left_joint",)
    assert FINGERS_OF["xarm6"] == ("drive_joint",)


def test_another_arms_finger_column(tmp_path):
    """The xArm6's one named finger joint (five more mimic it: the World adds them)."""
    data = copy.deepcopy(SOLVE_SHAPE)
    arm = [f"joint{i}" for i in range(1, 7)]
    data["robot"] = {"model": "xarm6", "joints": [*arm, "drive_joint"],
                     "tool_link": "xarm_gripper_base_link"}
    data["trajectory"] = [[0.1 * k for k in range(6)] + [0.2 + 0.1 * i] for i in range(5)]
    checked = read(tmp_path, data)
    assert checked.fingers == tuple((0.2 + 0.1 * i,) for i in range(5))
    assert checked.canonical.robot["joints"] == arm
    data["robot"]["joints"][-1] = "panda_finger_joint1"
    fails(tmp_path, data, "robot.joints", "'panda_finger_joint1' is a finger joint of the Panda",
          "'xarm6'")


def test_an_in_memory_solution_gets_the_same_checks():
    sol = Solution("d", "p", None, "solved", plan=("(a)",), robot={"joints": ["x"]},
                   trajectory=((0.0,), (1.0,)), phases=(Phase("(a)", 0, 0), Phase(None, 1, 1)),
                   objects={})
    with pytest.raises(SolutionFileError, match="starts at 1, expected 0") as info:
        check_solution(sol)
    assert info.value.key == "phases[1].start" and info.value.path == "<solution>"


# -- structural errors ------------------------------------------------------------


def test_a_gap_between_phases(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    data["phases"][2]["start"] = 3
    fails(tmp_path, data, "phases[2].start", "starts at 3, expected 2",
          "where the previous one ended (phases[1].end)")


def test_overlapping_motions(tmp_path):
    data = planar(line(5), [(None, 0, 2, None), (None, 1, 2, None), (PLAN[0], 2, 2, "a"),
                            (None, 2, 4, "a"), (PLAN[1], 4, 4, None)], [A0] * 4 + [A2] * 2)
    fails(tmp_path, data, "phases[1].start", "starts at 1, expected 2")


def test_phases_that_stop_short_of_the_last_waypoint(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    data["trajectory"].append([0.5, 0.0])
    fails(tmp_path, data, "phases[3].end", "ends at 4, expected 5", "last waypoint")


@pytest.mark.parametrize("count", [4, 6])
def test_wrong_pose_count(tmp_path, count):
    data = copy.deepcopy(SOLVE_SHAPE)
    data["objects"]["a"] = [A0] * count
    fails(tmp_path, data, "objects.a", "expected 5 poses", f"found {count}")


def test_wrong_pose_count_with_split_motions(tmp_path):
    """Split motions add boundaries: a pose for each, not one per merged motion."""
    data = planar(line(5), [(None, 0, 1, None), (None, 1, 2, None), (PLAN[0], 2, 2, "a"),
                            (None, 2, 4, "a"), (PLAN[1], 4, 4, None)], [A0, A0, A0, A2, A2])
    fails(tmp_path, data, "objects.a", "expected 6 poses", "found 5")


def test_a_finger_joint_on_a_robot_without_fingers(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    data["robot"]["joints"] = ["x", "panda_finger_joint1"]
    fails(tmp_path, data, "robot.joints", "'panda_finger_joint1' is a finger joint of the Panda",
          "'planar'")


def test_joint_names_and_columns_disagree(tmp_path):
    data = panda_with_fingers(tuple(f"panda_joint{i}" for i in range(1, 8)) + FINGER_JOINTS)
    data["robot"]["joints"].pop()
    fails(tmp_path, data, "robot.joints", "8 joint names for waypoints of 9 values")


def test_a_joint_named_twice(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    data["robot"]["joints"] = ["x", "x"]
    fails(tmp_path, data, "robot.joints", "joint 'x' named twice")


def test_action_phases_follow_the_plan(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    data["phases"][1]["action"] = "(place a goal)"
    fails(tmp_path, data, "phases[1].action", "expected '(pick a table)' (plan[0])",
          "found '(place a goal)'")
    data = copy.deepcopy(SOLVE_SHAPE)
    data["phases"][3].update(action=None, attached="a")
    fails(tmp_path, data, "phases", "none for '(place a goal)'")


def test_action_phases_match_the_plan_up_to_case_and_spaces(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    data["phases"][1]["action"] = "( PICK  a table )"
    assert read(tmp_path, data).canonical.phases[1].action == "( PICK  a table )"


def test_motions_in_one_gap_carry_one_object(tmp_path):
    data = planar(line(5), [(None, 0, 2, None), (PLAN[0], 2, 2, "a"), (None, 2, 3, "a"),
                            (None, 3, 4, None), (PLAN[1], 4, 4, None)], [A0] * 4 + [A2] * 2)
    fails(tmp_path, data, "phases[3].attached", "expected 'a' as in phases[2]", "found None")


def test_missing_key(tmp_path):
    data = copy.deepcopy(SOLVE_SHAPE)
    del data["phases"]
    fails(tmp_path, data, "phases", "missing key")
