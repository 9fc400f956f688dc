"""The grounded task: integer facts, frozenset states, operators, axioms.

A state is a frozenset of fact indices holding the *basic* facts only: derived
facts (axioms) are never stored in a state, they are recomputed from it (see
`Task.closure`) inside `applicable`, `apply`, `successors` and `is_goal`.
`Task.init` therefore holds no derived fact.

A ground condition that is not a plain conjunction of literals is kept as a
small tree and evaluated on the state, rather than split into several
operators: a literal is an int (`i` is fact i holds, `~i` is fact i does not
hold), an inner node is `("and", parts)` or `("or", parts)`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

Cond = int | tuple
TRUE: Cond = ("and", ())
FALSE: Cond = ("or", ())


def holds(cond: Cond, state) -> bool:
    """Evaluate a ground condition tree on a (closed) state."""
    if cond.__class__ is int:
        return cond in state if cond >= 0 else ~cond not in state
    tag, parts = cond
    if tag == "and":
        for part in parts:
            if not holds(part, state):
                return False
        return True
    for part in parts:
        if holds(part, state):
            return True
    return False


@dataclass(frozen=True)
class Condition:
    """A conjunction `pos & not neg & extra...` (extra: trees, see `holds`)."""

    pos: frozenset[int] = frozenset()
    neg: frozenset[int] = frozenset()
    extra: tuple[Cond, ...] = ()

    def holds(self, state) -> bool:
        if not self.pos <= state or not self.neg.isdisjoint(state):
            return False
        for cond in self.extra:
            if not holds(cond, state):
                return False
        return True


@dataclass(frozen=True)
class CondEffect:
    """`(when condition (and add... (not delete)...))`, condition on the state before."""

    condition: Condition
    add: frozenset[int] = frozenset()
    delete: frozenset[int] = frozenset()


@dataclass(frozen=True)
class Operator:
    name: str
    action: str
    args: tuple[str, ...]
    cost: float
    pre: Condition = Condition()
    add: frozenset[int] = frozenset()
    delete: frozenset[int] = frozenset()
    cond_effects: tuple[CondEffect, ...] = ()

    def __str__(self) -> str:
        return self.name


@dataclass(frozen=True)
class Axiom:
    """One ground rule `head <- pos & not neg` of a derived predicate.

    Rules are evaluated stratum by stratum (`layer`); a negated derived fact
    in `neg` always belongs to a lower stratum.
    """

    head: int
    pos: frozenset[int]
    neg: frozenset[int]
    layer: int


@dataclass(frozen=True)
class Task:
    name: str
    facts: tuple[str, ...]
    init: frozenset[int]
    goal: Condition
    operators: tuple[Operator, ...]
    unit_cost: bool
    axioms: tuple[Axiom, ...] = ()
    derived: frozenset[int] = frozenset()
    _index: dict = field(default=None, init=False, repr=False, compare=False)
    _free: tuple = field(default=(), init=False, repr=False, compare=False)
    _layers: tuple = field(default=(), init=False, repr=False, compare=False)

    def __post_init__(self):
        # Successor generation: each operator is filed under one positive
        # precondition fact, preferably one false initially (holding, at-x)
        # so that most states skip it without a subset test.
        index: dict[int, list[Operator]] = {}
        free: list[Operator] = []
        for op in self.operators:
            if op.pre.pos:
                outside = [f for f in op.pre.pos if f not in self.init]
                key = min(outside) if outside else min(op.pre.pos)
                index.setdefault(key, []).append(op)
            else:
                free.append(op)
        object.__setattr__(self, "_index", {k: tuple(v) for k, v in index.items()})
        object.__setattr__(self, "_free", tuple(free))
        object.__setattr__(self, "_layers", _axiom_layers(self.axioms))

    # ------------------------------------------------------------ axioms

    @property
    def has_axioms(self) -> bool:
        return bool(self.axioms)

    @property
    def has_conditional_effects(self) -> bool:
        return any(op.cond_effects for op in self.operators)

    def closure(self, state: frozenset[int]) -> frozenset[int]:
        """The state with every derived fact it implies (stratified fixpoint).

        Per layer, a counter per rule of its positive body facts not yet
        true; a rule fires when it reaches 0 and none of its negated facts
        (basic, or from a lower layer, hence settled) holds.
        """
        if not self._layers:
            return state
        facts = set(state)
        for heads, negs, counts, by_pos, unconditional in self._layers:
            counters = counts[:]
            # Every fact true before this layer, then each head as it comes true, is
            # counted once, from the one queue (a head counted twice fires a rule early).
            queue = [f for f in facts if f in by_pos]
            for i in unconditional:
                neg = negs[i]
                if (neg is None or neg.isdisjoint(facts)) and heads[i] not in facts:
                    facts.add(heads[i])
                    queue.append(heads[i])
            while queue:
                fact = queue.pop()
                for i in by_pos.get(fact, ()):
                    left = counters[i] - 1
                    counters[i] = left
                    if left == 0:
                        neg = negs[i]
                        if (neg is None or neg.isdisjoint(facts)) and heads[i] not in facts:
                            facts.add(heads[i])
                            queue.append(heads[i])
        return frozenset(facts)

    # ------------------------------------------------------------ search API

    def applicable(self, state: frozenset[int]) -> list[Operator]:
        return self._applicable(self.closure(state))

    def _applicable(self, closed: frozenset[int]) -> list[Operator]:
        result = []
        index = self._index
        for fact in closed:
            ops = index.get(fact)
            if ops:
                for op in ops:
                    if op.pre.holds(closed):
                        result.append(op)
        for op in self._free:
            if op.pre.holds(closed):
                result.append(op)
        return result

    def apply(self, state: frozenset[int], op: Operator) -> frozenset[int]:
        """The successor; effect conditions are evaluated on `state` (with axioms)."""
        if not op.cond_effects:
            return (state - op.delete) | op.add
        return self._apply(state, self.closure(state), op)

    @staticmethod
    def _apply(state, closed, op: Operator) -> frozenset[int]:
        if not op.cond_effects:
            return (state - op.delete) | op.add
        add, delete = set(op.add), set(op.delete)
        for eff in op.cond_effects:
            if eff.condition.holds(closed):
                add |= eff.add
                delete |= eff.delete
        # add-after-delete: a fact both added and deleted ends up true
        return (state - delete) | add

    def successors(self, state: frozenset[int],
                   closed: frozenset[int] | None = None) -> list[tuple[Operator, frozenset[int]]]:
        """(op, successor) for every applicable op, computing the axioms once
        (not at all when the caller has `closed`, the state's closure)."""
        if closed is None:
            closed = self.closure(state)
        apply = self._apply
        return [(op, apply(state, closed, op)) for op in self._applicable(closed)]

    def is_goal(self, state: frozenset[int]) -> bool:
        return self.goal.holds(self.closure(state))

    # ------------------------------------------------------------ helpers

    def state_names(self, state) -> list[str]:
        return sorted(self.facts[i] for i in state)

    def operator(self, name: str) -> Operator | None:
        for op in self.operators:
            if op.name == name:
                return op
        return None

    def __repr__(self) -> str:
        return (f"Task({self.name!r}, {len(self.facts)} facts, {len(self.operators)} operators, "
                f"{len(self.axioms)} axioms)")


def _axiom_layers(axioms: tuple[Axiom, ...]) -> tuple:
    by_layer: dict[int, list[Axiom]] = {}
    for ax in axioms:
        by_layer.setdefault(ax.layer, []).append(ax)
    layers = []
    for layer in sorted(by_layer):
        rules = by_layer[layer]
        by_pos: dict[int, list[int]] = {}
        for i, rule in enumerate(rules):
            for f in rule.pos:
                by_pos.setdefault(f, []).append(i)
        layers.append((
            [r.head for r in rules],
            [r.neg or None for r in rules],
            [len(r.pos) for r in rules],
            {k: tuple(v) for k, v in by_pos.items()},
            [i for i, r in enumerate(rules) if not r.pos],
        ))
    return tuple(layers)
