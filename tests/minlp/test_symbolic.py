"""The task's encoding alone (the lesson's §3): with one action a step, y >= d
preconditions, effects and frame axioms are exactly STRIPS progression, so the
shortest plan is found and a shorter horizon is infeasible."""

import pytest
from pyscipopt import Model, quicksum

from tampcli.minlp.symbolic import encode_task
from tampcli.pddl import parser
from tampcli.search.plan_text import parse_plan
from tampcli.search.validate import validate_plan
from tampcli.task.ground import ground
from tests.conftest import ROOT

DOMAIN = ROOT / "domains/blocksworld/domain.pddl"
PROBLEM = ROOT / "problems/blocksworld/p01.pddl"  # its optimal plan has 6 actions


def _solve(steps: int):
    domain, problem = parser.parse_domain_file(str(DOMAIN)), parser.parse_problem_file(str(PROBLEM))
    task = ground(domain, problem)
    model = Model()
    model.hideOutput()
    sym = encode_task(model, task, steps, frozenset())
    model.setObjective(quicksum(op.cost * sym.d[k][i] for k in range(1, steps + 1)
                                for i, op in enumerate(task.operators)), "minimize")
    model.optimize()
    if model.getStatus() != "optimal":
        return model.getStatus(), None, None
    plan = [task.operators[i].name for k in range(1, steps + 1)
            for i, v in enumerate(sym.d[k]) if model.getVal(v) > 0.5]
    return "optimal", model.getObjVal(), (domain, problem, plan)


def test_the_encoding_finds_an_optimal_plan_that_progresses_correctly():
    status, cost, (domain, problem, plan) = _solve(7)
    assert status == "optimal" and cost == pytest.approx(6.0)
    report = validate_plan(domain, problem, parse_plan("\n".join(plan), "<minlp>"))
    assert report.failure is None and report.cost == pytest.approx(6.0)


def test_a_horizon_shorter_than_the_optimal_plan_is_infeasible():
    assert _solve(5)[0] == "infeasible"
