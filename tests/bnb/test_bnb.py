"""Branch and bound on toy skeletons and toy evaluators (geometry as plain callables)."""

from dataclasses import dataclass

import pytest

from tampcli.bnb import BnBOptions, branch_and_bound


@dataclass(frozen=True)
class Op:
    name: str


@dataclass(frozen=True)
class Plan:
    operators: tuple
    cost: float


@dataclass(frozen=True)
class R:
    status: str
    cost: float | None = None
    worst_constraint: str | None = None
    proved: bool = False
    iterations: int = 1
    failed_actions: int | None = None


class Source:
    """A ranked list of plans that honours forbid_prefix, like TopK."""

    def __init__(self, plans):
        self.plans = [Plan(tuple(Op(n) for n in names), cost) for names, cost in plans]
        self.forbidden = []
        self.drawn = []

    def forbid_prefix(self, names):
        self.forbidden.append(tuple(names))

    def __iter__(self):
        for plan in self.plans:
            names = tuple(op.name for op in plan.operators)
            if any(names[:len(f)] == f for f in self.forbidden):
                continue
            self.drawn.append(names)
            yield plan


def table_evaluator(table, calls=None):
    """Evaluate by looking up (names, stage) -> R; default solved with cost 1 (0 for
    the relaxation "reach", whose bound then prunes nothing)."""

    def evaluate(ops, stage, warm, cutoff=None):
        names = tuple(op.name for op in ops)
        if calls is not None:
            calls.append((names, stage))
        for key, result in table.items():
            if names[:len(key[0])] == key[0] and key[1] == stage:
                return result
        return R("solved", 0.0 if stage == "reach" else 1.0)

    return evaluate


def test_first_feasible_skeleton_wins_when_later_cannot_beat_it():
    src = Source([(("a",), 1), (("b",), 100)])
    res = branch_and_bound(src, table_evaluator({}), BnBOptions(symbolic_weight=0.1))
    assert res.status == "solved"
    assert [op.name for op in res.best_plan] == ["a"]
    # objective 1 + 0.1 = 1.1 < 0.1 * 100: the second skeleton is never optimized. The
    # trajectory's NLP optimum is local, so the proved bound stays w * 1: not proved optimal.
    assert not res.optimal
    assert res.stats["stop"] == "best of the evaluated skeletons (0 heuristic prunes)"
    assert res.stats["skeletons_optimized"] == 1
    assert res.lower_bound == pytest.approx(0.1)


def test_the_bound_counts_what_a_local_failure_left_unproved():
    src = Source([(("a",), 1), (("b",), 3), (("c",), 100)])
    ev = table_evaluator({(("a",), "final"): R("infeasible", worst_constraint="local")})
    res = branch_and_bound(src, ev, BnBOptions(symbolic_weight=0.1))
    assert [op.name for op in res.best_plan] == ["b"]
    assert res.lower_bound == pytest.approx(0.1)  # a's failure is not proved
    assert res.stats["stop"] == "best of the evaluated skeletons (1 heuristic prunes)"
    proved = table_evaluator({(("a",), "final"): R("infeasible", worst_constraint="far",
                                                    proved=True)})
    res = branch_and_bound(Source([(("a",), 1), (("b",), 3), (("c",), 100)]), proved,
                           BnBOptions(symbolic_weight=0.1))
    assert res.lower_bound == pytest.approx(0.3)
    assert res.lower_bound <= res.best_objective


def test_infeasible_cheapest_skeleton_is_skipped_and_recorded():
    src = Source([(("a",), 1), (("b",), 2)])
    ev = table_evaluator({(("a",), "final"): R("infeasible", worst_constraint="region full")})
    res = branch_and_bound(src, ev, BnBOptions())
    assert [op.name for op in res.best_plan] == ["b"]
    assert res.skeletons[0].outcome == "infeasible"
    assert "region full" in res.skeletons[0].reason


def test_cheaper_trajectory_beats_cheaper_symbolic_cost():
    src = Source([(("push",), 1), (("pick", "place"), 2)])
    ev = table_evaluator({(("push",), "path"): R("solved", 5.0),
                          (("push",), "keyframes"): R("solved", 0.5),
                          (("pick",), "path"): R("solved", 2.0)})
    res = branch_and_bound(src, ev, BnBOptions(symbolic_weight=0.1))
    assert [op.name for op in res.best_plan] == ["pick", "place"]
    assert res.best_objective == pytest.approx(2.2)


def test_keyframe_bound_prunes_without_path_solve():
    src = Source([(("a",), 1), (("b",), 2)])
    calls = []
    ev = table_evaluator({(("a",), "path"): R("solved", 1.0),
                          (("b",), "keyframes"): R("solved", 3.0)}, calls)
    res = branch_and_bound(src, ev, BnBOptions())
    assert res.skeletons[1].outcome == "pruned"
    assert res.skeletons[1].bound_kind == "heuristic"
    assert (("b",), "path") not in calls


def test_the_relaxed_keyframe_bound_prunes_before_the_keyframe_nlp():
    src = Source([(("a",), 1), (("b",), 2)])
    calls = []
    ev = table_evaluator({(("a",), "path"): R("solved", 1.0),
                          (("b",), "reach"): R("solved", 3.0)}, calls)
    res = branch_and_bound(src, ev, BnBOptions())
    assert res.skeletons[1].outcome == "pruned"
    assert res.skeletons[1].stage == "reach"
    assert res.skeletons[1].bound_kind == "heuristic"  # a local optimum of a relaxation
    assert "reach (keyframes, no collisions) bound" in res.skeletons[1].reason
    assert (("b",), "keyframes") not in calls


def test_a_failed_relaxation_leaves_the_decision_to_the_keyframe_nlp():
    src = Source([(("a",), 1)])
    calls = []
    ev = table_evaluator({(("a",), "reach"): R("infeasible", worst_constraint="local")},
                         calls)
    res = branch_and_bound(src, ev, BnBOptions())
    assert res.status == "solved"
    assert [stage for _, stage in calls] == ["final", "reach", "keyframes", "path"]


def test_the_path_stage_gets_the_cutoff_of_the_incumbent_and_may_stop_there():
    src = Source([(("a",), 1), (("b",), 2)])
    cutoffs = []

    def evaluate(ops, stage, warm, cutoff=None):
        if stage == "path":
            cutoffs.append(cutoff)
            if ops[0].name == "b":
                return R("bounded", 1.3, worst_constraint="path bound 1.3 after motion 0")
        return R("solved", {"reach": 0.0, "keyframes": 0.5}.get(stage, 1.0))

    res = branch_and_bound(src, evaluate, BnBOptions(symbolic_weight=0.1))
    assert cutoffs == [None, pytest.approx(1.1 - 0.2)]  # a's objective 1.1, b's w * 2
    assert [op.name for op in res.best_plan] == ["a"]
    b = res.skeletons[1]
    assert (b.outcome, b.stage, b.bound_kind) == ("pruned", "path", "heuristic")
    assert "path bound 1.3 after motion 0" in b.reason
    assert res.stats["heuristic_prunes"] == 1


def test_a_motion_that_failed_at_the_path_stage_forbids_the_actions_up_to_it():
    plans = [(("x", "y", "z"), 3), (("x", "w", "z"), 4), (("x", "y", "v"), 5), (("q",), 6)]
    src = Source(plans)
    ev = table_evaluator({(("x", "y", "z"), "path"): R(
        "infeasible", worst_constraint="motion 1 before (y): no path", failed_actions=2)})
    res = branch_and_bound(src, ev, BnBOptions())
    assert src.forbidden == [("x", "y")]
    assert ("x", "y", "v") not in src.drawn and ("x", "w", "z") in src.drawn
    assert "(prefix x y failed)" in res.skeletons[0].reason
    assert res.stats["prefixes_forbidden"] == 1
    # Not proved: the failed skeleton's bound stays open.
    assert res.skeletons[0].rank in {r.rank for r in res.skeletons if r.outcome == "infeasible"}
    assert not res.optimal


def test_a_failed_motion_into_the_last_action_forbids_the_skeletons_going_on_after_it():
    """blind19 p04: (pick bar) (place bar goal) failed with the door blocked; the same
    carry followed by more actions failed again after 30 s."""
    plans = [(("x", "y"), 2), (("x", "y", "z"), 3), (("q", "x", "y"), 4)]
    src = Source(plans)
    ev = table_evaluator({(("x", "y"), "path"): R(
        "infeasible", worst_constraint="motion 1 before (y): no path", failed_actions=2)})
    res = branch_and_bound(src, ev, BnBOptions())
    assert src.forbidden == [("x", "y")]
    assert ("x", "y", "z") not in src.drawn and ("q", "x", "y") in src.drawn
    assert "(prefix x y failed)" in res.skeletons[0].reason


def test_infeasible_prefix_prunes_every_skeleton_sharing_it():
    plans = [(("x", "y", "z"), 3), (("x", "y", "w"), 4), (("x", "v"), 5), (("q",), 6)]
    src = Source(plans)
    ev = table_evaluator({(("x", "y"), "keyframes"): R("infeasible", worst_constraint="ik")})
    res = branch_and_bound(src, ev, BnBOptions())
    assert ("x", "y") in src.forbidden
    assert ("x", "y", "w") not in src.drawn  # never produced by the generator
    assert [op.name for op in res.best_plan] == ["x", "v"]


def test_no_solution_explains_why_and_is_a_limit_unless_proved():
    src = Source([(("a",), 1), (("b",), 2)])
    ev = table_evaluator({(("a",), "final"): R("infeasible", worst_constraint="out of reach"),
                          (("b",), "final"): R("infeasible", worst_constraint="too small")})
    res = branch_and_bound(src, ev, BnBOptions())
    assert res.status == "limit"
    assert "out of reach" in res.reason and "too small" in res.reason
    ev_proved = table_evaluator({
        (("a",), "final"): R("infeasible", worst_constraint="out of reach", proved=True),
        (("b",), "final"): R("infeasible", worst_constraint="too small", proved=True)})
    assert branch_and_bound(Source([(("a",), 1), (("b",), 2)]), ev_proved,
                            BnBOptions()).status == "unsolvable"


def test_no_solution_names_the_failure_most_skeletons_ended_on():
    """blind20 p01: 318 of 320 skeletons failed placing the pen into its case; the reason
    named the first three and "... and 317 more"."""
    plans = [(("x",), 1), (("y",), 2)] + [((f"p{i}", "put"), 3 + i) for i in range(5)]
    table = {(("x",), "final"): R("infeasible", worst_constraint="out of reach"),
             (("y",), "final"): R("infeasible", worst_constraint="too small")}
    for i in range(5):
        table[((f"p{i}", "put"), "final")] = R(
            "infeasible", worst_constraint=f"(put): overlaps rim by 0.{8 - i} cm")
    res = branch_and_bound(Source(plans), table_evaluator(table), BnBOptions())
    assert "... and 4 more" in res.reason
    assert res.reason.endswith(
        "the commonest failure, 5 of 7 skeletons: final stage infeasible: (put): overlaps "
        "rim by 0.8 cm")


def test_skeleton_limit():
    src = Source([((f"a{i}",), i) for i in range(10)])
    ev = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(10)})
    res = branch_and_bound(src, ev, BnBOptions(max_skeletons=3))
    assert res.status == "limit"
    assert len(res.skeletons) == 3
    assert "skeleton limit (3)" in res.reason


def test_by_default_only_an_answer_caps_the_skeletons():
    """Without -k, a search that has found nothing goes on past DEFAULT_SKELETONS (the
    time limit ends it); one with an answer draws that many at most (anytime: it
    would go on)."""
    from tampcli.bnb.values import DEFAULT_SKELETONS

    n = DEFAULT_SKELETONS + 15
    src = [((f"a{i}",), i) for i in range(n)]
    failing = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(n)})
    res = branch_and_bound(Source(src), failing, BnBOptions())
    assert res.status == "limit" and len(res.skeletons) == n
    assert res.stats["stop"] == "every skeleton tried"
    last = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(n - 1)})
    assert branch_and_bound(Source(src), last, BnBOptions()).status == "solved"
    answered = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(1, n)})
    free = [(names, 0) for names, _ in src]  # none priced out by the answer
    res = branch_and_bound(Source(free), answered, BnBOptions(anytime=True))
    assert res.status == "solved" and len(res.skeletons) == DEFAULT_SKELETONS
    assert res.stats["stop"] == "skeleton limit"


def test_time_limit_with_fake_clock():
    ticks = iter(range(1000))
    src = Source([((f"a{i}",), i) for i in range(10)])
    ev = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(10)})
    res = branch_and_bound(src, ev, BnBOptions(time_limit=5), clock=lambda: next(ticks))
    assert res.status == "limit" and res.stats["stop"] == "time limit"


def test_the_reserve_is_kept_only_once_there_is_an_answer():
    """With an answer the search stops `reserve` seconds early (action elimination's
    time); without one it goes on to the limit."""
    src = [((f"a{i}",), i) for i in range(20)]
    unsolved = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(20)})
    # each look at the clock a tenth of a second later
    ticks = iter(range(10000))
    res = branch_and_bound(Source(src), unsolved, BnBOptions(time_limit=10, reserve=4,
                                                              anytime=True, max_skeletons=100),
                           clock=lambda: next(ticks) / 10)
    seen_without = len(res.skeletons)
    solved = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(1, 20)})
    ticks = iter(range(10000))
    res = branch_and_bound(Source(src), solved, BnBOptions(time_limit=10, reserve=4,
                                                            anytime=True, max_skeletons=100),
                           clock=lambda: next(ticks) / 10)
    assert res.status == "solved" and res.stats["stop"] == "time limit"
    assert len(res.skeletons) < seen_without
    assert BnBOptions(time_limit=10, reserve=4).search_limit(True) == 6
    assert BnBOptions(time_limit=10, reserve=4).search_limit(False) == 10


def test_options_are_validated():
    with pytest.raises(ValueError):
        BnBOptions(max_skeletons=0)
    with pytest.raises(ValueError):
        BnBOptions(symbolic_weight=-1)


def test_skeleton_differing_only_in_symbolic_actions_is_not_optimized_again():
    # "cook" has no geometry: (move, cook, place) and (move, place, cook) are one NLP.
    src = Source([(("move", "cook", "place"), 3), (("move", "place", "cook"), 3),
                  (("move", "place", "cook", "move2"), 4)])
    calls = []
    res = branch_and_bound(src, table_evaluator({}, calls), BnBOptions(symbolic_weight=0.1),
                           is_geometric=lambda op: op.name != "cook")
    assert res.skeletons[1].outcome == "pruned"
    assert res.skeletons[1].bound_kind == "proved"
    assert "#1" in res.skeletons[1].reason
    assert not any(names == ("move", "place", "cook") for names, _ in calls)
    # A skeleton with other geometric actions is still evaluated.
    assert any(names == ("move", "place", "cook", "move2") for names, _ in calls)


def test_first_stops_at_the_first_feasible_skeleton():
    source = Source([(("a",), 1.0), (("b",), 2.0), (("c",), 3.0)])
    table = {(("a",), "final"): R("infeasible", worst_constraint="x")}
    result = branch_and_bound(source, table_evaluator(table), BnBOptions(first=True))
    assert result.status == "solved" and [op.name for op in result.best_plan] == ["b"]
    assert result.stats["stop"] == "first solution" and source.drawn == [("a",), ("b",)]


def test_every_failed_stage_reaches_the_learner():
    source = Source([(("a",), 1.0), (("b",), 2.0)])
    table = {(("a",), "keyframes"): R("infeasible", worst_constraint="(a): overlaps z")}
    heard = []
    branch_and_bound(source, table_evaluator(table), BnBOptions(prefix_pruning=False),
                     learn=lambda result: heard.append(result.worst_constraint))
    assert heard == ["(a): overlaps z"]


class ReorderingSource(Source):
    """Draws a dear skeleton first; its proved bound covers the cheap one still to come."""

    def lower_bound(self):
        left = [p.cost for p in self.plans if tuple(op.name for op in p.operators)
                not in self.drawn]
        return min(left, default=float("inf"))

    def solved(self, names):
        self.solved_names = names


def test_optimality_waits_for_the_sources_bound_when_skeletons_come_out_of_order():
    # After "dear" (objective 5), "dearer" alone would look like proof of optimality.
    source = ReorderingSource([(("dear",), 5.0), (("dearer",), 6.0), (("cheap",), 1.0)])
    table = {(("dear",), "path"): R("solved", 0.0), (("cheap",), "path"): R("solved", 0.0)}
    result = branch_and_bound(source, table_evaluator(table), BnBOptions(symbolic_weight=1.0))
    assert [op.name for op in result.best_plan] == ["cheap"]
    assert source.drawn[-1] == ("cheap",) and source.solved_names == ("cheap",)


def test_a_skeleton_drawn_past_the_time_limit_is_not_evaluated():
    """blind31 p01: the source took 24 s to draw the last skeleton, past the limit;
    it was evaluated all the same and the run ended 2.4 s late. Now the search looks
    at the clock again after each draw."""
    now = [0.0]

    class SlowSource(Source):
        def __iter__(self):
            for plan in super().__iter__():
                now[0] += 4.0  # each draw takes 4 s
                yield plan

    calls = []
    src = SlowSource([((f"a{i}",), i) for i in range(5)])
    evaluate = table_evaluator({((f"a{i}",), "final"): R("infeasible") for i in range(5)},
                               calls)
    res = branch_and_bound(src, evaluate, BnBOptions(time_limit=10), clock=lambda: now[0])
    assert res.stats["stop"] == "time limit"
    # drawn at 4 s and 8 s, evaluated; the third, drawn at 12 s, is not
    assert len(src.drawn) == 3
    assert {names for names, _ in calls} == {("a0",), ("a1",)}
    assert [r.plan for r in res.skeletons] == [("a0",), ("a1",)]
