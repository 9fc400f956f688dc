"""SLSQP on whitened variables (nlp_space.py): the change of variables, its
derivatives against finite differences, the same optimum inside the bounds, and
fewer iterations on a path-like NLP."""

import time

import numpy as np
import pytest

from tampcli.optimize.expr import Label
from tampcli.optimize.layout import Layout, waypoint_block
from tampcli.optimize.nlp import _Evaluator, solve_nlp
from tampcli.optimize.nlp_space import PlainSpace, WhitenedSpace, dense_hessian, space_of
from tampcli.optimize.path import smoothness_hessian
from tampcli.optimize.stages import Rows

T, N = 10, 2
Q_A, Q_B = np.array([0.0, 0.0]), np.array([1.0, 0.0])
CENTRE, RADIUS = np.array([0.5, -0.05]), 0.2


def path_nlp(hessian: bool):
    """A point's path from Q_A to Q_B on T segments, cost sum |dq|^2 (path.py's), each
    waypoint outside a disk across the straight line; the cost's Hessian given or not."""
    names = [waypoint_block(i) for i in range(1, T)]
    layout = Layout(tuple((name, N) for name in names))
    hess = smoothness_hessian(T, N)

    def evaluate(x):
        w = x.reshape(T - 1, N)
        qs = np.vstack([Q_A, w, Q_B])
        d = np.diff(qs, axis=0)
        rows = Rows()
        rows.cost = float(np.sum(d * d))
        for i, name in enumerate(names, start=1):
            rows.cost_grad[name] = 2.0 * (d[i - 1] - d[i])
            rel = w[i - 1] - CENTRE
            rows.ineq.add(np.array([rel @ rel - RADIUS ** 2]), {name: 2.0 * rel[None, :]},
                          Label("path", "disk", "m^2"))
        if hessian:
            rows.cost_hess = hess
        return rows

    return evaluate, layout


def _detour():
    """A start well clear of the disk: up and over it."""
    s = np.arange(1, T) / T
    return np.column_stack([s, 0.6 * np.sin(np.pi * s)]).reshape(-1)


BOUNDS = [(-2.0, 2.0)] * ((T - 1) * N)


def test_whitened_variables_make_the_cost_hessian_the_identity():
    evaluate, layout = path_nlp(True)
    ev = _Evaluator(evaluate, layout)
    ev(_detour())
    H = dense_hessian(ev.cost_hess, ev.slices, ev.nx)
    space = space_of(ev, BOUNDS)
    assert isinstance(space, WhitenedSpace)
    np.testing.assert_allclose(space.M.T @ H @ space.M, np.eye(ev.nx), atol=1e-10)
    x = np.random.default_rng(0).normal(size=ev.nx)
    np.testing.assert_allclose(space.to_x(space.to_y(x)), x, atol=1e-12)
    ev_plain = _Evaluator(path_nlp(False)[0], layout)
    ev_plain(_detour())
    assert isinstance(space_of(ev_plain, BOUNDS), PlainSpace)


def test_the_whitened_functions_match_finite_differences():
    evaluate, layout = path_nlp(True)
    ev = _Evaluator(evaluate, layout)
    ev(_detour())
    space = space_of(ev, [(-0.3, 2.0)] * ((T - 1) * N))
    args = space.minimize_args(ev, BOUNDS, False, True)
    y0 = space.to_y(_detour()) + np.random.default_rng(1).normal(scale=0.01, size=ev.nx)
    h = 1e-6

    def fd(fun):
        return np.array([(np.atleast_1d(fun(y0 + h * e)) - np.atleast_1d(fun(y0 - h * e)))
                         / (2 * h) for e in np.eye(len(y0))]).T

    np.testing.assert_allclose(args["jac"](y0), fd(args["fun"])[0], rtol=1e-5, atol=1e-7)
    (ineq,) = args["constraints"]
    J = ineq["jac"](y0)
    assert J.shape == (T - 1 + 2 * ev.nx, ev.nx)  # the disk rows, then the bound rows
    np.testing.assert_allclose(J, fd(ineq["fun"]), rtol=1e-5, atol=1e-7)


def _solve(hessian: bool, bounds=BOUNDS):
    evaluate, layout = path_nlp(hessian)
    return solve_nlp(evaluate, layout, _detour(), bounds, 200, time.perf_counter() + 60,
                     ftol=1e-9)


def test_a_whitened_solve_reaches_the_plain_optimum_in_fewer_iterations():
    plain, whitened = _solve(False), _solve(True)
    assert plain.status == whitened.status == "solved"
    assert whitened.cost == pytest.approx(plain.cost, rel=1e-4)
    np.testing.assert_allclose(whitened.x, plain.x, atol=1e-3)
    assert whitened.kkt is not None and whitened.kkt.stationarity < 1e-4
    assert whitened.iterations < 0.7 * plain.iterations, (whitened.iterations,
                                                          plain.iterations)


def test_a_whitened_solve_keeps_to_the_bounds():
    """With x at most 0.85 the last waypoint cannot sit where it would (0.9): the bound
    is active at the optimum, and the answer is inside it."""
    bounds = [(-2.0, 0.85), (-2.0, 2.0)] * (T - 1)
    plain, whitened = _solve(False, bounds), _solve(True, bounds)
    assert plain.status == whitened.status == "solved"
    lo, hi = np.array(bounds).T
    assert np.all(whitened.x >= lo) and np.all(whitened.x <= hi)
    assert np.max(whitened.x[0::2]) == pytest.approx(0.85, abs=1e-6)
    assert whitened.cost == pytest.approx(plain.cost, rel=1e-4)
    np.testing.assert_allclose(whitened.x, plain.x, atol=1e-3)
