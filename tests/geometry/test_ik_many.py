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


def test_grouped_batch_runs_each_group_as_alone():
    """ik._levenberg_marquardt_batch with `starts`: the seeds of several questions in
    one batch, each group stopping by its own first success in order, give what each
    group run alone gives (reached from the same seed, the same configuration)."""
    from tampcli.geometry import ik

    with World(panda_scene(), visuals=False) as world:
        rng = np.random.default_rng(5)
        truths = [rng.uniform(world.lower, world.upper) for _ in range(4)]
        targets = [world.tool_pose(q) for q in truths[:3]]
        targets.append(transforms.pose(None, (1.5, 0.3, 0.4)))  # no seed reaches it
        # seeds nearer the answer down the group: some succeed, from different rows;
        # the first group's first seed is its answer (the group is done at once, and
        # must not stop the others)
        groups = [np.clip([q + rng.normal(0.0, sigma, world.n)
                           for sigma in (2.0, 1.0, 0.5, 0.2, 0.05)], world.lower, world.upper)
                  for q in truths]
        groups[0][0] = truths[0]
        rows = slice(0, 6)
        alone = [ik._levenberg_marquardt_batch(world, t, g, rows, 200, 1e-5)
                 for t, g in zip(targets, groups, strict=True)]
        aims = np.array([t for t, g in zip(targets, groups, strict=True) for _ in g])
        qs, res = ik._levenberg_marquardt_batch(world, aims, np.vstack(groups), rows, 200,
                                                1e-5, starts=[0, 5, 10, 15])
    for k, (q1, r1) in enumerate(alone):
        q, r = qs[5 * k:5 * k + 5], res[5 * k:5 * k + 5]
        ok1, ok = r1 <= 1e-5, r <= 1e-5
        assert ok.any() == ok1.any()
        if ok1.any():
            i = int(np.argmax(ok1))
            assert int(np.argmax(ok)) == i
            np.testing.assert_allclose(q[i], q1[i], atol=1e-6)
    assert sum(bool((r <= 1e-5).any()) for _, r in alone) >= 2
    assert res[15:].min() > 0.5
