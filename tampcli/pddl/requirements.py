"""Requirements a domain and problem declare, those they actually use, and the
ones outside the accepted fragment (SPEC, "PDDL accepted").

A requirement tampcli does not support is treated by what the files do:

- Used: refused (exit 2), naming the requirement, at its first use. The
  grammar has no place for durative actions (where every use of
  :duration-inequalities and :continuous-effects lives), preferences,
  constraints and timed initial literals: parser.py refuses them by a scan
  before parsing. Numeric conditions, arithmetic, assignments
  and functions of an object type are refused by the tree builder. What the
  AST can hold, an increase of a function other than (total-cost) or a
  metric on one, is reported here as a use of :numeric-fluents and refused
  by check.py.
- Declared but unused: a warning at the requirement's key, and the files
  are read as if it were not declared. Refusing would turn away files that
  merely copy a long requirement list; saying nothing would hide that the
  planner ignores what the author may expect it to honour.
- :numeric-fluents and :fluents declared only for action costs (how IPC
  domains wrote costs before :action-costs existed): a warning that the
  functions are read as action costs; nothing else changes.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from tampcli.pddl import ast
from tampcli.pddl.types import OBJECT

COST = "total-cost"

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
    ":numeric-fluents": "numeric fluents",
}
# Outside the accepted fragment, and what each one is.
UNSUPPORTED = {
    ":durative-actions": "durative actions",
    ":duration-inequalities": "duration inequalities",
    ":continuous-effects": "continuous effects",
    ":preferences": "preferences",
    ":constraints": "constraints",
    ":timed-initial-literals": "timed initial literals",
    ":numeric-fluents": "numeric fluents",
    ":object-fluents": "object fluents",
    ":fluents": "numeric and object fluents",
}
# Declared by older domains whose only functions are action costs.
COST_ONLY = frozenset({":numeric-fluents", ":fluents"})


@dataclass(frozen=True)
class RequirementReport:
    declared: tuple[str, ...]  # as written, domain then problem
    used: tuple[str, ...]  # what the files need, in a fixed order
    missing: tuple[tuple[str, ast.Span, str], ...]  # (requirement, first use, which file)
    unknown: tuple[tuple[str, ast.Span, str], ...]  # (requirement, its key, which file)
    # Used although outside the fragment, to refuse: (requirement, first use, which file).
    unsupported: tuple[tuple[str, ast.Span, str], ...]
    # Declared, outside the fragment and unused, to warn about: (requirement, its key, file).
    ignored: tuple[tuple[str, ast.Span, str], ...]


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
    return _WHAT.get(requirement) or UNSUPPORTED.get(requirement, requirement)


def report(domain: ast.Domain, problem: ast.Problem | None = None) -> RequirementReport:
    declared = tuple(dict.fromkeys(domain.requirements + (problem.requirements if problem else ())))
    costs = cost_functions(domain)
    first: dict[str, tuple[ast.Span, str]] = {}
    for which, uses in (("domain", _domain_uses(domain, costs)),
                        ("problem", _problem_uses(problem, costs) if problem else ())):
        for req, span in uses:
            known = first.get(req)
            if known is None or known[1] == which and (span.line, span.column) < (
                    known[0].line, known[0].column):
                first[req] = (span, which)
    order = [":strips"] + sorted(_WHAT)
    used = tuple(r for r in order if r in first or r == ":strips")
    have = expand(declared)
    missing = tuple((r, *first[r]) for r in used if r in first and r not in have)
    keys = list(_keys(domain, "domain")) + (list(_keys(problem, "problem")) if problem else [])
    return RequirementReport(
        declared, used, missing,
        unknown=_first_of_each(k for k in keys if k[0] not in KNOWN),
        unsupported=tuple((r, *first[r]) for r in used if r in UNSUPPORTED),
        ignored=_first_of_each(k for k in keys if k[0] in UNSUPPORTED and k[0] not in first))


def cost_functions(domain: ast.Domain) -> frozenset[str]:
    """(total-cost) and the functions its increases add (static: increasing any other
    function is refused)."""
    amounts = {e.amount.name for action in domain.actions for e in _increases(action.effect)
               if e.function.name == COST and isinstance(e.amount, ast.FunctionTerm)}
    return frozenset({COST} | amounts)


def _keys(node: ast.Domain | ast.Problem, which: str) -> Iterator[tuple[str, ast.Span, str]]:
    """Each declared requirement at its key; at the definition for a tree built by hand."""
    spans = node.requirement_spans or (node.span,) * len(node.requirements)
    for requirement, span in zip(node.requirements, spans, strict=True):
        yield requirement, span, which


def _first_of_each(keys) -> tuple:
    """A requirement declared in both files (or twice) is reported once."""
    first: dict[str, tuple] = {}
    for key in keys:
        first.setdefault(key[0], key)
    return tuple(first.values())


def _domain_uses(domain: ast.Domain, costs: frozenset[str]) -> Iterator[tuple[str, ast.Span]]:
    for typed in domain.types:
        yield ":typing", typed.span
    for typed in _all_typed(domain):
        if typed.types != (OBJECT,):
            yield ":typing", typed.span
    for function in domain.functions:
        if function.name in costs:
            yield ":action-costs", function.span
    for action in domain.actions:
        yield from _formula_uses(action.precondition)
        yield from _effect_uses(action.effect)
    for axiom in domain.axioms:
        yield ":derived-predicates", axiom.span
        yield from _formula_uses(axiom.body)


def _problem_uses(problem: ast.Problem, costs: frozenset[str]) -> Iterator[tuple[str, ast.Span]]:
    for typed in problem.objects:
        if typed.types != (OBJECT,):
            yield ":typing", typed.span
    # Values of functions the domain never uses are inert data, not a use.
    for value in problem.init_values:
        if value.term.name in costs:
            yield ":action-costs", value.span
    if problem.metric is not None:
        if problem.metric.expression.name == COST:
            yield ":action-costs", problem.metric.span
        else:
            yield ":numeric-fluents", problem.metric.expression.span
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
            if e.function.name == COST:
                yield ":action-costs", e.span
            else:
                yield ":numeric-fluents", e.function.span


def _increases(effect: ast.Effect) -> Iterator[ast.Increase]:
    todo = [effect]
    while todo:
        e = todo.pop()
        if isinstance(e, ast.Increase):
            yield e
        elif isinstance(e, ast.AndEffect):
            todo.extend(e.parts)
        elif isinstance(e, (ast.ForallEffect, ast.WhenEffect)):
            todo.append(e.body)


def _typed_uses(params) -> Iterator[tuple[str, ast.Span]]:
    for typed in params:
        if typed.types != (OBJECT,):
            yield ":typing", typed.span
