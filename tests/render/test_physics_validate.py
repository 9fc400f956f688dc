"""`validate --physics`: the physics replay judges a solution. A tower stacked aligned
stands; one whose cubes each rest on the one below but overhang together falls, and
the verdict names the cubes that fell and the action that made them fall."""

import json

import numpy as np
import pytest
from tower_solution import DOMAIN, TOWER, tower_solution

from tampcli import solution as solution_file
from tampcli.render.inputs import load_inputs, mode_kind_of
from tampcli.render.physics import replay_physics
from tampcli.render.physics_values import drift_violations, object_mass
from tests.conftest import ROOT

TOWER_PROBLEM = TOWER / "tower4.pddl"
# Each cube's centre lies on the one below, so the geometric check passes; b and a
# together lean 2.7 cm out from c's centre, past its 2.5 cm half-width.
LEANING = {"c": (0.02, 0.0), "b": (0.02, 0.0), "a": (0.019, 0.0)}


@pytest.fixture(scope="module")
def tower(tmp_path_factory):
    path = tmp_path_factory.mktemp("tower") / "aligned.json"
    solution_file.write(tower_solution(), path)
    return path


@pytest.fixture(scope="module")
def leaning(tmp_path_factory):
    path = tmp_path_factory.mktemp("tower") / "leaning.json"
    solution_file.write(tower_solution(LEANING), path)
    return path


def test_aligned_tower_of_four_stands(cli, tower):
    run = cli("validate", "--json", "--physics", DOMAIN, TOWER_PROBLEM, tower)
    data = json.loads(run.out)
    assert run.code == 0, data["violations"]
    physics = data["physics"]
    assert set(physics["objects"]) == {"a", "b", "c", "d"}
    assert physics["max_distance"] < 0.005
    # each cube was lifted onto the tower, not left where it stood
    assert physics["objects"]["a"]["simulated"][2] == pytest.approx(0.06 + 0.05 + 0.04 + 0.015,
                                                                    abs=0.003)


def test_fingers_close_to_the_width_of_what_they_grasp(tower):
    inputs = load_inputs(tower)
    replay = replay_physics(inputs, mode_kind_of(inputs.modes))
    openings = {g.name: g.opening for g in replay.grips}
    assert openings == pytest.approx({"c": 0.05, "b": 0.04, "a": 0.03}, abs=0.004)


def test_leaning_tower_is_refused_naming_what_fell(cli, leaning):
    run = cli("validate", "--json", "--physics", DOMAIN, TOWER_PROBLEM, leaning)
    data = json.loads(run.out)
    assert run.code == 1
    # The stability check refuses it too (footprints off the faces below), and the
    # replay shows the fall.
    assert {v["kind"] for v in data["violations"]} == {"geometric", "physics"}
    fell = {v["object"]: v for v in data["violations"] if v["kind"] == "physics"}
    assert {"a", "b"} <= set(fell) and "d" not in fell
    assert fell["b"]["phase_label"] == "(stack a b)"
    assert data["physics"]["objects"]["b"]["distance"] > 0.05


def test_leaning_tower_text_names_object_drift_and_phase(cli, leaning):
    run = cli("validate", "--physics", DOMAIN, TOWER_PROBLEM, leaning)
    assert run.code == 1
    line = next(s for s in run.out.splitlines() if "physics: b ends" in s)
    assert "tolerance 0.01 m, 5 deg" in line and "(stack a b)" in line


def test_hand_sweeping_through_a_placed_cube_is_refused(cli, tmp_path):
    """Leaving each cube sideways, the fingers sweep through it in the first segment of
    the retreat: contact the planner allows there, and the replay lets through, but
    not 2 cm deep."""
    path = tmp_path / "sideways.json"
    solution_file.write(tower_solution(lift=False), path)
    run = cli("validate", "--json", "--physics", DOMAIN, TOWER_PROBLEM, path)
    data = json.loads(run.out)
    assert run.code == 1
    swept = [v for v in data["violations"] if v["kind"] == "physics"]
    assert [v["object"] for v in swept] == ["c"] and swept[0]["phase"] == 4
    assert "mm deeper than where it takes or lets go of it" in swept[0]["text"]
    overlap = data["physics"]["overlaps"][0]
    assert overlap["depth"] - overlap["contact"] > 0.015


def test_tolerance_flags_change_the_verdict(cli, tower):
    run = cli("validate", "--physics", DOMAIN, TOWER_PROBLEM, tower)
    assert run.code == 0, run.out
    run = cli("validate", "--physics", "--max-drift", "1e-6", "--max-turn", "1e-4", DOMAIN,
              TOWER_PROBLEM, tower)
    assert run.code == 1 and "physics:" in run.out, run.out


def test_without_the_flag_physics_is_not_consulted(cli, leaning):
    run = cli("validate", "--json", DOMAIN, TOWER_PROBLEM, leaning)
    data = json.loads(run.out)
    assert "physics" not in data
    assert {v["kind"] for v in data["violations"]} == {"geometric"}


def test_violations_match_the_replay(leaning):
    inputs = load_inputs(leaning)
    replay = replay_physics(inputs, mode_kind_of(inputs.modes))
    found = drift_violations(replay, 0.01, 5.0)
    assert {v.drift.name for v in found} == {o.name for o in replay.objects
                                             if o.distance > 0.01 or o.angle_deg > 5.0}
    b = next(v for v in found if v.drift.name == "b")
    # before a was stacked, b stood where the plan put it
    assert all(d.distance < 0.01 for d in b.drift.phases if d.phase < b.first.phase)


def test_masses_from_density_or_the_scene(leaning):
    scene = load_inputs(leaning).scene
    assert object_mass(scene.body("c"), 500.0) == pytest.approx(0.05 ** 3 * 500.0)
    assert object_mass(scene.body("a"), 500.0) == pytest.approx(0.02)  # `mass = 0.02`


@pytest.mark.parametrize("flag", ["--max-drift", "--max-turn"])
def test_non_positive_tolerance_exits_2(cli, leaning, flag):
    run = cli("validate", "--physics", flag, "0", DOMAIN, TOWER_PROBLEM, leaning)
    assert run.code == 2 and flag in run.err and "Traceback" not in run.err


def test_physics_of_an_unsolved_solution_is_invalid_not_bad_input(cli, tmp_path):
    """A solution.json that `solve` left unsolved has nothing to replay: the verdict is
    the plain one (invalid, exit 1), with a warning, not a rendering error."""
    import dataclasses

    unsolved = dataclasses.replace(tower_solution(), status="limit", reason="time limit",
                                   plan=(), trajectory=(), phases=(), objects={})
    path = tmp_path / "unsolved.json"
    solution_file.write(unsolved, path)
    run = cli("validate", "--physics", DOMAIN, TOWER_PROBLEM, path)
    assert run.code == 1, run.err
    assert "nothing replayed" in run.err and "render" not in run.err + run.out
    data = json.loads(cli("validate", "--json", "--physics", DOMAIN, TOWER_PROBLEM, path).out)
    assert data["valid"] is False and "physics" not in data


def test_physics_of_a_plan_file_exits_2(cli, tmp_path):
    plan = tmp_path / "plan.txt"
    plan.write_text("(pick c start)\n")
    run = cli("validate", "--physics", DOMAIN, TOWER_PROBLEM, plan)
    assert run.code == 2 and "solution.json" in run.err


# ---------------------------------------------------------------- library solutions

# The library's scenes (the blind robustness sets are judged in tests/robustness).
SCENES = sorted(s for s in ROOT.glob("problems/*/*.scene.toml")
                if not s.parent.name.startswith("robust-"))


def _key(scene) -> str:
    return f"{scene.parent.name}/{scene.name.split('.')[0]}"


def _solve_and_validate(cli, scene, tmp_path):
    domain = ROOT / "domains" / scene.parent.name / "domain.pddl"
    problem = scene.parent / (scene.name.split(".")[0] + ".pddl")
    out = tmp_path / "solution.json"
    solved = cli("solve", "--quiet", "--out", out, domain, problem)
    assert solved.code == 0, solved.err
    run = cli("validate", "--json", "--physics", domain, problem, out)
    data = json.loads(run.out)
    return run.code, data


@pytest.mark.parametrize("key", ["arm-pick-place/p01", "planar-tamp/p01"])
def test_quick_library_solutions_pass_physics(cli, key, tmp_path):
    scene = ROOT / "problems" / f"{key}.scene.toml"
    code, data = _solve_and_validate(cli, scene, tmp_path)
    assert code == 0, data["violations"]
    assert data["physics"]["max_distance"] < 0.01


@pytest.mark.slow
@pytest.mark.parametrize("scene", SCENES, ids=[_key(s) for s in SCENES])
def test_every_library_solution_passes_physics(cli, scene, tmp_path):
    code, data = _solve_and_validate(cli, scene, tmp_path)
    assert code == 0, data["violations"]


def test_a_turn_about_its_own_axis_is_no_drift_for_a_cylinder_or_a_sphere():
    from tampcli.geometry import transforms
    from tampcli.render.physics import _drift

    planned = transforms.pose_from_xyzquat((0.4, 0.0, 0.05, 0.0, 0.0, 0.0, 1.0))
    turned = planned.copy()
    c, s = np.cos(0.9), np.sin(0.9)
    turned[:3, :3] = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    tipped = planned.copy()
    tipped[:3, :3] = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    assert _drift(planned, turned)[1] == pytest.approx(np.degrees(0.9))  # a box
    assert _drift(planned, turned, "axis")[1] == pytest.approx(0.0, abs=1e-6)
    assert _drift(planned, tipped, "axis")[1] == pytest.approx(np.degrees(0.9))
    assert _drift(planned, tipped, "full")[1] == 0.0


def test_an_object_knocked_by_a_link_names_the_link_and_the_phase(cli, tmp_path):
    """A free motion whose fourth waypoint puts the left finger through cube a, which
    stands clear of the plan: the verdict names what struck it and when (blind31
    DOC_GAPS 1: the hand leaving a tower sideways swept a cube off it, and the verdict
    named only the phase)."""
    import dataclasses

    from tower_solution import TOWER as FOLDER

    from tampcli.geometry.scene import load_scene
    from tampcli.geometry.world import World

    solution = tower_solution()
    scene = load_scene(FOLDER / "tower4.scene.toml", geometric=False)
    with World(scene) as world:
        a = next(b for b in scene.bodies if b.name == "a").matrix[:3, 3]
        target = world.tool_pose(world.start)
        target[:3, 3] = a + [0.0, 0.04, 0.0]  # a finger where a stands
        q, residual = world.ik(target, world.start)
        assert residual < 1e-6
    trajectory = list(solution.trajectory)
    assert solution.phases[0].attached is None and solution.phases[0].end > 3
    trajectory[3] = tuple(float(v) for v in q)
    path = tmp_path / "knock.json"
    solution_file.write(dataclasses.replace(solution, trajectory=tuple(trajectory)), path)
    run = cli("validate", "--json", "--physics", DOMAIN, TOWER_PROBLEM, path)
    data = json.loads(run.out)
    assert run.code == 1
    knocked = [v for v in data["violations"] if v["kind"] == "physics"]
    assert [v["object"] for v in knocked] == ["a"]
    assert "touched by panda_leftfinger in phase 0: move" in knocked[0]["text"]
    touches = data["physics"]["touches"]
    assert touches[0]["object"] == "a" and touches[0]["link"] == "panda_leftfinger"
    assert touches[0]["phase"] == 0
    # the plan as made touches nothing it keeps clear
    inputs = load_inputs(_written(tmp_path))
    assert replay_physics(inputs, mode_kind_of(inputs.modes)).touches == ()


def _written(tmp_path):
    path = tmp_path / "aligned.json"
    solution_file.write(tower_solution(), path)
    return path
