"""The PDDL abstract syntax tree: frozen dataclasses that carry source spans.

Names are lower-cased when parsed (PDDL is case-insensitive). Variables keep
their `?`. The `span` of a node is excluded from equality so that a tree
printed and parsed again compares equal to the original.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Span:
    line: int
    column: int
    end_line: int
    end_column: int


NO_SPAN = Span(0, 0, 0, 0)


def _span() -> Span:
    return field(default=NO_SPAN, compare=False, repr=False)


@dataclass(frozen=True)
class Typed:
    """A name (object, constant, type or variable) and its type(s).

    `types` has one element, or several for `(either t1 t2)`.
    """

    name: str
    types: tuple[str, ...] = ("object",)
    span: Span = _span()


# ---------------------------------------------------------------- formulas


@dataclass(frozen=True)
class Atom:
    """`(p a b)`; `(= a b)` is an Atom with predicate "="."""

    predicate: str
    args: tuple[str, ...]
    span: Span = _span()


@dataclass(frozen=True)
class Not:
    part: Formula
    span: Span = _span()


@dataclass(frozen=True)
class And:
    parts: tuple[Formula, ...]
    span: Span = _span()


@dataclass(frozen=True)
class Or:
    parts: tuple[Formula, ...]
    span: Span = _span()


@dataclass(frozen=True)
class Imply:
    antecedent: Formula
    consequent: Formula
    span: Span = _span()


@dataclass(frozen=True)
class Exists:
    params: tuple[Typed, ...]
    body: Formula
    span: Span = _span()


@dataclass(frozen=True)
class Forall:
    params: tuple[Typed, ...]
    body: Formula
    span: Span = _span()


Formula = Atom | Not | And | Or | Imply | Exists | Forall
TRUE = And(())


# ---------------------------------------------------------------- effects


@dataclass(frozen=True)
class FunctionTerm:
    """`(f a b)`: a function application (only action costs are supported)."""

    name: str
    args: tuple[str, ...] = ()
    span: Span = _span()


@dataclass(frozen=True)
class Literal:
    """An add effect, or a delete effect when `negated`."""

    atom: Atom
    negated: bool = False
    span: Span = _span()


@dataclass(frozen=True)
class Increase:
    """`(increase (total-cost) amount)`; amount is a number or a function term."""

    function: FunctionTerm
    amount: float | FunctionTerm
    span: Span = _span()


@dataclass(frozen=True)
class AndEffect:
    parts: tuple[Effect, ...]
    span: Span = _span()


@dataclass(frozen=True)
class ForallEffect:
    params: tuple[Typed, ...]
    body: Effect
    span: Span = _span()


@dataclass(frozen=True)
class WhenEffect:
    condition: Formula
    body: Effect
    span: Span = _span()


Effect = Literal | Increase | AndEffect | ForallEffect | WhenEffect


# ---------------------------------------------------------------- domain


@dataclass(frozen=True)
class PredicateDef:
    name: str
    params: tuple[Typed, ...]
    span: Span = _span()


@dataclass(frozen=True)
class FunctionDef:
    name: str
    params: tuple[Typed, ...]
    type: str = "number"
    span: Span = _span()


@dataclass(frozen=True)
class Action:
    name: str
    params: tuple[Typed, ...]
    precondition: Formula = TRUE
    effect: Effect = AndEffect(())
    span: Span = _span()


@dataclass(frozen=True)
class Axiom:
    """A derived predicate: `(:derived (name params) body)`."""

    name: str
    params: tuple[Typed, ...]
    body: Formula
    span: Span = _span()


@dataclass(frozen=True)
class Domain:
    name: str
    requirements: tuple[str, ...] = ()
    types: tuple[Typed, ...] = ()  # each type with its parent type(s)
    constants: tuple[Typed, ...] = ()
    predicates: tuple[PredicateDef, ...] = ()
    functions: tuple[FunctionDef, ...] = ()
    actions: tuple[Action, ...] = ()
    axioms: tuple[Axiom, ...] = ()
    path: str | None = field(default=None, compare=False)
    span: Span = _span()
    requirement_spans: tuple[Span, ...] = field(default=(), compare=False, repr=False)

    def action(self, name: str) -> Action | None:
        for action in self.actions:
            if action.name == name:
                return action
        return None


# ---------------------------------------------------------------- problem


@dataclass(frozen=True)
class FunctionValue:
    """`(= (f a) 3)` in the initial state."""

    term: FunctionTerm
    value: float
    span: Span = _span()


@dataclass(frozen=True)
class Metric:
    direction: str  # "minimize" | "maximize"
    expression: FunctionTerm
    span: Span = _span()


@dataclass(frozen=True)
class Problem:
    name: str
    domain_name: str
    requirements: tuple[str, ...] = ()
    objects: tuple[Typed, ...] = ()
    init: tuple[Atom, ...] = ()
    init_values: tuple[FunctionValue, ...] = ()
    goal: Formula = TRUE
    metric: Metric | None = None
    path: str | None = field(default=None, compare=False)
    span: Span = _span()
    domain_name_span: Span = _span()
    requirement_spans: tuple[Span, ...] = field(default=(), compare=False, repr=False)
