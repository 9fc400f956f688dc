"""The variables SLSQP iterates on: the NLP's own, or whitened by the cost's Hessian.

SLSQP starts its quasi-Newton matrix at the identity and learns the
curvature from its steps. A path NLP's cost, (T / waypoints) * sum |dq|^2,
has a constant Hessian H (block tridiagonal, `Rows.cost_hess`) whose
eigenvalues span a factor of 40 at 10 segments: far from the identity, so
the first iterations step badly and the line search cuts them back. In the
variables y with x = M y, M = L^-T (H = L L^T), the cost's Hessian is the
identity, SLSQP's start is right for it, and only what the constraints add
is left to learn (arm-hanoi p01's 13 motions: 81 SLSQP iterations against
204, 110 evaluations against 371, the same paths within 0.2 % of cost).

The box bounds on x are then general linear rows on y (M y >= lower,
upper - M y >= 0), appended to the inequality rows SLSQP sees; the caller's
rows, bounds and answers stay in x.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np


class NlpSpace(Protocol):
    def to_x(self, y: np.ndarray) -> np.ndarray: ...

    def to_y(self, x: np.ndarray) -> np.ndarray: ...

    def minimize_args(self, ev, bounds, has_eq: bool, has_ineq: bool) -> dict:
        """scipy.optimize.minimize's fun, jac, bounds and constraints in y."""


def dense_hessian(pairs: dict, slices: dict, nx: int) -> np.ndarray:
    """The (nx, nx) matrix of `Rows.cost_hess`'s blocks (upper pairs mirrored)."""
    H = np.zeros((nx, nx))
    for (a, b), block in pairs.items():
        sa, sb = slices.get(a), slices.get(b)
        if sa is None or sb is None:
            continue
        H[sa, sb] += block
        if a != b:
            H[sb, sa] += block.T
    return H


def space_of(ev, bounds) -> NlpSpace:
    """Whitened where the evaluator's last rows give the cost's Hessian and it is
    positive definite (the path NLPs), the plain variables otherwise."""
    if ev.cost_hess:
        space = WhitenedSpace.of(dense_hessian(ev.cost_hess, ev.slices, ev.nx),
                                 [b[0] for b in bounds], [b[1] for b in bounds])
        if space is not None:
            return space
    return PlainSpace()


class PlainSpace:
    """y = x: SLSQP on the NLP's own variables and bounds."""

    def to_x(self, y):
        return np.asarray(y)

    def to_y(self, x):
        return np.asarray(x, dtype=float)

    def minimize_args(self, ev, bounds, has_eq, has_ineq):
        constraints = []
        if has_eq:
            constraints.append({"type": "eq", "fun": lambda x: ev(x)[2],
                                "jac": lambda x: ev(x)[3]})
        if has_ineq:
            constraints.append({"type": "ineq", "fun": lambda x: ev(x)[4],
                                "jac": lambda x: ev(x)[5]})
        return {"fun": lambda x: ev(x)[0], "jac": lambda x: ev(x)[1], "bounds": bounds,
                "constraints": constraints}


class WhitenedSpace:
    """x = M y, M = L^-T for the cost's Hessian H = L L^T (module doc)."""

    def __init__(self, L: np.ndarray, lower: np.ndarray, upper: np.ndarray):
        self.M = M = np.linalg.solve(L.T, np.eye(len(L)))
        self.M_inv = L.T
        low, high = np.isfinite(lower), np.isfinite(upper)
        self._lower, self._upper = lower[low], upper[high]
        self._low, self._high = low, high
        self._bound_jac = np.vstack([M[low], -M[high]])

    @classmethod
    def of(cls, hessian: np.ndarray, lower, upper) -> WhitenedSpace | None:
        """The space of a positive definite `hessian` (dense), or None."""
        try:
            L = np.linalg.cholesky(hessian)
        except np.linalg.LinAlgError:
            return None
        return cls(L, np.asarray(lower, dtype=float), np.asarray(upper, dtype=float))

    def to_x(self, y):
        return self.M @ y

    def to_y(self, x):
        return self.M_inv @ np.asarray(x, dtype=float)

    def minimize_args(self, ev, bounds, has_eq, has_ineq):
        M = self.M

        def ineq(y):
            x = M @ y
            return np.concatenate([ev(x)[4], x[self._low] - self._lower,
                                   self._upper - x[self._high]])

        constraints = [{"type": "ineq", "fun": ineq,
                        "jac": lambda y: np.vstack([ev(M @ y)[5] @ M, self._bound_jac])}]
        if has_eq:
            constraints.append({"type": "eq", "fun": lambda y: ev(M @ y)[2],
                                "jac": lambda y: ev(M @ y)[3] @ M})
        return {"fun": lambda y: ev(M @ y)[0], "jac": lambda y: M.T @ ev(M @ y)[1],
                "bounds": None, "constraints": constraints}
