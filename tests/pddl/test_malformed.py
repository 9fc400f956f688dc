"""A catalog of malformed inputs, run through `tampcli check`: each must exit 2
with `file:line:col: message`, the source line and a caret; never a traceback."""

import json
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent / "malformed"
BASE = HERE / "base-domain.pddl"

# file, error kind, line, column, message substring. Files named prob-* are
# problems checked against base-domain.pddl; the others are domains.
CATALOG = [
    ("syn-unbalanced.pddl", "syntax", 5, 20, "unexpected end of file"),
    ("syn-bad-character.pddl", "syntax", 3, 46, 'unexpected "%"'),
    ("syn-extra-paren.pddl", "syntax", 3, 3, 'a ")" too many'),
    ("syn-type-without-names.pddl", "syntax", 3, 11, "a type with no names before it"),
    ("syn-second-section.pddl", "syntax", 3, 3, "a second :predicates section"),
    ("syn-missing-define.pddl", "syntax", 1, 2, 'unexpected "domain"'),
    ("syn-action-without-name.pddl", "syntax", 3, 12, 'unexpected ":parameters"'),
    ("syn-effect-before-parameters.pddl", "syntax", 5, 5, 'unexpected ":parameters"'),
    ("syn-or-in-effect.pddl", "syntax", 6, 19, "`or` is not allowed here"),
    ("syn-too-deep.pddl", "syntax", 3, 1313, "nesting deeper than 256 levels"),
    ("syn-empty.pddl", "syntax", 1, 1, "unexpected end of file"),
    ("not-utf8.pddl", "input", 3, 6, "not UTF-8"),
    ("prob-as-domain.pddl", "input", 1, 1, "expected a domain definition"),
    ("unsupported-durative.pddl", "unsupported", 4, 3, "requirement :durative-actions"),
    ("unsupported-numeric-condition.pddl", "unsupported", 5, 19, "numeric conditions"),
    ("unsupported-decrease.pddl", "unsupported", 5, 13, "numeric effects (decrease)"),
    ("unsupported-preference.pddl", "unsupported", 5, 28, "requirement :preferences"),
    ("unsupported-constraints.pddl", "unsupported", 4, 3, "requirement :constraints"),
    ("unsupported-object-fluent.pddl", "unsupported", 4, 26, "requirement :object-fluents"),
    ("unsupported-increase-other.pddl", "unsupported", 7, 33,
     "only (total-cost) can be increased or minimized (requirement :numeric-fluents)"),
    ("unsupported-fluent-in-cost.pddl", "unsupported", 9, 24,
     "numeric fluents beyond action costs are not supported"),
    ("prob-timed-initial-literal.pddl", "unsupported", 6, 10,
     "timed initial literals are not supported (requirement :timed-initial-literals)"),
    ("prob-metric-other-function.pddl", "unsupported", 8, 22, "(requirement :numeric-fluents)"),
    ("prob-metric-maximize.pddl", "unsupported", 8, 12,
     "only `(:metric minimize (total-cost))` is supported, not maximize"),
    ("sem-undeclared-predicate.pddl", "semantic", 6, 14, "undeclared predicate q"),
    ("sem-wrong-arity.pddl", "semantic", 5, 19, "on takes 2 arguments, found 1"),
    ("sem-undeclared-type.pddl", "semantic", 6, 18, "undeclared type blok"),
    ("sem-undeclared-parent-type.pddl", "semantic", 3, 11, "undeclared parent type vehicle"),
    ("sem-type-cycle.pddl", "semantic", 3, 11, "its own ancestor"),
    ("sem-duplicate-action.pddl", "semantic", 5, 3, "duplicate action a (first declared on line 3)"),
    ("sem-duplicate-predicate.pddl", "semantic", 4, 16, "duplicate predicate p"),
    ("sem-duplicate-constant.pddl", "semantic", 5, 15, "duplicate constant home (first declared on line 4)"),
    ("sem-duplicate-parameter.pddl", "semantic", 4, 24, "duplicate parameter ?x in action a"),
    ("sem-free-variable.pddl", "semantic", 5, 26, "free variable ?y"),
    ("sem-unknown-constant.pddl", "semantic", 7, 20, "unknown constant floor"),
    ("sem-wrong-type-constant.pddl", "semantic", 8, 20, "table is of type place, expected block"),
    ("sem-wrong-type-variable.pddl", "semantic", 7, 23, "?p is of type place, expected truck"),
    ("sem-derived-undeclared.pddl", "semantic", 4, 3, "above is not declared in :predicates"),
    # Used by an action before it is derived: named where it is derived (blind20).
    ("sem-derived-undeclared-used.pddl", "semantic", 6, 3, "above is not declared in :predicates"),
    ("sem-derived-wrong-type.pddl", "semantic", 5, 31, "?y is of type place, declared as block"),
    ("sem-effect-on-derived.pddl", "semantic", 7, 14, "cannot be changed by an effect"),
    ("sem-increase-nonstatic.pddl", "semantic", 7, 46, "a number or a static function"),
    ("sem-undeclared-function.pddl", "semantic", 8, 37, "undeclared function distance"),
    ("prob-wrong-domain.pddl", "semantic", 2, 12, "problem is for domain logistics"),
    ("prob-unknown-object-init.pddl", "semantic", 6, 18, "unknown object or constant c"),
    ("prob-unknown-object-goal.pddl", "semantic", 7, 19, "unknown object or constant t2"),
    ("prob-duplicate-object.pddl", "semantic", 5, 13, "duplicate object t1"),
    ("prob-wrong-type-init.pddl", "semantic", 6, 16, "t1 is of type truck, expected place"),
    ("prob-init-arity.pddl", "semantic", 5, 19, "at takes 2 arguments, found 3"),
    ("prob-undeclared-object-type.pddl", "semantic", 3, 13, "undeclared type truk"),
    ("prob-negative-cost.pddl", "semantic", 7, 10, "negative action cost -3"),
    ("prob-free-variable-goal.pddl", "semantic", 6, 14, "free variable ?t"),
    ("prob-either-mismatch.pddl", "semantic", 7, 14, "(either cargo place), expected cargo"),
    ("prob-function-arity.pddl", "semantic", 6, 13, "distance takes 2 arguments, found 1"),
]


def _argv(name: str) -> list:
    path = HERE / name
    if name.startswith("prob-") and name != "prob-as-domain.pddl":
        return [BASE, path]
    return [path]


def test_catalog_covers_every_file():
    files = {p.name for p in HERE.glob("*.pddl")} - {BASE.name}
    assert files == {row[0] for row in CATALOG}
    assert len(CATALOG) >= 25


def test_base_domain_is_valid(cli):
    run = cli("check", BASE)
    assert run.code == 0, run.err


@pytest.mark.parametrize("name, kind, line, column, text", CATALOG, ids=[r[0] for r in CATALOG])
def test_malformed_input(cli, name, kind, line, column, text):
    argv = _argv(name)
    run = cli("check", *argv)
    assert run.code == 2
    assert "Traceback" not in run.err
    assert f"{HERE / name}:{line}:{column}: " in run.err
    assert text in run.err
    lines = run.err.rstrip("\n").splitlines()
    assert lines[-1].strip() == "^"
    # Split at "\n" only, as the lexer counts lines; an empty file has one empty line.
    source = (HERE / name).read_bytes().decode("utf-8", "replace").split("\n")[line - 1]
    assert lines[-2].strip() == source.strip().expandtabs(1)
    assert len(lines[-1]) - 1 == column + 1  # two spaces of indent, caret under the column

    as_json = cli("check", *argv, "--json")
    assert as_json.code == 2
    error = json.loads(as_json.out)["error"]
    assert (error["kind"], error["line"], error["column"]) == (kind, line, column)
    assert text in error["message"]
