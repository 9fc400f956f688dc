"""A carry's vertical ends (optimize/approach.py): a cylinder set down in a small
rimmed tray comes straight down past the rims; with nothing near, a carry is free."""

from __future__ import annotations

import shutil

import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.optimize.approach import CLEAR, RUNG, joined, lift, place_approach
from tampcli.optimize.collide import Held
from tampcli.optimize.grips import TopGrip
from tampcli.optimize.nlp import NlpOutcome

from .helpers import ROOT, lowered_folder, ops, solved_in_physics

RIM = 0.025  # m: the rims' height over the table
FLOOR = 0.01  # m: the tray floor's top
CAN = (0.022, 0.06)  # radius, height


def tray_folder(path, play: float, rims: bool = True, out: bool = False):
    """arm-pick-place with a can on the table and a square tray floor `play` wider
    than the can across (so the can, centred, stands play / 2 from each rim), its
    four rims 1.2 cm thick and 2.5 cm tall (or left out); the goal the can in the
    tray, or with `out` the can starting in the middle of the tray and the goal
    the table's spot."""
    src = ROOT / "domains" / "arm-pick-place"
    shutil.copy(src / "domain.pddl", path / "domain.pddl")
    shutil.copy(src / "modes.toml", path / "modes.toml")
    start, goal = ("tray", "start") if out else ("start", "tray")
    (path / "p.pddl").write_text(
        "(define (problem rimmed-tray) (:domain arm-pick-place)\n"
        "  (:objects can - block start tray - region)\n"
        f"  (:init (at can {start}) (clear can) (handempty))\n"
        f"  (:goal (at can {goal})))\n")
    side = 2 * CAN[0] + play
    x, y, t = 0.45, 0.25, 0.012
    parts = [("table", (1.0, 1.2, 0.04), (0.4, 0.0, -0.02)),
             ("floor", (side, side, FLOOR), (x, y, FLOOR / 2))]
    if rims:
        h, out = RIM, side / 2 + t / 2
        parts += [("rim-near", (t, side + 2 * t, h), (x - out, y, h / 2)),
                  ("rim-far", (t, side + 2 * t, h), (x + out, y, h / 2)),
                  ("rim-left", (side, t, h), (x, y + out, h / 2)),
                  ("rim-right", (side, t, h), (x, y - out, h / 2))]
    text = '[robot]\nmodel = "panda"\nbase = [0.0, 0.0, 0.0]\n'
    for name, size, pose in parts:
        text += (f'\n[[objects]]\nname = "{name}"\nshape = "box"\nsize = {list(size)}\n'
                 f'pose = {list(pose)}\nfixed = true\n')
    can = [x, y, FLOOR + CAN[1] / 2] if out else [0.55, -0.2, CAN[1] / 2]
    text += (f'\n[[objects]]\nname = "can"\nshape = "cylinder"\nsize = {list(CAN)}\n'
             f'pose = {can}\n')
    text += ('\n[[regions]]\nname = "start"\non = "table"\ncenter = [0.55, -0.2]\n'
             'size = [0.09, 0.09]\n')
    text += (f'\n[[regions]]\nname = "tray"\non = "floor"\ncenter = [{x}, {y}]\n'
             f'size = [{side}, {side}]\n')
    (path / "p.scene.toml").write_text(text)
    return path


def _carry_into_tray(problem):
    """(motion, q at the place, held): the carry of the can down onto the tray's
    centre, held from above, turned 0.4 rad from its grip's yaw."""
    world = problem.world
    m = problem.motions[1]
    # As the path stage carries a cylinder: the grasp as taken, its yaw not the grip's.
    grip = TopGrip((0.0, 0.0, 0.0), psi=0.0)
    held = Held("can", grip, 0.0, None, grip.matrix(0.0) @ transforms.pose(
        transforms.rot_z(0.4), (0.0, 0.0, 0.0)))
    rest = transforms.pose(np.eye(3), (0.45, 0.25, FLOOR + CAN[1] / 2))
    q, residual = world.ik(rest @ transforms.pose_inverse(held.grasp), seed=world.start)
    assert residual < 1e-5
    return m, np.asarray(q), held


SKELETON = ops("(pick can start)", "(place can tray)")


def test_a_place_between_rims_comes_straight_down_from_over_them(tmp_path):
    with lowered_folder(tray_folder(tmp_path, play=0.01), "p", SKELETON) as problem:
        m, q_b, held = _carry_into_tray(problem)
        assert m.enter_contact == {"floor"}
        a = place_approach(problem, m, q_b, held, {}, problem.checker)
        rest = problem.world.tool_pose(q_b) @ held.grasp
        # the can's bottom CLEAR over the rims' tops, in rungs RUNG apart at most
        assert a.targets[-1][2, 3] - CAN[1] / 2 == pytest.approx(RIM + CLEAR, abs=1e-9)
        assert a.rungs == int(np.ceil((RIM + CLEAR - FLOOR) / RUNG))
        heights = [t[2, 3] - rest[2, 3] for t in a.targets]
        assert np.all(np.diff([0.0, *heights]) <= RUNG + 1e-12)
        for target, q in zip(a.targets, a.qs, strict=True):
            # right above the resting pose, turned as there, and reached
            np.testing.assert_allclose(target[:3, :3], rest[:3, :3], atol=1e-9)
            np.testing.assert_allclose(target[:2, 3], rest[:2, 3], atol=1e-9)
            reached = problem.world.tool_pose(q) @ held.grasp
            np.testing.assert_allclose(reached[:3, 3], target[:3, 3], atol=1e-4)
            np.testing.assert_allclose(reached[:3, :3], target[:3, :3], atol=1e-4)


def test_a_take_from_between_rims_goes_straight_up_over_them(tmp_path):
    skeleton = ops("(pick can tray)", "(place can start)")
    with lowered_folder(tray_folder(tmp_path, play=0.01, out=True), "p", skeleton) as problem:
        m = problem.motions[1]
        assert m.leave_contact == {"floor"}
        _, q_a, held = _carry_into_tray(problem)
        climb = lift(problem, m, q_a, held, {}, problem.checker)
        rest = problem.world.tool_pose(q_a) @ held.grasp
        assert climb.targets[-1][2, 3] - CAN[1] / 2 == pytest.approx(RIM + CLEAR, abs=1e-9)
        for target, q in zip(climb.targets, climb.qs, strict=True):
            np.testing.assert_allclose(target[:2, 3], rest[:2, 3], atol=1e-9)
            reached = problem.world.tool_pose(q) @ held.grasp
            np.testing.assert_allclose(reached[:3, 3], target[:3, 3], atol=1e-4)


def test_a_place_with_nothing_near_is_left_free(tmp_path):
    with lowered_folder(tray_folder(tmp_path, play=0.01, rims=False), "p",
                        SKELETON) as problem:
        m, q_b, held = _carry_into_tray(problem)
        assert place_approach(problem, m, q_b, held, {}, problem.checker) is None


def test_a_can_set_down_between_rims_stands_in_the_physics_replay(cli, tmp_path):
    """Solved and replayed: 5 mm from each rim, the can ends upright where planned
    (blind8 p07's class: before the vertical approach, a cylinder came down across a
    rim between two collision samples and landed on its side)."""
    physics = solved_in_physics(cli, tray_folder(tmp_path, play=0.01), tmp_path)
    assert physics["objects"]["can"]["distance"] < 0.003


def test_the_descent_is_appended_to_the_carry_and_to_its_cost(tmp_path):
    with lowered_folder(tray_folder(tmp_path, play=0.01), "p", SKELETON) as problem:
        m, q_b, held = _carry_into_tray(problem)
        a = place_approach(problem, m, q_b, held, {}, problem.checker)
        n = problem.n
        free = np.vstack([problem.world.start + (a.qs[-1] - problem.world.start) * i / 4
                          for i in range(1, 4)])
        out = NlpOutcome(free.reshape(-1), "solved", 0.5, 0.0, None, 3, None, "")
        done = joined(out, None, a, problem.world.start, q_b, 2.0)
        waypoints = done.x.reshape(-1, n)
        # the free part's interior, then the rungs from the top down (q_b is the keyframe)
        np.testing.assert_array_equal(waypoints[:3], free)
        np.testing.assert_array_equal(waypoints[3:], np.array(a.qs[::-1]))
        path = np.vstack([*a.qs[::-1], q_b])
        assert done.cost == pytest.approx(0.5 + 2.0 * float(np.sum(np.diff(path, axis=0) ** 2)))


def test_a_climb_is_prepended_to_the_carry_and_to_its_cost(tmp_path):
    skeleton = ops("(pick can tray)", "(place can start)")
    with lowered_folder(tray_folder(tmp_path, play=0.01, out=True), "p", skeleton) as problem:
        m = problem.motions[1]
        _, q_a, held = _carry_into_tray(problem)
        climb = lift(problem, m, q_a, held, {}, problem.checker)
        q_b = problem.world.start
        free = np.vstack([climb.qs[-1] + (q_b - climb.qs[-1]) * i / 4 for i in range(1, 4)])
        out = NlpOutcome(free.reshape(-1), "solved", 0.5, 0.0, None, 3, None, "")
        done = joined(out, climb, None, q_a, q_b, 2.0)
        waypoints = done.x.reshape(-1, problem.n)
        np.testing.assert_array_equal(waypoints[:climb.rungs], np.array(climb.qs))
        np.testing.assert_array_equal(waypoints[climb.rungs:], free)
        path = np.vstack([q_a, *climb.qs])
        assert done.cost == pytest.approx(0.5 + 2.0 * float(np.sum(np.diff(path, axis=0) ** 2)))


def test_a_can_taken_from_between_rims_leaves_them_standing(cli, tmp_path):
    """Solved and replayed: the can lifted out of the tray 5 mm from its rims and set
    on the table ends where planned."""
    physics = solved_in_physics(cli, tray_folder(tmp_path, play=0.01, out=True), tmp_path)
    assert physics["objects"]["can"]["distance"] < 0.003


def test_a_stack_on_a_can_on_a_post_stands_in_the_physics_replay(cli, tmp_path):
    """blind15 p08: a can on a post (1.5 mm of play), a cap on the can, a coin on the
    cap. The cap's carry ended sideways, its bottom level with the can's top for the
    last 5 cm, and the physics replay knocked the can off the post (10.6 cm); a place
    onto a body that moves now comes straight down onto it."""
    folder = ROOT / "problems" / "blind15" / "p08"
    physics = solved_in_physics(cli, folder, tmp_path, problem=folder / "p08.pddl")
    assert max(o["distance"] for o in physics["objects"].values()) < 0.003
