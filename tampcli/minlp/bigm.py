"""Big-M implications with M computed from variable bounds (the lesson's Problem 2).

`c(x) <= M (1 - y)`, y binary: with y = 1 it is c(x) <= 0; with y = 0 it must
bind nothing, which holds when M >= sup c over the variables' box. Each M
here is that supremum, computed from the bounds, so it is both valid and as
tight as the box allows.
"""

from __future__ import annotations

from collections.abc import Sequence

from pyscipopt import quicksum

Term = tuple[float, object]  # (coefficient, SCIP variable)


def _bounds(var) -> tuple[float, float]:
    if isinstance(var, float | int):
        return float(var), float(var)
    return var.getLbOriginal(), var.getUbOriginal()


def linear_sup(terms: Sequence[Term], constant: float = 0.0) -> float:
    """sup of sum(c * x) + constant over the variables' box (finite bounds required)."""
    total = constant
    for c, var in terms:
        lo, hi = _bounds(var)
        total += c * (hi if c > 0 else lo)
    return total


def implies_le(model, switch, terms: Sequence[Term], rhs: float, name: str) -> None:
    """sum(c * x) <= rhs whenever the 0/1 expression `switch` is 1."""
    m = max(linear_sup(terms) - rhs, 0.0)
    lhs = quicksum(c * v for c, v in terms)
    model.addCons(lhs <= rhs + m * (1 - switch), name=name)


def implies_eq(model, switch, terms: Sequence[Term], rhs: float, name: str) -> None:
    implies_le(model, switch, terms, rhs, name + "_le")
    implies_le(model, switch, [(-c, v) for c, v in terms], -rhs, name + "_ge")


def implies_close(model, switch, a: Sequence, b: Sequence, radius: float, name: str) -> None:
    """||a - b||^2 <= radius^2 whenever `switch` is 1 (a, b: 2-D points of variables)."""
    sup = 0.0
    for u, v in zip(a, b, strict=True):
        (ulo, uhi), (vlo, vhi) = _bounds(u), _bounds(v)
        sup += max(uhi - vlo, vhi - ulo) ** 2
    m = max(sup - radius ** 2, 0.0)
    lhs = quicksum((u - v) * (u - v) for u, v in zip(a, b, strict=True))
    model.addCons(lhs <= radius ** 2 + m * (1 - switch), name=name)
