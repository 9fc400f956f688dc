"""A motion whose straight joint-space line meets every row is that line: the least
cost any path between its keyframes can have (|dq|^2 / T), found without an NLP.
A motion whose line is blocked is still optimized round the obstacle."""

import numpy as np

from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.optimize.verify import verify

from .helpers import ops


def _hits(scene, a, b, clearance: float) -> bool:
    pillar = scene.body("pillar")
    c = np.array(pillar.pose[:2])
    r = pillar.size[0] + scene.robot.radius + clearance
    return any(np.linalg.norm(a + s * (b - a) - c) < r for s in np.linspace(0, 1, 400))


def test_free_motions_are_straight_and_a_blocked_one_goes_round(planar):
    scene, modes, world = planar
    problem = lower(ops("(pick o start)", "(place o goal)"), scene, modes, world)
    keyframes = solve(problem, "keyframes")
    path = solve(problem, "path", keyframes)
    assert path.solved, path.worst_constraint
    assert verify(problem, path, factor=10) == []
    assert path.cost == sum(path.phase_costs)
    traj = path.trajectory
    motions = [p for p in path.phases if p.action is None]
    straight = blocked = 0
    for m in motions:
        span = traj[m.start:m.end + 1]
        a, b = span[0], span[-1]
        T = len(span) - 1
        line = np.linspace(a, b, T + 1)
        cost = float(np.sum(np.diff(span, axis=0) ** 2))
        # the robot's (x, y) is the planar robot's first two joints
        if _hits(scene, a[:2], b[:2], 0.0):
            blocked += 1
            assert not np.allclose(span, line, atol=1e-6)
            assert cost > float((b - a) @ (b - a)) / T + 1e-6
        elif not _hits(scene, a[:2], b[:2], 2 * problem.options.activation):
            straight += 1
            assert np.allclose(span, line, atol=1e-12)
            assert cost == np.float64(float(np.sum(np.diff(line, axis=0) ** 2)))
    assert blocked >= 1 and straight >= 1


def test_a_free_motion_takes_no_nlp(planar, monkeypatch):
    from tampcli.optimize.run import Run

    scene, modes, world = planar
    problem = lower(ops("(pick o start)",), scene, modes, world)
    keyframes = solve(problem, "keyframes")
    motions = []  # the path stage's motion NLPs (the keyframe NLPs of its face grips aside)
    path_nlp = Run.path_nlp

    def counted(self, *args):
        motions.append(1)
        return path_nlp(self, *args)

    monkeypatch.setattr(Run, "path_nlp", counted)
    path = solve(problem, "path", keyframes)
    assert path.solved, path.worst_constraint
    (m,) = [p for p in path.phases if p.action is None]
    span = path.trajectory[m.start:m.end + 1]
    assert not _hits(scene, span[0][:2], span[-1][:2], 2 * problem.options.activation)
    assert not motions
    assert np.allclose(span, np.linspace(span[0], span[-1], len(span)), atol=1e-12)


def test_a_motion_on_more_segments_is_weighed_as_if_it_had_the_options(planar):
    """phase_rows_fn's cost on T_k segments is (T_k / waypoints) * sum |dq|^2: the same
    |dq|^2 / waypoints for the straight line on any number of segments, with its gradient
    scaled alike (checked against finite differences off the line)."""
    from tampcli.optimize.assemble import walk
    from tampcli.optimize.grips import Kinematics
    from tampcli.optimize.path import phase_rows_fn

    scene, modes, world = planar
    problem = lower(ops("(pick o start)",), scene, modes, world)
    kfr = solve(problem, "keyframes")
    ctx = walk(problem, kfr.keyframes, kfr.choices, world.start)[0]
    T0 = problem.options.waypoints
    rng = np.random.default_rng(1)
    for T in (T0, 2 * T0 + 3):
        evaluate, layout = phase_rows_fn(problem, problem.motions[0], ctx.q_a, ctx.q_b,
                                         ctx.held, ctx.moved, Kinematics(world),
                                         problem.checker, T, 0, None, "motion")
        line = np.linspace(ctx.q_a, ctx.q_b, T + 1)[1:-1].reshape(-1)
        d = ctx.q_b - ctx.q_a
        np.testing.assert_allclose(evaluate(line).cost, float(d @ d) / T0, rtol=1e-12)
        x = line + rng.normal(0.0, 0.01, line.size)
        slices = layout.slices()
        grad = np.zeros(layout.size)
        for block, v in evaluate(x).cost_grad.items():
            grad[slices[block]] += v
        h = 1e-6
        fd = [(evaluate(x + h * e).cost - evaluate(x - h * e).cost) / (2 * h)
              for e in np.eye(layout.size)]
        np.testing.assert_allclose(grad, fd, atol=1e-6)
