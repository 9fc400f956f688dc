"""One Ipopt solve (through cyipopt) of the NLP that nlp.py hands SLSQP.

The same `evaluate(x) -> Rows` over the same layout and bounds, the same exact
Jacobians (handed over sparse: `_Callbacks`), the same wall-clock deadline and
stall test, and the same NlpOutcome: a solve is judged by its best point, at
FEASIBILITY, whichever solver found it. Its `kkt` is the certificate of
optimize/kkt.py at that point, as for SLSQP's answers.

Curvature: the cost's Hessian where the rows give it (Rows.cost_hess: the path
NLP's smoothness term) and none of the rows' (a collision distance has none we
can compute), so Ipopt steps as an SQP over the cost's curvature and the rows'
linearization; without a cost Hessian it builds a limited-memory quasi-Newton
one. Measured on arm-pick-place p02's path NLPs at T = 20: 100 evaluations with
the cost Hessian, 469 with the quasi-Newton one (SLSQP: 193).

cyipopt is an optional extra (`pip install 'tampcli[ipopt]'`): it is imported
when a solve asks for it, and `missing()` says what to install when it is not.
"""

from __future__ import annotations

import time

import numpy as np

from tampcli.optimize.nlp import (
    FEASIBILITY,
    BestPoint,
    NlpOutcome,
    _Evaluator,
    outcome_at,
    violation_of,
)
from tampcli.optimize.nlp_space import dense_hessian

INSTALL = "pip install 'tampcli[ipopt]'"
INFINITE = 2e19  # beyond Ipopt's nlp_upper_bound_inf (1e19): no bound
# Ipopt's return codes (ApplicationReturnStatus) that mean it stopped at a cap.
CAPS = {-1: "iterations", -4: "time", -5: "time"}  # iterations, CPU time, wall time
CONVERGED = (0, 1)  # Solve_Succeeded, Solved_To_Acceptable_Level
USER_STOP = 5  # the intermediate callback said stop (deadline or stall)
OPTIONS = {
    # Silent: no banner (sb), no iteration log.
    "print_level": 0,
    "sb": "yes",
    "mu_strategy": "adaptive",
    # Scaled KKT error; the rows are judged by the absolute tests below. Costs came out
    # as SLSQP's to 1e-4 rad^2 at 1e-4, in a quarter fewer iterations than at 1e-6.
    "tol": 1e-4,
    # Ipopt's absolute violation tests, a tenth of what the outcome is judged at, so
    # a point it calls converged is also feasible by FEASIBILITY.
    "constr_viol_tol": 0.1 * FEASIBILITY,
    "acceptable_constr_viol_tol": 0.1 * FEASIBILITY,
    "acceptable_tol": 1e-4,
}


class MissingIpopt(ImportError):
    """cyipopt is not installed."""


def missing() -> str | None:
    """What to install for Ipopt, or None when cyipopt imports."""
    try:
        import cyipopt  # noqa: F401
    except ImportError:
        return f"the Ipopt backend needs cyipopt: {INSTALL}"
    return None


class _Kept:
    """evaluate(x) that keeps the Rows it last returned."""

    def __init__(self, evaluate):
        self.evaluate = evaluate
        self.rows = None

    def __call__(self, x):
        self.rows = self.evaluate(x)
        return self.rows


class _Callbacks:
    """The problem object cyipopt calls: one cached evaluation per x serves all.

    Sparsity, fixed for the solve: the Jacobian's from the blocks each row
    depends on (RowSet.pattern), the Hessian's from the cost Hessian at the
    start (dense, a path NLP's Jacobian of (T-1) x joints columns took most of
    Ipopt's own time at T = 40). A non-zero outside them is an error in the
    rows, not something to drop: it stops the solve and is raised after it
    (cyipopt does not pass on every exception raised in a callback).
    """

    def __init__(self, ev: _Evaluator, kept: _Kept, best: BestPoint, deadline: float):
        self.ev, self.kept, self.best, self.deadline = ev, kept, best, deadline
        rows = kept.rows
        self.jac_mask = np.vstack([rows.eq.pattern(ev.slices, ev.nx),
                                   rows.ineq.pattern(ev.slices, ev.nx)])
        self.mask = dense_hessian(rows.cost_hess, ev.slices, ev.nx) != 0
        self.structure = np.nonzero(np.tril(self.mask))
        self.problem = None  # the cyipopt.Problem, for its current iterate
        self.stopped: str | None = None
        self.error: Exception | None = None

    def objective(self, x):
        return self.ev(x)[0]

    def gradient(self, x):
        return self.ev(x)[1]

    def constraints(self, x):
        out = self.ev(x)
        return np.concatenate([out[2], out[4]])

    def jacobianstructure(self):
        return np.nonzero(self.jac_mask)

    def jacobian(self, x):
        out = self.ev(x)
        J = np.vstack([out[3], out[5]])
        if np.any(J[~self.jac_mask]):
            self.error = ValueError("a row's Jacobian left the blocks it declared "
                                    "(RowSet.add's depends)")
        return J[self.jac_mask]

    def hessianstructure(self):
        return self.structure

    def hessian(self, x, _multipliers, obj_factor):
        self.ev(x)
        H = dense_hessian(self.kept.rows.cost_hess, self.ev.slices, self.ev.nx)
        if np.any(H[~self.mask]):
            self.error = ValueError("the cost Hessian left the sparsity it had at the start")
        return obj_factor * H[self.structure]

    def intermediate(self, alg_mod, iter_count, *_):
        iterate = self.problem.get_current_iterate()
        self.best.iterations = iter_count
        if iterate is not None:
            self.best.track(iterate["x"])
        if self.error is not None:
            return False
        if time.perf_counter() > self.deadline:
            self.stopped = "time"
        elif self.best.stalled:
            self.stopped = "stall"
        return self.stopped is None


def solve_ipopt(evaluate, layout, x0, bounds, max_iterations: int, deadline: float
                ) -> NlpOutcome:
    """nlp.solve_nlp's contract, solved by Ipopt; raises MissingIpopt without cyipopt."""
    try:
        import cyipopt
    except ImportError as err:
        raise MissingIpopt(missing()) from err
    kept = _Kept(evaluate)
    ev = _Evaluator(kept, layout)
    lo = np.array([b[0] for b in bounds], dtype=float)
    hi = np.array([b[1] for b in bounds], dtype=float)
    x0 = np.clip(np.asarray(x0, dtype=float), lo, hi)
    _, _, eq0, _, ineq0, _, _, _ = ev(x0)
    m_eq, m = len(eq0), len(eq0) + len(ineq0)
    best = BestPoint(ev, x0)
    best.track(x0)
    calls = _Callbacks(ev, kept, best, deadline)
    problem = cyipopt.Problem(
        n=layout.size, m=m, problem_obj=calls,
        lb=np.clip(lo, -INFINITE, INFINITE), ub=np.clip(hi, -INFINITE, INFINITE),
        cl=np.zeros(m), cu=np.where(np.arange(m) < m_eq, 0.0, INFINITE))
    calls.problem = problem
    for key, value in OPTIONS.items():
        problem.add_option(key, value)
    problem.add_option("hessian_approximation", "exact" if calls.mask.any() else "limited-memory")
    problem.add_option("max_iter", int(max_iterations))
    problem.add_option("max_wall_time", max(deadline - time.perf_counter(), 1e-3))
    x, info = problem.solve(x0)
    if calls.error is not None:
        raise calls.error
    status = int(info["status"])
    reason = calls.stopped if status == USER_STOP else CAPS.get(status)
    converged = status in CONVERGED and _violation(ev, x) <= FEASIBILITY
    if converged:
        # Its own point, with its multipliers, over an earlier iterate cheaper only for
        # lying closer to the feasibility limit.
        best.x = np.array(x, copy=True)
    else:
        best.track(x)
    message = info["status_msg"]
    message = message.decode() if isinstance(message, bytes) else str(message)
    return outcome_at(ev, best.x, reason, best.iterations, message, bounds)


def _violation(ev, x) -> float:
    out = ev(x)
    return violation_of(out[2], out[4])[0]
