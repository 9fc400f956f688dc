import json

import pytest

from tests.conftest import IPC, ROOT

BW = ROOT / "domains" / "blocksworld" / "domain.pddl"
BW1 = ROOT / "problems" / "blocksworld" / "p01.pddl"
GRIPPER = IPC / "gripper" / "domain.pddl"
GRIPPER1 = IPC / "gripper" / "prob01.pddl"
TRANSPORT = IPC / "transport-opt08-strips" / "domain.pddl"
TRANSPORT1 = IPC / "transport-opt08-strips" / "p01.pddl"
MICONIC_ADL = IPC / "miconic-fulladl" / "domain.pddl"
MICONIC_ADL1 = IPC / "miconic-fulladl" / "f1-0.pddl"


def _actions(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.startswith("(")]


def test_plan_prints_ipc_format_and_stats(cli):
    run = cli("plan", GRIPPER, GRIPPER1)
    assert run.code == 0, run.err
    lines = run.out.strip().splitlines()
    assert all(line.startswith("(") and line.endswith(")") for line in lines[:-1])
    assert lines[-1] == f"; cost = {len(lines) - 1} (unit cost)"
    assert "expanded" in run.err and "ground" in run.err and "parse" in run.err


def test_optimal_plan_with_general_cost(cli):
    run = cli("plan", TRANSPORT, TRANSPORT1, "--search", "astar", "--heuristic", "lmcut")
    assert run.code == 0, run.err
    assert run.out.strip().splitlines()[-1] == "; cost = 54 (general cost)"


def test_json_output(cli):
    run = cli("plan", GRIPPER, GRIPPER1, "--search", "astar", "--json")
    assert run.code == 0, run.err
    data = json.loads(run.out)
    assert data["status"] == "solved"
    assert data["plans"][0]["cost"] == 11 and len(data["plans"][0]["actions"]) == 11
    assert data["stats"]["heuristic"] == "lmcut" and data["stats"]["expanded"] > 0
    assert set(data["stats"]["seconds"]) == {"parse", "ground", "search"}


def test_out_file_matches_stdout(cli, tmp_path):
    out = tmp_path / "plan.txt"
    run = cli("plan", BW, BW1, "--out", out)
    assert run.code == 0, run.err
    assert out.read_text() == run.out


@pytest.mark.parametrize("search", ["astar", "gbfs", "lazy-gbfs", "wastar"])
def test_conditional_effects_through_the_cli(cli, search):
    run = cli("plan", MICONIC_ADL, MICONIC_ADL1, "--search", search, "--heuristic", "hmax")
    assert run.code == 0, run.err
    assert _actions(run.out)


def test_lmcut_on_conditional_effects_is_bad_input(cli):
    run = cli("plan", MICONIC_ADL, MICONIC_ADL1, "--search", "astar", "--heuristic", "lmcut")
    assert run.code == 2
    assert "lmcut does not support conditional effects" in run.err and "hmax" in run.err
    assert "Traceback" not in run.err


def test_default_optimal_heuristic_falls_back_on_conditional_effects(cli):
    run = cli("plan", MICONIC_ADL, MICONIC_ADL1, "--search", "astar", "--json")
    assert run.code == 0, run.err
    assert json.loads(run.out)["stats"]["heuristic"] == "hmax"


def _unsolvable(tmp_path):
    domain = tmp_path / "d.pddl"
    domain.write_text("""(define (domain d) (:predicates (p) (q))
      (:action a :parameters () :precondition (p) :effect (q)))""")
    problem = tmp_path / "p.pddl"
    problem.write_text("(define (problem x) (:domain d) (:init (q)) (:goal (p)))")
    return domain, problem


def test_unsolvable_exits_1(cli, tmp_path):
    run = cli("plan", *_unsolvable(tmp_path))
    assert run.code == 1
    assert "unsolvable" in run.err
    run = cli("plan", *_unsolvable(tmp_path), "--json")
    assert run.code == 1 and json.loads(run.out)["status"] == "unsolvable"


def test_limit_exits_1(cli):
    run = cli("plan", GRIPPER, IPC / "gripper" / "prob05.pddl", "--search", "astar",
              "--heuristic", "blind", "--max-expansions", "10")
    assert run.code == 1
    assert "limit" in run.err


@pytest.mark.parametrize("argv,message", [
    (["-k", "0"], "-k must be at least 1"),
    (["--time-limit", "0"], "time limit must be positive"),
    (["--weight", "0.5"], "weight must be >= 1"),
    (["--search", "dfs"], "invalid choice"),
])
def test_bad_flags_are_usage_errors(cli, argv, message):
    run = cli("plan", GRIPPER, GRIPPER1, *argv)
    assert run.code == 2
    assert message in run.err


def test_missing_file_is_bad_input(cli, tmp_path):
    run = cli("plan", GRIPPER, tmp_path / "nope.pddl")
    assert run.code == 2 and "file not found" in run.err


def test_top_k_writes_one_file_per_plan(cli, tmp_path):
    pytest.importorskip("tampcli.search.topk")
    out = tmp_path / "plan"
    run = cli("plan", GRIPPER, GRIPPER1, "-k", "3", "--out", out, "--json")
    assert run.code == 0, run.err
    plans = json.loads(run.out)["plans"]
    assert len(plans) == 3
    assert [p["cost"] for p in plans] == sorted(p["cost"] for p in plans)
    assert plans[0]["cost"] == 11
    assert out.exists() and (tmp_path / "plan.1").exists() and (tmp_path / "plan.2").exists()
    assert _actions(out.read_text()) == plans[0]["actions"]
    assert _actions((tmp_path / "plan.2").read_text()) == plans[2]["actions"]


ELEVATORS = IPC / "elevators-opt08-strips" / "domain.pddl"
ELEVATORS3 = IPC / "elevators-opt08-strips" / "p03.pddl"


def test_default_is_lama_and_drops_redundant_steps(cli):
    run = cli("plan", GRIPPER, GRIPPER1, "--json")
    assert run.code == 0, run.err
    stats = json.loads(run.out)["stats"]
    assert (stats["search"], stats["heuristic"]) == ("lama", "lmcount")
    assert stats["eliminated"] >= 0


def test_help_documents_lama_and_anytime(cli, capsys):
    with pytest.raises(SystemExit):
        cli("plan", "--help")
    text = " ".join(capsys.readouterr().out.split())
    assert "default lama" in text and "landmark count" in text and "--anytime" in text


def test_anytime_prints_each_better_plan_and_out_keeps_the_best(cli, tmp_path):
    out = tmp_path / "best.plan"
    run = cli("plan", ELEVATORS, ELEVATORS3, "--anytime", "--time-limit", "60", "--out", out)
    assert run.code == 0, run.err
    costs = [int(line.split()[3]) for line in run.out.splitlines() if line.startswith("; cost")]
    assert len(costs) >= 2 and costs == sorted(costs, reverse=True) and costs[-1] < costs[0]
    assert out.read_text().splitlines()[-1] == f"; cost = {costs[-1]} (general cost)"
    assert "anytime: weight" in run.err


def test_anytime_in_json_lists_the_costs_found(cli):
    run = cli("plan", GRIPPER, GRIPPER1, "--anytime", "--json", "--time-limit", "30")
    assert run.code == 0, run.err
    data = json.loads(run.out)
    found = data["stats"]["anytime"]
    assert found[0]["weight"] is None
    assert [f["cost"] for f in found] == sorted((f["cost"] for f in found), reverse=True)
    assert data["plans"][0]["cost"] == found[-1]["cost"]


def test_anytime_needs_k_1(cli):
    run = cli("plan", GRIPPER, GRIPPER1, "--anytime", "-k", "2")
    assert run.code == 2 and "--anytime" in run.err
