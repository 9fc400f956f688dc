"""A skeleton pruned by the reach bound of a short prefix (bnb/prefix_reach.py), on
toy skeletons whose every stage costs 0.1 per action: serial and parallel."""

import threading
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import pytest

from tampcli.bnb import BnBOptions, branch_and_bound, prefix_reach
from tampcli.bnb.parallel import parallel_branch_and_bound
from tampcli.bnb.skeleton_run import run_skeleton

from .test_bnb import Source

EACH = 0.1  # every stage's cost per action


@dataclass(frozen=True)
class Result:
    status: str
    cost: float
    names: tuple
    iterations: int = 1


def evaluator(calls):
    def evaluate(ops, stage, warm, cutoff=None):
        names = tuple(op.name for op in ops)
        calls.append((names, stage))
        return Result("solved", 0.0 if stage == "final" else EACH * len(names), names)

    return evaluate


# The first costs 0.4 + 0.1 * 4 = 0.8. The two of 7 actions (symbolic 7.7) have 0.03
# to spare, which their first two actions, a prefix they share, already cost more
# than; the one of 5 actions (symbolic 5) has 0.3 to spare: 6 actions' worth at
# twice the margin, more than half of its 5, so no prefix is tried.
PLANS = [
    (("a", "b", "c", "d"), 4.0),
    (("a", "b", "c", "d", "e"), 5.0),
    (("a", "b", "x", "y", "z", "u", "v"), 7.7),
    (("a", "b", "y", "x", "z", "u", "v"), 7.7),
]


def _ops(names):
    return tuple(type("Op", (), {"name": n})() for n in names)


def test_the_prefix_is_the_shortest_expected_to_cost_twice_the_margin():
    ops = _ops("abcdefgh")
    geometric = lambda op: op.name != "c"  # noqa: E731
    assert prefix_reach.per_action(0.8, _ops("abcd"), geometric) == pytest.approx(0.8 / 3)
    # 2 * 0.07 / 0.05 = 2.8: three geometric actions, a, b and d (c is symbolic).
    assert prefix_reach.prefix_length(ops, geometric, 0.07, 0.05) == 4
    # At least a pick and its place.
    assert prefix_reach.prefix_length(ops, geometric, 0.001, 0.05) == 2
    # More than half of the skeleton's 7 geometric actions: the whole reach instead.
    assert prefix_reach.prefix_length(ops, geometric, 0.1, 0.04) is None
    assert prefix_reach.prefix_length(ops, geometric, 0.1, None) is None


def test_a_skeleton_with_little_margin_is_pruned_by_its_prefix_reach():
    calls = []
    result = branch_and_bound(Source(PLANS), evaluator(calls), BnBOptions(symbolic_weight=0.1))
    assert [op.name for op in result.best_plan] == ["a", "b", "c", "d"]
    records = {r.plan: r for r in result.skeletons}
    for plan in PLANS[2:]:
        record = records[plan[0]]
        assert record.outcome == "pruned" and record.stage == "reach"
        assert "of its first 2 actions" in record.reason
        # 0.2 + 0.77 >= 0.8: the prefix's bound, not the whole reach's (0.7 + 0.77).
        assert record.bound == pytest.approx(0.97)
    # One reach NLP of the shared prefix, none of the whole skeletons.
    assert calls.count((("a", "b"), "reach")) == 1
    assert not any(stage == "reach" and len(names) == 7 for names, stage in calls)
    # The skeleton with room to spare is evaluated whole.
    assert records[PLANS[1][0]].reason.startswith("reach (keyframes, no collisions) bound")
    assert ((PLANS[1][0]), "reach") in calls


def test_anytime_tries_no_prefix():
    calls = []
    branch_and_bound(Source(PLANS), evaluator(calls),
                     BnBOptions(symbolic_weight=0.1, anytime=True))
    assert (("a", "b"), "reach") not in calls


class _Threads:
    def __init__(self, evaluate, workers):
        self.pool, self.evaluate = ThreadPoolExecutor(workers - 1), evaluate
        self.answers = {}  # rank -> (objective, cost per action)
        self.heard = threading.Event()

    def start(self):
        pass

    def submit(self, job):
        def run():
            if job.names != PLANS[0][0]:  # the others start once #1's answer is in
                self.heard.wait(timeout=10)
            return run_skeleton(job, _ops(job.names), self.evaluate, lambda op: True,
                                lambda: self.below(job.rank)[0],
                                lambda: self.below(job.rank)[1])

        return self.pool.submit(run)

    def below(self, rank):
        return min((v for r, v in list(self.answers.items()) if r < rank),
                   default=(1e9, None))

    def found(self, rank, objective, each=None):
        self.answers[rank] = (objective, each)
        self.heard.set()


def test_the_parallel_search_prunes_by_the_same_prefix():
    calls = []
    threads = _Threads(evaluator(calls), 2)
    try:
        # Four out at once: #3 and #4 are drawn before #1 is taken, and hear of its
        # answer (Workers.improved) only as they run.
        result = parallel_branch_and_bound(Source(PLANS), threads, evaluator(calls),
                                           BnBOptions(symbolic_weight=0.1, jobs=2))
    finally:
        threads.pool.shutdown(wait=True)
    records = {r.plan: r for r in result.skeletons}
    for plan in PLANS[2:]:
        assert records[plan[0]].outcome == "pruned"
        assert "of its first 2 actions" in records[plan[0]].reason
    assert not any(stage == "reach" and len(names) == 7 for names, stage in calls)
