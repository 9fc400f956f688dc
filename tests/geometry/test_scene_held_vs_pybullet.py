"""Held-object distances (FCL) vs PyBullet: the cube held by the Panda's tool vs every body.

PyBullet knows nothing of grasps: the cube is placed at its held pose (tool
pose @ grasp) with `World.set_state`, the replay method, and put back at its
start pose afterwards.
"""

import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.world import World

from .worlds import panda_scene, simulator

ACTIVATION = 0.1  # m: what the optimizer uses; pairs beyond it are pruned
FAR = 0.8  # m: every pair closer than this is compared
TOLERANCE = 0.002  # m
HELD = "a"


@pytest.fixture(scope="module")
def panda():
    with World(panda_scene()) as world:
        yield world, CollisionChecker(world)


def _pybullet_distance(world, a: str, b: str) -> float:
    sim = simulator(world)
    points = sim.pb.getClosestPoints(sim.bodies[a], sim.bodies[b], 1.0, -1, -1,
                                     physicsClientId=sim.client)
    return min(p[8] for p in points) if points else np.inf


def _held_distances(checker, q, grasp, activation) -> dict[str, float]:
    """Body name -> signed distance from the held cube, for the pairs within `activation`."""
    return {c.b.partition(":")[2]: c.distance
            for c in checker.distances(q, held=(HELD, grasp), activation=activation)
            if c.a == f"held:{HELD}" and c.b.startswith("body:")}


def _random_cases(world, count, seed):
    """(q, grasp): configurations in the joint limits; the cube turned about the tool
    axis and pushed up to 3 cm along it."""
    rng = np.random.default_rng(seed)
    for _ in range(count):
        q = rng.uniform(world.lower, world.upper)
        grasp = transforms.pose(transforms.rot_z(rng.uniform(-np.pi, np.pi)),
                                (0.0, 0.0, rng.uniform(0.0, 0.03)))
        yield q, grasp


def test_held_cube_distances_match_pybullet(panda):
    world, checker = panda
    others = [name for name in world.body_names if name != HELD]
    compared = penetrating = 0
    sim = simulator(world)
    start_pose = sim.pb.getBasePositionAndOrientation(sim.bodies[HELD],
                                                      physicsClientId=sim.client)
    try:
        for q, grasp in _random_cases(world, 100, seed=31):
            world.set_state(q, {HELD: world.tool_pose(q) @ grasp})
            ours = _held_distances(checker, q, grasp, FAR)
            near = _held_distances(checker, q, grasp, ACTIVATION)
            assert HELD not in ours  # the held cube is not also an obstacle at its start pose
            for name in others:
                theirs = _pybullet_distance(world, HELD, name)
                # The broad phase prunes only pairs that PyBullet also finds out of range.
                assert name in near or theirs > ACTIVATION - TOLERANCE, (q, name, theirs)
                if name not in ours:
                    assert theirs > FAR - TOLERANCE, (q, name, theirs)
                    continue
                mine = ours[name]
                if mine > 0 and theirs > 0:
                    assert abs(mine - theirs) < TOLERANCE, (q, name, mine, theirs)
                elif mine < -TOLERANCE:
                    assert theirs < 0, (q, name, mine, theirs)
                    penetrating += 1
                elif theirs < -TOLERANCE:
                    assert mine < 0, (q, name, mine, theirs)
                compared += 1
    finally:
        world.set_state(world.start, {b.name: b.matrix for b in world.scene.bodies})
    assert compared >= 250 and penetrating >= 3, (compared, penetrating)
    restored = sim.pb.getBasePositionAndOrientation(sim.bodies[HELD],
                                                    physicsClientId=sim.client)
    np.testing.assert_allclose(np.concatenate(restored), np.concatenate(start_pose), atol=1e-9)
