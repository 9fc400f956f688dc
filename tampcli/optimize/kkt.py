"""The KKT certificate at an NLP's answer (the lesson's Problem 3).

The NLP: min f(x) s.t. c(x) = 0, g(x) >= 0, lo <= x <= hi. At a KKT point
there are lambda (any sign) and mu >= 0 on the active rows with

    grad f = J_c^T lambda + J_act^T mu,

the active rows being the inequalities and bounds within ACTIVE of their
limit (a bound lo <= x_j is the row x_j - lo >= 0, so its gradient is e_j;
x_j <= hi is hi - x_j >= 0, gradient -e_j). The multipliers are fitted by
least squares twice: with mu >= 0 (scipy's bounded least squares, BVLS) and
with mu free. The signed fit's residual is the certificate's stationarity;
when the free fit does markedly better (the signed residual more than twice
the free one, and more than a small slack), only multipliers of the wrong
sign explain the gradient: dual feasibility fails, and the free fit's
multipliers are the ones reported (its least mu is negative). Short of
convergence both fits leave a residual, and a negative multiplier that only
trims it is noise, not a wrong sign (measured on arm-sort p01's NLPs: signed
residuals 1.0 to 1.5 times the free ones; arm-hanoi p01 has one motion whose
finger rows against a disk need mu = -0.38: 5.6e-3 signed, 7.5e-4 free).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import lsq_linear

from tampcli.solution_kkt import ActiveConstraint, KktCertificate

ACTIVE = 1e-4  # m or rad: an inequality or bound this near its limit is active
# The signed fit may leave twice the free fit's residual and this much more (relative
# to 1 + |grad f|) and still count as dual feasible (see the module docstring).
DUAL_SLACK = 1e-4


def certificate(grad, eq, jeq, ineq, jin, eq_labels, ineq_labels, x, bounds,
                blocks: dict[str, slice]) -> KktCertificate:
    """The certificate at x. `eq_labels`, `ineq_labels`: each row's expr.Label;
    `blocks`: the layout's block name -> slice of x (names a bound's variable)."""
    grad = np.asarray(grad, dtype=float)
    x = np.asarray(x, dtype=float)
    lo = np.array([b[0] for b in bounds], dtype=float)
    hi = np.array([b[1] for b in bounds], dtype=float)
    columns, slacks, names, kinds = [], [], [], []
    for i in range(len(eq)):
        columns.append(jeq[i])
        slacks.append(float(eq[i]))
        names.append(_name(eq_labels[i]))
        kinds.append("eq")
    for i in np.flatnonzero(np.asarray(ineq) <= ACTIVE):
        columns.append(jin[i])
        slacks.append(float(ineq[i]))
        names.append(_name(ineq_labels[i]))
        kinds.append("ineq")
    for side, sign, slack in (("lower", 1.0, x - lo), ("upper", -1.0, hi - x)):
        for j in np.flatnonzero(slack <= ACTIVE):
            e = np.zeros(len(x))
            e[j] = sign
            columns.append(e)
            slacks.append(float(slack[j]))
            names.append(f"{_block_of(j, blocks)} at its {side} bound")
            kinds.append("bound")
    violation = max([abs(s) for s, k in zip(slacks, kinds, strict=True) if k == "eq"]
                    + [max(-s, 0.0) for s, k in zip(slacks, kinds, strict=True) if k != "eq"]
                    + [0.0])
    norm = float(np.linalg.norm(grad))
    if not columns:
        return KktCertificate(norm, norm, norm, violation, 0.0, None, True)
    A = np.array(columns).T
    signed = np.array([k != "eq" for k in kinds])
    y_free, r_free = _fit(A, grad, None)
    y_sign, r_sign = _fit(A, grad, signed)
    dual = r_sign <= 2.0 * r_free + DUAL_SLACK * (1.0 + norm)
    y = y_sign if dual else y_free
    slack = np.array(slacks)
    least = float(y[signed].min()) if signed.any() else None
    complementarity = float(np.max(np.abs(y[signed] * slack[signed]))) if signed.any() else 0.0
    return KktCertificate(r_sign, r_free, norm, violation, complementarity, least, bool(dual),
                          active=_grouped(names, kinds, y))


def _fit(A: np.ndarray, b: np.ndarray, signed: np.ndarray | None) -> tuple[np.ndarray, float]:
    """Least-squares y of A y = b (with y >= 0 where `signed`), and |A y - b|."""
    if signed is None or not signed.any():
        y = np.linalg.lstsq(A, b, rcond=None)[0]
    else:
        lower = np.where(signed, 0.0, -np.inf)
        y = lsq_linear(A, b, bounds=(lower, np.full(len(lower), np.inf)), method="bvls").x
    return y, float(np.linalg.norm(A @ y - b))


def _name(label) -> str:
    return f"{label.step}: {label.what}"


def _block_of(j: int, blocks: dict[str, slice]) -> str:
    for name, s in blocks.items():
        if s.start <= j < s.stop:
            return name if s.stop - s.start == 1 else f"{name}[{j - s.start}]"
    return f"x[{j}]"


def _grouped(names, kinds, y) -> tuple[ActiveConstraint, ...]:
    """One entry per name, kind and, for an inequality or bound, sign of the multiplier
    (a row of the wrong sign is not hidden among its namesakes): its row count and
    its largest multiplier."""
    groups: dict[tuple[str, str, bool], tuple[int, float]] = {}
    for name, kind, value in zip(names, kinds, y, strict=True):
        key = (name, kind, _wrong(kind, value))
        rows, best = groups.get(key, (0, 0.0))
        groups[key] = (rows + 1, float(value) if abs(value) > abs(best) else best)
    return _ordered(ActiveConstraint(name, kind, rows, best)
                    for (name, kind, _), (rows, best) in groups.items())


def _wrong(kind: str, multiplier: float) -> bool:
    return kind != "eq" and bool(multiplier < 0)


def _ordered(active) -> tuple[ActiveConstraint, ...]:
    return tuple(sorted(active, key=lambda a: (-abs(a.multiplier), a.name)))


def combined(certificates) -> KktCertificate | None:
    """One certificate for NLPs solved apart (a path stage's motions): the worst of
    each measure, and every active constraint (same names merged)."""
    found = [c for c in certificates if c is not None]
    if not found:
        return None
    mins = [c.min_multiplier for c in found if c.min_multiplier is not None]
    groups: dict[tuple[str, str, bool], ActiveConstraint] = {}
    for c in found:
        for a in c.active:
            key = (a.name, a.kind, _wrong(a.kind, a.multiplier))
            old = groups.get(key)
            if old is not None:
                a = ActiveConstraint(a.name, a.kind, old.rows + a.rows,
                                     max(old.multiplier, a.multiplier, key=abs))
            groups[key] = a
    return KktCertificate(
        max(c.stationarity for c in found), max(c.free_stationarity for c in found),
        max(c.gradient for c in found), max(c.violation for c in found),
        max(c.complementarity for c in found), min(mins) if mins else None,
        all(c.dual_feasible for c in found), sum(c.nlps for c in found),
        _ordered(groups.values()))
