"""Semantic checks beyond the malformed catalog: warnings, requirements, the type hierarchy."""

import pytest

from tampcli.errors import PDDLSemanticError
from tampcli.pddl import check, parser
from tampcli.pddl.types import TypeHierarchy


def _domain(body: str, requirements: str = ""):
    req = f"(:requirements {requirements})" if requirements else ""
    return parser.parse_domain(f"(define (domain d) {req} {body})", None)


ADL_BODY = """
  (:types block place)
  (:predicates (on ?x - block ?y - (either block place)) (clear ?x - block))
  (:action move
    :parameters (?x - block ?to - (either block place))
    :precondition (and (clear ?x) (not (on ?x ?to))
                       (forall (?z - block) (imply (on ?z ?x) (= ?z ?x))))
    :effect (and (on ?x ?to)
                 (forall (?z - block) (when (on ?z ?x) (not (clear ?z))))))
"""


def test_undeclared_requirements_are_warnings_pointing_at_first_use():
    warnings = check.check(_domain(ADL_BODY, ":strips"))
    text = "\n".join(warnings)
    for req in (":typing", ":negative-preconditions", ":universal-preconditions",
                ":disjunctive-preconditions", ":equality", ":conditional-effects"):
        assert f"without declaring {req}" in text
    assert all(w.startswith("<input>:") for w in warnings)
    first_typing = next(w for w in warnings if ":typing" in w)
    assert first_typing.startswith("<input>:2:11:")  # `block` in (:types block place)


def test_adl_declares_them_all():
    assert check.check(_domain(ADL_BODY, ":adl")) == []


def test_requirement_report_lists_declared_and_used():
    report = check.requirements(_domain(ADL_BODY, ":adl :action-costs"))
    assert report.declared == (":adl", ":action-costs")
    assert ":conditional-effects" in report.used and ":strips" in report.used
    assert ":action-costs" not in report.used
    assert report.missing == ()


def test_derived_and_costs_without_requirements_warn():
    domain = _domain("""(:predicates (p) (q)) (:functions (total-cost) - number)
        (:derived (q) (p))
        (:action a :parameters () :effect (and (p) (increase (total-cost) 1)))""")
    text = "\n".join(check.check(domain))
    assert "without declaring :derived-predicates" in text
    assert "without declaring :action-costs" in text


def test_unknown_requirement_warns():
    warnings = check.check(_domain("(:predicates (p))", ":strips :stirps"))
    assert any("unknown requirement :stirps" in w for w in warnings)


def test_derived_predicate_may_follow_actions_and_be_used_in_them():
    domain = _domain("""(:predicates (p ?x) (q ?x))
        (:action a :parameters (?x) :precondition (q ?x) :effect (p ?x))
        (:derived (q ?y) (p ?y))""", ":derived-predicates")
    assert check.check(domain) == []


def test_variable_of_a_supertype_may_be_passed_but_not_a_disjoint_one():
    body = """(:types vehicle place - object truck - vehicle)
      (:predicates (at ?t - truck ?p - place))
      (:action a :parameters (?v - vehicle ?o - object ?p - place)
         :precondition (and (at ?v ?p) (at ?o ?p)) :effect (at ?v ?p))"""
    assert check.check(_domain(body, ":typing")) == []
    with pytest.raises(PDDLSemanticError, match=r"\?p is of type place, expected truck"):
        check.check(_domain(body.replace("(at ?o ?p))", "(at ?p ?p))"), ":typing"))


def test_problem_objects_may_repeat_a_constant_of_the_same_type():
    domain = _domain("""(:types place) (:constants home - place) (:predicates (at ?p - place))""",
                     ":typing")
    problem = parser.parse_problem("(define (problem p) (:domain d) (:objects home a - place)"
                                   " (:init (at home)) (:goal (at a)))")
    assert check.check(domain, problem) == []
    clash = parser.parse_problem("(define (problem p) (:domain d) (:types) (:objects home)"
                                 " (:init) (:goal (at home)))".replace("(:types) ", ""))
    with pytest.raises(PDDLSemanticError, match="constant of the domain"):
        check.check(domain, clash)


def test_quantified_goal_variables_are_bound():
    domain = _domain("(:predicates (p ?x))", ":universal-preconditions")
    problem = parser.parse_problem("(define (problem p) (:domain d) (:objects a b)"
                                   " (:init) (:goal (forall (?x) (p ?x))))")
    assert check.check(domain, problem) == []


def test_type_hierarchy_with_either_parents():
    domain = _domain("(:types a b - object c - (either a b) d - c)", ":typing")
    h = TypeHierarchy.of(domain)
    assert h.is_subtype("d", "a") and h.is_subtype("d", "b") and h.is_subtype("d", "object")
    assert not h.is_subtype("a", "b")
    assert h.fits(("d",), ("b",)) and not h.fits(("a",), ("b",))
    assert h.may_fit(("a",), ("b",))  # a `c` is both
    assert h.cyclic == ()

