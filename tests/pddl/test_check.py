"""Semantic checks beyond the malformed catalog: warnings, requirements, the type hierarchy."""

import pytest

from tampcli.errors import PDDLSemanticError, UnsupportedFeatureError
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


def test_unknown_requirement_warns_at_its_key():
    warnings = check.check(_domain("(:predicates (p))", ":strips :stirps"))
    assert warnings == ["<input>:1:43: unknown requirement :stirps"]


# An IPC-2006-style domain: costs written as numeric fluents, before :action-costs.
FLUENT_COSTS = """(:predicates (at ?x) (road ?x ?y))
  (:functions (total-cost) (length ?x ?y) (unused))
  (:action drive :parameters (?x ?y)
    :precondition (and (at ?x) (road ?x ?y))
    :effect (and (not (at ?x)) (at ?y) (increase (total-cost) (length ?x ?y))))"""


@pytest.mark.parametrize("requirement", [":fluents", ":numeric-fluents"])
def test_fluents_declared_for_action_costs_warn_once(requirement):
    domain = _domain(FLUENT_COSTS, f":strips :negative-preconditions {requirement}")
    warnings = check.check(domain)
    assert warnings == [f"<input>:1:67: declares {requirement}, which tampcli supports "
                        "only as action costs; here the functions are only action costs, so "
                        "they are read as such"]
    report = check.requirements(domain)
    assert ":action-costs" in report.used and ":numeric-fluents" not in report.used


def test_only_cost_functions_count_as_action_costs():
    report = check.requirements(_domain(FLUENT_COSTS, ":negative-preconditions :action-costs"))
    assert report.missing == () and ":action-costs" in report.used
    problem = parser.parse_problem("(define (problem p) (:domain d) (:objects a b)\n"
                                   " (:init (at a) (road a b) (= (unused) 4))\n (:goal (at b)))")
    bare = _domain("(:predicates (at ?x) (road ?x ?y)) (:functions (unused))")
    assert ":action-costs" not in check.requirements(bare, problem).used
    assert check.check(bare, problem) == []


def test_declared_but_unused_unsupported_requirements_warn_at_their_keys():
    keys = (":durative-actions :duration-inequalities :continuous-effects :preferences "
            ":constraints :timed-initial-literals :numeric-fluents :object-fluents")
    domain = _domain("(:predicates (p)) (:action a :parameters () :effect (p))", keys)
    warnings = check.check(domain)
    assert len(warnings) == 8
    assert warnings[0] == ("<input>:1:35: declares :durative-actions (durative actions), which "
                           "tampcli does not support; nothing uses it, so it is ignored")
    for requirement, warning in zip(keys.split(), warnings, strict=True):
        assert f"declares {requirement} (" in warning
    problem = parser.parse_problem("(define (problem p) (:domain d)\n"
                                   "  (:requirements :preferences :adl) (:goal (p)))", "p.pddl")
    assert check.check(_domain("(:predicates (p))"), problem) == [
        "p.pddl:2:18: declares :preferences (preferences), which tampcli does not support; "
        "nothing uses it, so it is ignored"]


def test_a_goals_quantifiers_are_uses_and_supported_unused_requirements_pass_silently():
    """docs/formats.md, "The PDDL tampcli reads": a goal's forall/exists needs its
    requirement (warned at the goal); a supported requirement declared and unused,
    and `(not (= ...))` (a use of :equality alone), give no warning."""
    body = ("(:types item bin) (:predicates (in ?i - item ?b - bin) (p ?a ?b - item))\n"
            " (:action a :parameters (?x ?y - item) :precondition (not (= ?x ?y))"
            " :effect (p ?x ?y))")
    problem_text = ("(define (problem q) (:domain d) (:objects i - item b - bin)\n"
                    " (:init) (:goal (forall (?i - item) (exists (?b - bin) (in ?i ?b)))))")
    problem = parser.parse_problem(problem_text, "q.pddl")
    bare = _domain(body, ":strips :typing :equality :negative-preconditions")
    warnings = check.check(bare, problem)
    assert warnings == [
        "q.pddl:2:37: uses `exists` without declaring :existential-preconditions",
        "q.pddl:2:17: uses `forall` conditions without declaring :universal-preconditions"]
    report = check.requirements(bare, problem)
    assert ":negative-preconditions" not in report.used and ":equality" in report.used
    assert ":universal-preconditions" not in check.requirements(bare).used
    declared = _domain(body, ":strips :typing :equality :negative-preconditions "
                             ":universal-preconditions :existential-preconditions")
    assert check.check(declared, problem) == []


def test_increasing_another_function_is_a_use_of_numeric_fluents_and_refused(tmp_path):
    path = tmp_path / "d.pddl"
    path.write_text("(define (domain d) (:requirements :numeric-fluents)\n"
                    "(:predicates (p)) (:functions (fuel))\n"
                    "(:action a :parameters () :effect (and (p) (increase (fuel) 2))))\n")
    domain = parser.parse_domain_file(path)
    report = check.requirements(domain)
    assert ":numeric-fluents" in report.used and ":action-costs" not in report.used
    assert [(r, w) for r, _, w in report.unsupported] == [(":numeric-fluents", "domain")]
    with pytest.raises(UnsupportedFeatureError, match="requirement :numeric-fluents") as err:
        check.check(domain)
    assert (err.value.line, err.value.column) == (3, 55)  # `fuel` in (increase (fuel) 2)


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

