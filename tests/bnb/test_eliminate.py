"""Greedy action elimination after branch and bound, with toy geometry."""

from dataclasses import dataclass

import numpy as np

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


def test_a_trailing_action_is_tried_first_its_keyframes_warm_from_the_answer():
    """blind19 p04: the answer's first action took the elimination's whole time (a path
    stage failing at its cap) before its last, useless one was tried. Prefixes of the
    answer come first now, their keyframe stage warm-started from the answer's path
    result (its keyframes and placements), the others after, from scratch."""
    from tampcli.optimize.result import TrajectoryResult
    from tampcli.optimize.values import Keyframes

    plan = ("(pick b)", "(pick a)", "(place a)", "(pick c)")
    answer_keyframes = Keyframes((np.full(3, 0.25),) * 4, {})
    calls = []

    def evaluate(ops, stage, warm, cutoff=None):
        names = tuple(op.name for op in ops)
        calls.append((names, stage, warm))
        return TrajectoryResult("solved", stage, names=names, cost=1.0,
                                keyframes=answer_keyframes if names == plan else Keyframes())

    def drop(ops, i):
        return ops[:i] + ops[i + 1:] if ops[i].name in ("(pick b)", "(pick c)") else None

    result = branch_and_bound(source(plan), evaluate, BnBOptions())
    searched = len(calls)
    result = eliminate_useless(result, evaluate, drop, 0.1, float("inf"))
    tried = [(names, stage, warm) for names, stage, warm in calls[searched:]]
    assert [t[0] for t in tried][:3] == [plan[:3]] * 3  # the prefix, its three stages
    keyframes_warm = tried[1][2]
    assert tried[1][1] == "keyframes" and keyframes_warm.names == plan[:3]
    assert keyframes_warm.keyframes is answer_keyframes
    assert "warm-started from the answer's" in result.skeletons[-2].reason
    # Then (pick b) goes too, from scratch: no prefix of the answer.
    assert tried[3][0] == plan[1:3] and tried[4][1] == "keyframes"
    assert tried[4][2].stage == "final"  # the final stage's result, as any skeleton's
    assert [op.name for op in result.best_plan] == ["(pick a)", "(place a)"]
