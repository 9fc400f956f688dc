"""The parser: tokens, case, spans, keywords as names, deep input, error texts."""

import re

import pytest

from tampcli.errors import InputError, PDDLSyntaxError, UnsupportedFeatureError
from tampcli.pddl import ast, parser
from tests.conftest import IPC

DOMAIN = """(define (domain d)
  (:requirements :typing)
  (:types block place - object)
  (:constants and - place)
  (:predicates (on ?x - block ?y - (either block place)) (clear ?x))
  (:action move
    :parameters (?x - block ?y - place)
    :precondition (and (clear ?x) (on ?x and))
    :effect (and (not (on ?x and)) (on ?x ?y))))
"""


def test_keyword_is_a_name_where_no_keyword_fits():
    domain = parser.parse_domain(DOMAIN)
    assert domain.constants == (ast.Typed("and", ("place",)),)
    assert domain.actions[0].precondition.parts[1] == ast.Atom("on", ("?x", "and"))
    assert domain.predicates[0].params[1].types == ("block", "place")


def test_names_are_lower_cased_and_keywords_case_insensitive():
    upper = parser.parse_domain(DOMAIN.upper())
    assert upper == parser.parse_domain(DOMAIN)


def test_atom_fast_path_and_long_form_give_equal_trees():
    plain = parser.parse_domain(DOMAIN)
    # A comment inside an atom, and a keyword head, take the token-by-token path.
    odd = DOMAIN.replace("(clear ?x))\n    :effect", "(clear ; why not\n ?x))\n    :effect")
    assert parser.parse_domain(odd) == plain
    assert plain.actions[0].precondition.parts[0].span == ast.Span(8, 24, 8, 34)


def test_atom_spans_cover_the_parentheses():
    problem = parser.parse_problem(
        "(define (problem p) (:domain d)\n (:objects a b)\n (:init (on a b)\n  (on b\n a))\n"
        " (:goal (on a b)))")
    first, second = problem.init
    assert first.span == ast.Span(3, 9, 3, 17)
    assert second.span == ast.Span(4, 3, 5, 4)
    assert problem.domain_name_span == ast.Span(1, 30, 1, 31)


def test_found_token_is_shown_as_written():
    with pytest.raises(PDDLSyntaxError) as err:
        parser.parse_domain("(define (domain d) (:predicates (p)) (:action A :parameters (?x) "
                            ":Effect (p) :Parameters))")
    assert 'unexpected ":Parameters"' in err.value.message


def test_numbers_and_costs():
    domain = parser.parse_domain(
        "(define (domain d) (:requirements :action-costs) (:predicates (p))"
        " (:functions (total-cost) - number)"
        " (:action a :parameters () :effect (and (p) (increase (total-cost) 2.5))))")
    assert domain.actions[0].effect.parts[1].amount == 2.5


PREFIX = "(define (domain d)\n(:action a :precondition "


@pytest.mark.parametrize("text, line, column", [
    ("(" * 2_500_000 + ")" * 2_500_000, 1, parser.MAX_NESTING + 1),
    (PREFIX + "(and " * 1_000_000, 2, len("(:action a :precondition ")
     + 5 * (parser.MAX_NESTING - 2) + 1),
    ("; ((((((\n" * 300_000 + "(define (domain d))", 300_001, 1),
])
def test_megabytes_of_nesting_end_in_a_located_error(text, line, column):
    assert len(text) >= 2_500_000
    if line == 300_001:  # parentheses in comments do not count
        assert isinstance(parser.parse(text), ast.Domain)
        return
    with pytest.raises(PDDLSyntaxError) as err:
        parser.parse(text, "deep.pddl")
    assert "nesting deeper than" in err.value.message
    assert (err.value.line, err.value.column) == (line, column)


def test_deep_but_allowed_nesting_parses():
    body = "(and " * 200 + "(p)" + ")" * 200
    domain = parser.parse_domain(
        f"(define (domain d) (:predicates (p)) (:action a :parameters () :precondition {body}"
        " :effect (p)))")
    assert isinstance(domain.actions[0].precondition, ast.And)


def test_problem_where_domain_expected_and_back():
    with pytest.raises(InputError, match="expected a domain"):
        parser.parse_domain("(define (problem p) (:domain d) (:init) (:goal (and)))")
    with pytest.raises(InputError, match="expected a problem"):
        parser.parse_problem("(define (domain d))")


def test_missing_and_directory_files(tmp_path):
    with pytest.raises(InputError, match="file not found"):
        parser.parse_domain_file(tmp_path / "nope.pddl")
    with pytest.raises(InputError, match="is a directory"):
        parser.parse_domain_file(tmp_path)


def test_empty_file_is_a_located_error_with_its_empty_line_and_a_caret():
    with pytest.raises(PDDLSyntaxError) as err:
        parser.parse("", "empty.pddl")
    assert err.value.line == 1 and err.value.column == 1
    assert err.value.render().splitlines()[-2:] == ["  ", "  ^"]


def test_source_lines_end_at_newlines_only():
    # A form feed is whitespace to the lexer, not a line end.
    with pytest.raises(PDDLSyntaxError) as err:
        parser.parse("(define (domain d)\f(:predicates (p))\n  (:action %))")
    assert (err.value.line, err.value.column) == (2, 12)
    assert err.value.source_line == "  (:action %))"


def test_timed_initial_literals_are_refused_by_name():
    with pytest.raises(UnsupportedFeatureError, match="requirement :timed-initial-literals") as err:
        parser.parse("(define (problem p) (:domain d)\n (:init (at t1 a)\n"
                     "  (AT 2.5 (not (at t1 a))))\n (:goal (at t1 b)))")
    assert (err.value.line, err.value.column) == (3, 3)


def test_cached_tables_parse_like_fresh_ones(tmp_path):
    cache = tmp_path / "grammar.lark-cache"
    fresh = parser.build_lark(False).parse(DOMAIN)
    written = parser.build_lark(str(cache)).parse(DOMAIN)
    assert cache.stat().st_size > 0
    loaded = parser.build_lark(str(cache)).parse(DOMAIN)
    assert fresh == written == loaded
    assert ast.Span(1, 1, 9, 49) == loaded.span == fresh.span
    cache.write_bytes(b"garbage\n")  # a broken cache is rebuilt, not an error
    assert parser.build_lark(str(cache)).parse(DOMAIN) == fresh


@pytest.mark.parametrize("name", ["blocks/domain.pddl", "miconic-fulladl/domain.pddl",
                                  "elevators-opt08-strips/p05.pddl", "psr-large/domain.pddl",
                                  "rovers/p03.pddl"])
def test_whole_atom_tokens_build_the_same_tree_as_token_by_token(name):
    text = (IPC / name).read_text()
    # A comment before every ")" keeps the lexer from taking any atom whole.
    slow = re.sub(r"\)", " ; no atom here\n)", re.sub(r";[^\n]*", "", text))
    assert parser.parse(slow) == parser.parse(text)
