"""Greedy action elimination after branch and bound, with toy geometry."""

from dataclasses import dataclass

import numpy as np
import pytest

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
    assert result.skeletons[-1].reason.startswith("the answer (#1) less (pick b) (action")
    assert result.lower_bound <= result.best_objective


def test_it_stays_when_the_shorter_skeleton_is_infeasible():
    plan = ("(pick a)", "(place a)", "(pick b)")
    result = branch_and_bound(source(plan), table_evaluator({}), BnBOptions())
    no_short = table_evaluator({(("(pick a)", "(place a)"), "final"): R("infeasible")})
    before = result.best_plan
    result = eliminate_useless(result, no_short, drop_tail_pick, 0.1, float("inf"))
    assert result.best_plan == before and result.stats["actions_eliminated"] == 0
    assert result.skeletons[-1].outcome == "infeasible"


def test_a_trailing_action_is_tried_first_its_path_from_the_answer():
    """blind19 p04: the answer's first action took the elimination's whole time (a path
    stage failing at its cap) before its last, useless one was tried. Prefixes of the
    answer come first now, their path stage started from the answer's path result (its
    keyframes, placements and motions: no keyframe NLP), the others after, from
    scratch."""
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
    tried = calls[searched:]
    assert [(t[0], t[1]) for t in tried[:2]] == [(plan[:3], "final"), (plan[:3], "path")]
    path_warm = tried[1][2]
    assert path_warm.names == plan[:3] and path_warm.keyframes is answer_keyframes
    assert "from the answer's keyframes and motions" in result.skeletons[-2].reason
    # Then (pick b) goes too, through the three stages from scratch: no prefix.
    assert [(t[0], t[1]) for t in tried[2:5]] == [(plan[1:3], s)
                                                 for s in ("final", "keyframes", "path")]
    assert tried[3][2].stage == "final"  # the final stage's result, as any skeleton's
    assert [op.name for op in result.best_plan] == ["(pick a)", "(place a)"]


def test_a_real_prefix_passes_again_on_the_answers_own_motions():
    """arm-pick-place p01 solved with a useless last pick: the 2-action prefix's path
    stage, started from that answer (eliminate._truncated), runs no keyframe NLP and
    takes the answer's motions as they are: the same waypoints, validated again."""
    import time
    from pathlib import Path

    from tampcli.bnb.eliminate import _truncated
    from tampcli.geometry.collision import CollisionChecker
    from tampcli.geometry.world import World
    from tampcli.pipeline import InputPaths, SolveOptions, Timers, read_inputs
    from tampcli.stage_evaluator import Geometry, StageEvaluator

    root = Path(__file__).resolve().parents[2]
    inputs = read_inputs(InputPaths(str(root / "domains" / "arm-pick-place" / "domain.pddl"),
                                    str(root / "problems" / "arm-pick-place" / "p01.pddl")),
                         Timers())
    with World(inputs.scene, visuals=False) as world:
        evaluate = StageEvaluator(inputs, Geometry(world, CollisionChecker(world)), SolveOptions(),
                              time.perf_counter() + 120)
        ops = {op.name: op for op in inputs.task.operators}
        plan = (ops["(pick a start)"], ops["(place a goal)"], ops["(pick a goal)"])
        warm = None
        for stage in ("final", "keyframes", "path"):
            warm = evaluate(plan, stage, warm)
        assert warm.status == "solved" and len(warm.motions) == len(warm.keyframes)
        names = tuple(op.name for op in plan[:2])
        prefix = evaluate(plan[:2], "path", _truncated(warm, names, plan))
        assert prefix.status == "solved"
        n = len(prefix.keyframes)
        assert 0 < n < len(warm.keyframes)
        for k in range(n):
            np.testing.assert_allclose(prefix.keyframes.q[k], warm.keyframes.q[k])
            np.testing.assert_allclose(prefix.motions[k], warm.motions[k], atol=1e-6)
        assert prefix.cost == pytest.approx(sum(warm.phase_costs[:n]), rel=1e-6)


def test_the_record_names_every_action_dropped_and_the_answer_it_came_from():
    """blind36 DOC_GAPS 3: a pick and its place dropped together were named as one."""
    def drop_pair(ops, i):
        names = [op.name for op in ops]
        if names[i] != "(pick b)" or "(place b)" not in names:
            return None
        return tuple(op for op in ops if op.name not in ("(pick b)", "(place b)"))

    plan = ("(pick b)", "(place b)", "(pick a)", "(place a)")
    result = branch_and_bound(source(plan), table_evaluator({}), BnBOptions())
    result = eliminate_useless(result, table_evaluator({}), drop_pair, 0.1, float("inf"))
    assert [op.name for op in result.best_plan] == ["(pick a)", "(place a)"]
    assert result.skeletons[-1].reason.startswith(
        "the answer (#1) less (pick b) (place b) (action elimination")
