"""The keyframe guess ranks a place's candidate yaws by how deep the hand is, not only
by whether it is within the margin.

blind2 p01 (written blind): a can side-grasped out of one roofed nook and put into
another, both open towards the robot between two posts. Every candidate place is
within the 1 cm margin of something; the one approaching along +x is 6 mm from
the roof, the others 3 cm into a post. Ranked by "within the margin or not", the
nearest configuration won and the keyframe NLP started with the hand in a post."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.init import keyframe_guess
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops

HERE = Path(__file__).resolve().parents[2] / "problems" / "blind2" / "p01"


@pytest.fixture(scope="module")
def nooks():
    with lowered_folder(HERE, "p01", ops("(pick can nook-a)", "(place can nook-b)")) as problem:
        yield problem


def test_the_place_in_the_nook_is_guessed_from_its_open_side(nooks):
    final = solve(nooks, "final")
    kf, _ = keyframe_guess(nooks, final.placements, nooks.world.start,
                           np.random.default_rng(0), jitter=0.4)
    approach = nooks.world.tool_pose(kf.q[1])[:3, 2]
    assert approach[0] > 0.9  # into the nook along +x, between its posts
    d = nooks.checker.min_distance(kf.q[1], None, None, frozenset({"can"}), static=False,
                                   horizon=0.05)
    assert d > -0.005  # touching at most (the keyframe NLP clears it), not 3 cm into a post
