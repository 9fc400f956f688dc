"""Skeletons that pass a symbolic state twice (a regrasp: pick, place, pick again),
none three times, after every loopless one, and only while none was feasible."""

from __future__ import annotations

import math

from tampcli.search.learned import LearningSource
from tampcli.search.topk import TopK
from tests.search.test_learned import moves, pen


def _revisits(task, plan) -> int:
    """The most times a plan passes one state, less one."""
    state, seen = task.init, {task.init: 1}
    for op in plan.operators:
        state = task.apply(state, op)
        seen[state] = seen.get(state, 0) + 1
    return max(seen.values()) - 1


def _plans(topk, limit):
    out = []
    for plan in topk:
        out.append(plan)
        if len(out) == limit:
            break
    return out


def test_no_state_three_times_in_cost_order_and_every_loopless_plan_among_them():
    task, _ = pen(1)
    loopless = [p.names for p in TopK(task, loopless=True)]
    plans = _plans(TopK(task, loopless=True, revisits=1), 2000)
    costs = [p.cost for p in plans]
    assert costs == sorted(costs)
    assert max(_revisits(task, p) for p in plans) == 1
    assert set(loopless) <= {p.names for p in plans}
    # the regrasp of a in place: pick it, set it down where it was, pick it again
    assert ("(pick a floor)", "(place a floor)", "(pick a floor)", "(place a goal)") in \
        {p.names for p in plans}
    # finite: it ends
    assert len(plans) < 2000


def _source(task):
    return LearningSource(task, lambda t: TopK(t, loopless=True), moves,
                          make_regrasps=lambda t: TopK(t, loopless=True, revisits=1))


def test_regrasps_come_after_the_loopless_skeletons_when_none_was_feasible():
    task, _ = pen(1)
    loopless = {p.names for p in TopK(task, loopless=True)}
    src = _source(task)
    drawn = []
    for plan in src:
        drawn.append(plan)
        if len(drawn) == len(loopless) + 3:
            break
    first = {p.names for p in drawn[:len(loopless)]}
    assert first == loopless
    assert all(_revisits(task, p) == 1 for p in drawn[len(loopless):])
    assert len(drawn) == len(loopless) + 3


def test_no_regrasps_once_a_skeleton_was_feasible():
    task, _ = pen(1)
    src = _source(task)
    drawn = [next(src)]
    src.solved(drawn[0].names)
    drawn += list(src)
    assert all(_revisits(task, p) == 0 for p in drawn)


def test_the_bound_counts_regrasps_not_drawn_while_nothing_was_feasible():
    task, _ = pen(1)
    cheapest = next(iter(TopK(task, loopless=True))).cost
    src = _source(task)
    loopless = len(list(TopK(task, loopless=True)))
    for _ in range(loopless):
        next(src)
    # every loopless skeleton drawn: the regrasps may still come, and cost no less
    # than the cheapest plan
    assert src.lower_bound() == cheapest
    plain = LearningSource(task, lambda t: TopK(t, loopless=True), moves)
    for _ in range(loopless):
        next(plain)
    assert plain.lower_bound() == math.inf


def test_the_source_waits_on_results_where_they_decide_what_comes_next():
    """A parallel search asks before drawing while skeletons are out: past the
    loopless skeletons worth drawing now, what comes next (the deferred ones, or
    regrasps while none was feasible) is for their results to decide."""
    task, _ = pen(1)
    loopless = {p.names for p in TopK(task, loopless=True)}
    src = _source(task)
    drawn = []
    while not src.waiting_on_results():
        # the skeleton it looked ahead at is the next drawn, and counted by the bound
        # until then (not drawn yet)
        ahead = src._ahead
        assert src.lower_bound() <= ahead.cost
        drawn.append(next(src))
        assert drawn[-1] is ahead
    assert drawn and {p.names for p in drawn} <= loopless
    assert src.waiting_on_results()  # asking again changes nothing
    # One was feasible: the deferred loopless ones come, no regrasp (as without asking).
    src.solved(drawn[0].names)
    rest = list(src)
    assert all(_revisits(task, p) == 0 for p in rest)
    assert {p.names for p in drawn + rest} <= loopless


def test_what_the_source_looked_ahead_at_is_not_lost_to_a_forbidden_prefix_or_learning():
    task, _ = pen(1)
    src = _source(task)
    assert not src.waiting_on_results()
    ahead = src._ahead.names
    # a prefix it does not start with: it still comes next
    src.forbid_prefix(("(no such action)",))
    assert next(src).names == ahead
    assert not src.waiting_on_results()
    ahead = src._ahead.names
    # a prefix it starts with: gone
    src.forbid_prefix(ahead[:1])
    assert all(p.names[:1] != ahead[:1] for p in _plans(src, 50))
