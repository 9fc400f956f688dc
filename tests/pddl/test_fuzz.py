"""Property: mutated PDDL (tokens deleted, inserted, swapped) is either accepted, and
then prints back to an equal tree, or refused with an InputError located inside
the file, with that line as its source line. Never another exception."""

import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tampcli.errors import InputError
from tampcli.pddl import check, parser, printer
from tests.conftest import IPC

PAIRS = [
    ("blocks/domain.pddl", "blocks/probBLOCKS-4-0.pddl"),
    ("elevators-opt08-strips/domain.pddl", "elevators-opt08-strips/p01.pddl"),
    ("miconic-fulladl/domain.pddl", "miconic-fulladl/f1-0.pddl"),
    ("psr-large/domain.pddl", "psr-large/p01-s29-n2-l5-f30.pddl"),
    ("satellite/domain.pddl", "satellite/p01-pfile1.pddl"),
]
TEXTS = [(IPC / d).read_text() for d, _ in PAIRS] + [(IPC / p).read_text() for _, p in PAIRS]
DOMAINS = {i + len(PAIRS): parser.parse_domain(TEXTS[i]) for i in range(len(PAIRS))}
TOKEN = re.compile(r"\(|\)|[^\s()]+")
VOCABULARY = ["(", ")", "-", "?x", "?y", "and", "not", "or", "either", "forall", "when", "=",
              ":action", ":parameters", ":effect", ":types", ":init", ":goal", "object",
              "increase", "(total-cost)", "1.5", "-2", "%", "total-cost", "define", "x",
              # refused or warned-about constructs, so their errors get located too
              "at", "10", "(at 10", ":requirements", ":fluents", ":durative-actions",
              ":durative-action", "preference", ":constraints", ":metric", "maximize",
              "decrease", "(fuel)", ":functions", "- number", "(= (fuel) 2)", "(> (fuel) 1)"]


@st.composite
def mutants(draw):
    index = draw(st.integers(0, len(TEXTS) - 1))
    text = TEXTS[index]
    for _ in range(draw(st.integers(1, 3))):
        spans = [m.span() for m in TOKEN.finditer(text)]
        kind = draw(st.sampled_from(["delete", "insert", "swap"]))
        i = draw(st.integers(0, len(spans) - 1))
        start, end = spans[i]
        if kind == "delete":
            text = text[:start] + text[end:]
        elif kind == "insert":
            word = draw(st.sampled_from(VOCABULARY + [text[start:end]]))
            text = text[:start] + word + " " + text[start:]
        else:
            j = draw(st.integers(0, len(spans) - 1))
            (a, b), (c, d) = sorted([spans[i], spans[j]])
            if b <= c:
                text = text[:a] + text[c:d] + text[b:c] + text[a:b] + text[d:]
    return index, text


@pytest.fixture(scope="session")
def mutant_file(tmp_path_factory):
    # A real file: the semantic checks read their source lines from it.
    return tmp_path_factory.mktemp("fuzz") / "mutant.pddl"


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutant=mutants())
def test_mutants_fail_only_with_located_input_errors(mutant_file, mutant):
    index, text = mutant
    mutant_file.write_text(text)
    try:
        tree = parser.parse(text, str(mutant_file))
        if isinstance(tree, parser.ast.Problem) and index in DOMAINS:
            check.check(DOMAINS[index], tree)
        elif isinstance(tree, parser.ast.Domain):
            check.check(tree)
    except InputError as err:
        lines = text.split("\n")
        assert err.line is not None and 1 <= err.line <= len(lines), err.render()
        assert err.column is not None and 1 <= err.column <= len(lines[err.line - 1]) + 1
        assert err.source_line == lines[err.line - 1], err.render()
        assert err.render().endswith("^")
        return
    assert parser.parse(printer.to_pddl(tree)) == tree
