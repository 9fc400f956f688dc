"""Every constraint Jacobian against central finite differences.

The kinematics are numpy float64 (not PyBullet's float32 FK), so a step of
1e-6 is fine for the smooth rows; collision rows use 1e-5 and points where
no witness pair switches within the step.
"""

import numpy as np
import pytest

from tampcli.optimize.grips import Kinematics, SideGrip, TopGrip, held_pose
from tampcli.optimize.init import final_guess, keyframe_guess
from tampcli.optimize.kinds.push_contact import FaceGrip
from tampcli.optimize.path import phase_layout, phase_rows_fn
from tampcli.optimize.problem import lower
from tampcli.optimize.stages import final_layout, final_rows, keyframe_layout, keyframe_rows
from tampcli.optimize.values import placement_blocks

from .helpers import central_differences, ops


def _check(rows_fn, layout, x, h=1e-6, tol=1e-5):
    slices = layout.slices()

    def parts(xx):
        rows = rows_fn(layout.unpack(xx))
        eq, jeq = rows.eq.assemble(slices, layout.size)
        ineq, jin = rows.ineq.assemble(slices, layout.size)
        grad = np.zeros(layout.size)
        for block, g in rows.cost_grad.items():
            if block in slices:
                grad[slices[block]] += g
        return rows.cost, grad, eq, jeq, ineq, jin

    cost, grad, eq, jeq, ineq, jin = parts(x)
    assert len(eq) + len(ineq) > 0
    fd_cost = central_differences(lambda xx: np.array([parts(xx)[0]]), x, h)[0]
    np.testing.assert_allclose(grad, fd_cost, atol=tol)
    if len(eq):
        np.testing.assert_allclose(jeq, central_differences(lambda xx: parts(xx)[2], x, h), atol=tol)
    if len(ineq):
        np.testing.assert_allclose(jin, central_differences(lambda xx: parts(xx)[4], x, h), atol=tol)
    return eq, ineq


BOX_SIDE = SideGrip((0.0, 0.0, 0.02), yaw=0.3, half=(0.05, 0.03), rim=0.05)


@pytest.mark.parametrize("kind, t", [("top", 0.4), ("push", 0.4), ("side", 0.4),
                                     ("box side x", 0.4), ("box corner", 0.9),
                                     ("box side y", 1.6), ("box corner", -2.2),
                                     ("box side x", 3.3)])
def test_held_pose_jacobians(wall, kind, t):
    _, _, world = wall
    kin = Kinematics(world)
    rng = np.random.default_rng(1)
    grip = {"top": TopGrip((0.0, 0.0, 0.01), psi=0.7),
            "push": FaceGrip((0.0, 0.0, 0.01), ((0.0, 1.0, 0.0), (-1.0, 0.0, 0.0),
                                                  (0.0, 0.0, 1.0)), (0.0, -1.0, 0.0),
                             (1.0, 0.0, 0.0), 0.045),
            "side": SideGrip((0.0, 0.0, 0.02), rho=0.08, yaw=0.3)}.get(kind, BOX_SIDE)
    q = rng.uniform(world.lower, world.upper)

    def value(qq, tt):
        h = held_pose(kin.frame(qq), grip, tt)
        return np.concatenate([h.pos, h.axes.reshape(-1, order="F")])

    h = held_pose(kin.frame(q), grip, t)
    analytic = np.vstack([h.dpos_dq, h.daxes_dq[:, 0], h.daxes_dq[:, 1], h.daxes_dq[:, 2]])
    np.testing.assert_allclose(analytic, central_differences(lambda qq: value(qq, t), q, 1e-6), atol=1e-6)
    dt = np.concatenate([h.dpos_dt, h.daxes_dt[:, 0], h.daxes_dt[:, 1], h.daxes_dt[:, 2]])
    fd_t = (value(q, t + 1e-6) - value(q, t - 1e-6)) / 2e-6
    np.testing.assert_allclose(dt, fd_t, atol=1e-6)


def test_final_rows_place_and_stack(wall):
    """Region containment, stacking on a moved body, separations, reach."""
    scene, modes, world = wall
    # Place a in goal then pick it and place it again: the second placement
    # is checked against a region and against the first (a moved body).
    problem = lower(ops("(pick a start)", "(place a goal)", "(pick a goal)",
                        "(place a start)"), scene, modes, world)
    assert problem.error is None
    layout = final_layout(problem)
    vals, origins = final_guess(problem)
    x = layout.pack(placement_blocks(vals)) + np.random.default_rng(0).normal(0, 0.03, layout.size)
    _check(lambda v: final_rows(problem, v, origins), layout, x)


def test_keyframe_rows_without_collisions(wall):
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start,
                                   np.random.default_rng(0))
    layout = keyframe_layout(problem)
    x = layout.pack(vals.blocks()) + np.random.default_rng(1).normal(0, 0.05, layout.size)
    kin = Kinematics(world)
    eq, _ = _check(lambda v: keyframe_rows(problem, v, choices, kin, problem.checker,
                                           world.start, collisions=False), layout, x)
    assert np.max(np.abs(eq)) > 1e-3  # away from the solution: the test sees real slopes


def test_keyframe_rows_with_an_anchored_placement(wall):
    """A placement kept near a spot (optimize/relocate's anchors): the disk row."""
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start,
                                   np.random.default_rng(0))
    layout = keyframe_layout(problem)
    x = layout.pack(vals.blocks()) + np.random.default_rng(3).normal(0, 0.05, layout.size)
    kin = Kinematics(world)
    spot = np.array([placements[1].x + 0.03, placements[1].y - 0.02])

    def rows(v, anchors):
        return keyframe_rows(problem, v, choices, kin, problem.checker, world.start,
                             collisions=False, anchors=anchors)

    _, free = _check(lambda v: rows(v, None), layout, x)
    _, anchored = _check(lambda v: rows(v, {1: (spot, 0.05)}), layout, x)
    assert len(anchored) == len(free) + 1


def test_keyframe_rows_planar_push_with_grip_parameter(planar):
    scene, modes, world = planar
    problem = lower(ops("(push o start goal floor)"), scene, modes, world)
    assert problem.grip_params == (0,)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    layout = keyframe_layout(problem)
    x = layout.pack(vals.blocks()) + np.random.default_rng(2).normal(0, 0.02, layout.size)
    kin = Kinematics(world)
    _check(lambda v: keyframe_rows(problem, v, choices, kin, problem.checker, world.start),
           layout, x, h=1e-6, tol=1e-5)


def test_collision_rows_at_active_contacts(wall):
    """Arm near the wall with the held cube: link and held-object rows are active."""
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    kin = Kinematics(world)
    from tampcli.optimize.assemble import walk

    contexts = walk(problem, vals, choices, world.start)
    ctx = contexts[1]  # carrying a over the wall
    m = problem.motions[1]
    T = 4
    evaluate, layout = phase_rows_fn(problem, m, ctx.q_a, ctx.q_b, ctx.held, ctx.moved, kin,
                                     problem.checker, T, 1, None, "carry")
    assert layout == phase_layout(problem, T)
    # Between the straight joint-space line (through the wall) and the lifted via
    # points: pick a blend with several active rows and no resting face contact
    # (a face-on-face distance has no unique gradient).
    from tampcli.optimize.path import via_points

    line = np.concatenate([ctx.q_a + (ctx.q_b - ctx.q_a) * i / T for i in range(1, T)])
    lifted = via_points(problem, ctx.q_a, ctx.q_b, T, 0.05, ctx.moved,
                        np.random.default_rng(0)).reshape(-1)
    limit = problem.options.activation - problem.options.margin - 1e-9
    for blend in np.linspace(0.2, 0.8, 13):
        x = (1 - blend) * line + blend * lifted
        ineq, _ = evaluate(x).ineq.assemble(layout.slices(), layout.size)
        if (ineq < limit).sum() >= 3 and np.all(np.abs(ineq + problem.options.margin) > 2e-3):
            break
    else:
        pytest.fail("no blend with active, non-degenerate contacts")
    _check(lambda v: evaluate(layout.pack(v)), layout, x, h=1e-5, tol=2e-3)


def _library(folder: str, stem: str):
    """(domain, scene, modes) of a library problem, through the product's loaders."""
    from tampcli.geometry.scene import load_scene
    from tampcli.optimize.modes import load_modes
    from tampcli.pddl import parser

    from .helpers import ROOT

    d = ROOT / "domains" / folder
    domain = parser.parse_domain_file(d / "domain.pddl")
    problem = parser.parse_problem_file(ROOT / "problems" / folder / f"{stem}.pddl")
    modes = load_modes(d / "modes.toml", domain)
    scene = load_scene(ROOT / "problems" / folder / f"{stem}.scene.toml", domain, problem,
                       modes=modes, geometric=False)
    return domain, scene, modes


def test_keyframe_rows_stacking_on_a_moved_cube():
    """Stacking on a support the skeleton moved (footprint, centre of mass, the tower
    pair's alignment rows), and rows that depend on two keyframes."""
    from tampcli.geometry.world import World

    domain, scene, modes = _library("arm-pick-place", "p05")
    with World(scene) as world:
        problem = lower(ops("(pick b start)", "(stack b c)", "(pick a start)", "(stack a b)"),
                        scene, modes, world, domain=domain)
        assert problem.error is None
        assert problem.steps[3].support == "b" and problem.steps[3].rest_z == pytest.approx(
            0.05 + 0.045 + 0.02)
        layout = final_layout(problem)
        vals, origins = final_guess(problem)
        x = layout.pack(placement_blocks(vals)) + np.random.default_rng(3).normal(0, 0.01, layout.size)
        _check(lambda v: final_rows(problem, v, origins), layout, x)
        placements, _ = final_guess(problem)
        kvals, choices = keyframe_guess(problem, placements, world.start,
                                        np.random.default_rng(0))
        klayout = keyframe_layout(problem)
        x = klayout.pack(kvals.blocks()) + np.random.default_rng(4).normal(0, 0.02, klayout.size)
        kin = Kinematics(world)
        _check(lambda v: keyframe_rows(problem, v, choices, kin, problem.checker, world.start,
                                       collisions=False), klayout, x)


def test_keyframe_rows_panda_push(wall):
    """The arm's push grip: a yaw-offset parameter and the object kept on its support."""
    from tampcli.optimize.modes import Mode

    scene, _, world = wall
    modes = {"push": Mode("push", "push", "?b", to="?to", params=("?b", "?from", "?to"))}
    problem = lower(ops("(push a start goal)"), scene, modes, world)
    assert problem.error is None and problem.grip_params == (0,)
    placements, _ = final_guess(problem)
    vals, choices = keyframe_guess(problem, placements, world.start, np.random.default_rng(0))
    layout = keyframe_layout(problem)
    x = layout.pack(vals.blocks()) + np.random.default_rng(5).normal(0, 0.03, layout.size)
    kin = Kinematics(world)
    _check(lambda v: keyframe_rows(problem, v, choices, kin, problem.checker, world.start,
                                   collisions=False), layout, x)


def _rect_distance(p, hx, hy) -> float:
    return float(np.hypot(max(abs(p[0]) - hx, 0.0), max(abs(p[1]) - hy, 0.0)))


@pytest.mark.parametrize("a", np.linspace(-np.pi, np.pi, 37))
def test_box_side_grip_touches_the_box_at_every_angle(a):
    """The planar rim's centre lies at the rim's radius from the box, not inside
    it: a constant centre distance (rim + larger half extent) put it 8 mm deep
    round the corners of planar-tamp p01's block."""
    grip = BOX_SIDE
    c, G, _, _ = grip.parts(a + grip.yaw)
    robot_in_box = G.T @ -c
    assert _rect_distance(robot_in_box[:2], 0.05, 0.03) == pytest.approx(grip.rim, abs=1e-9)


def test_keyframe_rows_moves_with_and_without_what_is_carried():
    """arm-kitchen's moves: the tool over its target, above the face the target lies on
    (the hand's fingertips, or what it carries), and what it carries within 3 degrees
    of upright."""
    from tampcli.geometry.world import World

    domain, scene, modes = _library("arm-kitchen", "p01")
    with World(scene) as world:
        problem = lower(ops("(move home counter)", "(pick cabbage counter)",
                            "(move counter sink)", "(place cabbage sink)"),
                        scene, modes, world, domain=domain)
        assert problem.error is None
        placements, _ = final_guess(problem)
        kvals, choices = keyframe_guess(problem, placements, world.start,
                                        np.random.default_rng(0))
        klayout = keyframe_layout(problem)
        x = klayout.pack(kvals.blocks()) + np.random.default_rng(5).normal(0, 0.02, klayout.size)
        kin = Kinematics(world)
        rows = keyframe_rows(problem, klayout.unpack(x), choices, kin, problem.checker,
                             world.start, collisions=False)
        labels = [label.what for label in rows.ineq.labels]
        assert any("hand below the top of what counter lies on" in w for w in labels)
        assert any("hand below the top of what sink lies on" in w for w in labels)
        assert any(w == "cabbage tilted" for w in labels)
        _check(lambda v: keyframe_rows(problem, v, choices, kin, problem.checker, world.start,
                                       collisions=False), klayout, x)
