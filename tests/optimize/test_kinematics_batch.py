"""Batched tool frames equal the one-configuration ones (the keyframe NLP uses them)."""

import numpy as np

from tampcli.geometry.world import World
from tampcli.optimize.grips import Kinematics

from .helpers import load


def test_batched_frames_equal_single_frames():
    _, _, scene, _ = load("wall")
    with World(scene) as world:
        kin = Kinematics(world)
        rng = np.random.default_rng(2)
        qs = rng.uniform(world.lower, world.upper, size=(6, world.n))
        for q, batched in zip(qs, kin.frames(qs), strict=True):
            single = Kinematics(world).frame(q)
            for name in ("p", "R", "Jp", "Jw"):
                np.testing.assert_allclose(getattr(batched, name), getattr(single, name),
                                           atol=1e-12, err_msg=name)
        assert kin.frames(np.zeros((0, world.n))) == []
