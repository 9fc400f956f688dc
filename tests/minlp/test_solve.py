"""The MINLP end to end: proved optima on small models, the hold evolution, solutions that
`validate` accepts, refusals of what it cannot model."""

import json
from pathlib import Path

import pytest

from tampcli import cli as cli_module
from tampcli.minlp import MinlpOptions, solve_minlp
from tampcli.minlp.model import build
from tampcli.minlp.solve import prepare
from tampcli.solution import write

ROOT = Path(__file__).resolve().parents[2]
PUSH = (str(ROOT / "domains/planar-push/domain.pddl"), str(ROOT / "problems/planar-push/p01.pddl"))
PUSH_P03 = (str(ROOT / "domains/planar-push/domain.pddl"),
            str(ROOT / "problems/planar-push/p03.pddl"))
DUAL = (str(ROOT / "domains/planar-tamp/domain.pddl"), str(ROOT / "problems/planar-tamp/p04.pddl"))


@pytest.fixture
def minlp_cli(cli, monkeypatch):
    """The real CLI with the MINLP command registered, as the lead wires it."""
    monkeypatch.setitem(cli_module.COMMANDS, "minlp", "tampcli.cli.minlp")
    monkeypatch.setitem(cli_module._HELP, "minlp", "the time-indexed MINLP")
    return cli


def test_a_small_model_is_solved_to_proved_optimality():
    sol = solve_minlp(*PUSH, options=MinlpOptions(steps=3, time_limit=60))
    assert sol.status == "solved"
    assert sol.stats["scip_status"] == "optimal"
    # Pushing the box round the obstacle would be a drag (outside the friction cone of
    # every face): pick and place it is.
    assert sol.plan == ("(pick box start)", "(place box goal)")
    assert sol.lower_bound == pytest.approx(sol.objective, rel=1e-4)
    # The objective is exactly tampcli's: squared displacements + w * symbolic cost.
    steps = zip(sol.trajectory, sol.trajectory[1:], strict=False)
    moved = sum((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2 for a, b in steps)
    assert sol.objective == pytest.approx(moved + 0.1 * 4.0)
    assert len(sol.trajectory) == 4


def test_hold_follows_grasp_and_place():
    options = MinlpOptions(steps=4, time_limit=60)
    prepared = prepare(*DUAL, None, None, options)
    built = build(prepared.task, prepared.scene, prepared.modes, prepared.lower,
                  prepared.upper, prepared.start, options)
    built.model.optimize()
    assert built.model.getStatus() == "optimal"
    val = built.model.getVal
    names = [op.name for op in prepared.task.operators]
    hold = [0.0] + [val(built.carry.hold["a"][k]) for k in range(1, 5)]
    for k in range(1, 5):
        grasp = sum(val(built.sym.d[k][i]) for i, n in enumerate(names) if n.startswith("(pick a"))
        place = sum(val(built.sym.d[k][i]) for i, n in enumerate(names)
                    if n.startswith("(place a"))
        assert hold[k] == pytest.approx(hold[k - 1] + grasp - place, abs=1e-6)
    assert max(hold) == pytest.approx(1.0) and hold[-1] == pytest.approx(0.0)
    # While held, the block keeps its offset to the disk.
    held = [k for k in range(1, 4) if hold[k] > 0.5]
    offsets = {tuple(round(val(built.objects["a"][k][a]) - val(built.robot[k][a]), 5)
                     for a in range(2)) for k in held + [held[-1] + 1]}
    assert len(offsets) == 1


def test_a_push_solution_at_8_steps_validates(minlp_cli, cli, tmp_path):
    # planar-push p03: a crate that cannot be lifted, pushed straight (p01, whose push
    # is a drag, is solved to a proved optimum and validated in the slow test below).
    out = tmp_path / "p03.solution.json"
    run = minlp_cli("minlp", *PUSH_P03, "--steps", "8", "--time-limit", "60", "--out", out)
    assert run.code == 0, run.err
    data = json.loads(out.read_text())
    assert data["plan"] == ["(push crate start goal table)"]
    assert len(data["trajectory"]) == 9
    assert data["lower_bound"] <= data["objective"] + 1e-9
    check = cli("validate", *PUSH_P03, out)
    assert check.code == 0, check.out + check.err
    assert check.out.startswith("valid")


def test_a_warm_start_from_a_solution_file_is_taken(tmp_path):
    first = solve_minlp(*DUAL, options=MinlpOptions(steps=4, time_limit=60))
    path = tmp_path / "warm.solution.json"
    write(first, path)
    again = solve_minlp(*DUAL, options=MinlpOptions(steps=4, time_limit=60,
                                                    warm_start=str(path)))
    assert again.stats["warm_start"].startswith("2 actions and the robot's waypoints")
    assert again.objective == pytest.approx(first.objective, rel=1e-4)


def test_a_fixed_schedule_keeps_the_actions_where_the_file_has_them(tmp_path):
    first = solve_minlp(*DUAL, options=MinlpOptions(steps=4, time_limit=60,
                                                    forced=("(place a far)",)))
    path = tmp_path / "far.solution.json"
    write(first, path)
    fixed = solve_minlp(*DUAL, options=MinlpOptions(steps=4, time_limit=60,
                                                    schedule=str(path)))
    assert fixed.plan == first.plan == ("(pick a ground)", "(place a far)")
    assert [(p.action, p.start, p.end) for p in fixed.phases] == \
        [(p.action, p.start, p.end) for p in first.phases]
    assert fixed.objective == pytest.approx(first.objective, rel=1e-4)


def test_a_forced_action_gives_the_other_skeleton():
    sol = solve_minlp(*DUAL, options=MinlpOptions(steps=4, time_limit=60,
                                                  forced=("(place a far)",)))
    assert sol.plan == ("(pick a ground)", "(place a far)")


def test_a_panda_scene_is_refused_with_exit_2(minlp_cli):
    run = minlp_cli("minlp", ROOT / "domains/arm-pick-place/domain.pddl",
                    ROOT / "problems/arm-pick-place/p01.pddl")
    assert run.code == 2
    assert "p01.scene.toml" in run.err and "robot.model" in run.err
    assert "planar robot only" in run.err and "Traceback" not in run.err


def test_a_sphere_is_refused_with_its_scene_key(minlp_cli, tmp_path):
    text = (ROOT / "problems/planar-push/p01.scene.toml").read_text()
    text = text.replace('shape = "cylinder"\nsize = [0.2, 0.1]', 'shape = "sphere"\nsize = [0.05]')
    scene = tmp_path / "p01.scene.toml"
    scene.write_text(text)
    run = minlp_cli("minlp", *PUSH, "--scene", scene, "--modes",
                    ROOT / "domains/planar-push/modes.toml")
    assert run.code == 2
    assert "objects.shape" in run.err and "box and cylinder bodies only" in run.err


@pytest.mark.slow
def test_scip_closes_the_gap_on_planar_push_p01_at_8_steps_within_120_s(cli, tmp_path):
    sol = solve_minlp(*PUSH, options=MinlpOptions(steps=8, time_limit=120, gap=0.01))
    assert sol.stats["gap"] is not None and sol.stats["gap"] <= 0.01
    out = tmp_path / "p01.solution.json"
    write(sol, out)
    check = cli("validate", *PUSH, out)
    assert check.code == 0, check.out + check.err
