"""The planar path stage tries first a grip whose every carry has a start (motion.passable):
blind19 p04, an 18 cm bar through a 12.4 cm doorway, passes held by an end face only."""

from __future__ import annotations

import dataclasses
import math
import time
from pathlib import Path

import pytest

from tampcli.optimize import path_stage
from tampcli.optimize.assemble import walk
from tampcli.optimize.keyframe_stage import keyframes_with
from tampcli.optimize.motion import passable
from tampcli.optimize.planar_motion import held_blocks
from tampcli.optimize.run import Run
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops

P04 = Path(__file__).resolve().parents[2] / "problems" / "blind19" / "p04"
PLAN = ("(pick puck door)", "(place puck side)", "(pick bar bar-home)", "(place bar bar-goal)")


@pytest.fixture(scope="module")
def p04():
    with lowered_folder(P04, "p04", ops(*PLAN)) as problem:
        yield problem


def _carry(run, grip_of_bar: float):
    kfr = keyframes_with(run, None, {2: grip_of_bar})
    assert kfr.solved
    (ctx,) = [c for c in walk(run.problem, kfr.keyframes, kfr.choices, run.start)
              if c.held is not None and c.held.name == "bar"]
    return ctx


def test_only_an_end_face_leaves_the_bar_a_passage(p04):
    run = Run(p04, "path")
    run.deadline = time.perf_counter() + 60
    side, end = _carry(run, math.pi / 2), _carry(run, 0.0)
    assert not passable(run, side)  # disk and bar span 14 cm across the door
    assert held_blocks(run, side)  # the disk alone passes
    assert passable(run, end)
    # With the bar put back out of the door, the disk's own route is the one asked:
    alone = dataclasses.replace(side, held=None, grasp=None)
    assert passable(run, alone)


def test_the_path_stage_carries_the_bar_end_on(p04):
    out = solve(p04, "path")
    assert out.status == "solved", out.worst_constraint
    bar = out.keyframes.grip[2]
    assert abs(math.sin(bar)) < 0.1  # an end face: 0 or 180 degrees


def test_a_door_the_puck_blocks_names_the_puck_from_the_grid_and_tries_no_other_face():
    """The bar carried before the puck is moved: the plane's grid has a route only with
    the puck left out, so the failure names it without the long sampling pass, and as
    the disk alone has no route either, no other face of the bar is tried."""
    with lowered_folder(P04, "p04", ops("(pick bar bar-home)", "(place bar bar-goal)")) as p:
        run = Run(p, "path")
        out = path_stage.path(run, None)
    assert out.status == "infeasible"
    assert "vs puck: in the way of every path found" in out.worst_constraint
    assert run.blocked_alone
