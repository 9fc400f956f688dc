import dataclasses

import pytest

from tampcli.errors import InputError, UnsupportedFeatureError
from tampcli.pddl import parser
from tampcli.task.ground import ground
from tests.task.tasks import CORRIDOR, by_name, corridor_problem, facts, make_task, replay


def test_static_facts_are_compiled_away_and_only_reachable_operators_kept():
    task = make_task(CORRIDOR, corridor_problem(4))
    assert not any(f.startswith("(link") for f in task.facts)
    # only linked moves: 3 forward + 3 backward, no (move r0 r0), no (move r0 r2)
    assert sorted(op.name for op in task.operators) == sorted(
        [f"(move r{i} r{i + 1})" for i in range(3)] + [f"(move r{i + 1} r{i})" for i in range(3)])
    assert task.unit_cost and all(op.cost == 1.0 for op in task.operators)


def test_successors_and_goal():
    task = make_task(CORRIDOR, corridor_problem(3))
    assert [op.name for op in task.applicable(task.init)] == ["(move r0 r1)"]
    s1 = task.apply(task.init, by_name(task, "(move r0 r1)"))
    assert facts(task, s1) == {"(at r1)", "(visited r1)"}
    assert sorted(op.name for op in task.applicable(s1)) == ["(move r1 r0)", "(move r1 r2)"]
    s2 = task.apply(s1, by_name(task, "(move r1 r2)"))
    assert task.is_goal(s2) and not task.is_goal(s1)
    assert isinstance(s2, frozenset) and hash(s2) == hash(frozenset(s2))


def test_ground_does_not_mutate_and_is_deterministic():
    domain = parser.parse_domain(CORRIDOR)
    problem = parser.parse_problem(corridor_problem(4))
    before = (dataclasses.astuple(domain), dataclasses.astuple(problem))
    first, second = ground(domain, problem), ground(domain, problem)
    assert (dataclasses.astuple(domain), dataclasses.astuple(problem)) == before
    assert first.facts == second.facts and first.operators == second.operators


TYPED = """
(define (domain typed)
  (:requirements :typing)
  (:types vehicle place - object truck plane - vehicle)
  (:constants depot - place)
  (:predicates (at ?v - vehicle ?p - place) (done))
  (:action go :parameters (?v - (either truck plane) ?p - place)
    :precondition (and)
    :effect (at ?v ?p))
  (:action fly :parameters (?v - plane) :precondition (at ?v depot) :effect (done)))
"""


def test_type_hierarchy_either_and_constants():
    task = make_task(TYPED, """(define (problem t) (:domain typed)
      (:objects t1 - truck p1 - plane home - place bike - vehicle)
      (:init) (:goal (done)))""")
    goes = sorted(op.name for op in task.operators if op.action == "go")
    # bike is a vehicle but neither truck nor plane; depot is a constant place
    assert goes == ["(go p1 depot)", "(go p1 home)", "(go t1 depot)", "(go t1 home)"]
    assert [op.name for op in task.operators if op.action == "fly"] == ["(fly p1)"]


ADL = """
(define (domain adl)
  (:requirements :adl)
  (:types light)
  (:predicates (on ?l - light) (power) (ready))
  (:action toggle-all :parameters ()
    :precondition (or (power) (ready))
    :effect (forall (?l - light)
              (and (when (on ?l) (not (on ?l)))
                   (when (not (on ?l)) (on ?l)))))
  (:action check :parameters ()
    :precondition (imply (power) (forall (?l - light) (on ?l)))
    :effect (ready)))
"""


def test_conditional_effects_are_evaluated_on_the_state_before():
    task = make_task(ADL, """(define (problem p) (:domain adl)
      (:objects a b - light) (:init (power) (on a)) (:goal (and (on b) (ready))))""")
    toggle = by_name(task, "(toggle-all)")
    assert len(task.operators) == 2  # the disjunction did not split the action
    s1 = task.apply(task.init, toggle)
    assert facts(task, s1) == {"(on b)"}  # (power) is static: compiled away
    s2 = task.apply(s1, toggle)
    assert facts(task, s2) == {"(on a)"}
    check = by_name(task, "(check)")
    assert check not in task.applicable(s1)  # power holds and not every light is on
    s3 = task.apply(s1, by_name(task, "(toggle-all)"))
    assert by_name(task, "(check)") not in task.applicable(s3)
    both = task.init | s1
    assert check in task.applicable(both)


def test_disjunctive_precondition_evaluated_per_state():
    task = make_task(ADL, """(define (problem p) (:domain adl)
      (:objects a - light) (:init (ready)) (:goal (on a)))""")
    assert {op.name for op in task.applicable(task.init)} == {"(toggle-all)", "(check)"}


AXIOMS = """
(define (domain reach)
  (:requirements :strips :derived-predicates :negative-preconditions)
  (:predicates (edge ?a ?b) (open ?a ?b) (path ?a ?b) (isolated ?a) (node ?a) (flag))
  (:derived (path ?a ?b) (or (open ?a ?b) (exists (?c) (and (open ?a ?c) (path ?c ?b)))))
  (:derived (isolated ?a) (and (node ?a) (not (exists (?b) (path ?a ?b)))))
  (:action open :parameters (?a ?b) :precondition (and (edge ?a ?b) (not (open ?a ?b)))
    :effect (open ?a ?b))
  (:action finish :parameters () :precondition (and (path n1 n4) (not (isolated n2)))
    :effect (flag)))
"""
AXIOMS_PROBLEM = """(define (problem r) (:domain reach)
  (:objects n1 n2 n3 n4)
  (:init (node n1) (node n2) (node n3) (node n4) (edge n1 n2) (edge n2 n3) (edge n3 n4))
  (:goal (flag)))"""


def test_axioms_are_a_stratified_fixpoint_not_stored_in_states():
    task = make_task(AXIOMS, AXIOMS_PROBLEM)
    assert task.axioms and all(task.facts[i].startswith(("(path", "(isolated", "(aux"))
                               for i in task.derived)
    assert not task.init & task.derived
    assert "(isolated n1)" in facts(task, task.init)
    state = task.init
    for name in ("(open n1 n2)", "(open n2 n3)", "(open n3 n4)"):
        assert by_name(task, "(finish)") not in task.applicable(state)
        state = task.apply(state, by_name(task, name))
        assert not state & task.derived
    closed = facts(task, state)
    assert {"(path n1 n4)", "(path n2 n4)", "(isolated n4)"} <= closed
    assert "(isolated n2)" not in closed
    assert by_name(task, "(finish)") in task.applicable(state)
    assert task.is_goal(task.apply(state, by_name(task, "(finish)")))


def test_unstratified_axioms_are_refused():
    domain = """(define (domain bad) (:requirements :derived-predicates)
      (:predicates (p) (q))
      (:derived (p) (not (q)))
      (:derived (q) (not (p)))
      (:action a :parameters () :precondition (p) :effect (and)))"""
    with pytest.raises(UnsupportedFeatureError, match="stratified"):
        make_task(domain, "(define (problem x) (:domain bad) (:init) (:goal (p)))")


COSTS = """
(define (domain costs)
  (:requirements :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place))
  (:functions (total-cost) - number (dist ?a ?b - place) - number)
  (:action drive :parameters (?a ?b - place)
    :precondition (and (at ?a) (road ?a ?b))
    :effect (and (at ?b) (not (at ?a)) (increase (total-cost) (dist ?a ?b))))
  (:action honk :parameters () :precondition (and) :effect (increase (total-cost) 2)))
"""


def test_action_costs_from_static_function_terms():
    problem = """(define (problem c) (:domain costs) (:objects x y - place)
      (:init (at x) (road x y) (= (dist x y) 7) (= (total-cost) 0))
      (:goal (at y)) (:metric minimize (total-cost)))"""
    task = make_task(COSTS, problem)
    assert not task.unit_cost
    assert by_name(task, "(drive x y)").cost == 7.0
    assert by_name(task, "(honk)").cost == 2.0


def test_missing_cost_value_is_an_input_error():
    problem = """(define (problem c) (:domain costs) (:objects x y - place)
      (:init (at x) (road x y)) (:goal (at y)) (:metric minimize (total-cost)))"""
    with pytest.raises(InputError, match=r"no value for \(dist x y\)"):
        make_task(COSTS, problem)


def test_goal_false_by_static_facts_is_never_reached():
    task = make_task(CORRIDOR, corridor_problem(3, goal="(link r0 r2)"))
    assert not task.is_goal(task.init)
    assert not any(task.is_goal(s) for _, s in task.successors(task.init))


def test_odd_inputs_do_not_crash():
    empty = make_task(CORRIDOR, "(define (problem e) (:domain corridor) (:init) (:goal (and)))")
    assert empty.operators == () and empty.is_goal(empty.init)
    plan = [by_name(make_task(CORRIDOR, corridor_problem(2)), "(move r0 r1)")]
    task = make_task(CORRIDOR, corridor_problem(2))
    assert task.is_goal(replay(task, plan))


def test_unconstrained_parameters_past_the_limit_are_refused():
    domain = """(define (domain wide) (:predicates (p ?a ?b ?c ?d ?e) (q))
      (:action a :parameters (?a ?b ?c ?d ?e) :precondition (not (p ?a ?b ?c ?d ?e))
        :effect (p ?a ?b ?c ?d ?e)))"""
    objects = " ".join(f"o{i}" for i in range(30))
    with pytest.raises(UnsupportedFeatureError, match="action a: grounding would enumerate 24,300,000"):
        make_task(domain, f"(define (problem w) (:domain wide) (:objects {objects}) (:init) (:goal (q)))")
