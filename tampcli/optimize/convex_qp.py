"""A convex QP solved with a certificate: the value is a proved lower bound.

    minimize 0.5 x'Px + c'x + r   s.t.  A x <= b,  E x = f,  lo <= x <= hi

with P positive semidefinite (checked). Any KKT point of a convex QP is a
global minimum, but a solver's point is only approximately one, so the bound
reported is not the solver's value: it is weak duality evaluated at the
solver's point x and multipliers (lambda >= 0, nu) fitted to it,

    f(y) >= L(y) >= L(x) + min over the box of grad L(x)'(y - x)   for every feasible y,

L the Lagrangian of the rows (the box kept as a set), convex in y. The
inequality holds for any x and any lambda >= 0, so the bound is proved
however inexact the solver was; a good solver makes it tight. An infeasible
QP gets a Farkas certificate from an LP (HiGHS), re-checked in numpy the
same way: when min over the box of lambda'(Ay - b) + nu'(Ey - f) > 0, no y
is feasible.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import linprog, minimize, nnls

ACTIVE = 1e-6  # a row with less slack than this is active when multipliers are fitted
FEASIBLE = 1e-7  # largest violation of a point called feasible
SAFETY = 1e-9  # relative: floating-point rounding in the certificate's own arithmetic


@dataclass(frozen=True)
class ConvexQP:
    P: np.ndarray  # (n, n), symmetric positive semidefinite
    c: np.ndarray  # (n,)
    r: float
    A: np.ndarray  # (m, n)
    b: np.ndarray  # (m,)
    E: np.ndarray  # (p, n)
    f: np.ndarray  # (p,)
    lo: np.ndarray  # (n,) finite
    hi: np.ndarray  # (n,) finite

    def value(self, x: np.ndarray) -> float:
        return float(0.5 * x @ self.P @ x + self.c @ x + self.r)

    def violation(self, x: np.ndarray) -> float:
        parts = [np.zeros(1), self.A @ x - self.b, np.abs(self.E @ x - self.f),
                 self.lo - x, x - self.hi]
        return float(max(np.max(p) for p in parts if p.size))


@dataclass(frozen=True)
class QPBound:
    """`value`: a lower bound on the QP's optimum (inf: proved infeasible) when
    `proved`; the solver's value otherwise (P was not positive semidefinite).
    `solver_value`: the objective at the solver's point (None when infeasible)."""

    value: float
    proved: bool
    solver_value: float | None
    x: np.ndarray | None


def is_convex(P: np.ndarray) -> bool:
    if not np.allclose(P, P.T, atol=1e-12):
        return False
    scale = max(1.0, float(np.max(np.abs(P)))) if P.size else 1.0
    return P.size == 0 or float(np.min(np.linalg.eigvalsh(P))) >= -1e-10 * scale


def solve_convex_qp(qp: ConvexQP) -> QPBound:
    """The QP's optimum as a proved lower bound (see the module docstring)."""
    x = _solve(qp)
    convex = is_convex(qp.P)
    feasible = qp.violation(x) <= FEASIBLE
    if not convex:
        return QPBound(qp.value(x) if feasible else np.inf, False,
                       qp.value(x) if feasible else None, x)
    if not feasible and infeasibility_certificate(qp):
        return QPBound(np.inf, True, None, None)
    lam, nu = _multipliers(qp, x)
    return QPBound(lagrangian_bound(qp, x, lam, nu), True,
                   qp.value(x) if feasible else None, x)


def _solve(qp: ConvexQP) -> np.ndarray:
    n = len(qp.c)
    x0 = np.clip(np.zeros(n), qp.lo, qp.hi)
    cons = []
    if len(qp.b):
        cons.append({"type": "ineq", "fun": lambda x: qp.b - qp.A @ x, "jac": lambda x: -qp.A})
    if len(qp.f):
        cons.append({"type": "eq", "fun": lambda x: qp.E @ x - qp.f, "jac": lambda x: qp.E})
    out = minimize(qp.value, x0, jac=lambda x: qp.P @ x + qp.c, method="SLSQP",
                   bounds=list(zip(qp.lo, qp.hi, strict=True)), constraints=cons,
                   options={"maxiter": 500, "ftol": 1e-14})
    return np.clip(np.asarray(out.x, dtype=float), qp.lo, qp.hi)


def _multipliers(qp: ConvexQP, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """lambda >= 0 on the active rows and nu, fitted to stationarity together with
    the multipliers of the active bounds (dropped after: the certificate's minimum
    over the box stands for them)."""
    grad = qp.P @ x + qp.c
    n = len(x)
    active = np.flatnonzero(qp.b - qp.A @ x <= ACTIVE) if len(qp.b) else np.zeros(0, int)
    at_lo = np.flatnonzero(x <= qp.lo + ACTIVE)
    at_hi = np.flatnonzero(x >= qp.hi - ACTIVE)
    lam, nu = np.zeros(len(qp.b)), np.zeros(len(qp.f))
    M = np.hstack([qp.A[active].T, qp.E.T, -qp.E.T, -np.eye(n)[:, at_lo], np.eye(n)[:, at_hi]])
    if M.shape[1] == 0:
        return lam, nu
    z, _ = nnls(M, -grad, maxiter=50 * M.shape[1])
    p = len(qp.f)
    lam[active] = z[:len(active)]
    nu = z[len(active):len(active) + p] - z[len(active) + p:len(active) + 2 * p]
    return lam, nu


def _box_min(g: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> float:
    """min over lo <= y <= hi of g'y."""
    return float(np.sum(np.minimum(g * lo, g * hi)))


def lagrangian_bound(qp: ConvexQP, x, lam, nu) -> float:
    """L(x) + min over the box of grad L(x)'(y - x): a lower bound on f over the
    feasible set for any x and any lam >= 0 (L is convex)."""
    lam = np.maximum(lam, 0.0)
    residual_a, residual_e = qp.A @ x - qp.b, qp.E @ x - qp.f
    lagrangian = qp.value(x) + lam @ residual_a + nu @ residual_e
    g = qp.P @ x + qp.c + qp.A.T @ lam + qp.E.T @ nu
    bound = lagrangian + _box_min(g, qp.lo, qp.hi) - float(g @ x)
    return bound - SAFETY * (1.0 + abs(bound))


def infeasibility_certificate(qp: ConvexQP) -> bool:
    """A Farkas certificate from an LP, re-checked in numpy: lam >= 0, nu with
    min over the box of (A'lam + E'nu)'y - b'lam - f'nu > 0."""
    m, p, n = len(qp.b), len(qp.f), len(qp.c)
    if m + p == 0:
        return False
    # Variables: lam (m), nu+ (p), nu- (p), t (n); maximize sum t - b'lam - f'nu with
    # t_i <= g_i lo_i, t_i <= g_i hi_i (g = A'lam + E'nu) and sum lam + nu+ + nu- <= 1.
    G = np.hstack([qp.A.T, qp.E.T, -qp.E.T])
    cost = -np.concatenate([-qp.b, -qp.f, qp.f, np.ones(n)])
    rows = [np.hstack([-G * bound[:, None], np.eye(n)]) for bound in (qp.lo, qp.hi)]
    norm = np.concatenate([np.ones(m + 2 * p), np.zeros(n)])[None, :]
    out = linprog(cost, A_ub=np.vstack([*rows, norm]),
                  b_ub=np.concatenate([np.zeros(2 * n), [1.0]]),
                  bounds=[(0, None)] * (m + 2 * p) + [(None, None)] * n, method="highs")
    if out.status != 0:
        return False
    lam = np.maximum(out.x[:m], 0.0)
    nu = out.x[m:m + p] - out.x[m + p:m + 2 * p]
    g = qp.A.T @ lam + qp.E.T @ nu
    margin = _box_min(g, qp.lo, qp.hi) - lam @ qp.b - nu @ qp.f
    scale = 1.0 + float(np.abs(lam) @ np.abs(qp.b) + np.abs(nu) @ np.abs(qp.f))
    return margin > SAFETY * scale
