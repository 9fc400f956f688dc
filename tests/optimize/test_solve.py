"""Whole stages on real scenes: the seed's planar example, a Panda over a wall,
an infeasible placement."""

import math

import numpy as np
import pytest

from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.optimize.verify import verify

from .helpers import ops

PLANAR_SKELETONS = {
    "push": ("(push o start goal floor)",),
    "pick-place": ("(pick o start)", "(place o goal)"),
}


def _segment_hits_pillar(scene, a, b):
    """Does the straight line from a to b pass through the pillar (robot radius included)?"""
    pillar = scene.body("pillar")
    c = np.array(pillar.pose[:2])
    r = pillar.size[0] + scene.robot.radius
    for s in np.linspace(0, 1, 200):
        if np.linalg.norm(a + s * (b - a) - c) < r:
            return True
    return False


def test_the_seed_push_is_a_drag(planar):
    """The seed's push goes 45 degrees off every face of the box (and bends round the
    pillar): outside the friction cone, so no longer a push."""
    scene, modes, world = planar
    problem = lower(ops(*PLANAR_SKELETONS["push"]), scene, modes, world)
    result = solve(problem, "keyframes")
    assert not result.solved
    assert "not into the pushed face" in result.worst_constraint


def test_seed_planar_example_pick_place_solves(planar):
    scene, modes, world = planar
    problem = lower(ops(*PLANAR_SKELETONS["pick-place"]), scene, modes, world)
    final = solve(problem, "final")
    assert final.solved
    keyframes = solve(problem, "keyframes", final)
    assert keyframes.solved and keyframes.bound_kind == "heuristic"
    path = solve(problem, "path", keyframes)
    assert path.solved, path.worst_constraint
    assert verify(problem, path, factor=10) == []
    # The obstacle is in the way of the straight line and the path goes around it.
    start = np.asarray(scene.body("o").pose[:2])
    goal = np.asarray(path.object_poses["o"][-1][:2])
    assert _segment_hits_pillar(scene, start, goal)
    traj = path.trajectory
    pillar = np.array(scene.body("pillar").pose[:2])
    dense = np.vstack([a + s * (b - a) for a, b in zip(traj, traj[1:], strict=False)
                       for s in np.linspace(0, 1, 10)])
    clearance = np.linalg.norm(dense - pillar, axis=1) - scene.body("pillar").size[0]
    assert clearance.min() >= scene.robot.radius - 1e-3
    # The object ends inside the goal region.
    region = scene.region("goal")
    assert np.all(np.abs(goal - np.array(region.center)) <= 0.5 * np.array(region.size))
    # Cost: the seed's smoothness term, and the keyframe value bounds it (Cauchy-Schwarz).
    assert path.cost == pytest.approx(float(np.sum(np.diff(traj, axis=0) ** 2)))
    assert keyframes.cost <= path.cost + 1e-9
    # Each stage carries its warm start's KKT certificates on, and adds its own.
    assert final.kkt.final is not None and final.kkt.keyframes is None
    assert keyframes.kkt.final == final.kkt.final and keyframes.kkt.keyframes is not None
    # (its keyframes: those the path went through, with the suction grip at a face's middle)
    assert path.kkt.final == final.kkt.final and path.kkt.keyframes is not None
    assert path.kkt.path.dual_feasible and path.kkt.path.stationarity < 1e-2
    assert len(path.phases) + 1 == len(path.object_poses["o"])


def test_the_path_stage_stops_at_a_cutoff_its_bound_reaches(planar):
    scene, modes, world = planar
    problem = lower(ops(*PLANAR_SKELETONS["pick-place"]), scene, modes, world)
    keyframes = solve(problem, "keyframes")
    path = solve(problem, "path", keyframes)
    assert path.solved
    # The reach relaxation drops rows: its cost is no more than the keyframes'.
    assert solve(problem, "reach").cost <= keyframes.cost + 1e-6
    # Any cutoff at or below the keyframes' least cost stops after the first motion,
    # with a bound between it and the path's cost.
    cut = solve(problem, "path", keyframes, cutoff=keyframes.cost)
    assert cut.status == "bounded" and not cut.solved
    assert keyframes.cost <= cut.cost <= path.cost + 1e-9
    assert "after motion 0" in cut.worst_constraint
    # A cutoff above the path's cost changes nothing.
    same = solve(problem, "path", keyframes, cutoff=path.cost + 1.0)
    assert same.solved and same.cost == pytest.approx(path.cost)


def test_panda_over_a_wall(wall):
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world,
                    OptimizeOptions(waypoints=6, time_limit=120.0))
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert verify(problem, result, factor=10) == []
    final = np.asarray(result.object_poses["a"][-1])
    region = scene.region("goal")
    assert np.all(np.abs(final[:2] - np.array(region.center)) <= 0.5 * np.array(region.size))
    assert final[2] == pytest.approx(0.025, abs=5e-3)
    # The wall was in the way: straight joint interpolation of the carry collides.
    carry = result.phases[2]
    assert carry.attached == "a"
    q0, q1 = result.trajectory[carry.start], result.trajectory[carry.end]
    grasp = result.grasps["a"]
    straight = [problem.checker.min_distance(q0 + s * (q1 - q0), None, ("a", grasp),
                                             frozenset({"table"})) for s in np.linspace(0, 1, 21)]
    assert min(straight) < 0
    kkt = result.kkt
    assert kkt.final is not None and kkt.keyframes is not None
    assert kkt.path is not None and math.isfinite(kkt.path.stationarity) and kkt.path.nlps >= 1


def test_blocked_region_is_infeasible_quickly_and_says_why(wall):
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a blocked)"), scene, modes, world)
    for stage in ("final", "keyframes", "path"):
        result = solve(problem, stage)
        assert result.status == "infeasible"
        assert "(place a blocked)" in result.worst_constraint
        assert "crate" in result.worst_constraint or "blocked" in result.worst_constraint
        assert result.iterations < problem.options.max_iterations


def test_object_larger_than_region_is_proved_infeasible(planar):
    scene, modes, world = planar
    import dataclasses

    small = dataclasses.replace(scene, regions=tuple(
        dataclasses.replace(r, size=(0.05, 0.05)) if r.name == "goal" else r
        for r in scene.regions))
    problem = lower(ops("(push o start goal floor)"), small, modes, world)
    result = solve(problem, "final")
    assert result.status == "infeasible" and result.proved
    # Sizes to the millimetre: whole centimetres would hide a 5 mm shortfall.
    assert "does not fit region goal (5.0 x 5.0 cm)" in result.worst_constraint


def test_move_ends_with_the_tool_in_the_region(planar):
    from tampcli.optimize.modes import Mode

    scene, _, world = planar
    modes = {"goto": Mode("goto", "move", to="?r", params=("?r",))}
    problem = lower(ops("(goto goal)"), scene, modes, world)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert [p.action for p in result.phases] == ["(goto goal)"]
    # Round the pillar, the planar route's segments are no longer than the disk is wide
    # (motion.planar_segments): at least `waypoints` of them.
    segments = result.phases[0].end - result.phases[0].start
    assert problem.options.waypoints <= segments <= 4 * problem.options.waypoints
    steps = np.linalg.norm(np.diff(result.trajectory, axis=0), axis=1)
    assert steps.max() <= 2 * 2 * scene.robot.radius
    region = scene.region("goal")
    end = result.trajectory[-1]
    assert np.all(np.abs(end - np.array(region.center)) <= 0.5 * np.array(region.size) + 1e-6)
    assert verify(problem, result) == []


def test_warm_start_from_a_solved_prefix(planar):
    scene, modes, world = planar
    prefix = lower(ops("(pick o start)"), scene, modes, world)
    warm = solve(prefix, "keyframes")
    assert warm.solved
    full = lower(ops("(pick o start)", "(place o goal)"), scene, modes, world)
    result = solve(full, "keyframes", warm)
    assert result.solved
    assert len(warm.keyframes) <= len(result.keyframes)
    path = solve(full, "path", result)
    assert path.solved and verify(full, path) == []


def test_time_limit_gives_limit_not_an_exception(wall):
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world,
                    OptimizeOptions(time_limit=0.01))
    result = solve(problem, "path")
    assert result.status == "limit"
    assert result.worst_constraint
