"""Prefix nodes bounded by a relaxation (bnb/prefix_bounds.py), on toy skeletons:
`relax` is a table of prefix -> (value, kind), geometry a table of stage results."""

import math
from dataclasses import dataclass

import pytest

from tampcli.bnb import BnBOptions, branch_and_bound

from .test_bnb import R, Source, table_evaluator


@dataclass(frozen=True)
class Bound:
    value: float
    kind: str = "proved"
    why: str | None = None


def relax_table(table, calls=None):
    """relax(ops): the table's entry for the prefix, else 0 (proved: a cost is >= 0)."""

    def relax(ops):
        names = tuple(op.name for op in ops)
        if calls is not None:
            calls.append(names)
        return table.get(names, Bound(0.0))

    return relax


def test_a_prefix_that_cannot_beat_the_incumbent_forbids_its_completions():
    # "a" solves at objective 1 + 0.1; every completion of "x" costs >= 2 in trajectory.
    src = Source([(("a",), 1), (("x", "y"), 2), (("x", "z"), 3), (("w",), 4)])
    ev_calls = []
    res = branch_and_bound(src, table_evaluator({}, ev_calls), BnBOptions(symbolic_weight=0.1),
                           relax=relax_table({("x",): Bound(2.0), ("w",): Bound(1.0)}))
    assert ("x",) in src.forbidden
    assert ("x", "z") not in src.drawn  # never produced
    pruned = res.skeletons[1]
    assert pruned.outcome == "pruned" and pruned.bound_kind == "proved"
    assert "prefix x" in pruned.reason and "(proved)" in pruned.reason
    assert not any(names[0] == "x" for names, _ in ev_calls)  # no NLP for them
    assert res.stats["heuristic_prunes"] == 0


def test_an_infeasible_relaxation_excludes_a_prefix_before_any_incumbent():
    src = Source([(("p", "q"), 1), (("p", "r"), 2), (("s",), 3)])
    res = branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1),
                           relax=relax_table({("p",): Bound(math.inf)}))
    assert [op.name for op in res.best_plan] == ["s"]
    assert src.forbidden == [("p",)] and ("p", "r") not in src.drawn
    assert res.skeletons[0].outcome == "infeasible"
    assert "infeasible (proved)" in res.skeletons[0].reason


def test_nodes_are_expanded_shortest_first_and_only_while_below_the_incumbent():
    src = Source([(("a",), 1), (("x", "y", "z"), 2)])
    calls = []
    branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1),
                     relax=relax_table({("x",): Bound(5.0)}, calls))
    # "x" already cannot beat "a" (1.1): its longer prefixes are never relaxed.
    assert ("x",) in calls
    assert ("x", "y") not in calls and ("x", "y", "z") not in calls


def test_the_lower_bound_is_the_least_proved_bound_of_the_open_nodes():
    # "a": objective 1.1, its relaxation 0.8; "b" fails locally (unproved), relaxed 1.5.
    src = Source([(("a",), 1), (("b",), 2)])
    ev = table_evaluator({(("b",), "final"): R("infeasible", worst_constraint="local")})
    table = {("a",): Bound(0.8), ("b",): Bound(0.5)}
    res = branch_and_bound(src, ev, BnBOptions(symbolic_weight=0.1), relax=relax_table(table))
    assert res.best_objective == pytest.approx(1.1)
    # min(0.1 + 0.8 (the incumbent's own skeleton), 0.2 + 0.5 (b, open)) = 0.7 > 0.2
    assert res.lower_bound == pytest.approx(0.7)
    assert res.stats["stop"] == "best of the evaluated skeletons (1 heuristic prunes)"
    without = branch_and_bound(Source([(("a",), 1), (("b",), 2)]), ev,
                               BnBOptions(symbolic_weight=0.1))
    assert without.lower_bound == pytest.approx(0.1)


def test_the_lower_bound_never_exceeds_the_objective():
    # A relaxation above the NLP's value (it cannot be, if proved; the bound is clipped).
    src = Source([(("a",), 1)])
    res = branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1),
                           relax=relax_table({("a",): Bound(3.0)}))
    assert res.lower_bound <= res.best_objective


def test_bounds_meeting_the_objective_prove_optimality():
    # The incumbent's relaxation equals its NLP value (1.0) and the other skeleton's
    # relaxation is infeasible: nothing can be cheaper.
    src = Source([(("a",), 1), (("b",), 2)])
    res = branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1),
                           relax=relax_table({("a",): Bound(1.0), ("b",): Bound(math.inf)}))
    assert res.optimal and res.stats["stop"] == "optimal (proved)"
    assert res.lower_bound == pytest.approx(res.best_objective)


def test_a_heuristic_relaxation_prunes_one_skeleton_and_says_so():
    src = Source([(("a",), 1), (("x", "y"), 2), (("x", "z"), 3)])
    res = branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1),
                           relax=relax_table({("x",): Bound(2.0, "heuristic")}))
    assert src.forbidden == []  # no proof: each completion is judged on its own
    assert ("x", "z") in src.drawn
    assert res.skeletons[1].bound_kind == "heuristic"
    assert res.stats["heuristic_prunes"] == 2
    assert res.lower_bound == pytest.approx(0.1)


def test_no_relaxation_keeps_the_symbolic_bound():
    src = Source([(("a",), 1), (("b",), 2)])
    res = branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1),
                           relax=lambda ops: None)
    assert res.lower_bound == pytest.approx(0.1)
    assert not any("relax" in (s.reason or "") for s in res.skeletons)


def test_what_blocks_a_relaxation_reaches_the_learner():
    src = Source([(("p",), 1), (("q", "p"), 2)])
    heard = []
    why = "(p): overlaps b wherever it is put down"
    res = branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1),
                           relax=relax_table({("p",): Bound(math.inf, why=why)}),
                           learn=lambda found: heard.append(found.worst_constraint))
    assert heard == [why]
    assert why in res.skeletons[0].reason
    assert [op.name for op in res.best_plan] == ["q", "p"]
