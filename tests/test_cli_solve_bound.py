"""`tampcli solve`'s proved lower bound on planar scenes: the collision-free QP of each
skeleton (optimize/relaxed.py) lifts it above w * symbolic cost, never above the
objective."""

import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOMAINS, PROBLEMS = ROOT / "domains", ROOT / "problems"


def _solve(cli, tmp_path, domain, problem):
    out = tmp_path / "solution.json"
    run = cli("solve", "--quiet", "--out", out, DOMAINS / domain / "domain.pddl",
              PROBLEMS / domain / f"{problem}.pddl")
    assert run.code == 0, run.err
    return json.loads(out.read_text())


def test_planar_push_p01_bound_is_above_the_symbolic_one(cli, tmp_path):
    sol = _solve(cli, tmp_path, "planar-push", "p01")
    assert sol["status"] == "solved"
    w = sol["symbolic_weight"]
    # Before: min over open skeletons of w * symbolic cost = w * 2 (the push, whose
    # failure was local). Then the push's relaxation was infeasible (a drag: no face's
    # friction cone reaches the goal), a proof. Now that proof is made before any
    # skeleton (the push cannot be the box's first move: bnb/lessons.first_move_proofs),
    # the push is never drawn, and the answer's own QP bound counts.
    assert sol["stats"]["learning_proved"] >= 1
    assert all(r["plan"] != ["(push box start goal table)"] for r in sol["skeletons"])
    assert sol["skeletons"][0]["plan"] == ["(pick box start)", "(place box goal)"]
    assert sol["lower_bound"] > w * 2 + 0.05
    assert sol["lower_bound"] <= sol["objective"]
    assert sol["lower_bound"] >= w * sol["symbolic_cost"]
    assert 0.0 <= sol["gap"] < 0.1


def test_a_feasible_push_is_bounded_by_its_own_relaxation(cli, tmp_path):
    """planar-push p03: the crate's push is the only skeleton; the bound is its QP."""
    sol = _solve(cli, tmp_path, "planar-push", "p03")
    assert sol["status"] == "solved"
    w = sol["symbolic_weight"]
    assert w * sol["symbolic_cost"] < sol["lower_bound"] <= sol["objective"]
    assert sol["stats"]["stop"] in ("optimal (proved)",
                                    "best of the evaluated skeletons (0 heuristic prunes)")


@pytest.mark.slow
@pytest.mark.parametrize("domain,problem", [
    ("planar-push", "p01"), ("planar-push", "p02"), ("planar-push", "p03"),
    ("planar-tamp", "p01"), ("planar-tamp", "p02"), ("planar-tamp", "p03"),
    ("planar-tamp", "p04")])
def test_every_library_planar_bound_is_below_the_nlp_of_its_skeleton(domain, problem):
    """The relaxation is one: no solved skeleton's trajectory beats its QP bound."""
    from tampcli.optimize.problem import lower
    from tampcli.optimize.relaxed import relaxed_bound
    from tampcli.pipeline import InputPaths, solving

    paths = InputPaths(str(DOMAINS / domain / "domain.pddl"),
                       str(PROBLEMS / domain / f"{problem}.pddl"))
    with solving(paths) as solved:
        sol, inputs = solved.solution, solved.inputs
        assert sol.lower_bound is not None and sol.lower_bound <= sol.objective
        by_name = {op.name: op for op in inputs.task.operators}
        checked = 0
        for s in sol.skeletons:
            if s.nlp_cost is None:
                continue
            skeleton = lower([by_name[n] for n in s.plan], inputs.scene, inputs.modes,
                             solved.world, domain=inputs.domain)
            bound = relaxed_bound(skeleton)
            assert bound.kind == "proved"
            assert bound.value <= s.nlp_cost + 1e-9, s.plan
            checked += 1
        assert checked >= 1
