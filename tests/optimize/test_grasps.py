"""Grasp families: the side grip's Jacobians, the keyframe rows of a side grasp, a bar
from under a low shelf (solved from the side, validated; infeasible from the top),
and modes.toml's `grasps` key."""

from __future__ import annotations

import dataclasses
import json
import math
import shutil

import numpy as np
import pytest

from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.optimize import grasp_families as F
from tampcli.optimize.bodies import BodyInfo
from tampcli.optimize.grips import Kinematics, PitchGrip, held_pose
from tampcli.optimize.init import final_guess, keyframe_guess
from tampcli.optimize.modes import load_modes
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.optimize.stages import keyframe_layout, keyframe_rows
from tampcli.optimize.units import cm
from tampcli.optimize.verify import verify
from tampcli.pddl import parser

from .helpers import ROOT, SCENES, central_differences, ops
from .test_gradients import _check

DOMAIN = ROOT / "domains" / "robust-arm" / "domain.pddl"
SHELF = SCENES / "shelf.pddl"
PLAN = ("(pick a under-shelf)", "(place a mat)")


@pytest.fixture(scope="module")
def shelf():
    domain = parser.parse_domain_file(DOMAIN)
    scene = load_scene(SCENES / "shelf.scene.toml", domain, parser.parse_problem_file(SHELF))
    modes = load_modes(DOMAIN.with_name("modes.toml"), domain)
    with World(scene) as world:
        yield scene, modes, world


@pytest.mark.parametrize(("psi", "roll"), [(0.0, 1.0), (0.5 * math.pi, -1.0), (0.7, 1.0)])
def test_pitch_grip_jacobians(shelf, psi, roll):
    _, _, world = shelf
    kin = Kinematics(world)
    grip = PitchGrip((-0.05, 0.01, 0.02), psi=psi, roll=roll)
    q = np.random.default_rng(3).uniform(world.lower, world.upper)
    t = 0.3

    def value(qq, tt):
        h = held_pose(kin.frame(qq), grip, tt)
        return np.concatenate([h.pos, h.axes.reshape(-1, order="F")])

    h = held_pose(kin.frame(q), grip, t)
    analytic = np.vstack([h.dpos_dq, h.daxes_dq[:, 0], h.daxes_dq[:, 1], h.daxes_dq[:, 2]])
    np.testing.assert_allclose(analytic, central_differences(lambda qq: value(qq, t), q, 1e-6), atol=1e-6)
    dt = np.concatenate([h.dpos_dt, h.daxes_dt[:, 0], h.daxes_dt[:, 1], h.daxes_dt[:, 2]])
    np.testing.assert_allclose(dt, (value(q, t + 1e-6) - value(q, t - 1e-6)) / 2e-6, atol=1e-6)
    # The grip is a rigid motion: the grasp point is the tool origin, the hand level.
    c, G, _, _ = grip.parts(t)
    np.testing.assert_allclose(G @ G.T, np.eye(3), atol=1e-12)
    np.testing.assert_allclose(-G.T @ c, grip.c0, atol=1e-12)
    assert abs((G.T @ [0.0, 1.0, 0.0])[2]) < 1e-12  # tool y (closing) horizontal


def _side_problem(shelf):
    scene, modes, world = shelf
    problem = lower(ops(*PLAN), scene, modes, world)
    assert problem.error is None and problem.grip_params == (0,)
    placements, _ = final_guess(problem)
    guess, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    return problem, guess, choices


def test_the_guess_takes_the_bar_from_the_side(shelf):
    _, guess, choices = _side_problem(shelf)
    assert choices[0].family == "side"
    assert 0.0 <= guess.grip[0] <= F.SIDE_PITCH


@pytest.mark.parametrize("collisions", [False, True])
def test_side_grasp_keyframe_rows(shelf, collisions):
    """The pitch's column (held pose, collision witness points, range rows) against
    finite differences; near the guess the hand's rows are active."""
    _, _, world = shelf
    problem, guess, choices = _side_problem(shelf)
    layout = keyframe_layout(problem)
    noise = 0.003 if collisions else 0.05
    x = layout.pack(guess.blocks()) + np.random.default_rng(1).normal(0, noise, layout.size)
    kin = Kinematics(world)
    eq, ineq = _check(lambda v: keyframe_rows(problem, v, choices, kin, problem.checker,
                                              world.start, collisions=collisions),
                      layout, x, h=1e-5 if collisions else 1e-6,
                      tol=1e-4 if collisions else 1e-5)
    assert np.max(np.abs(eq)) > 1e-3
    rows = keyframe_rows(problem, layout.unpack(x), choices, kin, problem.checker, world.start,
                         collisions=collisions)
    whats = {label.what for label in rows.ineq.labels}
    assert "side grasp pitched up" in whats
    if collisions:
        assert any(w.startswith("collision") for w in whats)


def test_side_grasp_solves_and_verifies(shelf):
    problem, _, _ = _side_problem(shelf)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert result.choices[0].family == "side"
    assert verify(problem, result) == []


def _domain_copy(tmp_path, grasps: str) -> tuple:
    """robust-arm's domain with `grasps` written into modes.toml's [pick] table."""
    d = tmp_path / "robust-arm"
    d.mkdir()
    shutil.copy(DOMAIN, d / "domain.pddl")
    text = DOMAIN.with_name("modes.toml").read_text()
    text = text.replace("[pick]\n", f"[pick]\n{grasps}\n", 1)
    assert grasps in text
    (d / "modes.toml").write_text(text)
    for suffix in (".pddl", ".scene.toml"):
        shutil.copy(SCENES / f"shelf{suffix}", tmp_path / f"shelf{suffix}")
    return d / "domain.pddl", tmp_path / "shelf.pddl"


def test_side_grasp_solves_and_validates_end_to_end(cli, tmp_path):
    domain, problem = _domain_copy(tmp_path, 'grasps = ["side"]')
    out = tmp_path / "solution.json"
    run = cli("solve", "--quiet", "--time-limit", "60", "--out", out, domain, problem)
    assert run.code == 0, run.err
    assert json.loads(out.read_text())["plan"] == ["(pick a under-shelf)", "(place a mat)"]
    check = cli("validate", domain, problem, out)
    assert check.code == 0, check.out + check.err


def test_top_grasps_only_cannot_reach_under_the_shelf(cli, tmp_path):
    domain, problem = _domain_copy(tmp_path, 'grasps = ["top"]')
    out = tmp_path / "solution.json"
    run = cli("solve", "--quiet", "--time-limit", "60", "--out", out, domain, problem)
    assert run.code == 1
    solution = json.loads(out.read_text())
    assert solution["status"] != "solved"
    first = solution["skeletons"][0]
    assert first["plan"] == ["(pick a under-shelf)", "(place a mat)"]
    assert first["outcome"] == "infeasible"
    assert "(pick a under-shelf)" in run.err and "shelf" in run.err


@pytest.mark.parametrize(("line", "message"), [
    ('grasps = ["top", "sidee"]', "unknown grasp family 'sidee'; expected one of top, side"),
    ('grasps = "top"', "expected a list of grasp families"),
    ("grasps = []", "expected a list of grasp families"),
])
def test_bad_grasps_is_a_located_error(cli, tmp_path, line, message):
    domain, problem = _domain_copy(tmp_path, line)
    run = cli("check", domain, problem)
    assert run.code == 2
    at = domain.with_name("modes.toml").read_text().splitlines().index(line) + 1
    assert f"modes.toml:{at}" in run.err and message in run.err, run.err


def test_grasps_on_a_mode_that_grasps_nothing(cli, tmp_path):
    domain, problem = _domain_copy(tmp_path, "")
    modes = domain.with_name("modes.toml")
    modes.write_text(modes.read_text().replace("[place]\n", '[place]\ngrasps = ["top"]\n'))
    run = cli("check", domain, problem)
    assert run.code == 2 and "mode 'place' takes no `grasps`" in run.err, run.err


def _box(x, y, z):
    return BodyInfo("b", "box", (x / 2, y / 2, z / 2), False, (0.5, 0.0, z / 2, 0.0), True)


def test_families_the_gripper_can_do():
    # Fits across its 4 cm side only: top and side, both closing across y.
    ok, why = F.possible(None, _box(0.12, 0.04, 0.06), 0.08)
    assert ok == ("top", "side") and why == []
    assert {c.psi for c in F.FAMILIES["side"].choices(_box(0.12, 0.04, 0.06), 0.08)} == {
        0.0, math.pi}
    # Wider than the opening both ways: nothing; with no fingers, no width limit.
    ok, why = F.possible(None, _box(0.12, 0.09, 0.06), 0.08)
    assert ok == () and "9.0 cm wide; the gripper opens 8.0 cm and takes at most 7.5 cm" in why[0]
    assert F.possible(None, _box(0.12, 0.09, 0.06), None)[0] == ("top", "side")
    # Too flat for the fingers from the side; the request keeps only what it names.
    ok, why = F.possible(["side"], _box(0.05, 0.05, 0.02), 0.08)
    assert ok == () and why[0].startswith("side: 2.0 cm tall")
    assert F.possible(["top"], _box(0.05, 0.05, 0.05), 0.08)[0] == ("top",)


def test_a_step_keeps_the_families_its_action_allows(shelf):
    scene, modes, world = shelf
    pick = dict(modes.table)["pick"]
    side = {**dict(modes.table), "pick": dataclasses.replace(pick, grasps=("side",))}
    problem = lower(ops(*PLAN), scene, side, world)
    assert problem.error is None  # the bar is 6 cm tall: a side grasp fits
    assert problem.steps[0].kind.families == ("side",)
    top = {**dict(modes.table), "pick": dataclasses.replace(pick, grasps=("top",))}
    problem = lower(ops(*PLAN), scene, top, world)
    assert problem.steps[0].kind.families == ("top",)
    assert problem.grip_params == ()  # a top grasp has no continuous parameter


def _tool(z_axis, y_axis):
    z, y = np.asarray(z_axis, float), np.asarray(y_axis, float)
    t = np.eye(4)
    t[:3, 0], t[:3, 1], t[:3, 2] = np.cross(y, z), y, z
    return t


def test_verify_knows_each_family_by_the_tool_pose():
    obj = np.eye(4)
    top, side = F.FAMILIES["top"], F.FAMILIES["side"]
    down = _tool([0, 0, -1], [0, 1, 0])
    level = _tool([1, 0, 0], [0, 1, 0])
    p = math.radians(40)
    pitched = _tool([math.cos(p), 0, -math.sin(p)], [0, 1, 0])
    steep = _tool([math.cos(1.3), 0, -math.sin(1.3)], [0, 1, 0])
    r = math.radians(20)
    rolled = _tool([1, 0, 0], [0, math.cos(r), math.sin(r)])
    assert top.holds(down, obj) and not side.holds(down, obj)
    assert side.holds(level, obj) and side.holds(pitched, obj) and not top.holds(level, obj)
    assert not side.holds(steep, obj) and not side.holds(rolled, obj)


@pytest.mark.parametrize(("arm", "name", "plan"), [
    ("xarm6", "shelf", PLAN),
    ("xarm6", "ledge", ("(pick a cubby)", "(place a tray)")),
    ("kuka_iiwa", "ledge", ("(pick a cubby)", "(place a tray)")),
])
def test_other_arms_grasp_from_the_side(tmp_path, arm, name, plan):
    """The families use the World's opening and fingertip depth, not the Panda's."""
    domain = parser.parse_domain_file(DOMAIN)
    text = (SCENES / f"{name}.scene.toml").read_text().replace('model = "panda"',
                                                                f'model = "{arm}"')
    text = "\n".join(ln for ln in text.splitlines() if not ln.startswith("start ="))
    path = tmp_path / f"{name}.scene.toml"
    path.write_text(text)
    scene = load_scene(path, domain, parser.parse_problem_file(SCENES / f"{name}.pddl"))
    modes = load_modes(DOMAIN.with_name("modes.toml"), domain)
    with World(scene) as world:
        assert world.gripper_opening is not None
        problem = lower(ops(*plan), scene, modes, world)
        result = solve(problem, "path")
        assert result.solved, result.worst_constraint
        assert result.choices[0].family == "side"
        assert verify(problem, result) == []


def test_a_refusal_at_the_edge_gives_the_figures_to_the_fraction_of_a_millimetre():
    """blind35 DOC_GAPS 1: the xArm6 opens 8.69 cm and takes 8.19; a case 8.195 cm wide
    was refused as "8.2 cm wide; ... takes at most 8.2 cm"."""
    ok, why = F.possible(None, _box(0.10, 0.08195, 0.06), 0.0869)
    assert ok == ()
    assert "8.195 cm wide; the gripper opens 8.69 cm and takes at most 8.19 cm" in why[0]
    # Round figures read as before.
    assert cm(0.09) == "9.0" and cm(0.12) == "12.0" and cm(0.0819) == "8.19"
