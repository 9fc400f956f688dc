"""World.ik_many (ik.IkMemo.ask_many): a batch of IK questions answered as one by one.

The keyframe guess asks a grasp family's grips and their places at once; the
batch must give what the questions asked in turn give (so a search finds the
same keyframes), memo hits within the batch included.
"""

import types

import numpy as np
import pytest

from tampcli.geometry import transforms
from tampcli.geometry.world import World
from .worlds import panda_scene


def _questions(world):
    rng = np.random.default_rng(7)
    reach = [world.tool_pose(rng.uniform(world.lower, world.upper)) for _ in range(6)]
    far = transforms.pose(None, (1.5, 0.3, 0.4))  # out of reach: every seed misses
    targets = [reach[0], reach[1], far, reach[2], reach[0], far, reach[3], reach[4],
               reach[5], reach[1]]
    seeds = [np.clip(world.start + rng.normal(0.0, 0.3, world.n), world.lower, world.upper)
             for _ in targets]
    seeds[4] = seeds[0]  # the same question again: a memo hit within the batch
    return targets, seeds, [int(rng.integers(1 << 30)) for _ in targets]


@pytest.mark.parametrize("warm", [False, True])
def test_ik_many_answers_as_one_question_after_another(warm):
    """The same outcome for each question (reached or not, from which seed), the same
    configuration to rounding, a repeated question the same answer, and the out-of-reach
    target's second asking (another seed) its first one's miss; `warm`: part of the
    batch asked before."""
    with World(panda_scene(), visuals=False) as one, World(panda_scene(), visuals=False) as many:
        targets, seeds, rng_seeds = _questions(one)
        if warm:
            for world in (one, many):
                world.ik(targets[1], seed=seeds[1], rng_seed=rng_seeds[1])
        expected = [one.ik(t, seed=s, rng_seed=r)
                    for t, s, r in zip(targets, seeds, rng_seeds, strict=True)]
        got = many.ik_many(targets, seeds, rng_seeds)
    assert len(got) == len(expected)
    for (q, res), (q1, res1) in zip(got, expected, strict=True):
        assert (res <= 1e-5) == (res1 <= 1e-5)
        np.testing.assert_allclose(q, q1, atol=1e-6)
    assert sum(res <= 1e-5 for _, res in got) == 8
    assert np.array_equal(got[4][0], got[0][0]) and got[5][1] == got[2][1] > 0.5
    got[0][0][:] = 0.0  # the caller's copy: the memo keeps its own
    assert not np.array_equal(got[4][0], got[0][0])


def test_guess_walk_draws_the_same_seeds_one_by_one_or_batched():
    """GuessWalk.solve_ik_many: the random draws of solve_ik in turn (the walk's rng
    ends in the same state), and the same answers, with jitter."""
    from tampcli.optimize.init import GuessWalk

    with World(panda_scene(), visuals=False) as one, World(panda_scene(), visuals=False) as many:
        targets, _, _ = _questions(one)
        walks = [GuessWalk(types.SimpleNamespace(world=w, planar=False, bodies={}), {},
                           w.start, np.random.default_rng(3), 0.2) for w in (one, many)]
        expected = [walks[0].solve_ik(t) for t in targets]
        got = walks[1].solve_ik_many(targets)
        assert walks[0].rng.integers(1 << 30) == walks[1].rng.integers(1 << 30)
    for (q, res), (q1, res1) in zip(got, expected, strict=True):
        assert (res <= 1e-5) == (res1 <= 1e-5)
        np.testing.assert_allclose(q, q1, atol=1e-6)
