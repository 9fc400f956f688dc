"""Greedy action elimination after branch and bound, with toy geometry."""

from dataclasses import dataclass

from tampcli.bnb import BnBOptions, branch_and_bound
from tampcli.bnb.eliminate import eliminate_useless
from tests.bnb.test_bnb import R, table_evaluator


@dataclass(frozen=True)
class Op:
    name: str
    cost: float = 1.0


@dataclass(frozen=True)
class Plan:
    operators: tuple
    cost: float


def source(names):
    ops = tuple(Op(n) for n in names)
    return [Plan(ops, float(len(ops)))]


def drop_tail_pick(ops, i):
    """Symbolically: only the trailing (pick b) is useless."""
    return ops[:i] + ops[i + 1:] if ops[i].name == "(pick b)" and i == len(ops) - 1 else None


def test_a_useless_trailing_action_goes_when_geometry_agrees():
    plan = ("(pick a)", "(place a)", "(pick b)")
    result = branch_and_bound(source(plan), table_evaluator({}), BnBOptions())
    result = eliminate_useless(result, table_evaluator({}), drop_tail_pick, 0.1, float("inf"))
    assert [op.name for op in result.best_plan] == ["(pick a)", "(place a)"]
    assert result.stats["actions_eliminated"] == 1
    assert result.skeletons[-1].reason.startswith("the answer less (pick b)")
    assert result.lower_bound <= result.best_objective


def test_it_stays_when_the_shorter_skeleton_is_infeasible():
    plan = ("(pick a)", "(place a)", "(pick b)")
    result = branch_and_bound(source(plan), table_evaluator({}), BnBOptions())
    no_short = table_evaluator({(("(pick a)", "(place a)"), "final"): R("infeasible")})
    before = result.best_plan
    result = eliminate_useless(result, no_short, drop_tail_pick, 0.1, float("inf"))
    assert result.best_plan == before and result.stats["actions_eliminated"] == 0
    assert result.skeletons[-1].outcome == "infeasible"
