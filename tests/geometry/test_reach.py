"""The arms' reach ball (geometry/reach.py): a bound no configuration within the joint
limits breaks, and tight (the farthest of many random configurations is within 1 cm)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tampcli.geometry.arms import ARMS
from tampcli.geometry.reach import reach_ball
from tampcli.geometry.scene import RobotSpec, Scene
from tampcli.geometry.world import World


@pytest.mark.parametrize("model", sorted(ARMS))
def test_no_configuration_puts_the_tool_outside_the_ball_and_some_come_near_its_edge(model):
    with World(Scene(None, RobotSpec(model))) as world:
        centre, radius = reach_ball(world)
        lo = np.where(np.isfinite(world.lower), world.lower, -math.pi)
        hi = np.where(np.isfinite(world.upper), world.upper, math.pi)
        qs = np.random.default_rng(7).uniform(lo, hi, size=(20000, world.n))
        far = np.linalg.norm(world.tool_poses(qs)[:, :3, 3] - centre, axis=1)
        assert far.max() <= radius + 1e-9
        assert far.max() >= radius - 0.01, (model, far.max(), radius)


def test_the_pandas_reach_is_not_its_top_grasp_reach():
    """The proofs used 0.855 m from the shoulder, a stretched arm with the hand down;
    the hand level, pointing away, reaches 9 cm further (a side grasp can place there)."""
    with World(Scene(None, RobotSpec("panda"))) as world:
        centre, radius = reach_ball(world)
        np.testing.assert_allclose(centre, (0.0, 0.0, 0.333), atol=1e-9)
        lo, hi = world.lower, world.upper
        qs = np.random.default_rng(1).uniform(lo, hi, size=(20000, world.n))
        assert np.linalg.norm(world.tool_poses(qs)[:, :3, 3] - centre, axis=1).max() > 0.9
        assert radius == pytest.approx(0.9489, abs=1e-3)
