"""Lifted PDDL semantics on the AST alone, for an independent plan validator.

Deliberately shares nothing with grounding (`tampcli.task`): formulas are
evaluated directly over typed objects, so that a grounding bug cannot hide
itself by also being in the checker. A state is a frozenset of ground atoms
`(predicate, arg, ...)` holding the basic facts; derived facts are added by
`World.closure` (stratified fixpoint) before anything is evaluated on it.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Mapping
from dataclasses import dataclass

from tampcli.errors import PDDLSemanticError
from tampcli.pddl import ast

GroundAtom = tuple[str, ...]
State = frozenset  # of GroundAtom
Binding = Mapping[str, str]


@dataclass(frozen=True)
class Effects:
    add: frozenset
    delete: frozenset
    cost: float


class World:
    """Objects, types, static function values and axioms of one domain + problem."""

    def __init__(self, domain: ast.Domain, problem: ast.Problem):
        self.domain, self.problem = domain, problem
        self._parents: dict[str, tuple[str, ...]] = {}
        for t in domain.types:
            self._parents[t.name] = tuple(p for p in t.types if p != t.name)
        self.object_types: dict[str, tuple[str, ...]] = {}
        for obj in (*domain.constants, *problem.objects):
            self.object_types[obj.name] = obj.types
        self._by_type: dict[str, tuple[str, ...]] = {}
        self._compiled: dict = {}
        self.values: dict[tuple[str, ...], float] = {
            (v.term.name, *v.term.args): v.value for v in problem.init_values}
        self.cost_function = (problem.metric.expression.name
                              if problem.metric is not None else "total-cost")
        # as grounding does: a metric or :action-costs means general costs (an
        # action with no increase then costs 0), otherwise every action costs 1
        self.unit_cost = not (problem.metric is not None
                              or ":action-costs" in domain.requirements)
        self.derived = frozenset(ax.name for ax in domain.axioms)
        self._strata = _stratify(domain.axioms, self.derived, domain.path)

    # ------------------------------------------------------------ types

    def supertypes(self, type_name: str) -> set[str]:
        seen, todo = {"object"}, [type_name]
        while todo:
            t = todo.pop()
            if t in seen:
                continue
            seen.add(t)
            todo.extend(self._parents.get(t, ()))
        return seen

    def is_of_type(self, obj: str, types: tuple[str, ...]) -> bool:
        """Does `obj` fit a parameter of type `types` (several for `either`)?"""
        wanted = set(types)
        return any(not wanted.isdisjoint(self.supertypes(t))
                   for t in self.object_types.get(obj, ()))

    def objects_of(self, types: tuple[str, ...]) -> tuple[str, ...]:
        key = "|".join(types)
        found = self._by_type.get(key)
        if found is None:
            found = tuple(o for o in self.object_types if self.is_of_type(o, types))
            self._by_type[key] = found
        return found

    def bindings(self, params: tuple[ast.Typed, ...], base: Binding) -> Iterator[dict[str, str]]:
        domains = [self.objects_of(p.types) for p in params]
        for combo in itertools.product(*domains):
            binding = dict(base)
            binding.update(zip((p.name for p in params), combo, strict=True))
            yield binding

    # ------------------------------------------------------------ states

    def initial_state(self) -> State:
        return frozenset((a.predicate, *a.args) for a in self.problem.init
                         if a.predicate not in self.derived and a.predicate != "=")

    def closure(self, state: State) -> State:
        """`state` plus every derived fact it implies, stratum by stratum."""
        if not self._strata:
            return state
        facts = set(state)
        for stratum in self._strata:
            rules = [(ax.name, self.compiled(ax.body, tuple(p.name for p in ax.params)),
                      [self.objects_of(p.types) for p in ax.params]) for ax in stratum]
            changed = True
            while changed:  # naive fixpoint: few objects, small bodies
                changed = False
                for name, body, domains in rules:
                    for combo in itertools.product(*domains):
                        head = (name, *combo)
                        if head not in facts and body(*combo, facts):
                            facts.add(head)
                            changed = True
        return frozenset(facts)

    # ------------------------------------------------------------ formulas

    def holds(self, f: ast.Formula, binding: Binding, state) -> bool:
        return self.compiled(f, tuple(binding))(*binding.values(), state)

    def compiled(self, f: ast.Formula, params: tuple[str, ...]):
        """f as a Python function of the values of `params`, then the state.

        Formulas are evaluated millions of times for derived predicates, so
        each is turned once into one Python expression (quantifiers become
        any/all over tuples of objects) instead of being walked node by node.
        """
        key = (id(f), params)
        fn = self._compiled.get(key)
        if fn is None:
            names = {p: f"v{i}" for i, p in enumerate(params)}
            scope: dict = {}
            try:
                body = self._expression(f, names, scope)
                args = ", ".join([*names.values(), "st"])
                exec(f"def fn({args}):\n    return {body}\n", scope)  # source from our own AST
                compiled = scope["fn"]
            except (SyntaxError, RecursionError, MemoryError):  # too deep for Python's parser
                def compiled(*values, _f=f, _params=params):
                    return self._interpret(_f, dict(zip(_params, values[:-1], strict=True)),
                                           values[-1])
            fn = self._compiled[key] = (f, compiled)  # f kept alive: its id stays unique
        return fn[1]

    def _interpret(self, f: ast.Formula, binding: Binding, state) -> bool:
        """The same semantics as `compiled`, node by node, for formulas too deep for it."""
        if isinstance(f, ast.Atom):
            args = tuple(binding.get(a, a) for a in f.args)
            return args[0] == args[1] if f.predicate == "=" else (f.predicate, *args) in state
        if isinstance(f, ast.And):
            return all(self._interpret(p, binding, state) for p in f.parts)
        if isinstance(f, ast.Or):
            return any(self._interpret(p, binding, state) for p in f.parts)
        if isinstance(f, ast.Not):
            return not self._interpret(f.part, binding, state)
        if isinstance(f, ast.Imply):
            return (not self._interpret(f.antecedent, binding, state)
                    or self._interpret(f.consequent, binding, state))
        if isinstance(f, (ast.Exists, ast.Forall)):
            test = any if isinstance(f, ast.Exists) else all
            return test(self._interpret(f.body, b, state)
                        for b in self.bindings(f.params, binding))
        raise TypeError(f"not a formula: {f!r}")

    def _expression(self, f: ast.Formula, names: dict[str, str], scope: dict) -> str:
        def term(a: str) -> str:
            return names[a] if a in names else repr(a)

        if isinstance(f, ast.Atom):
            if f.predicate == "=":
                return f"({term(f.args[0])} == {term(f.args[1])})"
            return "((" + ", ".join([repr(f.predicate), *map(term, f.args)]) + ",) in st)"
        if isinstance(f, (ast.And, ast.Or)):
            if not f.parts:
                return "True" if isinstance(f, ast.And) else "False"
            if len(f.parts) == 1:
                return self._expression(f.parts[0], names, scope)
            joiner = " and " if isinstance(f, ast.And) else " or "
            return "(" + joiner.join(self._expression(p, names, scope) for p in f.parts) + ")"
        if isinstance(f, ast.Not):
            return f"(not {self._expression(f.part, names, scope)})"
        if isinstance(f, ast.Imply):
            return (f"((not {self._expression(f.antecedent, names, scope)}) or "
                    f"{self._expression(f.consequent, names, scope)})")
        if isinstance(f, (ast.Exists, ast.Forall)):
            inner = dict(names)
            loops = []
            for p in f.params:
                var = inner[p.name] = f"v{len(scope)}_{len(inner)}"
                domain = f"objects{len(scope)}"
                scope[domain] = self.objects_of(p.types)
                loops.append(f"for {var} in {domain}")
            body = self._expression(f.body, inner, scope)
            word = "any" if isinstance(f, ast.Exists) else "all"
            return f"{word}({body} {' '.join(loops)})"
        raise TypeError(f"not a formula: {f!r}")

    def why_false(self, f: ast.Formula, binding: Binding, state) -> list[str]:
        """The smallest parts of `f` that make it false, in words (f must be false)."""
        if isinstance(f, ast.And):
            reasons = []
            for part in f.parts:
                if not self.holds(part, binding, state):
                    reasons.extend(self.why_false(part, binding, state))
            return reasons
        if isinstance(f, ast.Forall):
            for b in self.bindings(f.params, binding):
                if not self.holds(f.body, b, state):
                    where = ", ".join(f"{p.name} = {b[p.name]}" for p in f.params)
                    return [f"{r} (for {where})" for r in self.why_false(f.body, b, state)]
        if isinstance(f, ast.Not) and isinstance(f.part, ast.Atom):
            return [f"{show(f, binding)} is false: {show(f.part, binding)} holds"]
        return [f"{show(f, binding)} is false"]

    # ------------------------------------------------------------ effects

    def effects(self, e: ast.Effect, binding: Binding, state) -> Effects:
        """Adds, deletes and cost of `e`; conditions are read on `state` (closed)."""
        add: set = set()
        delete: set = set()
        cost = [0.0]
        self._collect(e, binding, state, add, delete, cost)
        return Effects(frozenset(add), frozenset(delete), cost[0])

    def _collect(self, e, binding, state, add, delete, cost) -> None:
        if isinstance(e, ast.Literal):
            atom = (e.atom.predicate, *(binding.get(a, a) for a in e.atom.args))
            (delete if e.negated else add).add(atom)
        elif isinstance(e, ast.AndEffect):
            for part in e.parts:
                self._collect(part, binding, state, add, delete, cost)
        elif isinstance(e, ast.WhenEffect):
            if self.holds(e.condition, binding, state):
                self._collect(e.body, binding, state, add, delete, cost)
        elif isinstance(e, ast.ForallEffect):
            for b in self.bindings(e.params, binding):
                self._collect(e.body, b, state, add, delete, cost)
        elif isinstance(e, ast.Increase):
            if e.function.name == self.cost_function:
                cost[0] += self.amount(e.amount, binding)
        else:
            raise TypeError(f"not an effect: {e!r}")

    def amount(self, amount: float | ast.FunctionTerm, binding: Binding) -> float:
        if not isinstance(amount, ast.FunctionTerm):
            return float(amount)
        key = (amount.name, *(binding.get(a, a) for a in amount.args))
        if key not in self.values:
            raise UndefinedValue("(" + " ".join(key) + ")")
        return self.values[key]


class UndefinedValue(Exception):
    """A cost term with no value in the problem's :init (makes the step invalid)."""


def show(f, binding: Binding) -> str:
    """A formula, with its variables replaced by their objects, in PDDL syntax."""
    if isinstance(f, ast.Atom):
        return "(" + " ".join((f.predicate, *(binding.get(a, a) for a in f.args))) + ")"
    if isinstance(f, ast.Not):
        return f"(not {show(f.part, binding)})"
    if isinstance(f, (ast.And, ast.Or)):
        word = "and" if isinstance(f, ast.And) else "or"
        return f"({word} " + " ".join(show(p, binding) for p in f.parts) + ")"
    if isinstance(f, ast.Imply):
        return f"(imply {show(f.antecedent, binding)} {show(f.consequent, binding)})"
    if isinstance(f, (ast.Exists, ast.Forall)):
        word = "exists" if isinstance(f, ast.Exists) else "forall"
        params = " ".join(f"{p.name} - {p.types[0] if len(p.types) == 1 else 'either'}"
                          for p in f.params)
        inner = {k: v for k, v in binding.items() if k not in {p.name for p in f.params}}
        return f"({word} ({params}) {show(f.body, inner)})"
    return repr(f)


def _occurrences(f: ast.Formula, positive: bool, out: list) -> None:
    """(predicate, polarity) of every atom in f; a quantifier keeps the polarity."""
    if isinstance(f, ast.Atom):
        out.append((f.predicate, positive))
    elif isinstance(f, ast.Not):
        _occurrences(f.part, not positive, out)
    elif isinstance(f, (ast.And, ast.Or)):
        for p in f.parts:
            _occurrences(p, positive, out)
    elif isinstance(f, ast.Imply):
        _occurrences(f.antecedent, not positive, out)
        _occurrences(f.consequent, positive, out)
    elif isinstance(f, (ast.Exists, ast.Forall)):
        _occurrences(f.body, positive, out)


def _stratify(axioms: tuple[ast.Axiom, ...], derived: frozenset,
              path: str | None) -> tuple[tuple, ...]:
    """Group axioms into strata: a negated derived predicate is in a lower stratum."""
    if not axioms:
        return ()
    level = dict.fromkeys(derived, 0)
    deps: list[tuple[ast.Axiom, list]] = []
    for ax in axioms:
        occ: list = []
        _occurrences(ax.body, True, occ)
        deps.append((ax, [(p, pos) for p, pos in occ if p in derived]))
    changed = True
    while changed:
        changed = False
        for ax, occ in deps:
            for pred, positive in occ:
                need = level[pred] + (0 if positive else 1)
                if need > level[ax.name]:
                    if need > len(derived):
                        raise PDDLSemanticError(
                            f"derived predicate {ax.name} depends negatively on itself "
                            "(the axioms are not stratifiable)",
                            path, ax.span.line or None, ax.span.column or None)
                    level[ax.name] = need
                    changed = True
    strata = [[] for _ in range(max(level.values()) + 1)]
    for ax in axioms:
        strata[level[ax.name]].append(ax)
    return tuple(tuple(s) for s in strata if s)

