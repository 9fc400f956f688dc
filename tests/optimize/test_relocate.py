"""Objects set down in a later motion's way are moved out of it (optimize/relocate).

robust-planar pen-k1: the blocker taken out of the pen is put down by the final
NLP at the yard's edge, in front of the pen's open end; the carry of the target
into the pen then has no path. The path stage must find that the blocker is the
obstruction, put it elsewhere in the yard, and solve the skeleton."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.optimize import relocate
from tampcli.optimize.assemble import walk
from tampcli.optimize.modes import load_modes
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve
from tampcli.pddl import parser

from .helpers import ops

ROOT = Path(__file__).resolve().parents[2]
DOMAIN = ROOT / "domains" / "robust-planar" / "domain.pddl"
PEN = ROOT / "problems" / "robust-planar" / "pen-k1"
SKELETON = ops("(pick b1 pen)", "(place b1 yard)", "(pick t yard)", "(place t pen)")


@pytest.fixture(scope="module")
def pen():
    domain = parser.parse_domain_file(DOMAIN)
    problem = parser.parse_problem_file(PEN.with_suffix(".pddl"))
    scene = load_scene(PEN.with_suffix(".scene.toml"), domain, problem)
    modes = load_modes(DOMAIN.with_name("modes.toml"), domain)
    with World(scene) as world:
        yield domain, scene, modes, world, CollisionChecker(world)


def _problem(pen, **options):
    domain, scene, modes, world, checker = pen
    return lower(SKELETON, scene, modes, world, OptimizeOptions(time_limit=60.0, **options),
                 domain=domain, checker=checker)


def test_only_objects_put_into_a_region_before_the_motion_are_relocatable(pen):
    problem = _problem(pen)
    moved = {"b1": np.eye(4)}
    assert relocatable_steps(problem, 3, moved) == {"b1": 1}
    assert relocatable_steps(problem, 1, moved) == {}  # b1 is still held on the way


def relocatable_steps(problem, motion, moved):
    return relocate.relocatable(problem, motion, moved)


def _b1_where_carry_starts(problem, result):
    contexts = walk(problem, result.keyframes, result.choices, problem.world.start)
    return contexts[3].moved["b1"][:2, 3]


def test_the_keyframes_block_the_carry_and_the_path_stage_moves_b1(pen):
    problem = _problem(pen)
    keyframes = solve(problem, "keyframes")
    assert keyframes.solved
    before = _b1_where_carry_starts(problem, keyframes)
    result = solve(problem, "path")
    assert result.solved, result.worst_constraint
    after = _b1_where_carry_starts(problem, result)
    # The keyframe NLP (cheapest carry) sets b1 down at the yard's edge in front of
    # the pen's open end (x 0.1): the target (26 cm long) cannot pass. The path
    # stage sets it down elsewhere in the yard.
    assert before[0] > -0.25 and abs(before[1]) < 0.15
    assert np.linalg.norm(after - before) > 0.1
    assert np.all(after >= [-0.75, -0.35]) and np.all(after <= [-0.05, 0.35])
