"""Lifted normalization: typed objects, negation normal form, axiom rules.

Nothing here grounds an action; it prepares the lifted pieces the grounder
needs: which objects have which type, formulas with negation pushed onto
atoms and `imply` removed, and derived-predicate bodies as Datalog-style
rules (a disjunction of conjunctions, existential variables lifted into the
rule). A disjunction that would multiply out past `DNF_LIMIT` conjunctions
becomes an auxiliary derived predicate instead, so rule sets stay linear in
the size of the body.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

from tampcli.errors import UnsupportedFeatureError
from tampcli.pddl import ast

DNF_LIMIT = 16
AUX_PREFIX = "aux-or-"


class Types:
    """Objects (constants included) by type, through the type hierarchy and `either`."""

    def __init__(self, domain: ast.Domain, problem: ast.Problem):
        parents: dict[str, set[str]] = {}
        for t in domain.types:
            parents.setdefault(t.name, set()).update(t.types)
        self._parents = parents
        members: dict[str, list[str]] = {"object": []}
        self.object_types: dict[str, set[str]] = {}
        for obj in (*domain.constants, *problem.objects):
            types = self.object_types.setdefault(obj.name, set())
            for t in obj.types:
                types |= self.ancestors(t)
        for obj in sorted(self.object_types):
            for t in self.object_types[obj]:
                members.setdefault(t, []).append(obj)
        self._members = {t: tuple(v) for t, v in members.items()}
        self.objects = tuple(sorted(self.object_types))

    def ancestors(self, t: str) -> set[str]:
        out, stack = {"object"}, [t]
        while stack:
            cur = stack.pop()
            if cur not in out or cur == "object":
                out.add(cur)
                stack.extend(p for p in self._parents.get(cur, ()) if p not in out)
        return out

    def objects_of(self, types: tuple[str, ...]) -> tuple[str, ...]:
        """Objects of any of `types` (one type, or the members of `either`)."""
        if len(types) == 1:
            return self._members.get(types[0], ())
        found = set()
        for t in types:
            found.update(self._members.get(t, ()))
        return tuple(sorted(found))

    def has_type(self, obj: str, types: tuple[str, ...]) -> bool:
        have = self.object_types.get(obj)
        return have is not None and any(t in have for t in types)


# ---------------------------------------------------------------- formulas


def nnf(f: ast.Formula, negated: bool = False) -> ast.Formula:
    """Negation normal form: `Not` only around atoms, no `Imply`."""
    if isinstance(f, ast.Atom):
        return ast.Not(f) if negated else f
    if isinstance(f, ast.Not):
        return nnf(f.part, not negated)
    if isinstance(f, ast.And):
        parts = tuple(nnf(p, negated) for p in f.parts)
        return ast.Or(parts) if negated else ast.And(parts)
    if isinstance(f, ast.Or):
        parts = tuple(nnf(p, negated) for p in f.parts)
        return ast.And(parts) if negated else ast.Or(parts)
    if isinstance(f, ast.Imply):
        return nnf(ast.Or((ast.Not(f.antecedent), f.consequent)), negated)
    if isinstance(f, ast.Exists):
        body = nnf(f.body, negated)
        return ast.Forall(f.params, body) if negated else ast.Exists(f.params, body)
    if isinstance(f, ast.Forall):
        body = nnf(f.body, negated)
        return ast.Exists(f.params, body) if negated else ast.Forall(f.params, body)
    raise UnsupportedFeatureError(f"unsupported formula {type(f).__name__}")


def free_vars(f: ast.Formula) -> set[str]:
    if isinstance(f, ast.Atom):
        return {a for a in f.args if a.startswith("?")}
    if isinstance(f, ast.Not):
        return free_vars(f.part)
    if isinstance(f, (ast.And, ast.Or)):
        out: set[str] = set()
        for p in f.parts:
            out |= free_vars(p)
        return out
    if isinstance(f, ast.Imply):
        return free_vars(f.antecedent) | free_vars(f.consequent)
    if isinstance(f, (ast.Exists, ast.Forall)):
        return free_vars(f.body) - {p.name for p in f.params}
    return set()


def substitute(f: ast.Formula, sub: dict[str, str]) -> ast.Formula:
    if isinstance(f, ast.Atom):
        return ast.Atom(f.predicate, tuple(sub.get(a, a) for a in f.args))
    if isinstance(f, ast.Not):
        return ast.Not(substitute(f.part, sub))
    if isinstance(f, ast.And):
        return ast.And(tuple(substitute(p, sub) for p in f.parts))
    if isinstance(f, ast.Or):
        return ast.Or(tuple(substitute(p, sub) for p in f.parts))
    if isinstance(f, ast.Imply):
        return ast.Imply(substitute(f.antecedent, sub), substitute(f.consequent, sub))
    if isinstance(f, (ast.Exists, ast.Forall)):
        inner = {k: v for k, v in sub.items() if k not in {p.name for p in f.params}}
        return type(f)(f.params, substitute(f.body, inner))
    return f


def conjuncts(f: ast.Formula) -> list[ast.Formula]:
    """The top-level conjunction of an NNF formula, flattened."""
    if isinstance(f, ast.And):
        out = []
        for p in f.parts:
            out.extend(conjuncts(p))
        return out
    return [f]


# ---------------------------------------------------------------- axiom rules


@dataclass(frozen=True)
class Rule:
    """`head <- literals`, over `params` (head parameters, then lifted ones).

    `literals` are Atom (positive) or Not(Atom); equality is an atom "=".
    """

    head: ast.Atom
    params: tuple[ast.Typed, ...]
    literals: tuple[ast.Formula, ...]


class _Namer:
    def __init__(self):
        self.count = itertools.count()

    def var(self, name: str) -> str:
        return f"{name}#{next(self.count)}"


def axiom_rules(domain: ast.Domain, types: Types) -> tuple[list[Rule], set[str]]:
    """The rules of every derived predicate, and the auxiliary predicates made."""
    rules: list[Rule] = []
    aux: set[str] = set()
    namer = _Namer()
    for axiom in domain.axioms:
        head = ast.Atom(axiom.name, tuple(p.name for p in axiom.params))
        var_types = {p.name: p.types for p in axiom.params}
        body = nnf(axiom.body)
        for extra, lits in _dnf(body, var_types, types, namer, rules, aux):
            rules.append(Rule(head, axiom.params + extra, lits))
    return rules, aux


_Conj = tuple[tuple[ast.Typed, ...], tuple[ast.Formula, ...]]


def _dnf(f, var_types, types: Types, namer: _Namer, rules: list[Rule], aux: set[str]) -> list[_Conj]:
    if isinstance(f, (ast.Atom, ast.Not)):
        return [((), (f,))]
    if isinstance(f, ast.Or):
        out: list[_Conj] = []
        for p in f.parts:
            out.extend(_dnf(p, var_types, types, namer, rules, aux))
        return out
    if isinstance(f, ast.Exists):
        sub, params = {}, []
        for p in f.params:
            new = namer.var(p.name)
            sub[p.name] = new
            params.append(ast.Typed(new, p.types))
        inner_types = dict(var_types, **{q.name: q.types for q in params})
        body = substitute(f.body, sub)
        return [(tuple(params) + extra, lits)
                for extra, lits in _dnf(body, inner_types, types, namer, rules, aux)]
    if isinstance(f, ast.Forall):
        names = [p.name for p in f.params]
        domains = [types.objects_of(p.types) for p in f.params]
        parts = tuple(substitute(f.body, dict(zip(names, combo, strict=True)))
                      for combo in itertools.product(*domains))
        return _dnf(ast.And(parts), var_types, types, namer, rules, aux)
    if isinstance(f, ast.And):
        children = [_dnf(p, var_types, types, namer, rules, aux) for p in f.parts]
        size = 1
        for c in children:
            size *= len(c)
        while size > DNF_LIMIT:
            # replace the widest disjunction by an auxiliary derived atom
            widest = max(range(len(children)), key=lambda i: len(children[i]))
            children[widest] = [((), (_aux_atom(f.parts[widest], children[widest], var_types,
                                                namer, rules, aux),))]
            size = 1
            for c in children:
                size *= len(c)
        out = []
        for combo in itertools.product(*children):
            params: tuple[ast.Typed, ...] = ()
            lits: tuple[ast.Formula, ...] = ()
            for extra, conj in combo:
                params += extra
                lits += conj
            out.append((params, lits))
        return out
    raise UnsupportedFeatureError(f"unsupported formula {type(f).__name__} in a derived predicate")


def _aux_atom(f, conjs: list[_Conj], var_types, namer: _Namer, rules: list[Rule], aux: set[str]):
    free = sorted(free_vars(f))
    name = f"{AUX_PREFIX}{next(namer.count)}"
    aux.add(name)
    head = ast.Atom(name, tuple(free))
    params = tuple(ast.Typed(v, var_types.get(v, ("object",))) for v in free)
    for extra, lits in conjs:
        rules.append(Rule(head, params + extra, lits))
    return head
