"""Branch and bound with skeletons evaluated concurrently (bnb/parallel.py), on toy
skeletons and evaluators run in a thread pool: the books must come out as the
serial search's, whatever order the evaluations finish in."""

import math
import random
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

from tampcli.bnb import BnBOptions, branch_and_bound
from tampcli.bnb.parallel import parallel_branch_and_bound
from tampcli.bnb.skeleton_run import answer, run_skeleton

from .test_bnb import R, Source, table_evaluator

PLANS = [
    (("a", "b"), 2.0),
    (("c", "d"), 2.0),
    (("c", "e", "f"), 3.0),
    (("i", "j", "k"), 3.0),
    (("a", "g", "h"), 3.0),
    (("l", "m", "n", "o"), 4.0),
]
# ("a", "b") fails at its keyframes, its prefix ("a",) with it; ("c", ...) costs 1.5
# on the path, ("i", "j", "k") 0.2: the best once the symbolic weight is counted.
TABLE = {
    (("a",), "keyframes"): R("infeasible", worst_constraint="a blocked"),
    (("c",), "path"): R("solved", 1.5),
    (("c",), "keyframes"): R("solved", 1.0),
    (("i", "j", "k"), "path"): R("solved", 0.2),
    (("i", "j", "k"), "keyframes"): R("solved", 0.1),
}


class _Threads:
    """Workers: `workers - 1` threads (the search solves one skeleton itself) that run
    whole skeletons as worker processes do, each telling its own answer at once;
    `delays` (seconds by skeleton) scrambles the order results come back in."""

    def __init__(self, evaluate, workers, delays=None):
        self.pool = ThreadPoolExecutor(max(workers - 1, 1))
        self.evaluate, self.delays = evaluate, delays
        self.answers = {}  # rank -> (objective, cost per action) (Workers.found)

    def start(self):
        pass

    def submit(self, job):
        def run():
            time.sleep((self.delays or {}).get(job.names, 0.0))
            ops = tuple(type("Op", (), {"name": n})() for n in job.names)
            out = run_skeleton(job, ops, self.evaluate, lambda op: True,
                               lambda: self.below(job.rank)[0], lambda: self.below(job.rank)[1])
            found = answer(job, out, ops, lambda op: True)
            if found is not None:
                self.found(job.rank, *found)
            return out

        return self.pool.submit(run)

    def below(self, rank):
        return min((v for r, v in list(self.answers.items()) if r < rank),
                   key=lambda v: v[0], default=(math.inf, None))

    def found(self, rank, objective, each=None):
        if objective < self.answers.get(rank, (math.inf, None))[0]:
            self.answers[rank] = (objective, each)


def _parallel(plans, table, workers, delays=None, **options):
    evaluate = table_evaluator(table)
    threads = _Threads(evaluate, workers, delays)
    try:
        return parallel_branch_and_bound(Source(plans), threads, evaluate,
                                         BnBOptions(jobs=workers, **options))
    finally:
        threads.pool.shutdown(wait=False, cancel_futures=True)


def _books(result):
    return [(r.rank, r.plan, r.outcome, r.stage, r.nlp_cost, r.reason) for r in result.skeletons]


@pytest.mark.parametrize("workers", [2, 3, 6])
def test_same_answer_as_the_serial_search(workers):
    serial = branch_and_bound(Source(PLANS), table_evaluator(TABLE), BnBOptions())
    parallel = _parallel(PLANS, TABLE, workers)
    assert serial.status == parallel.status == "solved"
    assert [op.name for op in parallel.best_plan] == [op.name for op in serial.best_plan] \
        == ["i", "j", "k"]
    assert parallel.best_objective == pytest.approx(serial.best_objective, abs=1e-12)
    assert parallel.stats["stop"] == serial.stats["stop"]
    # Before the first solution (#2) one skeleton is out at a time, as serially: #1's
    # infeasible prefix is forbidden before #5 ("a", "g", "h") is drawn, however many
    # workers (with 2 per job out from the start, 3 workers drew it, and it failed).
    assert all(r.outcome == "infeasible" for r in parallel.skeletons if r.plan[0] == "a")
    assert ("a", "g", "h") not in [r.plan for r in parallel.skeletons]
    assert _books(parallel)[:2] == _books(serial)[:2]


def test_the_books_do_not_depend_on_which_worker_finishes_first():
    rng = random.Random(3)
    reference = _books(_parallel(PLANS, TABLE, 3))
    for _ in range(3):
        delays = {names: rng.uniform(0.0, 0.05) for names, _ in PLANS}
        assert _books(_parallel(PLANS, TABLE, 3, delays)) == reference


def test_a_failing_evaluation_is_that_skeleton_failed_and_the_search_goes_on():
    def evaluate(ops, stage, warm, cutoff=None):
        if ops[0].name == "c":
            raise RuntimeError("the simulator fell over")
        return table_evaluator(TABLE)(ops, stage, warm, cutoff)

    threads = _Threads(evaluate, 2)
    try:
        result = parallel_branch_and_bound(Source(PLANS), threads, evaluate, BnBOptions(jobs=2))
    finally:
        threads.pool.shutdown(wait=False)
    assert result.status == "solved"
    assert [op.name for op in result.best_plan] == ["i", "j", "k"]
    failed = [r for r in result.skeletons if r.plan[0] == "c"]
    assert failed and all(r.outcome == "infeasible" for r in failed)
    assert all("worker failed: RuntimeError: the simulator fell over" in r.reason
               for r in failed)
    assert result.stats["heuristic_prunes"] >= len(failed)  # they may hide a better answer


def test_the_time_limit_cancels_what_is_out():
    release = threading.Event()

    def slow(ops, stage, warm, cutoff=None):
        release.wait(5.0)
        return R("solved", 1.0)

    def here(ops, stage, warm, cutoff=None):
        # This process's NLPs end by the deadline (the pipeline's evaluator); a worker's
        # may not be waited for. #1, alone out before a first solution, is quick (and
        # costly: none after it is pruned by its answer).
        if ops[0].name == "a":
            return R("solved", 2.0)
        release.wait(0.1)
        return R("solved", 1.0)

    threads = _Threads(slow, 2)
    started = time.perf_counter()
    try:
        result = parallel_branch_and_bound(Source(PLANS), threads, here,
                                           BnBOptions(jobs=2, time_limit=0.3))
    finally:
        release.set()
        threads.pool.shutdown(wait=False, cancel_futures=True)
    assert time.perf_counter() - started < 2.0
    assert result.status == "solved" and result.stats["stop"] == "time limit"
    # After #1's answer every other skeleton is out at once (WINDOW per job).
    assert [r.outcome for r in result.skeletons] == ["solved"] + ["not reached"] * 5
    assert all(r.reason == "cancelled: time" for r in result.skeletons[1:])
    assert result.lower_bound is not None and result.lower_bound <= 0.2 + 1e-12


def test_first_stops_at_the_first_solution():
    result = _parallel(PLANS, TABLE, 2, first=True)
    assert result.status == "solved" and result.stats["stop"] == "first solution"
    assert [op.name for op in result.best_plan] == ["c", "d"]


def test_jobs_is_checked():
    from tampcli.errors import OptionError

    for bad in (-1, 1.5, True):
        with pytest.raises(OptionError, match="jobs"):
            BnBOptions(jobs=bad)
    from tampcli.bnb.values import DEFAULT_JOBS_CAP

    assert 1 <= BnBOptions(jobs=0).processes() <= DEFAULT_JOBS_CAP
    assert BnBOptions(jobs=3).processes() == 3 and BnBOptions(jobs=9).processes() == 9


class _Deaf(_Threads):
    """Workers that never hear of a new incumbent."""

    def found(self, rank, objective, each=None):
        pass


def test_a_new_incumbent_spares_the_path_stage_of_a_skeleton_out_and_changes_no_book():
    # ("a", "b"), alone out before a first solution, answers 3.0; then the other two
    # are out at once.
    plans = [(("a", "b"), 2.0), (("c", "d"), 2.0), (("x", "y"), 2.0)]
    table = {(("a",), "keyframes"): R("solved", 2.6), (("a",), "path"): R("solved", 2.8),
             (("c",), "keyframes"): R("solved", 1.0), (("c",), "path"): R("solved", 1.5),
             (("x",), "keyframes"): R("solved", 2.0), (("x",), "path"): R("solved", 2.5)}
    books, paths = [], []
    for kind in (_Threads, _Deaf):
        calls = []
        evaluate = table_evaluator(table, calls)
        # ("x", "y") starts once ("c", "d") is taken: its keyframe bound 2.2 is above 1.7.
        threads = kind(evaluate, 2, delays={("x", "y"): 0.3})
        try:
            result = parallel_branch_and_bound(Source(plans), threads, evaluate,
                                               BnBOptions(jobs=2))
        finally:
            threads.pool.shutdown(wait=False)
        books.append(_books(result))
        paths.append([names for names, stage in calls if stage == "path"])
    assert books[0] == books[1]
    assert books[0][2][2:4] == ("pruned", "keyframes")
    assert paths == [[("a", "b"), ("c", "d")], [("a", "b"), ("c", "d"), ("x", "y")]]


def test_a_skeleton_out_hears_of_a_lower_rank_answer_before_the_books_take_it():
    """#1 answers first, alone (objective 3.0). Then #2, solved in this process, is
    slow; #3's answer (objective 0.4), found by the worker meanwhile, waits on #2 for
    its turn in the books, but #4, queued behind it in the same worker, hears of it at
    once (Workers.found, told by the worker itself) and stops at its keyframe bound
    (0.5 + 0.2 >= 0.4): no path stage; the books as the serial search's."""
    plans = [(("a", "b"), 2.0), (("s", "t"), 2.0), (("c", "d"), 2.0), (("e", "f"), 2.0)]
    table = {(("a",), "path"): R("solved", 2.8), (("s",), "path"): R("solved", 1.5),
             (("c",), "path"): R("solved", 0.2), (("c",), "keyframes"): R("solved", 0.1),
             (("e",), "keyframes"): R("solved", 0.5), (("e",), "path"): R("solved", 0.6)}
    calls = []
    quick = table_evaluator(table, calls)

    def evaluate(ops, stage, warm, cutoff=None):
        if ops[0].name == "s" and stage == "path":
            time.sleep(0.6)
        return quick(ops, stage, warm, cutoff)

    threads = _Threads(evaluate, 2)
    try:
        result = parallel_branch_and_bound(Source(plans), threads, evaluate, BnBOptions(jobs=2))
    finally:
        threads.pool.shutdown(wait=False)
    assert (("e", "f"), "path") not in calls
    serial = branch_and_bound(Source(plans), table_evaluator(table), BnBOptions())
    assert _books(result) == _books(serial)
    assert [r.outcome for r in result.skeletons] == ["solved", "solved", "solved", "pruned"]


def test_this_process_solves_the_first_skeleton_and_a_worker_the_next():
    """Two jobs: the lowest rank not started is solved here, so a problem of one
    skeleton never waits for a worker; before a first solution every skeleton is
    solved here, one at a time; after it, the next but one goes to the worker."""
    plans = [(("a", "b"), 2.0), (("c", "d"), 2.0), (("e", "f"), 2.0)]
    table = {(("a",), "path"): R("solved", 1.5), (("c",), "path"): R("solved", 0.2)}
    here = threading.get_ident()
    where = {}

    def evaluate(ops, stage, warm, cutoff=None):
        where[ops[0].name] = threading.get_ident() == here
        return table_evaluator(table)(ops, stage, warm, cutoff)

    threads = _Threads(evaluate, 2)
    try:
        parallel_branch_and_bound(Source(plans), threads, evaluate, BnBOptions(jobs=2))
    finally:
        threads.pool.shutdown(wait=False)
    assert where == {"a": True, "c": True, "e": False}


def test_after_a_first_solution_more_skeletons_are_out_at_once():
    """WINDOW: once there is an incumbent, a slow skeleton no longer holds the others
    back at 2 per job, nor do they wait queued behind it at a busy worker: the cheap
    ones after it are solved while it runs (arm-sort's slow #8, #13 and #17 then run
    side by side with the cheap ones)."""
    plans = [(("c", "d"), 2.0), (("s",), 2.0)] + [((f"p{i}",), 3.0) for i in range(8)]
    table = {(("c",), "path"): R("solved", 1.5), (("c",), "keyframes"): R("solved", 1.0)}
    inner = table_evaluator(table)
    started, slow = {}, []

    def evaluate(ops, stage, warm, cutoff=None):
        names = tuple(op.name for op in ops)
        started.setdefault(names, time.perf_counter())
        if names == ("s",) and stage == "keyframes":
            slow.append(time.perf_counter())
            time.sleep(0.5)
            slow.append(time.perf_counter())
        return inner(ops, stage, warm, cutoff)

    threads = _Threads(evaluate, 2)
    try:
        result = parallel_branch_and_bound(Source(plans), threads, evaluate,
                                           BnBOptions(jobs=2))
    finally:
        threads.pool.shutdown(wait=True)
    assert result.status == "solved" and len(result.skeletons) == len(plans)
    # ("s",) goes to the worker thread; this process takes every cheap one, the two
    # queued behind it there taken back (_take_back). 2 per job: p0 to p2 only, until
    # ("s",) is taken; without taking back, p2 to p7 (p0 and p1 wait behind it).
    before = [n for n, t in started.items() if n[0].startswith("p") and t < slow[1]]
    assert sorted(before) == [(f"p{i}",) for i in range(8)]
