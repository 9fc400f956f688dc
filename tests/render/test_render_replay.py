"""Replay timing and states, on hand-made solutions with the real Panda kinematics."""

import numpy as np
import pytest
from render_solutions import PANDA, panda_solution, planar_solution

from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.render.replay import Replay, schema_of


@pytest.fixture(scope="module")
def panda():
    sol = panda_solution(with_note=True)
    world = World(load_scene(PANDA / "p01.scene.toml", geometric=False))
    yield sol, world
    world.close()


def test_schema_of():
    assert schema_of("(pick a table)") == "pick"
    assert schema_of("( Place a goal )") == "place"


def test_frame_count_and_ends(panda):
    sol, world = panda
    replay = Replay(sol, world.tool_pose, duration=2.0, pause=0.25)
    # four pauses (start, pick, place, note, end = 5) plus two seconds of motion
    assert replay.duration == pytest.approx(2.0 + 5 * 0.25)
    states = replay.states(10)
    assert len(states) == replay.frame_count(10) == round(replay.duration * 10) + 1
    np.testing.assert_allclose(states[0].q, sol.trajectory[0])
    np.testing.assert_allclose(states[-1].q, sol.trajectory[-1])
    assert states[0].label == "start" and states[-1].label == "done"
    assert states[-1].step == states[-1].steps == 3


def test_motion_speed_is_even_in_joint_space(panda):
    sol, world = panda
    replay = Replay(sol, world.tool_pose, duration=3.0, pause=0.0)
    q = np.array([s.q for s in replay.states(50)])
    steps = np.linalg.norm(np.diff(q, axis=0), axis=1)
    moving = steps[steps > 1e-9]
    # Waypoints are unevenly spaced (segments of different lengths); frames are not.
    assert moving.max() / np.median(moving) < 1.05
    waypoint_steps = np.linalg.norm(np.diff(np.array(sol.trajectory), axis=0), axis=1)
    assert waypoint_steps.max() / np.median(waypoint_steps) > 1.5


def test_pause_at_each_instantaneous_action(panda):
    sol, world = panda
    replay = Replay(sol, world.tool_pose, duration=2.0, pause=0.5)
    states = replay.states(20)
    labels = [s.label for s in states]
    for action in sol.plan:
        held = [s for s in states if s.label == action]
        assert 8 <= len(held) <= 11, (action, len(held))
        assert all(np.allclose(s.q, held[0].q) for s in held)
    assert labels.index("(pick a table)") < labels.index("carry a") < labels.index(
        "(place a goal)")


def test_held_object_follows_the_tool(panda):
    sol, world = panda
    replay = Replay(sol, world.tool_pose, duration=2.0)
    carrying = [s for s in replay.states(20) if s.label == "carry a"]
    assert len(carrying) > 5
    grasp = np.linalg.inv(carrying[0].poses["a"]) @ world.tool_pose(np.array(carrying[0].q))
    for s in carrying:
        relative = np.linalg.inv(s.poses["a"]) @ world.tool_pose(np.array(s.q))
        np.testing.assert_allclose(relative, grasp, atol=1e-9)
        np.testing.assert_allclose(s.poses["b"], world.body_pose("b"), atol=1e-9)
        assert s.fingers_closed and s.held == "a"
    # the carry ends exactly where the plan puts the cube down
    place = next(s for s in replay.states(20) if s.label == "(place a goal)")
    relative = np.linalg.inv(place.poses["a"]) @ world.tool_pose(np.array(place.q))
    np.testing.assert_allclose(relative, grasp, atol=1e-6)
    assert not replay.state_at(replay.duration).fingers_closed


def test_fingers_switch_half_way_through_a_grasp(panda):
    sol, world = panda
    replay = Replay(sol, world.tool_pose, duration=2.0, pause=0.5)
    pick = [s.fingers_closed for s in replay.states(20) if s.label == "(pick a table)"]
    assert pick[0] is False and pick[-1] is True
    place = [s.fingers_closed for s in replay.states(20) if s.label == "(place a goal)"]
    assert place[0] is True and place[-1] is False


def test_captions_count_steps(panda):
    sol, world = panda
    states = Replay(sol, world.tool_pose, duration=2.0).states(10)
    seen = {(s.label, s.step) for s in states}
    assert ("move", 1) in seen and ("(pick a table)", 1) in seen and ("carry a", 2) in seen
    assert ("(place a goal)", 2) in seen and ("(note b)", 3) in seen
    assert all(s.steps == 3 for s in states)


def test_keyframes_only_for_geometric_actions(panda):
    sol, world = panda
    replay = Replay(sol, world.tool_pose)
    assert [k.label for k in replay.keyframes()] == ["(pick a table)", "(place a goal)"]
    by_mode = Replay(sol, world.tool_pose, mode_kind=lambda a: {
        "pick": "grasp", "place": "place", "note": "move"}[schema_of(a)])
    assert len(by_mode.keyframes()) == 3


def test_push_moves_the_object_with_the_disk():
    sol = planar_solution()
    with World(load_scene(PANDA.parent / "planar" / "p01.scene.toml", geometric=False)) as world:
        replay = Replay(sol, world.tool_pose, duration=2.0)
        states = replay.states(20)
        pushing = [s for s in states if s.label == "(push box start goal)"]
        assert len(pushing) > 5
        y = [s.poses["box"][1, 3] for s in pushing]
        assert y[-1] - y[0] > 0.3 and all(b >= a for a, b in zip(y, y[1:], strict=False))
        gap = [s.poses["box"][1, 3] - s.q[1] for s in pushing]
        assert max(gap) - min(gap) < 1e-9  # a rigid push: box and disk keep their distance
        assert not any(s.fingers_closed or s.held for s in pushing)
        assert [k.label for k in replay.keyframes()] == ["(push box start goal)"]


def test_speed_and_duration_options(panda):
    sol, world = panda
    slow = Replay(sol, world.tool_pose, speed=0.5, pause=0.0)
    fast = Replay(sol, world.tool_pose, speed=1.0, pause=0.0)
    assert slow.duration == pytest.approx(2 * fast.duration)
    assert Replay(sol, world.tool_pose, duration=4.0, pause=0.0).duration == pytest.approx(4.0)


def _edit(sol, **changes):
    from tampcli.solution import Solution

    return Solution(**{**sol.__dict__, **changes})


def test_a_move_action_that_carries_holds_the_object(panda):
    from tampcli.solution import Phase

    sol, world = panda
    phases = list(sol.phases)
    carry = phases[2]
    phases[2] = Phase("(goto goal)", carry.start, carry.end, "a")
    replay = Replay(_edit(sol, phases=tuple(phases)), world.tool_pose, duration=2.0)
    going = [s for s in replay.states(20) if s.label == "(goto goal)"]
    assert len(going) > 5 and all(s.held == "a" and s.fingers_closed for s in going)


def test_ending_on_an_instantaneous_action(panda):
    sol, world = panda
    end = sol.phases[3].end  # the place
    cut = _edit(sol, phases=sol.phases[:4], trajectory=sol.trajectory[:end + 1],
                objects={k: v[:5] for k, v in sol.objects.items()})
    replay = Replay(cut, world.tool_pose, duration=2.0)
    assert not replay.state_at(replay.duration).fingers_closed
    assert any(s.fingers_closed for s in replay.states(10))


def test_finger_columns_of_a_file_drive_the_fingers(panda):
    sol, world = panda
    n = len(sol.trajectory)
    fingers = [(0.04 - 0.03 * i / (n - 1), 0.01 + 0.02 * i / (n - 1)) for i in range(n)]
    replay = Replay(sol, world.tool_pose, duration=2.0, pause=0.0, fingers=fingers)
    states = replay.states(20)
    assert states[0].fingers == pytest.approx(fingers[0])
    assert states[-1].fingers == pytest.approx(fingers[-1])
    moving = next(s for s in states if not np.allclose(s.q, sol.trajectory[0]))
    assert fingers[-1][0] <= moving.fingers[0] <= fingers[0][0]  # interpolated, in range
    assert all(k.fingers is not None for k in replay.keyframes())
    assert Replay(sol, world.tool_pose).states(5)[0].fingers is None  # the rule decides


def test_world_sets_the_fingers_it_is_given(panda):
    from tests.geometry.worlds import simulator

    sol, world = panda
    world.set_state(np.asarray(sol.trajectory[0]), fingers=(0.012, 0.031))
    sim = simulator(world)
    got = [sim.pb.getJointState(sim.robot, j, physicsClientId=sim.client)[0] for j in sim.fingers]
    assert got == pytest.approx([0.012, 0.031])


def test_a_symbolic_action_holds_what_it_held_to_its_end(panda):
    """blind6 p04: a `scan` (mode none) while holding a widget. The replay let go of it
    halfway through the scan's pause (the "after" half), and the physics replay
    dropped it onto the scanner."""
    import dataclasses

    from render_solutions import _pose

    from tampcli.geometry import transforms
    from tampcli.solution import Phase

    sol, world = panda
    pick, carry = sol.phases[1], sol.phases[2]
    mid = (carry.start + carry.end) // 2
    phases = list(sol.phases[:2]) + [
        Phase(None, carry.start, mid, "a"), Phase("(scan a)", mid, mid, "a"),
        Phase(None, mid, carry.end, "a")] + list(sol.phases[3:])
    q = np.asarray(sol.trajectory)
    grasp = transforms.pose_inverse(world.tool_pose(q[pick.end])) @ \
        transforms.pose_from_xyzquat(sol.objects["a"][2])
    at_mid = _pose(world.tool_pose(q[mid]) @ grasp)
    a = sol.objects["a"]
    b = sol.objects["b"]
    scanned = dataclasses.replace(
        sol, phases=tuple(phases), plan=[sol.plan[0], "(scan a)", *sol.plan[1:]],
        objects={"a": a[:3] + [at_mid, at_mid] + a[3:], "b": b + b[:2]})
    replay = Replay(scanned, world.tool_pose, duration=2.0, pause=0.5, mode_kind=lambda x: {
        "pick": "grasp", "place": "place", "scan": "none", "note": "none"}[schema_of(x)])
    scanning = [s for s in replay.states(40) if s.label == "(scan a)"]
    assert len(scanning) > 10
    assert all(s.held == "a" and s.fingers_closed for s in scanning)
