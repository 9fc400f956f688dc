"""A ball set down by the physics replay stays where the plan puts it: the robot is
still, not just on target, when it lets go, and the replay's contacts resist rolling
as real ones do (blind9 p08: released at about 1 cm/s with no rolling resistance, its
ball rolled on for 2.8 cm)."""

from __future__ import annotations

import shutil

import pybullet as pb
from render_solutions import PANDA, panda_solution

from tampcli.render.inputs import load_inputs
from tampcli.render.physics import replay_physics
from tampcli.render.physics_values import PhysicsSettings


def _ball_scene(folder) -> None:
    """The render tests' Panda scene with cube a turned into a ball (r 2.5 cm)."""
    for name in ("domain.pddl", "p01.pddl"):
        shutil.copy(PANDA / name, folder / name)
    text = (PANDA / "p01.scene.toml").read_text()
    cube = 'name = "a"\nshape = "box"\nsize = [0.05, 0.05, 0.05]'
    assert cube in text
    (folder / "p01.scene.toml").write_text(
        text.replace(cube, 'name = "a"\nshape = "sphere"\nsize = [0.025]'))


def test_a_ball_set_down_at_speed_is_let_go_at_rest(tmp_path):
    _ball_scene(tmp_path)
    # one segment per leg: the tool comes down onto the place at the replay's full speed
    solution = panda_solution(folder=tmp_path, steps=1)
    # Without rolling resistance any speed at the release rolls the ball on for good:
    # let go once the joints were within 0.0002 rad of the place but still moving
    # (about 1 cm/s at the tool), it ended 3.5 mm away; let go at rest, 0.05 mm.
    frictionless = replay_physics(load_inputs(solution),
                                  settings=PhysicsSettings(rolling_friction=0.0))
    assert _distance(frictionless, "a") < 5e-4
    assert _distance(replay_physics(load_inputs(solution)), "a") < 5e-4


def _distance(replay, name: str) -> float:
    return next(o.distance for o in replay.objects if o.name == name)


def _rolled(settings: PhysicsSettings, speed: float, radius: float = 0.026,
            seconds: float = 3.0) -> float:
    """How far (m) a 50 g ball set rolling at `speed` (m/s) on a level floor goes
    with the replay's contact parameters on both."""
    c = pb.connect(pb.DIRECT)
    try:
        pb.setGravity(0.0, 0.0, -9.81, physicsClientId=c)
        pb.setTimeStep(1.0 / settings.hz, physicsClientId=c)
        floor = pb.createMultiBody(0.0, pb.createCollisionShape(
            pb.GEOM_BOX, halfExtents=[0.5, 0.5, 0.005], physicsClientId=c),
            basePosition=[0.0, 0.0, -0.005], physicsClientId=c)
        ball = pb.createMultiBody(0.05, pb.createCollisionShape(
            pb.GEOM_SPHERE, radius=radius, physicsClientId=c),
            basePosition=[0.0, 0.0, radius], physicsClientId=c)
        for uid in (floor, ball):
            pb.changeDynamics(uid, -1, lateralFriction=settings.friction,
                              restitution=settings.restitution,
                              spinningFriction=settings.spinning_friction,
                              rollingFriction=settings.rolling_friction, physicsClientId=c)
        pb.resetBaseVelocity(ball, [speed, 0.0, 0.0], [0.0, speed / radius, 0.0],
                             physicsClientId=c)
        for _ in range(int(seconds * settings.hz)):
            pb.stepSimulation(physicsClientId=c)
        return float(pb.getBasePositionAndOrientation(ball, physicsClientId=c)[0][0])
    finally:
        pb.disconnect(c)


def test_the_replay_resists_rolling_as_a_hard_ball_on_a_hard_floor():
    """A 0.1 mm lever arm (r_a f_b + r_b f_a in Bullet): a ball rolling at v stops after
    v^2 / (2 a), a = 5/7 g lever / R; 1 cm/s on a 2.6 cm ball, 1.9 mm. At no
    resistance it went 2.8 cm in 3 s and was still rolling."""
    settings = PhysicsSettings()
    lever = 2 * settings.friction * settings.rolling_friction
    assert abs(lever - 1e-4) < 1e-12
    expected = 0.01 ** 2 / (2 * 5 / 7 * 9.81 * lever / 0.026)
    distance = _rolled(settings, 0.01)
    assert 0.5 * expected < distance < 1.5 * expected, (distance, expected)
    # and at rest it stays at rest
    assert abs(_rolled(settings, 0.0)) < 1e-6
