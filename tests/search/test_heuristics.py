import dataclasses
import math

import pytest

from tampcli.errors import UnsupportedFeatureError
from tampcli.search.heuristics import HEURISTICS
from tampcli.search.heuristics.additive import HFF
from tampcli.search.searches import astar
from tests.task.tasks import ADL_FREE_TOGGLE, ipc_task, make_task

# From s one step to x, then one step each to g1 and g2: h* = 3.
FORK = """
(define (domain fork)
  (:predicates (s) (x) (g1) (g2) (never))
  (:action a :parameters () :precondition (s) :effect (x))
  (:action b :parameters () :precondition (x) :effect (g1))
  (:action c :parameters () :precondition (x) :effect (g2))
  (:action d :parameters () :precondition (never) :effect (g1)))
"""


def fork(goal="(and (g1) (g2))"):
    return make_task(FORK, f"(define (problem f) (:domain fork) (:init (s)) (:goal {goal}))")


def test_known_values_on_the_fork():
    task = fork()
    values = {name: HEURISTICS[name](task)(task.init) for name in HEURISTICS}
    assert values == {"hmax": 2.0, "hadd": 4.0, "hff": 3.0, "lmcut": 3.0, "blind": 1.0,
                      "lmcount": 3.0}


def test_goal_states_are_zero_and_dead_ends_infinite():
    task = fork()
    done = frozenset(i for i, f in enumerate(task.facts) if f in ("(g1)", "(g2)"))
    dead = fork(goal="(and (g1) (never))")
    for name, make in HEURISTICS.items():
        assert make(task)(done) == 0.0, name
        if name != "blind":
            assert make(dead)(dead.init) == math.inf, name


def test_hff_relaxed_plan_names_the_operators():
    task = fork()
    cost, ops = HFF(task).relaxed_plan(task.init)
    assert cost == 3.0
    assert sorted(task.operators[i].name for i in ops) == ["(a)", "(b)", "(c)"]


def _reachable_states(task, limit):
    seen, frontier = {task.init}, [task.init]
    while frontier and len(seen) < limit:
        nxt = []
        for state in frontier:
            for _, succ in task.successors(state):
                if succ not in seen:
                    seen.add(succ)
                    nxt.append(succ)
        frontier = nxt
    return list(seen)[:limit]


@pytest.mark.parametrize("domain,problem", [
    ("blocks", "probBLOCKS-4-1.pddl"),
    ("gripper", "prob01.pddl"),
    ("transport-opt08-strips", "p01.pddl"),
    ("parcprinter-08-strips", "p01.pddl"),
])
def test_admissible_heuristics_never_exceed_the_true_cost(domain, problem):
    task = ipc_task(domain, problem)
    hmax, lmcut, blind = (HEURISTICS[n](task) for n in ("hmax", "lmcut", "blind"))
    states = _reachable_states(task, 12)
    for state in states:
        sub = dataclasses.replace(task, init=state)
        result = astar(sub, HEURISTICS["blind"](sub))
        h_star = result.cost if result.status == "solved" else math.inf
        assert hmax(state) <= lmcut(state) + 1e-9 <= h_star + 1e-9
        assert blind(state) <= h_star


def test_lmcut_refuses_conditional_effects_with_an_alternative():
    task = make_task(*ADL_FREE_TOGGLE)
    with pytest.raises(UnsupportedFeatureError, match="lmcut does not support conditional effects.*hmax"):
        HEURISTICS["lmcut"](task)
    for name in ("hff", "hadd", "hmax", "blind"):
        assert HEURISTICS[name](task)(task.init) >= 1.0


def test_heuristics_see_through_axioms():
    task = ipc_task("psr-small", "p01-s2-n1-l2-f50.pddl")
    assert task.axioms or task.operators
    values = {name: HEURISTICS[name](task)(task.init) for name in ("hmax", "hadd", "hff", "lmcut")}
    assert all(0 < v < math.inf for v in values.values())
    assert values["hmax"] <= values["lmcut"] <= 8  # optimal cost 8 (REFERENCE.csv)


def test_unit_cost_hff_with_buckets_matches_the_heap():
    # the bucket queue of whole-number costs must give h_add's own values
    task = ipc_task("elevators-opt08-strips", "p03.pddl")
    unit = HFF(task, unit_cost=True)
    goal = unit.relaxed.goal
    state = task.init
    for op in astar(task, HFF(task)).plan:
        heap, _ = unit.relaxed.explore(state, additive=True, costs=unit.costs)
        buckets, _ = unit.relaxed.explore(state, additive=True, costs=unit.costs, integral=True)
        assert heap[goal] == buckets[goal] > 0
        state = task.apply(state, op)
    assert unit(task.init) == len(unit.relaxed_plan(task.init)[1]) > 0


SWITCH = """
(define (domain switch)
  (:requirements :negative-preconditions)
  (:predicates (on) (done))
  (:action off :parameters () :precondition (on) :effect (not (on)))
  (:action finish :parameters () :precondition (not (on)) :effect (done)))
"""


def test_hff_with_negations_counts_undoing_what_a_condition_needs_false():
    task = make_task(SWITCH, "(define (problem s) (:domain switch) (:init (on)) (:goal (done)))")
    # the plain relaxation assumes (not (on)): one step; with negations, two
    assert HFF(task)(task.init) == 1.0
    with_negations = HFF(task, unit_cost=True, negations=True)
    assert with_negations(task.init) == 2.0
    assert {task.operators[i].name for i in with_negations.relaxed_plan(task.init)[1]} == {
        "(off)", "(finish)"}
    after = task.apply(task.init, task.operator("(off)"))
    assert with_negations(after) == 1.0
