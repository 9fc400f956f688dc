"""Action elimination meets skeletons the search already judged: none is optimized twice."""

from collections import Counter
from pathlib import Path

import pytest

from tampcli.bnb import BnBOptions, branch_and_bound
from tampcli.bnb.eliminate import eliminate_useless
from tampcli.pipeline import InputPaths, solve
from tests.bnb.test_bnb import R, table_evaluator
from tests.bnb.test_eliminate import Op, Plan

ROOT = Path(__file__).resolve().parents[2]

SHORT, LONG = ("(pick a)", "(place a)"), ("(pick b)", "(place b)", "(pick a)", "(place a)")


def plans(*names):
    """Ranked plans of unit-cost actions, in the order given."""
    return [Plan(tuple(Op(n) for n in plan), float(len(plan))) for plan in names]


def drop_b(ops, i):
    """Symbolically: dropping (pick b) drops (place b) too (b is no longer held)."""
    return ops[2:] if i == 0 and ops[0].name == "(pick b)" else None


def test_planar_tamp_p02_evaluates_the_blocked_skeleton_once():
    """The blocker moved away, less the move, is the skeleton that failed first: the
    elimination pass used to optimize it again and list it twice."""
    problem = ROOT / "problems" / "planar-tamp" / "p02.pddl"
    solution = solve(InputPaths(str(ROOT / "domains" / "planar-tamp" / "domain.pddl"),
                                str(problem)))
    assert solution.status == "solved" and len(solution.plan) == 4
    plans = Counter(record.plan for record in solution.skeletons)
    assert max(plans.values()) == 1, plans
    stats = solution.stats
    assert stats["elimination_skipped"] == 1 and stats["elimination_skeletons"] == 0
    assert len(solution.skeletons) == stats["skeletons_generated"] + \
        stats["elimination_skeletons"]


def test_a_shorter_skeleton_found_infeasible_is_not_evaluated_again():
    calls = []
    table = {(SHORT, "keyframes"): R("infeasible", worst_constraint="blocked")}
    result = branch_and_bound(plans(SHORT, LONG), table_evaluator(table, calls),
                              BnBOptions(prefix_pruning=False))
    assert result.judged[SHORT].outcome == "infeasible"
    calls.clear()
    result = eliminate_useless(result, table_evaluator(table, calls), drop_b, 0.1,
                               float("inf"))
    assert calls == [] and [r.plan for r in result.skeletons] == [SHORT, LONG]
    assert result.stats["elimination_skipped"] == 1
    assert result.stats["actions_eliminated"] == 0


def test_a_shorter_skeleton_solved_by_the_search_keeps_its_path():
    """It lost on its objective; elimination takes it whatever the objective, from the
    path the search found."""
    table = {(SHORT, "path"): R("solved", 5.0)}
    result = branch_and_bound(plans(SHORT, LONG), table_evaluator(table),
                              BnBOptions(anytime=True))
    assert [op.name for op in result.best_plan] == list(LONG)
    calls = []
    result = eliminate_useless(result, table_evaluator(table, calls), drop_b, 0.1,
                               float("inf"))
    assert calls == []
    assert [op.name for op in result.best_plan] == list(SHORT) and result.best.cost == 5.0
    last = result.skeletons[-1]
    assert last.rank == 3 and last.outcome == "solved" and "solved as #1" in last.reason
    assert result.stats["elimination_skeletons"] == 1


def test_a_shorter_skeleton_pruned_by_a_bound_is_evaluated_and_says_why():
    table = {(SHORT, "keyframes"): R("solved", 9.0)}
    result = branch_and_bound(plans(LONG, SHORT), table_evaluator(table),
                              BnBOptions())
    assert result.judged[SHORT].outcome == "pruned"
    calls = []
    result = eliminate_useless(result, table_evaluator(table, calls), drop_b, 0.1,
                               float("inf"))
    assert (SHORT, "path") in calls
    assert "#2 again, pruned there" in result.skeletons[-1].reason
    assert len(result.skeletons) == result.stats["skeletons_generated"] + \
        result.stats["elimination_skeletons"]


def test_a_shorter_skeleton_that_failed_at_its_path_stage_is_tried_again():
    """blind7 p03: a carry through a maze failed in the 2-action skeleton (its path
    stage starts from sampled paths) and passed in a 4-action one; the answer kept the
    useless drop and fetch. A keyframe failure would fail again; a path failure may not."""
    calls = []
    table = {(SHORT, "path"): R("infeasible", worst_constraint="no path")}
    result = branch_and_bound(plans(SHORT, LONG), table_evaluator(table, calls),
                              BnBOptions(prefix_pruning=False))
    assert result.judged[SHORT].outcome == "infeasible"
    assert result.judged[SHORT].stage == "path"
    assert [op.name for op in result.best_plan] == list(LONG)
    calls.clear()
    result = eliminate_useless(result, table_evaluator({}, calls), drop_b, 0.1, float("inf"))
    assert (SHORT, "path") in calls
    assert [op.name for op in result.best_plan] == list(SHORT)
    assert result.stats["elimination_skipped"] == 0
    assert result.stats["actions_eliminated"] == 2


def test_a_shorter_skeleton_that_met_a_body_in_its_way_is_not_tried_again():
    """blind15 p06: the answer less the push of the crate out of the corridor is the
    skeleton whose carry met the crate in every path; run again it meets it again."""
    from tampcli.optimize.motion import IN_THE_WAY

    calls = []
    row = f"motion 1 before (place a g): collision planar_body vs b: {IN_THE_WAY} (...)"
    table = {(SHORT, "path"): R("infeasible", worst_constraint=row)}
    result = branch_and_bound(plans(SHORT, LONG), table_evaluator(table, calls),
                              BnBOptions(prefix_pruning=False))
    assert result.judged[SHORT].stage == "path"
    calls.clear()
    result = eliminate_useless(result, table_evaluator({}, calls), drop_b, 0.1, float("inf"))
    assert calls == [] and [op.name for op in result.best_plan] == list(LONG)
    assert result.stats["elimination_skipped"] == 1


def test_a_dear_answer_left_by_elimination_yields_to_a_cheaper_minimal_plan():
    """blind15 p02: the answer less its useless moves cost 9.89 where a plan the search
    had solved, with nothing to drop, cost 1.56: that one is the answer."""
    other = ("(pick c)", "(place c)")
    table = {(other, "path"): R("solved", 1.0), (LONG, "keyframes"): R("solved", 0.5),
             (LONG, "path"): R("solved", 0.5), (SHORT, "path"): R("solved", 10.0)}
    result = branch_and_bound(plans(other, LONG), table_evaluator(table),
                              BnBOptions(prefix_pruning=False))
    assert [op.name for op in result.best_plan] == list(LONG)
    operators = {name: Op(name) for name in (*other, *LONG)}
    result = eliminate_useless(result, table_evaluator(table), drop_b, 0.1, float("inf"),
                               operators)
    assert result.stats["actions_eliminated"] == 2
    assert [op.name for op in result.best_plan] == list(other)
    assert result.best_objective == pytest.approx(1.0 + 0.1 * 2)
    # Without the task's operators, the shorter answer stays, dear as it is.
    result = branch_and_bound(plans(other, LONG), table_evaluator(table),
                              BnBOptions(prefix_pruning=False))
    result = eliminate_useless(result, table_evaluator(table), drop_b, 0.1, float("inf"))
    assert [op.name for op in result.best_plan] == list(SHORT)


def test_a_shorter_skeleton_whose_path_row_named_a_movable_body_is_not_tried_again():
    """blind21 p06: the answer less the cube's carry is the skeleton whose push ran the
    crate into the cube; run again (11 s) it meets the cube again."""
    calls = []
    row = ("path stage infeasible: motion 1 before (place a g): collision a vs b "
           "(margin 1 mm) by 3.7 cm")
    table = {(SHORT, "path"): R("infeasible", worst_constraint=row)}
    result = branch_and_bound(plans(SHORT, LONG), table_evaluator(table, calls),
                              BnBOptions(prefix_pruning=False))
    calls.clear()
    result = eliminate_useless(result, table_evaluator({}, calls), drop_b, 0.1, float("inf"),
                               movable=frozenset({"a", "b"}))
    assert calls == [] and [op.name for op in result.best_plan] == list(LONG)
    assert result.stats["elimination_skipped"] == 1
    # Without b among the movable bodies (a wall), nothing is learned: it is tried again.
    result = branch_and_bound(plans(SHORT, LONG), table_evaluator(table, calls),
                              BnBOptions(prefix_pruning=False))
    calls.clear()
    eliminate_useless(result, table_evaluator({}, calls), drop_b, 0.1, float("inf"),
                      movable=frozenset({"a"}))
    assert (SHORT, "path") in calls
