"""Narrow passages and contacts that begin as touching: the margin schedule, the
sampled start, and `verify` holding every contact a motion enters or leaves to
1 mm (the robustness sets' classes 2 and 6)."""

import dataclasses

import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.geometry.locate import find_modes
from tampcli.geometry.scene import load_scene
from tampcli.optimize.modes import load_modes
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.path import MotionMargins, allowed_contacts
from tampcli.optimize.problem import lower
from tampcli.optimize.skeleton import MotionPhase
from tampcli.optimize.solve import solve
from tampcli.optimize.verify import PENETRATION, verify
from tampcli.pddl import parser

from .helpers import ROOT, ops

# RRT-Connect's time through a 5 mm gap is heavy-tailed: a generous budget keeps
# the test about the schedule, not about the sampler's luck.
PATIENT = OptimizeOptions(sampling_checks=120_000, time_limit=120.0)


@pytest.fixture
def robust():
    """(set, problem stem) -> (scene, modes, World), the World closed after the test."""
    from tampcli.geometry.world import World
    opened = []

    def load(kind: str, stem: str):
        dom_path = ROOT / "domains" / kind / "domain.pddl"
        domain = parser.parse_domain_file(str(dom_path))
        prob = ROOT / "problems" / kind / f"{stem}.pddl"
        problem = parser.parse_problem_file(str(prob))
        scene = load_scene(prob.with_suffix(".scene.toml"), domain, problem, geometric=False)
        modes = load_modes(find_modes(dom_path), domain)
        world = World(scene)
        opened.append(world)
        return scene, modes, world, domain

    yield load
    for world in opened:
        world.close()


def _lowered(robust, kind, stem, plan, options=None):
    scene, modes, world, domain = robust(kind, stem)
    return lower(ops(*plan), scene, modes, world, options or OptimizeOptions(), domain=domain)


def _carry(result, name: str) -> int:
    return next(i for i, p in enumerate(result.phases) if p.attached == name and p.end > p.start)


def _clearance(problem, result, phase_index: int, name: str, factor: int = 40) -> float:
    """Least distance between `name` and anything moving in a phase (the robot, the
    held object), at `factor` points per segment."""
    phase = result.phases[phase_index]
    traj = np.asarray(result.trajectory)
    poses = {n: transforms.pose_from_xyzquat(v[phase_index])
             for n, v in result.object_poses.items()}
    held = None
    if phase.attached is not None:
        world = problem.world
        held = (phase.attached, transforms.pose_inverse(world.tool_pose(traj[phase.start]))
                @ poses[phase.attached])
    qs = [(1 - s) * traj[i] + s * traj[i + 1] for i in range(phase.start, phase.end)
          for s in np.arange(factor) / factor]
    others = {n: t for n, t in poses.items() if n != phase.attached}
    found = problem.checker.distances_many(np.array(qs), others, held, None, 0.05)
    return min((c.distance for cs in found for c in cs if c.b == f"body:{name}"),
               default=np.inf)


def test_touching_replaces_ignoring_at_the_ends_of_a_motion():
    m = MotionPhase(0, 0, None, None, "free", enter_contact=frozenset({"a"}),
                    leave_contact=frozenset({"table"}), sliding=frozenset({"bench"}))
    assert allowed_contacts(m) == {"bench"}
    own = MotionMargins({"wall": 0.001}, {"a": -0.0003}, {"table": 0.0})
    assert own.at(0.5, 10) == {"wall": 0.001, "table": 0.0}
    assert own.at(5.0, 10) == {"wall": 0.001}
    assert own.at(9.5, 10) == {"wall": 0.001, "a": -0.0003}
    assert MotionMargins.touching(m).at(9.5, 10)["a"] < 0


def test_planar_disk_through_a_doorway_with_5_mm_a_side(robust):
    """robust-planar p03's first motion: the 10 cm disk through an 11 cm doorway. A 1 cm
    margin made it infeasible; the tight margin and a sampled start pass it."""
    problem = _lowered(robust, "robust-planar", "p03", ["(pick a east)"], PATIENT)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert verify(problem, result) == []
    traj = np.asarray(result.trajectory)
    fine = np.concatenate([np.linspace(a, b, 50) for a, b in zip(traj, traj[1:], strict=False)])
    crossing = fine[np.argmin(np.abs(fine[:, 0]))]
    assert 0.045 < crossing[1] < 0.155  # through the doorway (y 0.045 .. 0.155)
    assert _clearance(problem, result, 0, "wall-low") > -PENETRATION


def test_the_margin_is_kept_where_there_is_room(robust):
    """The schedule relaxes the margin only where it must: the wide free motions of
    robust-planar p03 keep their 1 cm from a."""
    problem = _lowered(robust, "robust-planar", "p03", ["(pick a east)"], PATIENT)
    result = solve(problem, "path")
    assert result.solved
    # The approach's waypoints before its last segment stay 1 cm from a (the margin).
    traj = np.asarray(result.trajectory)
    phase = result.phases[0]
    a = problem.scene.body("a").pose
    far = [np.linalg.norm(q - np.array(a[:2])) for q in traj[phase.start:phase.end - 1]]
    assert min(far) > 0.05 + 0.04 + 0.01 - 1e-3


def test_panda_puts_a_cube_into_a_slot_with_5_mm_a_side(robust):
    """robust-arm p03: a 5 cm cube into a 6 cm slot; refused by the keyframe NLP's 1 cm
    margin before, and dipped into a wall between the path's sample points."""
    problem = _lowered(robust, "robust-arm", "p03", ["(pick a start)", "(place a slot)"],
                       PATIENT)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert verify(problem, result) == []
    carry = _carry(result, "a")
    assert _clearance(problem, result, carry, "wall-left") > -PENETRATION
    assert _clearance(problem, result, carry, "wall-right") > -PENETRATION


def test_a_stacked_cube_touches_the_one_below_not_penetrates(robust):
    """arm-pick-place p05's tower: the carry's last segment may touch b (the contact it
    enters), 1 mm deep at most, at every point of it (it went 2.4 mm into b when the
    whole last segment ignored b)."""
    problem = _lowered(robust, "arm-pick-place", "p05",
                       ["(pick b start)", "(stack b c)", "(pick a start)", "(stack a b)"])
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert _clearance(problem, result, _carry(result, "a"), "b") > -PENETRATION


def test_a_carried_cube_keeps_clear_of_the_one_placed_beside_its_goal(robust):
    """arm-pick-place p03: a is put down beside b (1 mm from it: what a place sets down
    keeps the placement gap). Held to the tight margin all the way down when a stood
    1 cm from b, a's corner once dipped 0.8 mm into b between the sample points and the
    physics replay knocked b over; near keys keep half their keyframe distance, at
    least the tight margin, and the carry ends straight down."""
    problem = _lowered(robust, "arm-pick-place", "p03",
                       ["(pick b start)", "(place b goal)", "(pick a start)", "(place a goal)"])
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    carry = _carry(result, "a")
    b = transforms.pose_from_xyzquat(result.object_poses["b"][carry])
    a = transforms.pose_from_xyzquat(result.object_poses["a"][carry + 1])
    placed = problem.checker.body_distance("a", a, "b", b).distance
    assert placed < 0.02, "a is not put down beside b: the test would not test the carry"
    assert _clearance(problem, result, carry, "b") > 0.0005  # 40 points a segment


def _sunk(problem, result, depth: float):
    """The result with its last keyframe (a place) `depth` lower and the object with it."""
    world = problem.world
    traj = np.array(result.trajectory)
    end = result.phases[-2].end  # the carry's end: the place keyframe
    target = world.tool_pose(traj[end])
    target[2, 3] -= depth
    q, res = world.ik(target, seed=traj[end])
    assert res < 1e-4
    traj[end:] = q
    poses = {k: [list(p) for p in v] for k, v in result.object_poses.items()}
    obj = result.phases[-2].attached
    for p in poses[obj][-2:]:
        p[2] -= depth
    return dataclasses.replace(result, trajectory=traj, object_poses=poses)


def test_verify_reports_a_place_that_sinks_into_its_support(wall):
    """The contact a motion enters is touching: the old rule ignored the support for
    the whole last segment and the keyframe, so 5 mm deep passed."""
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    result = solve(problem, "path")
    assert result.solved and verify(problem, result) == []
    found = verify(problem, _sunk(problem, result, 0.005))
    assert any("collision a vs table" in p for p in found), found


def test_verify_reports_a_retreat_through_the_object_just_placed(planar):
    """After a place the next motion leaves the object: touching, not sweeping through
    it (the checker's finding on arm-pick-place p03 and robust-arm p01)."""
    scene, modes, world = planar
    problem = lower(ops("(pick o start)", "(place o goal)", "(pick o goal)"), scene, modes,
                    world)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert verify(problem, result) == []
    traj = np.array(result.trajectory)
    retreat = [p for p in result.phases if p.end > p.start][2]
    start = traj[retreat.start]
    centre = np.array(result.object_poses["o"][-1][:2])
    # The first interior waypoint mirrored through o's centre: the first segment
    # crosses o while both of its ends only touch it.
    traj[retreat.start + 1] = 2 * centre - start
    found = verify(problem, dataclasses.replace(result, trajectory=traj))
    assert any("collision planar_body vs o" in p for p in found), found


def test_verify_reports_a_suction_grip_inside_the_disk(planar):
    """The planar robot holds its object against its rim: the collision model leaves
    the held object against the tool out, so verify measures that contact itself
    (the checker found the disk 8 mm inside planar-tamp p01's block)."""
    scene, modes, world = planar
    problem = lower(ops("(pick o start)", "(place o goal)"), scene, modes, world)
    result = solve(problem, "path")
    assert result.solved and verify(problem, result) == []
    carry = _carry(result, "o")
    traj = np.asarray(result.trajectory)
    poses = {k: [list(p) for p in v] for k, v in result.object_poses.items()}
    for i in (carry, carry + 1):  # 5 mm towards the disk, at both ends of the carry
        tool = traj[result.phases[carry].start if i == carry else result.phases[carry].end]
        o = np.array(poses["o"][i][:2])
        poses["o"][i][:2] = list(o + 0.005 * (tool - o) / np.linalg.norm(tool - o))
    found = verify(problem, dataclasses.replace(result, object_poses=poses))
    assert any("collision planar_body vs o" in p for p in found), found


def test_fingers_do_not_brush_what_they_are_about_to_grasp(robust):
    """robust-arm p04: the open fingers straddle the cylinder with centimetres to
    spare at the grasp; on the way down a finger brushed it (0.1 mm inside our
    hulls, 1.1 to 1.4 mm inside the independent checker's PyBullet, before our hulls
    were rounded by its 1 mm margin as its are). A contact
    being entered is never closer than at its keyframe, nor than the margin."""
    problem = _lowered(robust, "robust-arm", "p04", ["(pick a start)"])
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    traj = np.asarray(result.trajectory)
    at_grasp = problem.checker.distances(traj[-1], None, None, frozenset(), 0.05)
    grasp_gap = min(c.distance for c in at_grasp if c.b == "body:a")
    assert grasp_gap > problem.options.margin
    # The margin holds at the NLP's sample points; between them (40 a segment here)
    # it may dip by millimetres, not to touching.
    assert _clearance(problem, result, 0, "a") > 0.003


def test_face_grips_put_the_rim_at_the_middle_of_each_face(planar):
    from tampcli.optimize.keyframe_stage import face_grips as _face_grips

    scene, modes, world = planar
    problem = lower(ops("(pick o start)", "(place o goal)"), scene, modes, world)
    kf = solve(problem, "keyframes")
    assert kf.solved
    (step, t), = kf.keyframes.grip.items()
    yaw = kf.choices[step].yaw
    tries = [grips[step] for grips in _face_grips(problem, kf)]
    assert 3 <= len(tries) <= 4
    for f in tries:
        quarter = (f - yaw) / (np.pi / 2)
        assert quarter == pytest.approx(round(quarter), abs=1e-9)
        assert abs(f - t) <= np.pi + 1e-9
    assert [abs(f - t) for f in tries] == sorted(abs(f - t) for f in tries)


def test_a_face_the_disk_cannot_reach_costs_no_collision_nlp(monkeypatch):
    """planar-tamp p01: the path stage tries the face nearest the keyframe NLP's own
    contact angle first. Where that face cannot be reached even without collisions,
    its relaxation says so and the keyframe NLP with collisions is not paid for (it
    took 26 iterations, 0.37 s, to fail); the NLP's own angle then solves the path."""
    from tampcli.optimize import path_stage

    from .helpers import lowered_library

    calls = []
    keyframes_with = path_stage.keyframes_with

    def recorded(run, warm, grips=None, *args, **kwargs):
        out = keyframes_with(run, warm, grips, *args, **kwargs)
        calls.append((grips is not None, kwargs.get("collisions", True), out.solved))
        return out

    monkeypatch.setattr(path_stage, "keyframes_with", recorded)
    folder = ROOT / "problems" / "planar-tamp"
    skeleton = ops("(pick a ground)", "(place a goal)", "(pick b ground)", "(place b goal)")
    with lowered_library(folder, ROOT / "domains" / "planar-tamp", "p01", skeleton) as problem:
        kf = solve(problem, "keyframes")
        path = solve(problem, "path", kf)
    assert path.solved, path.worst_constraint
    # The face's relaxation failed, and nothing else was tried at that face.
    assert calls == [(True, False, False)]


def test_other_faces_are_not_tried_for_a_failure_before_their_grasps():
    """path_stage: a path that failed on the motion into step 1 is not solved again
    with other faces for grasps at steps 2 and 4 (their grips leave that motion's
    ends where they were); one that failed on the motion into step 2 is."""
    from tampcli.optimize.path_stage import _before_the_grips
    from tampcli.optimize.result import TrajectoryResult

    def failed(actions):
        return TrajectoryResult("infeasible", "path", ("a",) * 5, failed_actions=actions)

    assert _before_the_grips(failed(2), {2: 0.0, 4: 1.5})  # the motion into step 1
    assert not _before_the_grips(failed(3), {2: 0.0, 4: 1.5})  # the approach to grasp 2
    assert not _before_the_grips(failed(None), {2: 0.0})
    assert not _before_the_grips(None, {2: 0.0})


def test_what_a_place_sets_down_keeps_the_placement_gap_not_the_robots_margin():
    """arm-sort p01, two cubes into the blue bin: at the second place keyframe the
    held cube keeps the placement rows' 1 mm from the first (the final stage packs
    them so), while the fingers beside it keep the robot's 1 cm."""
    import numpy as np

    from tampcli.optimize.grips import Kinematics
    from tampcli.optimize.stages import keyframe_rows

    from .helpers import lowered_library

    skeleton = ops("(pick blue1 workspace)", "(place blue1 blue-bin)",
                   "(pick blue2 workspace)", "(place blue2 blue-bin)")
    with lowered_library(ROOT / "problems" / "arm-sort", ROOT / "domains" / "arm-sort", "p01",
                         skeleton) as problem:
        kf = solve(problem, "keyframes")
        assert kf.solved, kf.worst_constraint
        rows = keyframe_rows(problem, kf.keyframes.blocks(), kf.choices,
                             Kinematics(problem.world), problem.checker,
                             np.asarray(problem.world.start))
    values = dict(zip(((lab.step, lab.what) for lab in rows.ineq.labels),
                      np.concatenate(rows.ineq.values), strict=False))
    place = "(place blue2 blue-bin)"
    gap = values[(place, "collision blue2 vs blue1 (margin 1 mm)")]
    assert -1e-4 <= gap < 0.009  # set down nearer its neighbour than the robot's margin
    robot = [what for step, what in values if step == place and "panda_" in what]
    assert robot and all(what.endswith("(margin 10 mm)") for what in robot)
