"""The relaxed bound of a planar skeleton (optimize/relaxed.py) and the certified
convex QP under it (optimize/convex_qp.py): closed forms, a relaxation of the
real NLP, proved labels only where the relaxation is a convex QP."""

import math

import numpy as np
import pytest

from tampcli.optimize.convex_qp import (
    ConvexQP,
    lagrangian_bound,
    solve_convex_qp,
)
from tampcli.optimize.problem import lower
from tampcli.optimize.relaxed import DIRECTIONS, relaxed_bound
from tampcli.optimize.relaxed_apart import Apart
from tampcli.optimize.solve import solve
from tampcli.optimize.verify import INSIDE, RIGID, STILL

from .helpers import ROOT, ops


def _qp(P, c, A=(), b=(), E=(), f=(), lo=-10.0, hi=10.0, r=0.0):
    P = np.atleast_2d(np.asarray(P, dtype=float))
    n = len(P)
    A = np.asarray(A, dtype=float).reshape(-1, n)
    E = np.asarray(E, dtype=float).reshape(-1, n)
    return ConvexQP(P, np.asarray(c, dtype=float), r, A, np.asarray(b, dtype=float), E,
                    np.asarray(f, dtype=float), np.full(n, lo), np.full(n, hi))


def test_a_one_dimensional_qp_gets_its_closed_form():
    # (x - 3)^2 = 0.5 * 2 x^2 - 6 x + 9 with x <= 1: the optimum is 4, at x = 1.
    out = solve_convex_qp(_qp([[2.0]], [-6.0], A=[[1.0]], b=[1.0], r=9.0))
    assert out.proved
    assert out.value <= 4.0
    assert out.value == pytest.approx(4.0, abs=1e-7)


def test_an_equality_and_an_active_bound_are_certified():
    # min x^2 + y^2 s.t. x + y = 1, x >= 0.8 (a box bound): (0.8, 0.2), value 0.68.
    qp = ConvexQP(2 * np.eye(2), np.zeros(2), 0.0, np.zeros((0, 2)), np.zeros(0),
                  np.array([[1.0, 1.0]]), np.array([1.0]), np.array([0.8, -5.0]),
                  np.array([5.0, 5.0]))
    out = solve_convex_qp(qp)
    assert out.proved and out.value <= 0.68
    assert out.value == pytest.approx(0.68, abs=1e-7)


def test_the_certificate_is_a_lower_bound_at_any_point_and_multipliers():
    """Weak duality holds for every x and every lambda >= 0, however bad."""
    qp = _qp(np.diag([2.0, 4.0]), [-2.0, 1.0], A=[[1.0, 1.0], [-1.0, 2.0]], b=[0.5, 1.0])
    optimum = solve_convex_qp(qp).solver_value
    rng = np.random.default_rng(0)
    for _ in range(200):
        x = rng.uniform(-3, 3, 2)
        lam = rng.uniform(0, 5, 2)
        assert lagrangian_bound(qp, x, lam, np.zeros(0)) <= optimum + 1e-12


def test_contradicting_rows_are_proved_infeasible():
    # x >= 2 and x <= 1.
    out = solve_convex_qp(_qp([[2.0]], [0.0], A=[[1.0], [-1.0]], b=[1.0, -2.0]))
    assert out.proved and math.isinf(out.value)


def test_a_non_convex_cost_is_not_proved():
    out = solve_convex_qp(_qp([[-2.0]], [0.0], lo=-1.0, hi=1.0))
    assert not out.proved


def test_pick_and_place_bound_has_its_closed_form(planar):
    """Box o at (0.2, 0.2), the disk from (0, 0), goal [0.8, 1.0]^2: the grasp can be
    reached no closer than |c0| - h(d) (h the support of the rounded footprint grown
    by the touch tolerance, in the direction d of the start: one of the polygon's
    normals), and the object travels to the goal's nearest admissible centre, less
    the drift validate allows a held object over its one carrying motion. The creep
    it allows at the two mode switches (STILL each) is best spent towards the goal:
    the carry is longer than the way to the grasp."""
    scene, modes, world = planar
    problem = lower(ops("(pick o start)", "(place o goal)"), scene, modes, world)
    out = relaxed_bound(problem)
    assert out.kind == "proved"
    assert DIRECTIONS % 8 == 0  # the diagonal is one of the directions
    T = problem.options.waypoints
    half, rim = 0.03, scene.robot.radius + 2e-3
    c0 = np.array([0.2, 0.2])
    h = 2 * half / math.sqrt(2) + rim
    creep = math.sqrt(2) * 2 * STILL
    grasp = np.linalg.norm(c0) - h + creep
    corner = 0.8 + half - INSIDE
    carry = math.sqrt(2) * (corner - 0.2 - (RIGID + 2 * STILL)) - creep
    assert out.value == pytest.approx((grasp ** 2 + carry ** 2) / T, abs=1e-8)


def test_the_bound_is_below_the_nlp_optimum(planar):
    scene, modes, world = planar
    problem = lower(ops("(pick o start)", "(place o goal)"), scene, modes, world)
    bound = relaxed_bound(problem)
    path = solve(problem, "path")
    assert path.solved, path.worst_constraint
    keyframes = solve(problem, "keyframes")
    assert bound.value <= keyframes.cost <= path.cost
    assert bound.value > 0.5 * path.cost  # and not a trivial one


def test_a_prefix_bounds_its_completions(planar):
    scene, modes, world = planar
    prefix = relaxed_bound(lower(ops("(pick o start)"), scene, modes, world))
    whole = relaxed_bound(lower(ops("(pick o start)", "(place o goal)"), scene, modes, world))
    assert prefix.kind == whole.kind == "proved"
    assert 0.0 < prefix.value < whole.value


def test_the_seed_push_is_proved_infeasible_by_the_friction_cone(planar):
    """The goal lies 45 degrees off every face's normal: no face's cone reaches it,
    and the keyframe NLP agrees (a drag)."""
    scene, modes, world = planar
    problem = lower(ops("(push o start goal floor)"), scene, modes, world)
    out = relaxed_bound(problem)
    assert out.kind == "proved" and math.isinf(out.value)
    assert out.qps == 0  # no face's cone meets the goal: proved before any QP (push_reach)
    assert "friction cone" in out.why
    # The failing push named, as the NLPs name it: the skeleton source learns from it.
    assert out.why.startswith("(push o start goal floor): motion not into the pushed face")
    assert solve(problem, "keyframes").status == "infeasible"


def test_an_arm_has_no_such_relaxation(wall):
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    assert relaxed_bound(problem) is None


def test_an_apart_row_holds_exactly_where_its_option_does():
    rng = np.random.default_rng(1)
    u, w = np.array([0.6, 0.8]), 0.1
    for other in (np.array([0.3, -0.2]), 2):
        pair = Apart(0, other, ((u, w),))
        for _ in range(100):
            x = rng.uniform(-1, 1, 4)
            p = other if isinstance(other, np.ndarray) else x[2:4]
            a, b = pair.row(0, 4)
            assert (a @ x <= b) == (u @ (x[:2] - p) >= w)


def test_a_blocked_region_is_proved_full():
    """planar-tamp p02: b fills the goal region; a cannot be put down beside it (no
    separating axis leaves room), with b moved first it can."""
    from tampcli.geometry.world import World
    from tampcli.pipeline import InputPaths, Timers, read_inputs

    inputs = read_inputs(InputPaths(str(ROOT / "domains/planar-tamp/domain.pddl"),
                                    str(ROOT / "problems/planar-tamp/p02.pddl")), Timers())
    by_name = {op.name: op for op in inputs.task.operators}
    with World(inputs.scene) as world:
        def bound(*names):
            return relaxed_bound(lower([by_name[n] for n in names], inputs.scene,
                                       inputs.modes, world, domain=inputs.domain))
        blocked = bound("(pick a ground)", "(place a goal)")
        assert blocked.kind == "proved" and math.isinf(blocked.value)
        assert blocked.why.startswith("(place a goal): overlaps b")
        cleared = bound("(pick b goal)", "(place b ground)", "(pick a ground)",
                        "(place a goal)")
        assert cleared.kind == "proved" and 0.0 < cleared.value < math.inf
