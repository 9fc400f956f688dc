"""Lifted domain + problem -> grounded Task (never mutates its input).

Stages: objects by type; derived predicates as stratified rules; relaxed
reachability over lifted rules (reach.py) to find the bindings worth
grounding; then each reachable binding is instantiated, its conditions
simplified against the static facts (predicates no action changes), equality
and the unreachable atoms. Only fluent and derived atoms become facts.
"""

from __future__ import annotations

import itertools

from tampcli.errors import InputError, UnsupportedFeatureError
from tampcli.pddl import ast
from tampcli.task import normalize
from tampcli.task.normalize import Types, conjuncts, nnf
from tampcli.task.reach import LiftedRule, reachable
from tampcli.task.task import FALSE, TRUE, Axiom, CondEffect, Condition, Operator, Task

TOTAL_COST = "total-cost"


def ground(domain: ast.Domain, problem: ast.Problem) -> Task:
    return _Grounder(domain, problem).task()


def _fact_name(pred: str, args: tuple[str, ...]) -> str:
    return "(" + " ".join((pred, *args)) + ")"


def _effect_literals(effect: ast.Effect, forall: tuple = ()):
    """(Literal, forall params) for every literal of an effect, conditions ignored."""
    if isinstance(effect, ast.Literal):
        yield effect, forall
    elif isinstance(effect, ast.AndEffect):
        for part in effect.parts:
            yield from _effect_literals(part, forall)
    elif isinstance(effect, ast.ForallEffect):
        yield from _effect_literals(effect.body, forall + effect.params)
    elif isinstance(effect, ast.WhenEffect):
        yield from _effect_literals(effect.body, forall)


class _Grounder:
    def __init__(self, domain: ast.Domain, problem: ast.Problem):
        self.domain, self.problem = domain, problem
        self.types = Types(domain, problem)
        if problem.metric is not None and problem.metric.direction != "minimize":
            raise UnsupportedFeatureError("only `(:metric minimize (total-cost))` is supported",
                                          problem.path, problem.metric.span.line or None,
                                          problem.metric.span.column or None)
        self.use_costs = problem.metric is not None or ":action-costs" in domain.requirements
        self.rules, aux = normalize.axiom_rules(domain, self.types)
        self.derived = {a.name for a in domain.axioms} | aux
        self.fluent = {lit.atom.predicate for action in domain.actions
                       for lit, _ in _effect_literals(action.effect)}
        self.init_atoms = {(a.predicate, a.args) for a in problem.init if a.predicate != "="}
        self.values = {(v.term.name, v.term.args): v.value for v in problem.init_values}
        self.pre_nnf = [nnf(a.precondition) for a in domain.actions]

    def is_static(self, pred: str) -> bool:
        return pred not in self.fluent and pred not in self.derived

    # ------------------------------------------------------------ reachability

    def _lifted_rules(self) -> tuple[list[LiftedRule], list[LiftedRule]]:
        action_rules = []
        for action, pre in zip(self.domain.actions, self.pre_nnf, strict=True):
            body, equal = [], []
            for part in conjuncts(pre):
                if isinstance(part, ast.Atom):
                    if part.predicate == "=":
                        equal.append((part.args[0], part.args[1], True))
                    else:
                        body.append((part.predicate, part.args))
                elif isinstance(part, ast.Not) and part.part.predicate == "=":
                    equal.append((part.part.args[0], part.part.args[1], False))
            heads = [(lit.atom.predicate, lit.atom.args, tuple((p.name, p.types) for p in forall))
                     for lit, forall in _effect_literals(action.effect) if not lit.negated]
            action_rules.append(LiftedRule([(p.name, p.types) for p in action.params],
                                           body, heads, equal, f"action {action.name}"))
        axiom_rules = []
        for rule in self.rules:
            body, equal = [], []
            for lit in rule.literals:
                if isinstance(lit, ast.Atom):
                    if lit.predicate == "=":
                        equal.append((lit.args[0], lit.args[1], True))
                    else:
                        body.append((lit.predicate, lit.args))
                elif lit.part.predicate == "=":
                    equal.append((lit.part.args[0], lit.part.args[1], False))
            axiom_rules.append(LiftedRule([(p.name, p.types) for p in rule.params], body,
                                          [(rule.head.predicate, rule.head.args, ())], equal,
                                          f"derived predicate {rule.head.predicate}"))
        return action_rules, axiom_rules

    # ------------------------------------------------------------ the task

    def task(self) -> Task:
        action_rules, axiom_rules = self._lifted_rules()
        atoms = reachable(action_rules + axiom_rules, self.init_atoms, self.types)
        kept = sorted(a for a in atoms if not self.is_static(a[0]))
        self.fact_id = {a: i for i, a in enumerate(kept)}
        facts = tuple(_fact_name(p, args) for p, args in kept)

        operators = []
        for action, pre, rule in zip(self.domain.actions, self.pre_nnf, action_rules, strict=True):
            names = [p.name for p in action.params]
            for binding in sorted(rule.bindings):
                op = self._operator(action, pre, dict(zip(names, binding, strict=True)), binding)
                if op is not None:
                    operators.append(op)

        axioms = self._axioms(axiom_rules)
        goal = _condition(self.cond(nnf(self.problem.goal), {}))
        if goal is None:
            goal = Condition(extra=(FALSE,))
        init = frozenset(self.fact_id[a] for a in self.init_atoms if a in self.fact_id
                         and a[0] not in self.derived)
        derived = frozenset(i for a, i in self.fact_id.items() if a[0] in self.derived)
        return Task(self.problem.name, facts, init, goal, tuple(operators), not self.use_costs,
                    axioms, derived)

    # ------------------------------------------------------------ conditions

    def atom(self, pred: str, args: tuple[str, ...]):
        """TRUE/FALSE for static and equality atoms, else the fact index (FALSE if unreachable)."""
        if pred == "=":
            return TRUE if args[0] == args[1] else FALSE
        if self.is_static(pred):
            return TRUE if (pred, args) in self.init_atoms else FALSE
        idx = self.fact_id.get((pred, args))
        return FALSE if idx is None else idx

    def cond(self, f: ast.Formula, sub: dict):
        """A ground, simplified condition tree (see task.holds) for an NNF formula."""
        if isinstance(f, ast.Atom):
            return self.atom(f.predicate, tuple(sub.get(a, a) for a in f.args))
        if isinstance(f, ast.Not):
            lit = self.atom(f.part.predicate, tuple(sub.get(a, a) for a in f.part.args))
            if lit.__class__ is int:
                return ~lit
            return FALSE if lit == TRUE else TRUE
        if isinstance(f, ast.And):
            return _junction("and", (self.cond(p, sub) for p in f.parts))
        if isinstance(f, ast.Or):
            return _junction("or", (self.cond(p, sub) for p in f.parts))
        if isinstance(f, (ast.Exists, ast.Forall)):
            names = [p.name for p in f.params]
            domains = [self.types.objects_of(p.types) for p in f.params]

            def parts():
                for combo in itertools.product(*domains):
                    inner = dict(sub)
                    inner.update(zip(names, combo, strict=True))
                    yield self.cond(f.body, inner)

            return _junction("or" if isinstance(f, ast.Exists) else "and", parts())
        raise UnsupportedFeatureError(f"unsupported formula {type(f).__name__}")

    # ------------------------------------------------------------ operators

    def _operator(self, action: ast.Action, pre, sub: dict, args: tuple[str, ...]):
        precondition = _condition(self.cond(pre, sub))
        if precondition is None:
            return None
        buckets: dict = {}
        cost = [0.0]
        self._effect(action.effect, sub, TRUE, buckets, cost, action)
        add, delete = buckets.pop(TRUE, (set(), set()))
        cond_effects = []
        for tree, (c_add, c_del) in buckets.items():
            condition = _condition(tree)
            c_add, c_del = frozenset(c_add - add), frozenset(c_del - delete)
            if condition is not None and (c_add or c_del):
                cond_effects.append(CondEffect(condition, c_add, c_del))
        return Operator(_fact_name(action.name, args), action.name, args,
                        cost[0] if self.use_costs else 1.0, precondition,
                        frozenset(add), frozenset(delete), tuple(cond_effects))

    def _effect(self, effect, sub, when, buckets, cost, action) -> None:
        if isinstance(effect, ast.Literal):
            atom = (effect.atom.predicate, tuple(sub.get(a, a) for a in effect.atom.args))
            idx = self.fact_id.get(atom)
            if idx is None:
                # deleting an atom that never holds; an unreachable add cannot happen
                return
            add, delete = buckets.setdefault(when, (set(), set()))
            (delete if effect.negated else add).add(idx)
        elif isinstance(effect, ast.AndEffect):
            for part in effect.parts:
                self._effect(part, sub, when, buckets, cost, action)
        elif isinstance(effect, ast.ForallEffect):
            names = [p.name for p in effect.params]
            for combo in itertools.product(*(self.types.objects_of(p.types) for p in effect.params)):
                inner = dict(sub)
                inner.update(zip(names, combo, strict=True))
                self._effect(effect.body, inner, when, buckets, cost, action)
        elif isinstance(effect, ast.WhenEffect):
            condition = _junction("and", (when, self.cond(nnf(effect.condition), sub)))
            if condition != FALSE:
                self._effect(effect.body, sub, condition, buckets, cost, action)
        elif isinstance(effect, ast.Increase):
            if effect.function.name != TOTAL_COST:
                raise UnsupportedFeatureError(
                    f"only (increase (total-cost) ...) is supported, found ({effect.function.name})",
                    self.domain.path, effect.span.line or None, effect.span.column or None)
            if when != TRUE:
                raise UnsupportedFeatureError("a conditional (increase (total-cost) ...) is not supported",
                                              self.domain.path, effect.span.line or None,
                                              effect.span.column or None)
            if self.use_costs:
                cost[0] += self._amount(effect.amount, sub, action)

    def _amount(self, amount, sub, action) -> float:
        if isinstance(amount, ast.FunctionTerm):
            key = (amount.name, tuple(sub.get(a, a) for a in amount.args))
            value = self.values.get(key)
            if value is None:
                raise InputError(f"action {action.name}: no value for {_fact_name(*key)} in :init",
                                 self.problem.path, key=_fact_name(*key))
        else:
            value = float(amount)
        if value < 0:
            raise InputError(f"action {action.name}: negative action cost {value:g}",
                             self.problem.path)
        return float(value)

    # ------------------------------------------------------------ axioms

    def _axioms(self, axiom_rules: list[LiftedRule]) -> tuple[Axiom, ...]:
        if not self.rules:
            return ()
        layer = _strata(self.rules, self.derived, self.domain)
        seen, out = set(), []
        for rule, lifted in zip(self.rules, axiom_rules, strict=True):
            names = [p.name for p in rule.params]
            for binding in sorted(lifted.bindings):
                sub = dict(zip(names, binding, strict=True))
                head = self.fact_id.get((rule.head.predicate,
                                         tuple(sub.get(a, a) for a in rule.head.args)))
                if head is None:
                    continue
                pos, neg, dead = set(), set(), False
                for lit in rule.literals:
                    negated = isinstance(lit, ast.Not)
                    atom = lit.part if negated else lit
                    val = self.atom(atom.predicate, tuple(sub.get(a, a) for a in atom.args))
                    if val.__class__ is int:
                        (neg if negated else pos).add(val)
                    elif (val == TRUE) == negated:
                        dead = True
                        break
                if dead:
                    continue
                key = (head, frozenset(pos), frozenset(neg))
                if key not in seen:
                    seen.add(key)
                    out.append(Axiom(head, key[1], key[2], layer[rule.head.predicate]))
        return tuple(out)


def _strata(rules, derived: set[str], domain: ast.Domain) -> dict[str, int]:
    """Layer of each derived predicate: >= its positive, > its negated derived parts."""
    level = dict.fromkeys(derived, 0)
    changed = True
    while changed:
        changed = False
        for rule in rules:
            head = rule.head.predicate
            for lit in rule.literals:
                negated = isinstance(lit, ast.Not)
                pred = (lit.part if negated else lit).predicate
                if pred in derived:
                    need = level[pred] + (1 if negated else 0)
                    if level[head] < need:
                        if need > len(derived):
                            raise UnsupportedFeatureError(
                                f"derived predicate {head} depends negatively on itself "
                                "(the axioms are not stratified)", domain.path)
                        level[head] = need
                        changed = True
    return level


def _junction(tag: str, parts):
    """Simplified ("and"|"or", parts): flattened, constants folded."""
    unit, zero = (TRUE, FALSE) if tag == "and" else (FALSE, TRUE)
    out = {}
    for c in parts:
        if c == zero:
            return zero
        if c == unit:
            continue
        if c.__class__ is tuple and c[0] == tag:
            for sub in c[1]:
                out[sub] = None
        else:
            out[c] = None
    if not out:
        return unit
    if len(out) == 1:
        return next(iter(out))
    return (tag, tuple(out))


def _condition(tree) -> Condition | None:
    """A Condition from a tree; None when it can never hold."""
    if tree == FALSE:
        return None
    parts = tree[1] if tree.__class__ is tuple and tree[0] == "and" else (tree,)
    pos, neg, extra = set(), set(), []
    for p in parts:
        if p.__class__ is int:
            (pos if p >= 0 else neg).add(p if p >= 0 else ~p)
        else:
            extra.append(p)
    if pos & neg:
        return None
    return Condition(frozenset(pos), frozenset(neg), tuple(extra))
