"""Big-M implications (the lesson's Problem 2): binding only when the binary is 1, and
M large enough that the constraint binds nothing when it is 0."""

import pytest
from pyscipopt import Model

from tampcli.minlp.bigm import implies_close, implies_le, linear_sup


def _solve(switch_value, build):
    model = Model()
    model.hideOutput()
    y = model.addVar("y", vtype="B", lb=switch_value, ub=switch_value)
    x = model.addVar("x", lb=-5.0, ub=5.0)
    z = model.addVar("z", lb=-2.0, ub=3.0)
    build(model, y, x, z)
    model.setObjective(x + 0.5 * z, "maximize")
    model.optimize()
    assert model.getStatus() == "optimal"
    return model.getVal(x), model.getVal(z)


def test_linear_sup_takes_each_bound_by_the_coefficient_sign():
    model = Model()
    x = model.addVar("x", lb=-5.0, ub=5.0)
    z = model.addVar("z", lb=-2.0, ub=3.0)
    assert linear_sup([(2.0, x), (-1.0, z)], 1.0) == pytest.approx(2 * 5 + 2 + 1)


def test_linear_implication_binds_only_when_its_binary_is_one():
    def build(model, y, x, z):
        implies_le(model, y, [(1.0, x), (1.0, z)], 1.0, "c")

    x, z = _solve(1.0, build)
    assert x + z == pytest.approx(1.0, abs=1e-6)
    x, z = _solve(0.0, build)  # vacuous: the box's own corner is reachable
    assert (x, z) == (pytest.approx(5.0), pytest.approx(3.0))


def test_quadratic_implication_binds_only_when_its_binary_is_one():
    def build(model, y, x, z):
        implies_close(model, y, (x, 0.0), (z, 0.0), 1.0, "c")

    x, z = _solve(1.0, build)
    assert abs(x - z) <= 1.0 + 1e-6
    assert x == pytest.approx(4.0, abs=1e-5)  # x = z + 1 with z at its bound 3
    x, z = _solve(0.0, build)
    assert (x, z) == (pytest.approx(5.0), pytest.approx(3.0))
