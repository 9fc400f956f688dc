"""The printer: parse(print(tree)) == tree on the awkward cases."""

import pytest

from tampcli.pddl import ast, parser, printer

DOMAIN = """(define (domain Odd)
  (:requirements :adl :action-costs)
  (:types a b - object c - (either a b))
  (:constants k1 k2 - c free)
  (:predicates (p ?x - (either a b) ?y) (q) (r ?x ?y - c ?z))
  (:functions (total-cost) - number (w ?x - a) - number)
  (:action act
    :parameters (?x ?y - c ?z)
    :precondition (and)
    :effect (and (q) (increase (total-cost) 0.1)))
  (:action act2
    :parameters ()
    :precondition (or (q) (not (q)) (imply (q) (exists (?v) (p ?v k1))) (= k1 k2))
    :effect (and (forall (?v - a) (when (p ?v free) (not (q))))
                 (increase (total-cost) (w k1))))
  (:action empty :parameters ())
  (:derived (q) (exists (?x - a) (p ?x ?x))))
"""

PROBLEM = """(define (problem P1) (:domain odd)
  (:objects x - a y - b z)
  (:init (q) (p x y) (= (total-cost) 0) (= (w x) 0.000015))
  (:goal (forall (?v - c) (p ?v z)))
  (:metric minimize (total-cost)))
"""


@pytest.mark.parametrize("text", [DOMAIN, PROBLEM], ids=["domain", "problem"])
def test_round_trip(text):
    tree = parser.parse(text)
    printed = printer.to_pddl(tree)
    assert parser.parse(printed) == tree
    assert printer.to_pddl(parser.parse(printed)) == printed


def test_numbers_print_without_exponents():
    problem = parser.parse_problem(PROBLEM)
    assert "0.000015" in printer.to_pddl(problem)
    assert problem.init_values[1].value == 0.000015


def test_untyped_names_keep_no_type_and_typed_ones_keep_theirs():
    domain = parser.parse_domain(DOMAIN)
    text = printer.print_domain(domain)
    assert "(:constants k1 k2 - c free)" in text
    assert "(r ?x ?y - c ?z)" in text
    assert "(p ?x - (either a b) ?y)" in text


def test_long_lists_are_broken_into_lines_of_at_most_the_width():
    objects = tuple(ast.Typed(f"object-number-{i}", ("thing",)) for i in range(60))
    problem = ast.Problem("p", "d", objects=objects,
                          init=tuple(ast.Atom("at", (o.name, "home")) for o in objects))
    text = printer.print_problem(problem)
    assert max(map(len, text.splitlines())) <= printer.WIDTH + 10
    assert parser.parse_problem(text) == problem


def test_empty_goal_and_no_metric():
    problem = ast.Problem("p", "d")
    assert parser.parse_problem(printer.to_pddl(problem)) == problem


def test_not_a_tree():
    with pytest.raises(TypeError):
        printer.to_pddl(ast.Atom("p", ()))
