"""One SLSQP solve with exact Jacobians, a wall-time cap and stall detection.

The NLP is given as `evaluate(x) -> Rows` (cost, its gradient, equality and
inequality rows); one evaluation serves the objective and both constraint
calls SLSQP makes at the same x.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize

from tampcli.optimize.kkt import certificate
from tampcli.optimize.nlp_space import space_of
from tampcli.solution_kkt import KktCertificate

FEASIBILITY = 1e-4  # m or rad: max violation still called feasible
STALL_ITERATIONS = 25  # stop when the best point has not improved for this many iterations
# ... or for this many evaluations: SLSQP's line search on collision rows that are only
# piecewise smooth can take 6-20 evaluations an iteration and get nowhere (arm-sort #13:
# 26 iterations, 170 evaluations, 1.4 s, no better than its start), where a solve that
# progresses takes 1-1.5 an iteration.
STALL_EVALUATIONS = 75
STALL_PENALTY = 100.0  # weight of the violation (m, rad) against the cost (rad^2) in the merit
STALL_GAIN = 1e-4  # relative improvement of the merit that counts as progress
RESTART_VIOLATION = 1e-2  # m or rad: a point this close to feasible is worth a restart
RESTART_GAIN = 0.05  # relative cost saving below the best feasible point that is worth one


@dataclass(frozen=True)
class NlpOutcome:
    x: np.ndarray
    status: str  # "solved" | "infeasible" | "limit"
    cost: float
    violation: float
    worst: str | None  # the worst violated row, in words
    iterations: int
    kkt: KktCertificate | None  # optimize/kkt.py, at a solved answer
    message: str
    stopped: str | None = None  # "time" | "iterations" | "stall" when SLSQP did not finish


class _Stop(Exception):
    pass


class _Evaluator:
    def __init__(self, evaluate, layout):
        self.evaluate = evaluate
        self.slices = layout.slices()
        self.nx = layout.size
        self._x = None
        self._out = None
        self.calls = 0
        self.cost_hess: dict = {}  # the last rows' (Rows.cost_hess)

    def __call__(self, x):
        if self._x is not None and np.array_equal(x, self._x):
            return self._out
        self.calls += 1
        rows = self.evaluate(x)
        self.cost_hess = rows.cost_hess
        grad = np.zeros(self.nx)
        for block, g in rows.cost_grad.items():
            s = self.slices.get(block)
            if s is not None:
                grad[s] += g
        eq, jeq = rows.eq.assemble(self.slices, self.nx)
        ineq, jin = rows.ineq.assemble(self.slices, self.nx)
        self._x = np.array(x, copy=True)
        self._out = (rows.cost, grad, eq, jeq, ineq, jin, rows.eq.labels, rows.ineq.labels)
        return self._out


def violation_of(eq, ineq) -> tuple[float, int, str]:
    """(max violation, index, "eq"/"ineq")."""
    ve = np.abs(eq) if len(eq) else np.zeros(0)
    vi = np.maximum(-ineq, 0.0) if len(ineq) else np.zeros(0)
    best = (0.0, -1, "")
    if len(ve) and ve.max() > best[0]:
        best = (float(ve.max()), int(ve.argmax()), "eq")
    if len(vi) and vi.max() > best[0]:
        best = (float(vi.max()), int(vi.argmax()), "ineq")
    return best


def violation_at(evaluate, layout, x) -> float:
    """The largest constraint violation of the NLP at x (m or rad)."""
    eq, ineq = (_Evaluator(evaluate, layout)(x)[i] for i in (2, 4))
    return violation_of(eq, ineq)[0]


def outcome_of(evaluate, layout, x, bounds, message: str) -> NlpOutcome:
    """The NlpOutcome of a point found without SLSQP (no iterations)."""
    return outcome_at(_Evaluator(evaluate, layout), np.asarray(x, dtype=float), None, 0,
                      message, bounds)


def nlp_feasible(evaluate, layout, x) -> bool:
    return violation_at(evaluate, layout, x) <= FEASIBILITY


class BestPoint:
    """The best point so far (least violation beyond FEASIBILITY, then least cost)
    and the iteration it last improved at: the stall test of every backend.
    `iterations` is set by the caller (the backend's own count)."""

    def __init__(self, ev: _Evaluator, x0: np.ndarray):
        self.ev = ev
        self.x = x0.copy()
        self.key = (np.inf, np.inf)
        self.merit = np.inf
        self.merit_x = x0.copy()
        self.merit_violation = np.inf
        self.progress = 0
        self.progress_calls = 0  # ev.calls when the best point last improved
        self.iterations = 0

    def track(self, x) -> None:
        cost, _, eq, _, ineq, _, _, _ = self.ev(x)
        v = violation_of(eq, ineq)[0]
        key = (max(v - FEASIBILITY, 0.0), cost)
        if key < self.key:
            bv, bc = self.key
            if key[0] < 0.99 * bv or (key[0] == 0 and (bv > 0 or key[1] < bc - 1e-6 * (1 + abs(bc)))):
                self.improved()
            self.x, self.key = np.array(x, copy=True), key
        # Iterates often approach a much cheaper optimum slightly outside the
        # feasibility tolerance (measured on arm-kitchen's keyframes: cost 0.33 at
        # violations of 1e-4..1e-3 while the best feasible point costs 1.3); a
        # falling merit is progress too, so the stall test does not cut them off.
        merit = cost + STALL_PENALTY * max(v - FEASIBILITY, 0.0)
        if not np.isfinite(self.merit) or \
                merit < self.merit - STALL_GAIN * (1.0 + abs(self.merit)):
            self.merit = merit
            self.merit_x, self.merit_violation = np.array(x, copy=True), v
            self.improved()

    def improved(self) -> None:
        self.progress, self.progress_calls = self.iterations, self.ev.calls

    @property
    def stalled(self) -> bool:
        return (self.iterations - self.progress > STALL_ITERATIONS
                or self.ev.calls - self.progress_calls > STALL_EVALUATIONS)


def outcome_at(ev: _Evaluator, x, reason, iterations: int, message: str, bounds) -> NlpOutcome:
    """The NlpOutcome of a backend's answer x: solved within FEASIBILITY (with its KKT
    certificate), else the worst row in words."""
    cost, grad, eq, jeq, ineq, jin, leq, lin = ev(x)
    v, i, kind = violation_of(eq, ineq)
    if v <= FEASIBILITY:
        status, worst = "solved", None
    else:
        status = "limit" if reason in ("time", "iterations") else "infeasible"
        value = eq[i] if kind == "eq" else ineq[i]
        worst = (leq if kind == "eq" else lin)[i].words(value)
    kkt = certificate(grad, eq, jeq, ineq, jin, leq, lin, x, bounds, ev.slices) \
        if status == "solved" else None
    return NlpOutcome(x, status, float(cost), v, worst, iterations, kkt, message, reason)


def solve_nlp(evaluate, layout, x0, bounds, max_iterations: int, deadline: float,
              ftol: float = 1e-6) -> NlpOutcome:
    ev = _Evaluator(evaluate, layout)
    lower, upper = [b[0] for b in bounds], [b[1] for b in bounds]
    x0 = np.clip(np.asarray(x0, dtype=float), lower, upper)
    best = BestPoint(ev, x0)
    _, _, eq0, _, ineq0, _, _, _ = ev(x0)
    space = space_of(ev, bounds)
    args = space.minimize_args(ev, bounds, len(eq0) > 0, len(ineq0) > 0)

    def callback(yk):
        best.track(space.to_x(yk))
        best.iterations += 1
        if time.perf_counter() > deadline:
            raise _Stop("time")
        # SLSQP can wander (collision rows are only piecewise smooth): stop when the
        # best point (least violation, then least cost) has not really improved for
        # a while. An infeasible skeleton is found out this way, not at the cap.
        if best.stalled:
            raise _Stop("stall")

    best.track(x0)

    def run(start, cap):
        """(reason or None, message) of one SLSQP run from `start`."""
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                res = minimize(x0=space.to_y(start), method="SLSQP", callback=callback,
                               options={"maxiter": cap, "ftol": ftol}, **args)
        except _Stop as stop:
            return str(stop), f"stopped: {stop}"
        best.track(space.to_x(res.x))
        return ("iterations" if res.status == 9 else None), str(res.message)

    reason, message = run(x0, max_iterations)
    # From its own start SLSQP would only repeat the same iterations (arm-sort: 26 of
    # them, three times per search).
    if reason != "time" and _worth_restart(best) and best.iterations < max_iterations \
            and not np.array_equal(best.merit_x, x0):
        # SLSQP can creep along a cheap valley just outside the feasible set (arm-kitchen
        # keyframes: cost 0.31 at a 0.1 degree tilt for 25 iterations, while the best
        # feasible point cost 1.30); a fresh start there, with a fresh quasi-Newton
        # Hessian, usually steps onto it.
        best.improved()
        reason, message = run(best.merit_x, max(max_iterations - best.iterations,
                                                2 * STALL_ITERATIONS))
    # Whitened, the bounds are rows SLSQP meets within its tolerance: the answer is
    # put back inside them (a last step of at most that tolerance).
    x = np.clip(best.x, lower, upper)
    return outcome_at(ev, x, reason, best.iterations, message, bounds)


def _worth_restart(best: BestPoint) -> bool:
    """Whether the merit's best point is nearly feasible and clearly cheaper than the
    best feasible point."""
    v = best.merit_violation
    if not FEASIBILITY < v <= RESTART_VIOLATION:
        return False
    cost = best.merit - STALL_PENALTY * (v - FEASIBILITY)
    violation, best_cost = best.key
    return violation > 0 or cost < best_cost - RESTART_GAIN * (1.0 + abs(best_cost))
