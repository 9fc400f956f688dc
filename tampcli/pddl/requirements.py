"""Requirements a domain and problem declare, and those they actually use."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from tampcli.pddl import ast
from tampcli.pddl.types import OBJECT

# What a declared requirement stands for (PDDL 3.1).
IMPLIES = {
    ":adl": (":strips", ":typing", ":negative-preconditions", ":disjunctive-preconditions",
             ":equality", ":quantified-preconditions", ":conditional-effects"),
    ":quantified-preconditions": (":existential-preconditions", ":universal-preconditions"),
    ":fluents": (":numeric-fluents", ":object-fluents"),
    # Older IPC domains declare numeric fluents for action costs.
    ":numeric-fluents": (":action-costs",),
}
KNOWN = frozenset({
    ":strips", ":typing", ":negative-preconditions", ":disjunctive-preconditions", ":equality",
    ":existential-preconditions", ":universal-preconditions", ":quantified-preconditions",
    ":conditional-effects", ":fluents", ":numeric-fluents", ":object-fluents", ":adl",
    ":durative-actions", ":duration-inequalities", ":continuous-effects",
    ":derived-predicates", ":timed-initial-literals", ":preferences", ":constraints",
    ":action-costs",
})
_WHAT = {
    ":typing": "types",
    ":negative-preconditions": "negative conditions",
    ":disjunctive-preconditions": "`or` / `imply`",
    ":existential-preconditions": "`exists`",
    ":universal-preconditions": "`forall` conditions",
    ":equality": "`=`",
    ":conditional-effects": "`when` / `forall` effects",
    ":derived-predicates": "derived predicates",
    ":action-costs": "action costs",
}


@dataclass(frozen=True)
class RequirementReport:
    declared: tuple[str, ...]  # as written, domain then problem
    used: tuple[str, ...]  # what the files need, in a fixed order
    missing: tuple[tuple[str, ast.Span, str], ...]  # (requirement, first use, which file)
    unknown: tuple[str, ...]


def expand(declared) -> frozenset[str]:
    """Everything the declared requirements stand for (`:strips` always)."""
    result, todo = {":strips"}, list(declared)
    while todo:
        req = todo.pop()
        if req not in result:
            result.add(req)
            todo.extend(IMPLIES.get(req, ()))
    return frozenset(result)


def describe(requirement: str) -> str:
    return _WHAT.get(requirement, requirement)


def report(domain: ast.Domain, problem: ast.Problem | None = None) -> RequirementReport:
    declared = tuple(dict.fromkeys(domain.requirements + (problem.requirements if problem else ())))
    first: dict[str, tuple[ast.Span, str]] = {}
    for which, uses in (("domain", _domain_uses(domain)),
                        ("problem", _problem_uses(problem) if problem else ())):
        for req, span in uses:
            known = first.get(req)
            if known is None or known[1] == which and (span.line, span.column) < (
                    known[0].line, known[0].column):
                first[req] = (span, which)
    order = [":strips"] + sorted(_WHAT)
    used = tuple(r for r in order if r in first or r == ":strips")
    have = expand(declared)
    missing = tuple((r, *first[r]) for r in used if r in first and r not in have)
    unknown = tuple(r for r in declared if r not in KNOWN)
    return RequirementReport(declared, used, missing, unknown)


def _domain_uses(domain: ast.Domain) -> Iterator[tuple[str, ast.Span]]:
    for typed in domain.types:
        yield ":typing", typed.span
    for typed in _all_typed(domain):
        if typed.types != (OBJECT,):
            yield ":typing", typed.span
    for function in domain.functions:
        yield ":action-costs", function.span
    for action in domain.actions:
        yield from _formula_uses(action.precondition)
        yield from _effect_uses(action.effect)
    for axiom in domain.axioms:
        yield ":derived-predicates", axiom.span
        yield from _formula_uses(axiom.body)


def _problem_uses(problem: ast.Problem) -> Iterator[tuple[str, ast.Span]]:
    for typed in problem.objects:
        if typed.types != (OBJECT,):
            yield ":typing", typed.span
    for value in problem.init_values:
        yield ":action-costs", value.span
    if problem.metric is not None:
        yield ":action-costs", problem.metric.span
    yield from _formula_uses(problem.goal)


def _all_typed(domain: ast.Domain) -> Iterator[ast.Typed]:
    yield from domain.constants
    for pred in domain.predicates:
        yield from pred.params
    for function in domain.functions:
        yield from function.params
    for action in domain.actions:
        yield from action.params
    for axiom in domain.axioms:
        yield from axiom.params


def _formula_uses(formula: ast.Formula) -> Iterator[tuple[str, ast.Span]]:
    todo = [formula]
    while todo:
        f = todo.pop()
        if isinstance(f, ast.Atom):
            if f.predicate == "=":
                yield ":equality", f.span
        elif isinstance(f, ast.Not):
            # `(not (= a b))` counts as equality alone, as every IPC domain has it.
            if not (isinstance(f.part, ast.Atom) and f.part.predicate == "="):
                yield ":negative-preconditions", f.span
            todo.append(f.part)
        elif isinstance(f, (ast.And, ast.Or)):
            if isinstance(f, ast.Or):
                yield ":disjunctive-preconditions", f.span
            todo.extend(f.parts)
        elif isinstance(f, ast.Imply):
            yield ":disjunctive-preconditions", f.span
            todo.extend((f.antecedent, f.consequent))
        elif isinstance(f, (ast.Exists, ast.Forall)):
            kind = ":existential" if isinstance(f, ast.Exists) else ":universal"
            yield kind + "-preconditions", f.span
            yield from _typed_uses(f.params)
            todo.append(f.body)


def _effect_uses(effect: ast.Effect) -> Iterator[tuple[str, ast.Span]]:
    todo = [effect]
    while todo:
        e = todo.pop()
        if isinstance(e, ast.AndEffect):
            todo.extend(e.parts)
        elif isinstance(e, ast.ForallEffect):
            yield ":conditional-effects", e.span
            yield from _typed_uses(e.params)
            todo.append(e.body)
        elif isinstance(e, ast.WhenEffect):
            yield ":conditional-effects", e.span
            yield from _formula_uses(e.condition)
            todo.append(e.body)
        elif isinstance(e, ast.Increase):
            yield ":action-costs", e.span


def _typed_uses(params) -> Iterator[tuple[str, ast.Span]]:
    for typed in params:
        if typed.types != (OBJECT,):
            yield ":typing", typed.span
