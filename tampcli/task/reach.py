"""Lifted relaxed reachability: which atoms and which parameter bindings can occur.

Each action (and each axiom rule) is a Datalog rule: its positive atomic
preconditions are the body, its add effects the heads; delete effects,
negative literals and anything not a plain atom are ignored, so the result
over-approximates what is reachable. Evaluation is semi-naive: when an atom
is first processed, only the bindings that use it are built, by joining it
with the atoms processed before it, one body atom at a time through an
index (predicate, position, object). The cartesian product of the objects is
never enumerated, except for parameters no positive atom mentions.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

from tampcli.errors import UnsupportedFeatureError
from tampcli.task.normalize import Types

GroundAtom = tuple  # (predicate, args)

# Parameters no positive precondition constrains are enumerated over their
# types; past this many combinations for one partial binding, refuse rather
# than run for hours.
MAX_FREE_COMBINATIONS = 2_000_000


@dataclass
class LiftedRule:
    """params: [(name, types)]; body: [(pred, args)]; heads: [(pred, args, forall params)]."""

    params: list[tuple[str, tuple[str, ...]]]
    body: list[tuple[str, tuple[str, ...]]]
    heads: list[tuple[str, tuple[str, ...], tuple]]
    equal: list[tuple[str, str, bool]] = field(default_factory=list)
    name: str = ""
    bindings: set = field(default_factory=set)
    plans: list = field(default_factory=list)


def _is_var(a: str) -> bool:
    return a.startswith("?")


def _plan(rule: LiftedRule, first: int) -> list[int]:
    """Join order after body atom `first`: most bound variables first."""
    bound = {a for a in rule.body[first][1] if _is_var(a)}
    rest = [i for i in range(len(rule.body)) if i != first]
    order = []
    while rest:
        best = max(rest, key=lambda i: (sum(1 for a in rule.body[i][1] if a in bound or not _is_var(a)),
                                        -len(rule.body[i][1])))
        rest.remove(best)
        order.append(best)
        bound |= {a for a in rule.body[best][1] if _is_var(a)}
    return order


def reachable(rules: list[LiftedRule], init: set[GroundAtom], types: Types) -> set[GroundAtom]:
    """All relaxed-reachable atoms; fills each rule's `bindings` (tuples in param order)."""
    facts: set[GroundAtom] = set(init)
    queue = list(init)
    by_pred: dict[str, list[tuple]] = {}
    index: dict[tuple, list[tuple]] = {}
    triggers: dict[str, list[tuple[LiftedRule, int]]] = {}
    for rule in rules:
        rule.plans = [_plan(rule, i) for i in range(len(rule.body))]
        for i, (pred, _) in enumerate(rule.body):
            triggers.setdefault(pred, []).append((rule, i))

    def emit(rule: LiftedRule, binding: dict) -> None:
        free = [(name, ts) for name, ts in rule.params if name not in binding]
        for name, ts in rule.params:
            if name in binding and not types.has_type(binding[name], ts):
                return
        choices = [types.objects_of(ts) for _, ts in free]
        if free and math.prod(len(c) for c in choices) > MAX_FREE_COMBINATIONS:
            raise UnsupportedFeatureError(
                f"{rule.name}: grounding would enumerate {math.prod(len(c) for c in choices):,} "
                f"combinations of {', '.join(n for n, _ in free)}, which no positive precondition "
                "constrains")
        for combo in itertools.product(*choices):
            full = dict(binding)
            full.update(zip((n for n, _ in free), combo, strict=True))
            if any((full.get(a, a) == full.get(b, b)) != same for a, b, same in rule.equal):
                continue
            key = tuple(full[name] for name, _ in rule.params)
            if key in rule.bindings:
                continue
            rule.bindings.add(key)
            for pred, args, forall in rule.heads:
                if forall:
                    names = [n for n, _ in forall]
                    for objs in itertools.product(*(types.objects_of(ts) for _, ts in forall)):
                        sub = dict(full)
                        sub.update(zip(names, objs, strict=True))
                        atom = (pred, tuple(sub.get(a, a) for a in args))
                        if atom not in facts:
                            facts.add(atom)
                            queue.append(atom)
                else:
                    atom = (pred, tuple(full.get(a, a) for a in args))
                    if atom not in facts:
                        facts.add(atom)
                        queue.append(atom)

    def join(rule: LiftedRule, order: list[int], k: int, binding: dict) -> None:
        if k == len(order):
            emit(rule, binding)
            return
        pred, args = rule.body[order[k]]
        candidates = None
        for pos, a in enumerate(args):
            val = binding.get(a) if _is_var(a) else a
            if val is not None:
                candidates = index.get((pred, pos, val), ())
                break
        if candidates is None:
            candidates = by_pred.get(pred, ())
        for cand in candidates:
            new = _match(args, cand, binding)
            if new is not None:
                join(rule, order, k + 1, new)

    for rule in rules:
        if not rule.body:
            emit(rule, {})
    while queue:
        atom = queue.pop()
        pred, args = atom
        by_pred.setdefault(pred, []).append(args)
        for pos, val in enumerate(args):
            index.setdefault((pred, pos, val), []).append(args)
        for rule, i in triggers.get(pred, ()):
            binding = _match(rule.body[i][1], args, {})
            if binding is not None:
                join(rule, rule.plans[i], 0, binding)
    return facts


def _match(pattern: tuple[str, ...], args: tuple[str, ...], binding: dict) -> dict | None:
    if len(pattern) != len(args):
        return None
    new = None
    for a, val in zip(pattern, args, strict=True):
        if a.startswith("?"):
            have = binding.get(a) if new is None else new.get(a)
            if have is None:
                if new is None:
                    new = dict(binding)
                new[a] = val
            elif have != val:
                return None
        elif a != val:
            return None
    return binding if new is None else new
