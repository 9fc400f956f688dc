"""The reach ball of the arms other than the Panda (world_state.reach_of): the
farthest of many sampled tool positions, sampled once per problem."""

from __future__ import annotations

import math
import types
from pathlib import Path

import numpy as np
import pytest

from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.optimize.world_state import REACH_SAMPLES, reach_of

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("scene", ["arm-kuka/p01", "arm-xarm/p01"])
def test_the_reach_ball_is_the_farthest_sample_and_is_sampled_once(scene):
    scene = load_scene(ROOT / "problems" / f"{scene}.scene.toml")
    with World(scene, visuals=False) as world:
        problem = types.SimpleNamespace(scene=scene, planar=False, world=world, memo={})
        centre, radius = reach_of(problem)
        # One configuration at a time, as a reader would write it.
        rng = np.random.default_rng(0)
        lo = np.where(np.isfinite(world.lower), world.lower, -math.pi)
        hi = np.where(np.isfinite(world.upper), world.upper, math.pi)
        far = max(np.linalg.norm(world.tool_pose(rng.uniform(lo, hi))[:3, 3] - centre)
                  for _ in range(REACH_SAMPLES))
        assert radius == pytest.approx(1.05 * far, abs=1e-12)
        assert 0.5 < radius < 2.0
        # The final NLP asks at every evaluation: no forward kinematics the second time.
        world_fk = world.tool_poses
        world.tool_poses = None
        try:
            assert reach_of(problem)[1] == radius
        finally:
            world.tool_poses = world_fk
