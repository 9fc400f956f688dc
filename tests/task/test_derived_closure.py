"""The derived facts of a state (Task.closure): each rule fires once all its body holds."""

from __future__ import annotations

import json

DOMAIN = """(define (domain c)
  (:requirements :strips :derived-predicates)
  (:predicates (base) (f) (g) (a) (b))
  (:derived (a) (base))
  (:derived (b) (and (a) (f)))
  (:action setf :parameters () :precondition (g) :effect (f))
  (:action setg :parameters () :precondition () :effect (g)))
"""

REACH = """(define (domain r)
  (:requirements :strips :typing :derived-predicates)
  (:types node)
  (:predicates (edge ?a ?b - node) (start ?a - node) (reach ?a - node))
  (:derived (reach ?a - node) (start ?a))
  (:derived (reach ?b - node) (exists (?a - node) (and (reach ?a) (edge ?a ?b))))
  (:action connect :parameters (?a ?b - node) :precondition (reach ?a)
    :effect (edge ?a ?b)))
"""


def test_a_rule_true_by_static_facts_counts_once(cli, tmp_path):
    """blind19's docs helper found it: (a) follows from the static (base) alone, and
    was counted twice, so (b) = (a) and (f) fired without (f): the empty plan."""
    (tmp_path / "d.pddl").write_text(DOMAIN)
    (tmp_path / "p.pddl").write_text("(define (problem p) (:domain c) (:init (base)) "
                                     "(:goal (b)))")
    out = cli("plan", tmp_path / "d.pddl", tmp_path / "p.pddl", "--json")
    assert out.code == 0, out.err
    assert json.loads(out.out)["plans"][0]["actions"] == ["(setg)", "(setf)"]


def test_recursive_reachability_needs_its_edges(cli, tmp_path):
    """reach is recursive; x reaches z only through an edge the plan adds."""
    (tmp_path / "d.pddl").write_text(REACH)
    (tmp_path / "p.pddl").write_text(
        "(define (problem p) (:domain r) (:objects x y z - node) (:init (start x)) "
        "(:goal (reach z)))")
    out = cli("plan", tmp_path / "d.pddl", tmp_path / "p.pddl", "--json")
    assert out.code == 0, out.err
    assert json.loads(out.out)["plans"][0]["actions"] == ["(connect x z)"]
