import json
import subprocess
import sys

import pytest

from tests.conftest import IPC, ROOT

GRIPPER = IPC / "gripper" / "domain.pddl"
GRIPPER1 = IPC / "gripper" / "prob01.pddl"
PLAN = ["(pick ball1 rooma left)", "(pick ball2 rooma right)", "(move rooma roomb)",
        "(drop ball2 roomb right)", "(drop ball1 roomb left)", "(move roomb rooma)",
        "(pick ball3 rooma right)", "(pick ball4 rooma left)", "(move rooma roomb)",
        "(drop ball4 roomb left)", "(drop ball3 roomb right)"]


@pytest.fixture
def plan_file(tmp_path):
    def write(lines, name="plan.txt"):
        path = tmp_path / name
        path.write_text("\n".join(lines) + "\n")
        return path

    return write


def test_valid_plan_exits_0_with_cost(cli, plan_file):
    run = cli("validate", GRIPPER, GRIPPER1, plan_file(PLAN + ["; cost = 11 (unit cost)"]))
    assert run.code == 0, run.err
    assert run.out.startswith("valid, cost 11")


def test_invalid_plan_exits_1_and_lists_the_step(cli, plan_file):
    run = cli("validate", GRIPPER, GRIPPER1, plan_file(PLAN[1:]))
    assert run.code == 1
    assert "step 4 (line 4) (drop ball1 roomb left): precondition (carry ball1 left) is false" \
        in run.out


def test_unknown_object_is_an_invalid_plan_not_bad_input(cli, plan_file):
    run = cli("validate", GRIPPER, GRIPPER1, plan_file(["(pick ball9 rooma left)"]))
    assert run.code == 1
    assert "step 1 (line 1)" in run.out and "unknown object ball9" in run.out


def test_goal_not_reached(cli, plan_file):
    run = cli("validate", GRIPPER, GRIPPER1, plan_file(PLAN[:-1]))
    assert run.code == 1
    assert "at the end: goal not reached: (at ball3 roomb) is false" in run.out


def test_bad_plan_syntax_exits_2_with_location(cli, plan_file):
    path = plan_file(["(pick ball1 rooma left)", "(move rooma roomb"])
    run = cli("validate", GRIPPER, GRIPPER1, path)
    assert run.code == 2
    assert f"{path}:3:1:" in run.err and "not closed" in run.err
    assert "Traceback" not in run.err


def test_json_output(cli, plan_file):
    run = cli("validate", "--json", GRIPPER, GRIPPER1, plan_file(PLAN[1:]))
    data = json.loads(run.out)
    assert data["status"] == "invalid" and data["valid"] is False
    assert data["violations"][0]["step"] == 4
    assert data["violations"][0]["line"] == 4
    run = cli("validate", "--json", GRIPPER, GRIPPER1, plan_file(PLAN))
    data = json.loads(run.out)
    assert (data["status"], data["cost"], data["steps"]) == ("valid", 11, 11)


def test_declared_cost_mismatch_is_a_warning(cli, plan_file):
    run = cli("validate", GRIPPER, GRIPPER1, plan_file(PLAN + ["; cost = 9 (unit cost)"]))
    assert run.code == 0
    assert "declares cost 9" in run.err


def write_solution(tmp_path, plan):
    from tampcli import solution

    path = tmp_path / "solution.json"
    solution.write(solution.Solution(str(GRIPPER), str(GRIPPER1), None, "solved",
                                     plan=tuple(plan), symbolic_cost=len(plan)), path)
    return path


def test_solution_json_plan_is_checked(cli, tmp_path):
    run = cli("validate", "--json", GRIPPER, GRIPPER1, write_solution(tmp_path, PLAN[:-1]))
    data = json.loads(run.out)
    assert run.code == 1
    assert data["violations"][0]["kind"] == "symbolic"
    assert "goal not reached" in data["violations"][0]["reason"]


def test_symbolic_solution_json_is_valid(cli, tmp_path):
    run = cli("validate", "--json", GRIPPER, GRIPPER1, write_solution(tmp_path, PLAN))
    data = json.loads(run.out)
    assert run.code == 0, run.out + run.err
    assert data["status"] == "valid" and data["cost"] == 11
    assert data["geometry"] in ("checked", "unavailable")


def test_solution_json_not_json_exits_2(cli, plan_file):
    run = cli("validate", GRIPPER, GRIPPER1,
              plan_file(['{"plan": ["(move rooma roomb)",]}'], "solution.json"))
    assert run.code == 2, run.out
    assert ":1:" in run.err and "not valid JSON" in run.err
    assert "Traceback" not in run.err


@pytest.mark.parametrize("edit,where", [
    (lambda d: d.pop("plan"), "plan: missing key"),
    (lambda d: d.update(plan="(move rooma roomb)"), "plan: expected a list"),
    (lambda d: d.update(plan=["(move rooma roomb)", 3]), "plan[1]: expected a string"),
    (lambda d: d.update(plan=["(move rooma roomb) (move roomb rooma)"]),
     "plan[0]: expected one step"),
])
def test_bad_solution_json_exits_2(cli, tmp_path, edit, where):
    path = write_solution(tmp_path, PLAN)
    data = json.loads(path.read_text())
    edit(data)
    path.write_text(json.dumps(data))
    run = cli("validate", GRIPPER, GRIPPER1, path)
    assert run.code == 2, run.out
    assert f"{path}: {where}" in run.err
    assert "Traceback" not in run.err


PLANAR = ROOT / "domains" / "planar-tamp" / "domain.pddl"
PLANAR1 = ROOT / "problems" / "planar-tamp" / "p01.pddl"


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    """A real solution.json of a geometric problem, made by `tampcli solve`."""
    out = tmp_path_factory.mktemp("solve") / "p01.json"
    subprocess.run([sys.executable, "-m", "tampcli", "solve", str(PLANAR), str(PLANAR1),
                    "--out", str(out), "--time-limit", "120", "--quiet"],
                   check=True, capture_output=True, timeout=300, cwd=ROOT)
    data = json.loads(out.read_text())
    assert data["status"] == "solved"
    data["scene"] = str((ROOT / data["scene"]).resolve())
    out.write_text(json.dumps(data))
    return out, data


def test_geometric_solution_is_valid(cli, solved):
    path, _ = solved
    run = cli("validate", "--json", PLANAR, PLANAR1, path)
    data = json.loads(run.out)
    assert run.code == 0, run.out
    assert data["geometry"] == "checked" and data["violations"] == []


def test_geometric_violation_is_listed(cli, solved, tmp_path):
    _, data = solved
    data = dict(data, trajectory=[list(q) for q in data["trajectory"]])
    data["trajectory"][5] = [5.0, 5.0]  # far outside the workspace
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(data))
    run = cli("validate", PLANAR, PLANAR1, bad)
    assert run.code == 1
    assert "waypoint 5" in run.out
