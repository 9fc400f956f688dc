"""verify: the independent check, on results and on solution.json files."""

import dataclasses

import numpy as np
import pytest

from tampcli import solution
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.optimize.verify import verify, verify_solution_file

from .helpers import SCENES, domain_path, load, ops

PLAN = ("(pick o start)", "(place o goal)")


@pytest.fixture(scope="module")
def solved(planar):
    scene, modes, world = planar
    problem = lower(ops(*PLAN), scene, modes, world)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    return problem, result


def _write(tmp_path, problem, result, **changes):
    world = problem.world
    sol = solution.Solution(
        domain=str(domain_path("planar")), problem=str(SCENES / "planar.pddl"),
        scene=str(SCENES / "planar.scene.toml"), status="solved", plan=PLAN,
        symbolic_cost=4.0, cost=result.cost, robot={
            "model": "planar", "joints": list(world.joint_names), "tool_link": world.tool_link},
        trajectory=tuple(tuple(q) for q in result.trajectory), phases=result.phases,
        objects=result.object_poses, modes=str(domain_path("planar").with_name("modes.toml")))
    sol = dataclasses.replace(sol, **changes)
    path = tmp_path / "solution.json"
    solution.write(sol, path)
    return path


def test_solution_file_round_trip_is_valid(tmp_path, solved):
    problem, result = solved
    path = _write(tmp_path, problem, result)
    assert verify_solution_file(path) == []
    # As `tampcli validate` calls it: with the parsed domain and problem.
    domain, problem_ast, _, _ = load("planar")
    assert verify_solution_file(path, domain, problem_ast) == []


def test_a_waypoint_through_the_pillar_is_a_collision(tmp_path, solved):
    problem, result = solved
    traj = [list(q) for q in result.trajectory]
    pillar = problem.scene.body("pillar").pose
    phase = result.phases[2]  # carrying o
    traj[phase.start + 3] = [pillar[0], pillar[1]]
    path = _write(tmp_path, problem, result, trajectory=tuple(map(tuple, traj)))
    problems = verify_solution_file(path)
    assert any("collision" in p and "pillar" in p for p in problems), problems


def test_an_object_left_outside_its_region_is_reported(tmp_path, solved):
    problem, result = solved
    objects = {k: [list(p) for p in v] for k, v in result.object_poses.items()}
    objects["o"][-1][0] += 0.3
    problems = verify_solution_file(_write(tmp_path, problem, result, objects=objects))
    assert any("outside region goal" in p for p in problems), problems
    # ... and it jumped at the release.
    assert any("(place o goal): o jumps" in p for p in problems), problems


def test_joint_limits_and_unmoved_objects(solved):
    problem, result = solved
    traj = np.array(result.trajectory)
    traj[1, 0] = problem.world.upper[0] + 0.5
    bad = dataclasses.replace(result, trajectory=traj)
    assert any("outside" in p and "joint x" in p for p in verify(problem, bad))
    poses = {k: [list(p) for p in v] for k, v in result.object_poses.items()}
    poses["o"][1][1] += 0.05  # moved during the free approach, while nobody holds it
    moved = dataclasses.replace(result, object_poses=poses)
    assert any("moves but is not attached" in p for p in verify(problem, moved))


def test_a_push_that_starts_away_from_the_object(planar):
    scene, modes, world = planar
    problem = lower(ops("(push o start goal floor)"), scene, modes, world)
    result = solve(problem, "path")
    assert result.solved and verify(problem, result) == []
    push = result.phases[1]
    assert push.action == "(push o start goal floor)" and push.attached == "o"
    traj = np.array(result.trajectory)
    traj[push.start] += np.array([0.0, -0.1])
    problems = verify(problem, dataclasses.replace(result, trajectory=traj))
    assert any("the push starts" in p and "away from o" in p for p in problems), problems
