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
from tampcli.optimize.modes import load_modes
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.path import allowed_contacts
from tampcli.optimize.problem import lower
from tampcli.optimize.run import Run
from tampcli.optimize.solve import solve
from tampcli.optimize.values import Placement
from tampcli.pddl import parser

from .helpers import lowered_folder, ops

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


def _carry_through_the_corridor(problem, b1_xy):
    """An Obstruction as relocate.find leaves it: the carry of t from the yard into
    the pen's open end (x 0.1) along y = 0, with b1 set down at b1_xy."""
    grasp = np.eye(4)
    grasp[0, 3], grasp[2, 3] = -0.18, -0.01  # t held beside the disk, as the grip puts it
    b1 = np.eye(4)
    b1[:3, 3] = (*b1_xy, 0.025)
    path = np.array([[-0.32, -0.15], [-0.25, 0.0], [0.46, 0.0]])
    ignore = allowed_contacts(problem.motions[3]) | {"b1"}
    return relocate.Obstruction(3, path, ("b1",), ("t", grasp), {"b1": b1}, ignore)


def test_a_blocker_in_the_corridor_is_given_spots_clear_of_the_carry(pen):
    problem = _problem(pen)
    run = Run(problem, "path")
    obstruction = _carry_through_the_corridor(problem, (-0.09, 0.0))
    first = {1: Placement(-0.09, 0.0, 0.0), 3: Placement(0.3, 0.0, 0.0)}
    assert not relocate.still_clear(run, obstruction, first)
    found = relocate.relocations(run, obstruction, first)
    assert len(found) == 3
    for move in found:
        xy, radius = move.anchors[1]
        assert 0.0 < radius <= relocate.ANCHOR
        np.testing.assert_allclose(move.origins[1], xy)
        np.testing.assert_allclose(move.origins[3], [0.3, 0.0])  # t's placement kept
        assert np.all(xy >= [-0.75, -0.35]) and np.all(xy <= [-0.05, 0.35])  # the yard
        assert relocate.still_clear(run, obstruction, {1: Placement(*xy, 0.0)})


def test_the_path_stage_solves_the_skeleton_whatever_the_keyframes_chose(pen):
    # Where the keyframe NLP sets b1 down depends on its start; wherever that is,
    # the carry must find its way (b1 relocated where it is in the way).
    result = solve(_problem(pen), "path")
    assert result.solved, result.worst_constraint


def test_what_the_motion_carries_is_no_obstruction_of_its_own(monkeypatch):
    """blind33 p02 (written blind): the bar put back in its nook and taken again; the
    carry after it looked for a path with the bar left out, as an object this skeleton
    had set down (17 s of sampling a path that ignored what it carried)."""
    from types import SimpleNamespace

    from tampcli.optimize.collide import Held
    from tampcli.optimize.grips import TopGrip

    folder = Path(__file__).resolve().parents[2] / "problems" / "blind33" / "p02"
    asked = []
    monkeypatch.setattr(relocate, "sampled_path", lambda *a, **k: asked.append(1))
    skeleton = ops("(grab bar nook)", "(drop bar nook)", "(grab bar nook)", "(drop bar goal)")
    with lowered_folder(folder, "p02", skeleton) as problem:
        carry = next(m for m in problem.motions if m.step == 3)  # into (drop bar goal)
        bar = np.eye(4)
        assert relocate.relocatable(problem, carry.index, {"bar": bar}) == {"bar": 1}
        ctx = SimpleNamespace(index=carry.index, moved={"bar": bar},
                              held=Held("bar", TopGrip((0.0, 0.0, 0.0)), 0.0, None, np.eye(4)),
                              q_a=np.zeros(problem.n), q_b=np.zeros(problem.n))
        assert relocate.find(SimpleNamespace(problem=problem), ctx, None) is None
    assert not asked
