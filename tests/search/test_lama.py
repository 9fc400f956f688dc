"""LAMA's pieces: landmarks and their count, the lama search, greedy action
elimination, and the anytime improvement; on tiny tasks and a few IPC problems."""

import pytest

from tampcli.pddl.load import load
from tampcli.search.anytime import Improvement, Outcome, improve
from tampcli.search.eliminate import eliminate_redundant
from tampcli.search.heuristics import HEURISTICS
from tampcli.search.heuristics.landmarks import LandmarkCount
from tampcli.search.searches import SearchLimits, astar, lama, lazy_gbfs
from tampcli.search.validate import validate_plan
from tampcli.task.ground import ground
from tests.pddl import ipc
from tests.task.tasks import CORRIDOR, by_name, corridor_problem, make_task, replay

# Two keys, two doors: every plan fetches key k1 before opening d1 and so on.
KEYS = """
(define (domain keys)
  (:predicates (at-start) (has ?k) (open ?d) (opens ?k ?d) (spare))
  (:action fetch :parameters (?k) :precondition (at-start) :effect (has ?k))
  (:action unlock :parameters (?k ?d) :precondition (and (has ?k) (opens ?k ?d))
    :effect (open ?d))
  (:action drop :parameters (?k) :precondition (has ?k) :effect (not (has ?k))))
"""
KEYS_PROBLEM = """(define (problem k) (:domain keys) (:objects k1 k2 d1 d2)
  (:init (at-start) (opens k1 d1) (opens k2 d2)) (:goal (and (open d1) (open d2))))"""


def _names(task, facts):
    return sorted(task.facts[f] for f in facts)


def test_landmarks_are_the_goals_and_the_shared_preconditions_before_them():
    task = make_task(KEYS, KEYS_PROBLEM)
    lm = LandmarkCount(task)
    # at-start is static, so not a fact of the grounded task
    assert sorted(_names(task, node) for node in lm.landmarks) == [
        ["(has k1)"], ["(has k2)"], ["(open d1)"], ["(open d2)"]]
    assert lm.orderings == 2
    assert lm(task.init) == 4.0


def test_either_key_is_a_disjunctive_landmark():
    # either key opens either door: neither key is a landmark, one of the two is
    task = make_task(KEYS, KEYS_PROBLEM.replace("(opens k2 d2)",
                                                "(opens k2 d2) (opens k2 d1) (opens k1 d2)"))
    lm = LandmarkCount(task)
    nodes = sorted(_names(task, node) for node in lm.landmarks)
    assert nodes == [["(has k1)", "(has k2)"], ["(open d1)"], ["(open d2)"]]
    assert lm(task.init) == 3.0
    s1 = task.apply(task.init, by_name(task, "(fetch k2)"))
    lm.progress(task.init, s1)
    assert lm(s1) == 2.0
    # with k1 needed only for d2 (k2 does not open it), k1 is a landmark alone and
    # the disjunction that holds it is dropped
    task = make_task(KEYS, KEYS_PROBLEM.replace("(opens k2 d2)", "(opens k2 d1) (opens k1 d2)"))
    nodes = sorted(_names(task, node) for node in LandmarkCount(task).landmarks)
    assert nodes == [["(has k1)"], ["(open d1)"], ["(open d2)"]]


def test_landmark_count_follows_the_path():
    task = make_task(KEYS, KEYS_PROBLEM)
    lm = LandmarkCount(task)
    s1 = task.apply(task.init, by_name(task, "(fetch k1)"))
    lm.progress(task.init, s1)
    assert lm(s1) == 3.0
    # dropping the key before its door is open: has k1 is needed again
    s2 = task.apply(s1, by_name(task, "(drop k1)"))
    lm.progress(s1, s2)
    assert lm(s2) == 4.0
    s3 = task.apply(s1, by_name(task, "(unlock k1 d1)"))
    lm.progress(s1, s3)
    assert lm(s3) == 2.0
    # without a recorded path, what is ordered before a true landmark counts as reached
    fresh = LandmarkCount(task)
    assert fresh(s3) == 2.0


def test_landmark_count_sees_an_unreachable_goal_as_a_dead_end():
    task = make_task(KEYS, KEYS_PROBLEM.replace("(opens k2 d2)", ""))
    assert LandmarkCount(task)(task.init) == float("inf")
    assert lama(task, LandmarkCount(task)).status == "unsolvable"


def test_lama_solves_the_tiny_tasks():
    for task in (make_task(KEYS, KEYS_PROBLEM), make_task(CORRIDOR, corridor_problem(6))):
        result = lama(task, LandmarkCount(task))
        assert result.status == "solved"
        assert task.is_goal(replay(task, result.plan))
        assert result.stats["expanded"] <= 10


def _ipc(first: int):
    out = []
    for domain in ipc.domains():
        for problem in ipc.problems(domain)[:first]:
            out.append((ipc.domain_of(problem), problem))
    return out


FEW = [pair for pair in _ipc(1) if pair[1].parent.name in (
    "blocks", "gripper", "logistics00", "elevators-opt08-strips", "miconic-fulladl", "psr-small",
    "rovers", "assembly")]


@pytest.mark.parametrize("domain, problem", FEW, ids=[p.parent.name for _, p in FEW])
def test_lama_plans_are_valid_on_ipc(domain, problem):
    loaded = load(domain, problem)
    task = ground(loaded.domain, loaded.problem)
    result = lama(task, LandmarkCount(task), SearchLimits(time_limit=60))
    assert result.status == "solved"
    report = validate_plan(loaded.domain, loaded.problem, [op.name for op in result.plan])
    assert report.valid and report.cost == pytest.approx(result.cost)


def test_elimination_drops_a_detour_and_what_it_made_necessary():
    task = make_task(CORRIDOR, corridor_problem(4))
    steps = ["(move r0 r1)", "(move r1 r0)", "(move r0 r1)", "(move r1 r2)", "(move r2 r3)"]
    plan = [by_name(task, s) for s in steps]
    shorter = eliminate_redundant(task, plan)
    assert [op.name for op in shorter] == ["(move r0 r1)", "(move r1 r2)", "(move r2 r3)"]
    assert eliminate_redundant(task, shorter) == shorter


def test_elimination_keeps_a_plan_without_redundancy():
    task = make_task(KEYS, KEYS_PROBLEM)
    plan = [by_name(task, s) for s in ("(fetch k1)", "(unlock k1 d1)", "(fetch k2)",
                                       "(unlock k2 d2)")]
    assert list(eliminate_redundant(task, plan)) == plan
    padded = plan[:2] + [by_name(task, "(fetch k1)"), by_name(task, "(drop k1)")] + plan[2:]
    assert list(eliminate_redundant(task, padded)) == plan


ELIMINATE = _ipc(2)


@pytest.mark.parametrize("domain, problem", ELIMINATE,
                         ids=[f"{p.parent.name}/{p.name}" for _, p in ELIMINATE])
def test_elimination_never_makes_an_ipc_plan_invalid(domain, problem):
    loaded = load(domain, problem)
    task = ground(loaded.domain, loaded.problem)
    # lazy GBFS plans without preferred-first tie-breaking have detours to drop
    result = lazy_gbfs(task, HEURISTICS["hadd"](task), SearchLimits(time_limit=60))
    assert result.status == "solved"
    shorter = eliminate_redundant(task, result.plan)
    report = validate_plan(loaded.domain, loaded.problem, [op.name for op in shorter])
    assert report.valid, report.failure
    assert report.cost <= result.cost + 1e-9
    assert len(shorter) <= len(result.plan)


def test_astar_bound_prunes_every_plan_not_cheaper():
    task = make_task(CORRIDOR, corridor_problem(5))
    hff, lmcut = HEURISTICS["hff"](task), HEURISTICS["lmcut"](task)
    assert astar(task, hff, SearchLimits(bound=5)).cost == 4
    for h in (hff, lmcut):
        assert astar(task, h, SearchLimits(bound=4)).status == "unsolvable"


def test_anytime_improves_to_the_optimum_and_proves_it():
    task = make_task(CORRIDOR, corridor_problem(5))
    detour = [by_name(task, s) for s in ("(move r0 r1)", "(move r1 r2)", "(move r2 r1)",
                                         "(move r1 r2)", "(move r2 r3)", "(move r3 r4)")]
    steps = list(improve(task, detour, HEURISTICS["hff"], time_limit=30))
    *found, end = steps
    assert all(isinstance(s, Improvement) for s in found) and isinstance(end, Outcome)
    assert [s.cost for s in found] == [4.0] and found[0].weight == 5.0
    assert end.reason == "optimal"
    assert task.is_goal(replay(task, found[0].plan))


def test_anytime_stops_at_the_time_limit():
    loaded = load(*_ipc(3)[0])  # assembly
    task = ground(loaded.domain, loaded.problem)
    first = lama(task, LandmarkCount(task)).plan
    steps = list(improve(task, first, HEURISTICS["hff"], time_limit=0.05))
    assert steps[-1] == Outcome("limit")
    costs = [s.cost for s in steps[:-1]]
    assert costs == sorted(costs, reverse=True)


@pytest.mark.parametrize("folder, name", [("blocks", "probBLOCKS-4-0.pddl"),
                                          ("transport-opt08-strips", "p02.pddl"),
                                          ("psr-large", "p02-s46-n3-l5-f50.pddl")])
def test_elimination_shortens_ipc_plans_with_detours(folder, name):
    problem = ipc.IPC / folder / name
    loaded = load(ipc.domain_of(problem), problem)
    task = ground(loaded.domain, loaded.problem)
    plan = lazy_gbfs(task, HEURISTICS["hadd"](task)).plan
    shorter = eliminate_redundant(task, plan)
    assert len(shorter) < len(plan)
    assert validate_plan(loaded.domain, loaded.problem, [op.name for op in shorter]).valid
