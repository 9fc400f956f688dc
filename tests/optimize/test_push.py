"""push as a push: the face contact, the friction-cone rule, its rows and its check.

A straight push of the planar test scene's box (the goal moved to the box's
right, clear of the pillar) is solved once; verify then judges hand-made
changes of it. Every new row is checked against finite differences.
"""

import dataclasses
import math

import numpy as np
import pytest

from tampcli.optimize.bodies import BodyInfo
from tampcli.optimize.expr import RowSet, planar_pose
from tampcli.optimize.grips import Kinematics, held_pose
from tampcli.optimize.init import final_guess, keyframe_guess
from tampcli.optimize.kinds.push import Push
from tampcli.optimize.kinds.push_contact import (
    PUSH_FRICTION,
    arm_face_grip,
    candidate_faces,
    contacted_face,
    face_of,
    level_face_grip,
    level_lift,
    planar_face_grip,
)
from tampcli.optimize.layout import Layout, waypoint_block
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.optimize.stages import Rows, final_layout, final_rows
from tampcli.optimize.values import placement_blocks
from tampcli.optimize.verify import verify

from .helpers import central_differences, ops
from .test_gradients import _check

PUSH = "(push o start goal floor)"
BOX = BodyInfo("b", "box", (0.06, 0.04, 0.03), False, (0.0, 0.0, 0.03, 0.0), True)


def _straight(scene):
    """The planar scene with its goal to the right of the box: a straight push along +x."""
    return dataclasses.replace(scene, regions=tuple(
        dataclasses.replace(r, center=(0.8, 0.2)) if r.name == "goal" else r
        for r in scene.regions))


@pytest.fixture(scope="module")
def pushed(planar):
    scene, modes, world = planar
    problem = lower(ops(PUSH), _straight(scene), modes, world)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert verify(problem, result) == []
    return problem, result


def _push_phase(result):
    (phase,) = [p for p in result.phases if p.action == PUSH]
    return phase


def _verify_with(problem, result, change):
    traj = np.array(result.trajectory)
    phase = _push_phase(result)
    change(traj, phase)
    return verify(problem, dataclasses.replace(result, trajectory=traj))


# ---------------------------------------------------------------- faces


def test_faces_are_named_by_their_inward_normal():
    assert face_of(BOX, 0.0).depth == pytest.approx(0.06)  # the -x face, 8 cm wide
    assert face_of(BOX, 0.0).width == pytest.approx(0.04)
    assert face_of(BOX, 0.5 * math.pi).depth == pytest.approx(0.04)
    assert contacted_face(BOX, (-0.2, 0.01)).angle == pytest.approx(0.0)
    assert contacted_face(BOX, (0.01, 0.1)).angle == pytest.approx(1.5 * math.pi)
    assert candidate_faces(BOX, (0.0, -1.0))[0] == pytest.approx(-0.5 * math.pi)
    disk = BodyInfo("d", "cylinder", (0.05, 0.05, 0.03), False, (0, 0, 0.03, 0), True)
    assert candidate_faces(disk, (1.0, 1.0)) == [pytest.approx(0.25 * math.pi)]


@pytest.mark.parametrize("grip, face, tool_z", [
    (planar_face_grip(face_of(BOX, 0.5 * math.pi), 0.3, -0.01, 0.05),
     face_of(BOX, 0.5 * math.pi), (0.0, 0.0, 1.0)),
    (arm_face_grip(face_of(BOX, math.pi)), face_of(BOX, math.pi), (0.0, 0.0, -1.0)),
    (level_face_grip(face_of(BOX, 0.0), 0.015), face_of(BOX, 0.0), (1.0, 0.0, 0.0)),
], ids=["planar", "arm-down", "arm-level"])
def test_face_grip_offset_derivative_and_touch(grip, face, tool_z):
    t = 0.013
    c, G, dc, dG = grip.parts(t)
    fd = (grip.parts(t + 1e-6)[0] - grip.parts(t - 1e-6)[0]) / 2e-6
    np.testing.assert_allclose(dc, fd, atol=1e-8)
    np.testing.assert_allclose(G @ G.T, np.eye(3), atol=1e-12)
    # The tool origin, seen from the object, lies outside the pushed face, offset t along
    # it; the tool's z axis (object frame) points down, or level into the face.
    local = -G.T @ c
    assert local @ face.normal < -face.depth
    assert local @ face.tangent == pytest.approx(t)
    np.testing.assert_allclose(G.T[:, 2], tool_z, atol=1e-12)


def test_a_level_hand_runs_above_the_support_and_below_the_top():
    tall = dataclasses.replace(BOX, half=(0.06, 0.04, 0.04))
    lift = level_lift(tall)
    assert lift == pytest.approx(0.016)  # its axis 5.6 cm above: the wrist 1.1 cm clear
    grip = level_face_grip(face_of(tall, 0.0), lift)
    c, G, _, _ = grip.parts(0.0)
    assert (-G.T @ c)[2] == pytest.approx(lift)
    # 6 cm tall: as high as the fingertips allow, the axis 1 cm below its top (the
    # wrist 5 mm above the support, clear of it by the tight margin).
    assert level_lift(BOX) == pytest.approx(0.02)
    flat = dataclasses.replace(BOX, half=(0.06, 0.06, 0.02))  # robust-arm p09's crate
    assert level_lift(flat) is None  # too low for the hand to clear the support


# ---------------------------------------------------------------- gradients


def test_final_rows_keep_the_pushed_yaw(planar):
    scene, modes, world = planar
    problem = lower(ops(PUSH), _straight(scene), modes, world)
    layout = final_layout(problem)
    vals, origins = final_guess(problem)
    x = layout.pack(placement_blocks(vals)) + np.random.default_rng(1).normal(0, 0.05,
                                                                               layout.size)
    eq, _ = _check(lambda v: final_rows(problem, v, origins), layout, x)
    assert np.max(np.abs(eq)) > 1e-3  # the yaw row sees a turned placement


def test_keyframe_rows_hold_the_cone(planar):
    """The keyframe NLP's cone rows are there and can be violated (a sideways end)."""
    from tampcli.optimize.stages import keyframe_layout, keyframe_rows

    scene, modes, world = planar
    problem = lower(ops(PUSH), _straight(scene), modes, world)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    layout = keyframe_layout(problem)
    blocks = dict(vals.blocks())
    blocks["k1"] = blocks["k1"] + np.array([0.0, 0.4])  # the end dragged sideways
    x = layout.pack(blocks)
    rows = keyframe_rows(problem, layout.unpack(x), choices, Kinematics(world),
                         problem.checker, world.start, collisions=False)
    ineq, _ = rows.ineq.assemble(layout.slices(), layout.size)
    drag = [v for v, lab in zip(ineq, rows.ineq.labels, strict=True)
            if "not into the pushed face" in lab.what]
    assert len(drag) == 2 and min(drag) < -0.1
    _check(lambda v: keyframe_rows(problem, v, choices, Kinematics(world), problem.checker,
                                   world.start, collisions=False), layout, x)


def test_keyframe_rows_panda_level_push(wall):
    """The level hand's grip through the keyframe rows (the wall scene's cube made 8 cm
    tall, standing on the floor as before)."""
    from tampcli.geometry.world import World
    from tampcli.optimize.modes import Mode
    from tampcli.optimize.stages import keyframe_layout, keyframe_rows

    scene, _, _ = wall
    tall = dataclasses.replace(scene, bodies=tuple(
        dataclasses.replace(b, size=(0.05, 0.05, 0.08), pose=(*b.pose[:2], 0.04, *b.pose[3:]))
        if b.name == "a" else b for b in scene.bodies))
    modes = {"push": Mode("push", "push", "?b", to="?to", params=("?b", "?from", "?to"))}
    with World(tall) as world:
        problem = lower(ops("(push a start goal)"), tall, modes, world)
        placements, _ = final_guess(problem)
        vals, choices = keyframe_guess(problem, placements, world.start,
                                       np.random.default_rng(0))
        choices = {0: dataclasses.replace(choices[0], level=True, reach=None)}
        layout = keyframe_layout(problem)
        x = layout.pack(vals.blocks()) + np.random.default_rng(6).normal(0, 0.03, layout.size)
        _check(lambda v: keyframe_rows(problem, v, choices, Kinematics(world),
                                       problem.checker, world.start, collisions=False),
               layout, x)


def _path_rows_check(problem, world, held, q_a, q_b, T=4, seed=0):
    kin = Kinematics(world)
    layout = Layout(tuple((waypoint_block(i), problem.n) for i in range(1, T)))
    line = np.concatenate([q_a + (q_b - q_a) * i / T for i in range(1, T)])
    x = line + np.random.default_rng(seed).normal(0, 0.02, layout.size)

    def rows_of(v):
        rows = Rows()
        qs = [q_a, *(v[waypoint_block(i)] for i in range(1, T)), q_b]
        Push().path_rows(rows, "push", problem, qs, held, kin)
        return rows

    _check(rows_of, layout, x)
    return rows_of(layout.unpack(x))


def test_path_rows_planar(pushed):
    problem, result = pushed
    from tampcli.optimize.assemble import walk

    ctx = walk(problem, result.keyframes, result.choices, problem.world.start)[1]
    rows = _path_rows_check(problem, problem.world, ctx.held, ctx.q_a, ctx.q_b)
    assert len(np.concatenate(rows.ineq.values)) == 2 * 4  # two cone rows per step


def test_path_rows_panda(wall):
    from tampcli.optimize.modes import Mode

    scene, _, world = wall
    modes = {"push": Mode("push", "push", "?b", to="?to", params=("?b", "?from", "?to"))}
    problem = lower(ops("(push a start goal)"), scene, modes, world)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    from tampcli.optimize.assemble import walk

    ctx = walk(problem, vals, choices, world.start)[1]
    rows = _path_rows_check(problem, world, ctx.held, ctx.q_a, ctx.q_b)
    assert {lab.what for lab in rows.ineq.labels} == {"motion not into the pushed face (a drag)"}
    assert {lab.what for lab in rows.eq.labels} == {"pushed object turns"}
    assert len(rows.eq.values) == 3  # one per interior waypoint


def test_same_yaw_and_cone_rows_on_poses():
    """The PoseX rows alone, on two placements as variables."""
    from tampcli.optimize.kinds.push_contact import cone_rows, same_yaw

    def rows_of(x):
        a = planar_pose("a", *x[0:2], 0.03, x[2])
        b = planar_pose("b", *x[3:5], 0.03, x[5])
        rows = RowSet()
        cone_rows(rows, "push", a, b, 0.5 * math.pi)
        same_yaw(rows, "push", a, b)
        return np.concatenate(rows.values), rows

    x = np.array([0.1, 0.2, 0.1, 0.15, 0.5, 0.15])
    vals, rows = rows_of(x)
    jac = np.zeros((len(vals), 6))
    at = 0
    for v, j in zip(rows.values, rows.jacs, strict=True):
        for block, a in j.items():
            jac[at:at + len(v), (0 if block == "a" else 3):(3 if block == "a" else 6)] += a
        at += len(v)
    np.testing.assert_allclose(jac, central_differences(lambda xx: rows_of(xx)[0], x, 1e-6), atol=1e-6)
    assert vals[0] > 0 and vals[1] > 0  # (0.05, 0.3) is 15 deg off the -y face's normal


# ---------------------------------------------------------------- verify


def test_the_solved_push_moves_into_its_face(pushed):
    problem, result = pushed
    phase = _push_phase(result)
    o = np.array(result.object_poses["o"][0][:2])
    traj = np.asarray(result.trajectory)
    assert contacted_face(problem.bodies["o"], traj[phase.start] - o).angle == 0.0
    steps = np.diff(traj[phase.start:phase.end + 1], axis=0)
    assert np.all(np.abs(steps[:, 1]) <= PUSH_FRICTION * steps[:, 0] + 1e-9)
    assert np.sum(steps[:, 0]) > 0.4


def test_a_push_that_starts_away_from_the_object(pushed):
    def away(traj, phase):
        traj[phase.start:phase.end + 1] += np.array([-0.005, 0.0])

    found = _verify_with(*pushed, away)  # 5 mm beyond the 0.5 mm gap of a touch
    assert any("the push starts 0.6 cm away from o" in p for p in found), found


def test_a_pusher_inside_the_object(pushed):
    def inside(traj, phase):
        traj[phase.start:phase.end + 1] += np.array([0.005, 0.0])

    found = _verify_with(*pushed, inside)
    assert any("the pusher is 4.5 mm inside o" in p for p in found), found


def test_a_drag_is_refused(pushed):
    def drag(traj, phase):
        n = phase.end - phase.start
        traj[phase.start:phase.end + 1] = traj[phase.start] + np.outer(
            np.arange(n + 1) / n, [0.1, 0.3])

    found = _verify_with(*pushed, drag)
    assert any("(a drag" in p and "72 deg off the normal" in p for p in found), found


def test_a_pull_is_refused(pushed):
    def pull(traj, phase):
        n = phase.end - phase.start
        traj[phase.start:phase.end + 1] = traj[phase.start] + np.outer(
            np.arange(n + 1) / n, [-0.1, 0.0])

    found = _verify_with(*pushed, pull)
    assert any("180 deg off the normal" in p for p in found), found


def test_the_approach_may_not_cut_through_the_object(pushed):
    def cut(traj, phase):
        traj[phase.start - 1] = traj[phase.start] + np.array([0.12, 0.0])

    found = _verify_with(*pushed, cut)
    assert any("inside o" in p for p in found), found


def test_pushed_grip_keeps_the_object_at_its_place(pushed):
    """The object rides on the face grip exactly where verify measures it."""
    problem, result = pushed
    phase = _push_phase(result)
    from tampcli.optimize.assemble import walk

    ctx = walk(problem, result.keyframes, result.choices, problem.world.start)[1]
    h = held_pose(Kinematics(problem.world).frame(result.trajectory[phase.end]), ctx.held.grip,
                  ctx.held.t)
    after = result.phases.index(phase) + 1  # the boundary at the push's end
    np.testing.assert_allclose(h.pos, np.asarray(result.object_poses["o"][after][:3]),
                               atol=1e-6)


@pytest.mark.parametrize("kind", ["down", "level", "planar"])
def test_path_cone_rows_take_the_face_normal_in_the_world(kind):
    """A push straight along the face's inward normal meets the cone rows with room to
    spare; a drag along the face breaks one. The tool frame differs from the
    object's for a level hand and for the planar disk at a yaw: the normal must be
    carried to the world through the tool (once failed: a level push into a low
    garage reported a drag of 2 mm)."""
    from scipy.spatial.transform import Rotation

    from tampcli.optimize.grips import HeldPose
    from tampcli.optimize.kinds.push_contact import (
        Face,
        arm_face_grip,
        level_face_grip,
        path_rows,
        planar_face_grip,
    )

    face = Face(0.5 * math.pi, 0.05, 0.05)
    grip = {"down": arm_face_grip(face), "level": level_face_grip(face, 0.01, 0.1),
            "planar": planar_face_grip(face, 0.7, 0.0, 0.05)}[kind]
    tool = np.eye(3) if kind == "planar" else Rotation.from_euler("z", 0.4).as_matrix()
    axes = tool @ np.array(grip.axes)
    normal = axes @ face.normal  # the face's inward normal in the world
    tangent = axes @ face.tangent
    zero = np.zeros((3, 7))

    def rows_for(direction):
        poses = [HeldPose(s * direction, axes, zero, np.zeros((3, 3, 7)), None, None)
                 for s in (0.0, 0.02, 0.04)]
        ineq, eq = RowSet(), RowSet()
        path_rows(ineq, eq, "push", poses, [None, None, None], grip, kind == "planar")
        return np.concatenate(ineq.values)

    assert np.all(rows_for(normal) > 0.0)
    assert np.min(rows_for(tangent)) < -0.01


def test_a_pushed_cylinder_may_turn_with_the_hand(wall):
    """A cylinder's footprint is the same at any yaw: neither its push's keyframe rows
    nor its path rows hold its yaw (a box's do, test_path_rows_panda)."""
    from tampcli.geometry.world import World
    from tampcli.optimize.assemble import walk
    from tampcli.optimize.modes import Mode
    from tampcli.optimize.stages import keyframe_layout, keyframe_rows

    scene, _, _ = wall
    can = dataclasses.replace(scene, bodies=tuple(
        dataclasses.replace(b, shape="cylinder", size=(0.025, b.size[2])) if b.name == "a"
        else b for b in scene.bodies))
    modes = {"push": Mode("push", "push", "?b", to="?to", params=("?b", "?from", "?to"))}
    with World(can) as world:
        problem = lower(ops("(push a start goal)"), can, modes, world)
        assert problem.bodies["a"].disk
        placements, _ = final_guess(problem)
        vals, choices = keyframe_guess(problem, placements, world.start,
                                       np.random.default_rng(0))
        layout = keyframe_layout(problem)
        rows = keyframe_rows(problem, layout.unpack(layout.pack(vals.blocks())), choices,
                             Kinematics(world), problem.checker, world.start,
                             collisions=False)
        assert "pushed object turns" not in {lab.what for lab in rows.eq.labels}
        ctx = walk(problem, vals, choices, world.start)[1]
        path = _path_rows_check(problem, world, ctx.held, ctx.q_a, ctx.q_b)
        assert not path.eq.values
        assert {lab.what for lab in path.ineq.labels} == {
            "motion not into the pushed face (a drag)"}
