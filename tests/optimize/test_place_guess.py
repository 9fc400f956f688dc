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

from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.optimize.init import keyframe_guess
from tampcli.optimize.modes import load_modes
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.pddl import parser

from .helpers import ops

HERE = Path(__file__).resolve().parents[2] / "problems" / "blind2" / "p01"


@pytest.fixture(scope="module")
def nooks():
    domain = parser.parse_domain_file(HERE / "domain.pddl")
    problem = parser.parse_problem_file(HERE / "p01.pddl")
    scene = load_scene(HERE / "p01.scene.toml", domain, problem)
    modes = load_modes(HERE / "modes.toml", domain)
    with World(scene) as world:
        yield lower(ops("(pick can nook-a)", "(place can nook-b)"), scene, modes, world,
                    OptimizeOptions(), domain=domain, checker=CollisionChecker(world))


def test_the_place_in_the_nook_is_guessed_from_its_open_side(nooks):
    final = solve(nooks, "final")
    kf, _ = keyframe_guess(nooks, final.placements, nooks.world.start,
                           np.random.default_rng(0), jitter=0.4)
    approach = nooks.world.tool_pose(kf.q[1])[:3, 2]
    assert approach[0] > 0.9  # into the nook along +x, between its posts
    d = nooks.checker.min_distance(kf.q[1], None, None, frozenset({"can"}), static=False,
                                   horizon=0.05)
    assert d > -0.005  # touching at most (the keyframe NLP clears it), not 3 cm into a post
