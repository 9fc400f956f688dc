"""Ranked plans: against exhaustive enumeration, against K* (kstar-planner), and forbid_prefix."""

from __future__ import annotations

import itertools
from collections import Counter
from pathlib import Path

import pytest

from tampcli.pddl import parser
from tampcli.search.topk import Plan, TopK
from tampcli.search.validate import validate_plan
from tampcli.task.ground import ground

INF = float("inf")
ROOT = Path(__file__).resolve().parents[2]
IPC = ROOT / "benchmarks" / "ipc"


def task_of(domain: Path, problem: Path):
    dom, prob = parser.parse_domain_file(domain), parser.parse_problem_file(problem)
    return ground(dom, prob), dom, prob


def all_plans(task, bound: float, loopless: bool,
              max_len: int = 10**9) -> list[tuple[float, tuple[str, ...]]]:
    """Every plan of cost <= bound (and length <= max_len), by depth-first enumeration."""
    found = []

    def dfs(state, g, names, seen):
        if task.is_goal(state):
            found.append((g, names))
        if len(names) == max_len:
            return
        for op, nxt in task.successors(state):
            if g + op.cost > bound or (loopless and nxt in seen):
                continue
            dfs(nxt, g + op.cost, names + (op.name,), seen | {nxt})

    dfs(task.init, 0.0, (), frozenset([task.init]))
    return sorted(found)


def check_against_enumeration(task, k: int, loopless: bool, dom=None, prob=None,
                              max_len: int = 10**9):
    plans = list(itertools.islice(TopK(task, loopless=loopless), k))
    # costs equal up to float rounding (sums of the same costs in another order)
    costs = [round(p.cost, 9) for p in plans]
    assert costs == sorted(costs)
    bound = costs[-1]
    reference = sorted((round(c, 9), names)
                       for c, names in all_plans(task, bound + 1e-6, loopless, max_len))
    # the k cheapest costs are the k smallest of all plans up to the k-th cost
    assert costs == [c for c, _ in reference[:len(costs)]]
    # below the k-th cost the plans themselves must be exactly the same set
    below = {names for c, names in reference if c < bound}
    got = [p.names for p in plans]
    assert len(set(got)) == len(got), "a plan came out twice"
    assert below <= set(got)
    for p in plans:
        assert sum(op.cost for op in p.operators) == pytest.approx(p.cost)
        if loopless:
            assert loopless_ok(task, p)
        if dom is not None:
            report = validate_plan(dom, prob, list(p.names))
            assert report.valid and report.cost == pytest.approx(p.cost), report.failure
    return plans


def loopless_ok(task, plan: Plan) -> bool:
    state, seen = task.init, {task.init}
    for op in plan.operators:
        state = task.apply(state, op)
        if state in seen:
            return False
        seen.add(state)
    return True


SMALL = [
    pytest.param(ROOT / "domains/blocksworld/domain.pddl", ROOT / "problems/blocksworld/p01.pddl",
                 60, id="sussman"),
    pytest.param(ROOT / "domains/gripper/domain.pddl", ROOT / "problems/gripper/p01.pddl", 60,
                 id="gripper-2"),
    pytest.param(IPC / "blocks/domain.pddl", IPC / "blocks/probBLOCKS-4-0.pddl", 12,
                 id="blocks-4-0"),
    pytest.param(IPC / "psr-small/p01-domain.pddl", IPC / "psr-small/p01-s2-n1-l2-f50.pddl", 40,
                 id="psr-small-1"),
    pytest.param(IPC / "miconic-fulladl/domain.pddl", IPC / "miconic-fulladl/f1-0.pddl", 40,
                 id="miconic-fulladl-1"),
    pytest.param(IPC / "briefcaseworld/domain.pddl", IPC / "briefcaseworld/pfile1.pddl", 40,
                 id="briefcaseworld-1"),
]


@pytest.mark.parametrize("loopless", [False, True], ids=["standard", "loopless"])
@pytest.mark.parametrize("domain,problem,k", SMALL)
def test_k_best_equal_exhaustive_enumeration(domain, problem, k, loopless):
    task, dom, prob = task_of(domain, problem)
    check_against_enumeration(task, k, loopless, dom, prob)


# ---------------------------------------------------------------- a toy with costs and cycles

TOY_DOMAIN = """
(define (domain ring)
  (:requirements :strips :typing :action-costs :conditional-effects :derived-predicates)
  (:types node)
  (:predicates (at ?n - node) (edge ?a ?b - node) (free ?a ?b - node) (lit) (done))
  (:derived (done) (and (at n3) (lit)))
  (:functions (total-cost) - number (len ?a ?b - node) - number)
  (:action go
    :parameters (?a ?b - node)
    :precondition (and (at ?a) (edge ?a ?b))
    :effect (and (at ?b) (not (at ?a)) (increase (total-cost) (len ?a ?b))))
  (:action hop
    :parameters (?a ?b - node)
    :precondition (and (at ?a) (free ?a ?b))
    :effect (and (at ?b) (not (at ?a))))
  (:action toggle
    :parameters ()
    :effect (and (when (lit) (not (lit))) (when (not (lit)) (lit))
                 (increase (total-cost) 1))))
"""

TOY_PROBLEM = """
(define (problem ring1) (:domain ring)
  (:objects n0 n1 n2 n3 - node)
  (:init (at n0) (edge n0 n1) (edge n1 n2) (edge n2 n3) (edge n0 n2) (edge n2 n0) (edge n1 n0)
         (free n1 n2) (free n2 n1)
         (= (len n0 n1) 1) (= (len n1 n2) 2) (= (len n2 n3) 1) (= (len n0 n2) 4)
         (= (len n2 n0) 1) (= (len n1 n0) 3) (= (total-cost) 0))
  (:goal (done))
  (:metric minimize (total-cost)))
"""


def make_toy(hops: bool):
    text = TOY_PROBLEM if hops else TOY_PROBLEM.replace("(free n1 n2) (free n2 n1)", "")
    dom, prob = parser.parse_domain(TOY_DOMAIN), parser.parse_problem(text)
    return ground(dom, prob), dom, prob


@pytest.fixture(scope="module")
def toy():
    return make_toy(hops=True)


@pytest.mark.parametrize("hops", [False, True], ids=["costly-cycles", "zero-cost-cycle"])
def test_toy_standard_mode_with_cycles_costs_and_conditional_effects(hops):
    task, dom, prob = make_toy(hops)
    # with the zero-cost hop cycle n1 <-> n2 there are infinitely many plans
    # of each cost; plans up to 12 steps are enough to fill the first 40
    check_against_enumeration(task, 40, False, dom, prob, max_len=12)


def test_derived_predicates_with_landmark_cut():
    # without the conditional `toggle`, LM-cut (with the axioms relaxed) is the heuristic
    a = TOY_DOMAIN.index("  (:action toggle")
    dom = parser.parse_domain(TOY_DOMAIN[:a] + ")")
    text = TOY_PROBLEM.replace("(:init (at n0)", "(:init (at n0) (lit)")
    prob = parser.parse_problem(text.replace("(free n1 n2) (free n2 n1)", ""))
    task = ground(dom, prob)
    topk = TopK(task)
    assert type(topk._graph.heuristic).__name__ == "LandmarkCut"
    assert task.axioms
    check_against_enumeration(task, 30, False, dom, prob, max_len=12)
    check_against_enumeration(task, 10_000, True, dom, prob)


def test_fractional_costs():
    text = TOY_PROBLEM.replace("(free n1 n2) (free n2 n1)", "")
    for old, new in (("n0 n1) 1", "n0 n1) 0.1"), ("n1 n2) 2", "n1 n2) 0.2"),
                     ("n2 n3) 1", "n2 n3) 0.7"), ("n0 n2) 4", "n0 n2) 0.3"),
                     ("n2 n0) 1", "n2 n0) 0.3"), ("n1 n0) 3", "n1 n0) 0.6")):
        assert old in text
        text = text.replace(old, new)
    dom, prob = parser.parse_domain(TOY_DOMAIN), parser.parse_problem(text)
    task = ground(dom, prob)
    check_against_enumeration(task, 40, False, dom, prob)
    check_against_enumeration(task, 10_000, True, dom, prob)


@pytest.mark.parametrize("hops", [False, True], ids=["costly-cycles", "zero-cost-cycle"])
def test_toy_loopless_gives_every_simple_plan(hops):
    task, dom, prob = make_toy(hops)
    plans = check_against_enumeration(task, 10_000, True, dom, prob)
    assert len(plans) == len(all_plans(task, 1e9, True))


def test_standard_mode_stays_lazy_on_a_zero_cost_cycle(toy):
    task, _, _ = toy
    plans = list(itertools.islice(TopK(task), 500))
    assert len(plans) == 500
    assert [p.cost for p in plans] == sorted(p.cost for p in plans)


def test_loopless_mode_ends(toy):
    topk = TopK(toy[0], loopless=True)
    plans = list(topk)
    assert plans and topk.stats["status"] == "exhausted"
    assert len(plans) == len({p.names for p in plans})


def test_unsolvable_task_yields_nothing():
    dom = parser.parse_domain(TOY_DOMAIN)
    prob = parser.parse_problem(TOY_PROBLEM.replace("(edge n2 n3)", ""))
    topk = TopK(ground(dom, prob))
    assert list(topk) == []
    assert topk.stats["status"] == "exhausted"


# ---------------------------------------------------------------- forbid_prefix

@pytest.mark.parametrize("loopless", [False, True], ids=["standard", "loopless"])
def test_forbid_prefix(loopless):
    task, _, _ = task_of(IPC / "blocks/domain.pddl", IPC / "blocks/probBLOCKS-4-0.pddl")
    free = list(itertools.islice(TopK(task, loopless=loopless), 120))
    topk = TopK(task, loopless=loopless)
    first = next(topk)
    assert first.names == free[0].names
    prefix = first.names[:2]
    topk.forbid_prefix(prefix)
    rest = list(itertools.islice(topk, 30))
    assert all(p.names[:2] != prefix for p in rest)
    # the others are still produced, in the same order as without the prefix
    expected = [p for p in free[1:] if p.names[:2] != prefix]
    assert len(expected) >= len(rest) == 30
    assert [p.names for p in rest] == [p.names for p in expected[:30]]


def test_forbidding_everything_and_nested_prefixes():
    task, _, _ = task_of(ROOT / "domains/blocksworld/domain.pddl",
                         ROOT / "problems/blocksworld/p01.pddl")
    topk = TopK(task)
    p = next(topk)
    topk.forbid_prefix(p.names)  # the exact plan, then a prefix of it, then all
    topk.forbid_prefix(p.names[:1])
    assert all(q.names[:1] != p.names[:1] for q in itertools.islice(topk, 20))
    topk.forbid_prefix(())
    assert list(itertools.islice(topk, 5)) == []


def test_time_limit_is_a_status():
    task, _, _ = task_of(IPC / "logistics00/domain.pddl", IPC / "logistics00/probLOGISTICS-4-0.pddl")
    topk = TopK(task, time_limit=0.05)
    # plans may loop, so there are infinitely many: only the limit ends this
    for _ in topk:
        pass
    assert topk.stats["status"] == "limit"


def test_bad_time_limit():
    from tampcli.errors import UsageError

    task, _, _ = task_of(ROOT / "domains/blocksworld/domain.pddl",
                         ROOT / "problems/blocksworld/p01.pddl")
    with pytest.raises(UsageError):
        TopK(task, time_limit=0)


# ---------------------------------------------------------------- K* (kstar-planner)

KSTAR = [
    pytest.param("gripper", "prob01", 10),
    pytest.param("gripper", "prob01", 100),
    pytest.param("blocks", "probBLOCKS-4-0", 10),
    pytest.param("blocks", "probBLOCKS-4-0", 100),
    pytest.param("logistics00", "probLOGISTICS-4-0", 10, marks=pytest.mark.slow),
    pytest.param("logistics00", "probLOGISTICS-4-0", 100, marks=pytest.mark.slow),
    pytest.param("elevators-opt08-strips", "p01", 10, marks=pytest.mark.slow),
    pytest.param("elevators-opt08-strips", "p01", 100, marks=pytest.mark.slow),
]


def kstar_costs(domain: str, problem: str, k: int) -> list[float]:
    planners = pytest.importorskip("kstar_planner.planners")
    result = planners.plan_topk(IPC / domain / "domain.pddl", IPC / domain / f"{problem}.pddl",
                                k, timeout=300)
    return sorted(float(p["cost"]) for p in result["plans"])


@pytest.mark.parametrize("domain,problem,k", KSTAR)
def test_costs_equal_kstar(domain, problem, k):
    task, dom, prob = task_of(IPC / domain / "domain.pddl", IPC / domain / f"{problem}.pddl")
    plans = list(itertools.islice(TopK(task), k))
    assert [p.cost for p in plans] == kstar_costs(domain, problem, k)
    assert len({p.names for p in plans}) == k
    for p in plans[:: max(1, k // 10)]:
        assert validate_plan(dom, prob, list(p.names)).cost == p.cost
    counts = Counter(p.cost for p in plans)
    assert sum(counts.values()) == k


# ---------------------------------------------------------------- LM-cut with landmarks

def exact_distances(task):
    """h* of every reachable state, by backward Dijkstra over the whole state space."""
    import heapq

    states, edges, todo = {task.init}, [], [task.init]
    while todo:
        s = todo.pop()
        for op, t in task.successors(s):
            edges.append((s, op, t))
            if t not in states:
                states.add(t)
                todo.append(t)
    preds = {s: [] for s in states}
    for s, op, t in edges:
        preds[t].append((op.cost, s))
    dist = {s: float("inf") for s in states}
    heap = [(0.0, i, s) for i, s in enumerate(s for s in states if task.is_goal(s))]
    for _, _, s in heap:
        dist[s] = 0.0
    heapq.heapify(heap)
    tie = len(heap)
    while heap:
        d, _, s = heapq.heappop(heap)
        if d > dist[s]:
            continue
        for c, p in preds[s]:
            if d + c < dist[p]:
                dist[p] = d + c
                tie += 1
                heapq.heappush(heap, (d + c, tie, p))
    return dist, edges


@pytest.mark.parametrize("domain,problem", [
    (IPC / "blocks/domain.pddl", IPC / "blocks/probBLOCKS-4-0.pddl"),
    (IPC / "gripper/domain.pddl", IPC / "gripper/prob01.pddl"),
])
def test_landmark_cut_values_and_successor_bounds_are_admissible(domain, problem):
    from tampcli.search.heuristics import LMCut
    from tampcli.search.topk_landmarks import LandmarkCut

    task, _, _ = task_of(domain, problem)
    dist, edges = exact_distances(task)
    ours, theirs = LandmarkCut(task), LMCut(task)
    index = {id(op): i for i, op in enumerate(task.operators)}
    cache = {}
    for s in dist:
        h, found, rest = ours.landmarks(s)
        cache[s] = (h, found)
        assert rest is None
        assert h <= dist[s] + 1e-9
        assert h == theirs(s)  # the same algorithm as the shared heuristic
        assert h == pytest.approx(sum(m for m, _ in found))
        budget = h / 2
        partial, _, rest = ours.landmarks(s, budget)
        if h > budget and h > 0:
            assert budget < partial <= h
            assert rest is not None
            resumed, _, rest2 = ours.landmarks(s, float("inf"), rest)
            assert rest2 is None and resumed == h
    for s, op, t in edges:
        h, found = cache[s]
        bound = h - sum(m for m, ops in found if index[id(op)] in ops)
        assert bound <= dist[t] + 1e-9
        # LM-cut on t starting from the landmarks it inherits from s
        inherited = [lm for lm in found if index[id(op)] not in lm[1]]
        value, more, rest = ours.landmarks(t, inherited=inherited)
        assert rest is None and more[:len(inherited)] == inherited
        assert bound - 1e-9 <= value <= dist[t] + 1e-9
        assert value == pytest.approx(sum(m for m, _ in more))
        charged = Counter()
        for m, ops in more:
            for o in ops:
                charged[o] += m
        assert all(charged[i] <= task.operators[i].cost + 1e-9 for i in charged)
        if value > 0 and value < INF:
            partial, _, rest = ours.landmarks(t, value / 2, inherited=inherited)
            if rest is not None:
                assert ours.landmarks(t, INF, rest)[0] == pytest.approx(value)


def test_initial_state_already_a_goal_gives_the_empty_plan_first():
    dom = parser.parse_domain(TOY_DOMAIN)
    prob = parser.parse_problem(TOY_PROBLEM.replace("(:goal (done))", "(:goal (at n0))"))
    task = ground(dom, prob)
    for loopless in (False, True):
        plans = list(itertools.islice(TopK(task, loopless=loopless), 5))
        assert plans[0].operators == () and plans[0].cost == 0
        reference = all_plans(task, plans[-1].cost, loopless, max_len=10)
        assert [p.cost for p in plans] == [c for c, _ in reference][:5]
