"""The path stage's NLP backends: Ipopt against SLSQP on the same NLPs, the cost
Hessian Ipopt steps with, `auto`'s rule, and `solve --nlp` from the command line."""

import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from tampcli.errors import OptionError
from tampcli.optimize.backends import BACKENDS, IPOPT_FROM, Auto, Ipopt, Slsqp
from tampcli.optimize.collide import contact_rows
from tampcli.optimize.expr import Label, RowSet
from tampcli.optimize.grips import Kinematics
from tampcli.optimize.init import final_guess, keyframe_guess
from tampcli.optimize.layout import Layout
from tampcli.optimize.nlp import FEASIBILITY
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.path import phase_rows_fn, smoothness_hessian, via_points
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.optimize.stages import Rows
from tampcli.optimize.verify import verify

from .helpers import ops

needs_ipopt = pytest.mark.skipif(Ipopt().missing() is not None,
                                 reason="needs cyipopt (the ipopt extra)")

ROOT = Path(__file__).resolve().parents[2]
PLANAR = (ROOT / "domains/planar-tamp/domain.pddl", ROOT / "problems/planar-tamp/p01.pddl")
LAYOUT = Layout((("a", 2), ("b", 1)))
BOUNDS = [(-5.0, 5.0), (-5.0, 5.0), (-5.0, 0.5)]


def small_nlp(x, radius=1.0):
    """min |a - (4, 1)|^2 + (b - 3)^2  s.t.  a0 + a1 + b = 1,  |a|^2 <= radius^2,
    b <= 0.5 (a bound): the disk, the plane and the bound all active at the optimum."""
    a, b = x[:2], x[2]
    rows = Rows()
    rows.cost = float((a[0] - 4) ** 2 + (a[1] - 1) ** 2 + (b - 3) ** 2)
    rows.cost_grad = {"a": 2 * (a - [4.0, 1.0]), "b": np.array([2 * (b - 3)])}
    rows.eq.add(a[0] + a[1] + b - 1, {"a": np.array([[1.0, 1.0]]), "b": np.array([[1.0]])},
                Label("small", "plane", ""))
    rows.ineq.add(radius ** 2 - a @ a, {"a": -2 * a[None, :]}, Label("small", "disk", ""))
    return rows


def _solve(backend, evaluate, x0=(0.0, 0.0, 0.0)):
    return backend.solve(evaluate, LAYOUT, np.array(x0), BOUNDS, 200, time.perf_counter() + 30)


@needs_ipopt
def test_ipopt_reaches_slsqps_optimum_of_a_small_nlp():
    slsqp, ipopt = _solve(Slsqp(), small_nlp), _solve(Ipopt(), small_nlp)
    assert slsqp.status == ipopt.status == "solved"
    # The optimum: b at its bound, a on the disk and on the plane a0 + a1 = 0.5.
    assert ipopt.x[2] == pytest.approx(0.5, abs=1e-6)
    assert ipopt.x[0] + ipopt.x[1] == pytest.approx(0.5, abs=1e-6)
    assert ipopt.x[:2] @ ipopt.x[:2] == pytest.approx(1.0, abs=1e-6)
    np.testing.assert_allclose(ipopt.x, slsqp.x, atol=1e-5)
    assert ipopt.cost == pytest.approx(slsqp.cost, abs=1e-5)
    assert ipopt.violation <= FEASIBILITY and ipopt.worst is None
    # The certificate at its answer (bound, plane and disk all active).
    assert ipopt.kkt is not None and ipopt.kkt.stationarity < 1e-5 and ipopt.kkt.dual_feasible
    assert ipopt.iterations > 0 and ipopt.stopped is None


@needs_ipopt
def test_ipopt_uses_the_cost_hessian_where_rows_give_one():
    """A badly scaled quadratic: one Newton step with its Hessian, many quasi-Newton ones
    without."""
    scale = np.array([1.0, 30.0, 1000.0])
    target = np.array([1.0, -2.0, 0.25])

    def quadratic(x, hessian=False):
        rows = Rows()
        rows.cost = float(scale @ (x - target) ** 2)
        g = 2 * scale * (x - target)
        rows.cost_grad = {"a": g[:2], "b": g[2:]}
        if hessian:
            rows.cost_hess = {("a", "a"): np.diag(2 * scale[:2]),
                              ("b", "b"): np.array([[2 * scale[2]]])}
        return rows

    plain = _solve(Ipopt(), quadratic)
    exact = _solve(Ipopt(), lambda x: quadratic(x, hessian=True))
    assert plain.status == exact.status == "solved"
    np.testing.assert_allclose(exact.x, target, atol=1e-4)
    assert exact.iterations < plain.iterations


@needs_ipopt
def test_a_hessian_outside_its_starting_sparsity_is_an_error():
    def drifting(x):
        rows = small_nlp(x)
        rows.cost_hess = {("a", "a"): 2 * np.eye(2)}
        if x[2] > -0.9:  # not at the start
            rows.cost_hess[("a", "b")] = np.ones((2, 1))
        return rows

    with pytest.raises(ValueError, match="sparsity"):
        _solve(Ipopt(), drifting, x0=(0.0, 0.0, -1.0))


@needs_ipopt
def test_a_jacobian_outside_its_declared_blocks_is_an_error():
    def undeclared(x):
        rows = small_nlp(x)
        # A row that depends on b once b has moved, and does not say so at the start.
        jac = {"b": np.array([[1.0]])} if x[2] > -0.9 else {}
        rows.ineq.add(x[2] + 10.0, jac, Label("small", "far", ""))
        return rows

    with pytest.raises(ValueError, match="declared"):
        _solve(Ipopt(), undeclared, x0=(0.0, 0.0, -1.0))
    declared = _solve(Ipopt(), lambda x: _declared(undeclared(x)), x0=(0.0, 0.0, -1.0))
    assert declared.status == "solved"


def _declared(rows):
    rows.ineq.blocks[-1] |= {"b"}
    return rows


@needs_ipopt
def test_ipopt_reports_an_infeasible_nlp_by_its_worst_row():
    out = _solve(Ipopt(), lambda x: small_nlp(x, radius=0.1))  # the plane misses the disk
    assert out.status == "infeasible"
    assert out.violation > FEASIBILITY
    assert out.worst.startswith("small: ")
    assert out.kkt is None


@needs_ipopt
def test_ipopt_stops_at_the_deadline():
    out = Ipopt().solve(small_nlp, LAYOUT, np.zeros(3), BOUNDS, 200, time.perf_counter() - 1)
    assert out.stopped == "time"
    assert out.iterations <= 1


def test_the_smoothness_hessian_matches_finite_differences_of_the_gradient(wall):
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    from tampcli.optimize.assemble import walk

    ctx = walk(problem, vals, choices, world.start)[1]
    T = 5
    evaluate, layout = phase_rows_fn(problem, problem.motions[1], ctx.q_a, ctx.q_b, ctx.held,
                                     ctx.moved, Kinematics(world), problem.checker, T, 0, None,
                                     "carry")
    slices = layout.slices()

    def grad(x):
        g = np.zeros(layout.size)
        for block, v in evaluate(x).cost_grad.items():
            g[slices[block]] += v
        return g

    x = via_points(problem, ctx.q_a, ctx.q_b, T, 0.05, ctx.moved,
                   np.random.default_rng(0)).reshape(-1)
    h = 1e-6
    fd = np.array([(grad(x + h * e) - grad(x - h * e)) / (2 * h) for e in np.eye(layout.size)])
    H = np.zeros((layout.size, layout.size))
    for (a, b), block in evaluate(x).cost_hess.items():
        H[slices[a], slices[b]] += block
        if a != b:
            H[slices[b], slices[a]] += block.T
    np.testing.assert_allclose(H, fd, atol=1e-6)
    assert evaluate(x).cost_hess.keys() == smoothness_hessian(T, problem.n).keys()


def test_collision_rows_with_nothing_near_declare_their_waypoints():
    """Beyond the activation distance the rows are constant (no Jacobian), but they
    depend on the waypoints of their sample point once something comes near."""
    rows = RowSet()
    contact_rows(rows, "carry", [], [("w1", 0.25), ("w2", 0.75)], None, None, {},
                 ["wall", "self"], activation=0.05, margin=0.01)
    layout = Layout((("w1", 2), ("w2", 2), ("w3", 2)))
    _, jac = rows.assemble(layout.slices(), layout.size)
    assert not jac.any()
    expected = np.array([[True] * 4 + [False] * 2] * 2)
    np.testing.assert_array_equal(rows.pattern(layout.slices(), layout.size), expected)


def test_path_rows_keep_to_the_jacobian_pattern_they_start_with(wall):
    """Through the wall and over it: rows inactive at the start become active, in the
    blocks the start's pattern has for them."""
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    from tampcli.optimize.assemble import walk

    ctx = walk(problem, vals, choices, world.start)[1]
    T = 6
    evaluate, layout = phase_rows_fn(problem, problem.motions[1], ctx.q_a, ctx.q_b, ctx.held,
                                     ctx.moved, Kinematics(world), problem.checker, T, 1, None,
                                     "carry")
    slices = layout.slices()
    line = np.concatenate([ctx.q_a + (ctx.q_b - ctx.q_a) * i / T for i in range(1, T)])
    lifted = via_points(problem, ctx.q_a, ctx.q_b, T, 0.05, ctx.moved,
                        np.random.default_rng(0)).reshape(-1)
    start = evaluate(lifted).ineq
    pattern = start.pattern(slices, layout.size)
    # Sparse: a collision row depends on the one or two waypoints of its sample point.
    assert pattern.mean() < 0.5
    idle = ~np.any(start.assemble(slices, layout.size)[1] != 0, axis=1)
    woke = np.zeros_like(idle)
    for blend in np.linspace(0.0, 1.0, 6):
        rows = evaluate((1 - blend) * line + blend * lifted).ineq
        _, jac = rows.assemble(slices, layout.size)
        assert not np.any(jac[~pattern])
        np.testing.assert_array_equal(rows.pattern(slices, layout.size), pattern)
        woke |= idle & np.any(jac != 0, axis=1)
    assert woke.any()  # rows with no gradient at the start got one, inside the pattern


@needs_ipopt
def test_the_path_stage_with_ipopt_passes_verify(wall):
    scene, modes, world = wall
    options = OptimizeOptions(waypoints=8, nlp="ipopt")
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world, options)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    assert verify(problem, result, factor=10) == []
    slsqp = solve(problem, "path", options=OptimizeOptions(waypoints=8, nlp="slsqp"))
    # Both find a smooth carry over the wall: costs within a fifth of each other.
    assert result.cost == pytest.approx(slsqp.cost, rel=0.2)


@needs_ipopt
@needs_ipopt
def test_auto_picks_ipopt_from_its_size_only():
    # Whitened SLSQP was faster at every size measured: the default rule picks it.
    assert IPOPT_FROM is None
    assert isinstance(Auto().pick(10_000), Slsqp)
    assert isinstance(Auto(ipopt_from=3).pick(LAYOUT.size), Ipopt)
    assert isinstance(Auto(ipopt_from=4).pick(LAYOUT.size), Slsqp)


def test_auto_falls_back_to_slsqp_without_cyipopt(monkeypatch):
    monkeypatch.setitem(sys.modules, "cyipopt", None)  # what an absent package imports as
    assert isinstance(Auto(ipopt_from=1).pick(10_000), Slsqp)
    assert "tampcli[ipopt]" in Ipopt().missing()
    out = _solve(Auto(ipopt_from=1), small_nlp)
    assert out.status == "solved"


def test_options_name_a_backend():
    assert set(BACKENDS) == {"slsqp", "ipopt", "auto"}
    assert OptimizeOptions().nlp == "auto"
    with pytest.raises(OptionError, match="slsqp, ipopt, auto"):
        OptimizeOptions(nlp="snopt")


@needs_ipopt
def test_solve_with_ipopt_gives_a_valid_planar_solution(cli, tmp_path):
    out = tmp_path / "solution.json"
    run = cli("solve", *PLANAR, "--nlp", "ipopt", "--first", "--out", out)
    assert run.code == 0, run.err
    assert "Ipopt" not in run.out + run.err and "EXIT" not in run.out + run.err
    check = cli("validate", *PLANAR, out)
    assert check.code == 0, check.err + check.out
    assert "valid" in check.out + check.err


@needs_ipopt
def test_nothing_from_ipopt_reaches_the_terminal():
    """Ipopt's banner and log go to the process's stdout from C: only a subprocess sees
    them."""
    code = ("import time, numpy as np\n"
            "from tampcli.optimize.backends import Ipopt\n"
            "from tampcli.optimize.layout import Layout\n"
            "from tampcli.optimize.stages import Rows\n"
            "def evaluate(x):\n"
            "    rows = Rows()\n"
            "    rows.cost, rows.cost_grad = float((x[0] - 1) ** 2), {'a': 2 * (x - 1)}\n"
            "    return rows\n"
            "out = Ipopt().solve(evaluate, Layout((('a', 1),)), np.zeros(1), [(-2, 2)], 50, "
            "time.perf_counter() + 30)\n"
            "assert out.status == 'solved' and abs(out.x[0] - 1) < 1e-4\n")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert run.returncode == 0, run.stderr
    assert run.stdout == "" and run.stderr == ""


def test_solve_nlp_ipopt_without_cyipopt_is_a_usage_error():
    code = ("import sys; sys.modules['cyipopt'] = None\n"
            "from tampcli.cli import main\n"
            f"sys.exit(main(['solve', {str(PLANAR[0])!r}, {str(PLANAR[1])!r}, "
            "'--nlp', 'ipopt']))\n")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert run.returncode == 2
    assert "--nlp" in run.stderr and "tampcli[ipopt]" in run.stderr
    assert "Traceback" not in run.stderr
