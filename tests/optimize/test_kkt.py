"""The KKT certificate (optimize/kkt.py) on NLPs small enough to solve by hand:
min x^2 + y^2 under one linear row, whose multiplier is known."""

import math
import time

import numpy as np
import pytest

from tampcli.optimize.expr import Label
from tampcli.optimize.kkt import certificate, combined
from tampcli.optimize.layout import Layout
from tampcli.optimize.nlp import solve_nlp
from tampcli.optimize.stages import Rows
from tampcli.solution_kkt import ActiveConstraint, KktCertificate

BLOCKS = {"x": slice(0, 1), "y": slice(1, 2)}
FREE = [(-10.0, 10.0)] * 2
ROW = Label("(toy)", "x + y against 1")


def _sq(p):
    """f = x^2 + y^2 and its gradient."""
    return float(p @ p), 2.0 * p


def _cert(p, a, b, kind="ineq", bounds=FREE, f=_sq):
    """The certificate at p of min f s.t. a.p + b (>= or =) 0."""
    p = np.asarray(p, dtype=float)
    _, grad = f(p)
    row, jac = np.array([a @ p + b]), np.array([a], dtype=float)
    none, empty = np.zeros(0), np.zeros((0, 2))
    if kind == "eq":
        return certificate(grad, row, jac, none, empty, [ROW], [], p, bounds, BLOCKS)
    return certificate(grad, none, empty, row, jac, [], [ROW], p, bounds, BLOCKS)


def test_the_gradient_of_the_toy_cost_is_its_finite_difference():
    p, h = np.array([0.3, -0.7]), 1e-6
    fd = [(_sq(p + h * e)[0] - _sq(p - h * e)[0]) / (2 * h) for e in np.eye(2)]
    assert _sq(p)[1] == pytest.approx(fd, abs=1e-8)


def test_an_active_inequality_carries_the_gradient_with_mu_one():
    """min x^2 + y^2 s.t. x + y >= 1: at (1/2, 1/2), grad f = (1, 1) = 1 * (1, 1)."""
    c = _cert([0.5, 0.5], np.array([1.0, 1.0]), -1.0)
    assert c.stationarity == pytest.approx(0.0, abs=1e-12)
    assert c.dual_feasible and c.min_multiplier == pytest.approx(1.0)
    assert c.gradient == pytest.approx(math.sqrt(2))
    assert c.violation == 0.0 and c.complementarity == pytest.approx(0.0, abs=1e-12)
    assert c.active == (ActiveConstraint("(toy): x + y against 1", "ineq", 1, pytest.approx(1.0)),)


def test_an_inactive_inequality_has_no_multiplier():
    """x + y >= -1 at the unconstrained minimum (0, 0): slack 1, not active, mu = 0."""
    c = _cert([0.0, 0.0], np.array([1.0, 1.0]), 1.0)
    assert c.active == () and c.min_multiplier is None
    assert c.stationarity == 0.0 and c.dual_feasible


def test_a_point_held_by_a_wrong_signed_multiplier_is_not_dual_feasible():
    """x + y <= 1 (1 - x - y >= 0) at (1/2, 1/2): grad f = (1, 1) = -1 * (-1, -1). Only
    mu = -1 explains it; with mu >= 0 the residual is all of |grad f|."""
    c = _cert([0.5, 0.5], np.array([-1.0, -1.0]), 1.0)
    assert not c.dual_feasible
    assert c.free_stationarity == pytest.approx(0.0, abs=1e-12)
    assert c.stationarity == pytest.approx(math.sqrt(2))
    assert c.min_multiplier == pytest.approx(-1.0)
    assert c.active[0].multiplier == pytest.approx(-1.0)


def test_an_equality_multiplier_has_either_sign():
    """x + y = 1 at (1/2, 1/2): lambda = 1; written as 1 - x - y = 0: lambda = -1, and
    neither is a failure of dual feasibility."""
    for a, b, lam in ((np.array([1.0, 1.0]), -1.0, 1.0), (np.array([-1.0, -1.0]), 1.0, -1.0)):
        c = _cert([0.5, 0.5], a, b, kind="eq")
        assert c.dual_feasible and c.stationarity == pytest.approx(0.0, abs=1e-12)
        assert c.min_multiplier is None
        assert c.active == (ActiveConstraint("(toy): x + y against 1", "eq", 1,
                                             pytest.approx(lam)),)


def test_an_active_bound_is_named_by_its_block_and_has_its_multiplier():
    """min (x - 2)^2 + y^2 with x <= 1: at (1, 0) grad f = (-2, 0) = 2 * (-1, 0)."""
    def f(p):
        d = p - np.array([2.0, 0.0])
        return float(d @ d), 2.0 * d

    c = _cert([1.0, 0.0], np.array([0.0, 1.0]), 5.0, bounds=[(-10.0, 1.0), (-10.0, 10.0)], f=f)
    assert c.stationarity == pytest.approx(0.0, abs=1e-12) and c.dual_feasible
    assert c.active == (ActiveConstraint("x at its upper bound", "bound", 1, pytest.approx(2.0)),)
    wide = certificate(np.zeros(4), np.zeros(0), np.zeros((0, 4)), np.zeros(0),
                       np.zeros((0, 4)), [], [], np.array([0.0, 0.0, -1.0, 0.0]),
                       [(-1.0, 1.0)] * 4, {"k0": slice(0, 2), "k1": slice(2, 4)})
    assert [a.name for a in wide.active] == ["k1[0] at its lower bound"]


def test_dependent_rows_with_a_nonnegative_fit_are_dual_feasible():
    """Rows x >= 0, 2x >= 0, -x >= 0 active at 0 with grad f = (1, 0): the least-norm
    free fit is (1, 2, -1) / 6, negative in one place, but mu = (1, 0, 0) fits exactly."""
    grad = np.array([1.0, 0.0])
    jin = np.array([[1.0, 0.0], [2.0, 0.0], [-1.0, 0.0]])
    labels = [Label("(toy)", w) for w in ("x", "2x", "-x")]
    c = certificate(grad, np.zeros(0), np.zeros((0, 2)), np.zeros(3), jin, [], labels,
                    np.zeros(2), FREE, BLOCKS)
    assert c.dual_feasible and c.stationarity == pytest.approx(0.0, abs=1e-9)
    assert c.min_multiplier >= 0.0


def _two_rows(grad, jin):
    """Two active inequality rows of one name at the origin."""
    return certificate(np.asarray(grad, dtype=float), np.zeros(0), np.zeros((0, 2)),
                       np.zeros(2), np.asarray(jin, dtype=float), [], [ROW, ROW], np.zeros(2),
                       FREE, BLOCKS)


def test_a_negative_multiplier_that_only_trims_the_residual_is_not_a_wrong_sign():
    """grad f = (1, 0.1), one active row (0, -1): mu = -0.1 takes the residual from
    1.005 to 1; short of convergence that is noise, and mu >= 0 is reported."""
    c = certificate(np.array([1.0, 0.1]), np.zeros(0), np.zeros((0, 2)), np.zeros(1),
                    np.array([[0.0, -1.0]]), [], [ROW], np.zeros(2), FREE, BLOCKS)
    assert c.free_stationarity == pytest.approx(1.0)
    assert c.stationarity == pytest.approx(math.hypot(1.0, 0.1))
    assert c.dual_feasible and c.min_multiplier == 0.0


def test_a_wrong_signed_row_is_not_hidden_among_its_namesakes():
    """grad f = (1, 1) from rows (1, 0) and (0, -1) of one name: mu = (1, -1). The
    two multipliers are reported apart, so the one of the wrong sign shows."""
    c = _two_rows([1.0, 1.0], [[1.0, 0.0], [0.0, -1.0]])
    assert not c.dual_feasible and c.min_multiplier == pytest.approx(-1.0)
    assert c.stationarity == pytest.approx(1.0)
    assert sorted(a.multiplier for a in c.active) == pytest.approx([-1.0, 1.0])
    assert {a.name for a in c.active} == {"(toy): x + y against 1"}
    same = _two_rows([1.0, 1.0], [[1.0, 0.0], [0.0, 1.0]])
    assert same.active == (ActiveConstraint("(toy): x + y against 1", "ineq", 2,
                                            pytest.approx(1.0)),)
    # Equality multipliers have no wrong sign: one group whatever their signs.
    eq = certificate(np.array([1.0, 1.0]), np.zeros(2), np.array([[1.0, 0.0], [0.0, -1.0]]),
                     np.zeros(0), np.zeros((0, 2)), [ROW, ROW], [], np.zeros(2), FREE, BLOCKS)
    assert eq.dual_feasible and len(eq.active) == 1 and eq.active[0].rows == 2


def _toy(x):
    """min x^2 + y^2 s.t. x + y >= 1 (active) and x - y >= -5 (inactive), as the
    stages write their rows."""
    rows = Rows()
    rows.cost, g = _sq(np.asarray(x))
    rows.cost_grad = {"x": g[:1], "y": g[1:]}
    rows.ineq.add(np.array([x[0] + x[1] - 1.0]), {"x": np.ones((1, 1)), "y": np.ones((1, 1))},
                  ROW)
    rows.ineq.add(np.array([x[0] - x[1] + 5.0]), {"x": np.ones((1, 1)), "y": -np.ones((1, 1))},
                  Label("(toy)", "x - y against -5"))
    return rows


def test_solve_nlp_returns_the_certificate_of_its_answer():
    layout = Layout((("x", 1), ("y", 1)))
    out = solve_nlp(_toy, layout, np.array([2.0, -1.0]), FREE, 100, time.perf_counter() + 30)
    assert out.status == "solved"
    assert out.x == pytest.approx([0.5, 0.5], abs=1e-5)
    c = out.kkt
    assert c.stationarity < 1e-4 and c.dual_feasible
    assert c.min_multiplier == pytest.approx(1.0, abs=1e-4)
    assert [a.name for a in c.active] == ["(toy): x + y against 1"]


def test_certificates_combine_to_the_worst_of_each_measure():
    a = KktCertificate(1e-6, 1e-6, 1.0, 0.0, 1e-9, 0.5, True, 1,
                       (ActiveConstraint("m0: collision a vs b", "ineq", 2, 0.5),))
    b = KktCertificate(1e-3, 1e-5, 2.0, 1e-5, 0.0, -0.2, False, 1,
                       (ActiveConstraint("m0: collision a vs b", "ineq", 1, -0.7),
                        ActiveConstraint("m1: upright", "eq", 1, 0.1)))
    c = combined([a, None, b])
    assert (c.stationarity, c.free_stationarity, c.gradient, c.violation) == (1e-3, 1e-5, 2.0,
                                                                               1e-5)
    assert c.complementarity == 1e-9 and c.min_multiplier == -0.2
    assert not c.dual_feasible and c.nlps == 2
    assert c.active == (ActiveConstraint("m0: collision a vs b", "ineq", 1, -0.7),
                        ActiveConstraint("m0: collision a vs b", "ineq", 2, 0.5),
                        ActiveConstraint("m1: upright", "eq", 1, 0.1))
    again = combined([a, a])
    assert again.active == (ActiveConstraint("m0: collision a vs b", "ineq", 4, 0.5),)
    assert combined([None]) is None

