"""The keyframe guess's batched clash query (init.GuessWalk.clashes) answers each
configuration as the one-at-a-time `clash` does: grasp._choose asks it for a grasp
family's candidates at once (arm-sort -k 6: 10.0-10.2 s against 10.7-11.7 s, the
same answer)."""

from __future__ import annotations

import numpy as np

from tampcli.optimize.init import GuessWalk, final_guess
from tampcli.optimize.problem import lower

from .helpers import ops


def test_batched_clashes_equal_one_at_a_time(wall):
    scene, modes, world = wall
    problem = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    placements, _ = final_guess(problem)
    walk = GuessWalk(problem, placements, world.start, np.random.default_rng(0), 0.0)
    qs = np.random.default_rng(4).uniform(world.lower, world.upper, (40, world.n))
    moved = dict(walk.poses)
    ignores = [{"a"} if i % 2 else {"a", "table"} for i in range(len(qs))]
    batched = walk.clashes(qs, moved, ignores)
    single = [walk.clash(q, moved, ignore=i) for q, i in zip(qs, ignores, strict=True)]
    np.testing.assert_allclose(batched, single, atol=1e-12)
    assert sum(c > 0 for c in single) >= 5  # random arms do come within the margin
