"""A motion started in and out along the approach axis (axial_start.py): blind29 p01's
sample carried out of a closed booth through its 28 cm window, which the via-point
start (a lift into the booth's roof) could not solve and the sampler took 27 s for."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.approach import rung_clear
from tampcli.optimize.assemble import walk
from tampcli.optimize.axial_start import RUNG, _back_off, axial_start
from tampcli.optimize.keyframe_stage import keyframes
from tampcli.optimize.motion import _solve_phase
from tampcli.optimize.path import allowed_contacts, via_points
from tampcli.optimize.run import Run

from .helpers import lowered_folder, ops

P01 = Path(__file__).resolve().parents[2] / "problems" / "blind29" / "p01"


@pytest.fixture(scope="module")
def booth():
    skeleton = ops("(pick sample hood-a)", "(place sample rack)")
    with lowered_folder(P01, "p01", skeleton) as problem:
        run = Run(problem, "path")
        kf = keyframes(run, None)
        assert kf.solved
        yield run, walk(problem, kf.keyframes, kf.choices, run.start)


def _carry(contexts):
    (carry,) = [ctx for ctx in contexts if ctx.held is not None]
    return carry


def test_the_carry_out_of_the_booth_solves_from_the_axial_start_not_from_the_lift(booth):
    run, contexts = booth
    ctx = _carry(contexts)
    problem, T = run.problem, run.problem.options.waypoints
    checks, margin = problem.options.interpolation_checks, problem.options.margin
    label = "the carry"
    held_height = 2 * problem.bodies[ctx.held.name].half[2]
    lift = via_points(problem, ctx.q_a, ctx.q_b, T, held_height, ctx.moved, run.rng,
                      ctx.held).reshape(-1)
    assert _solve_phase(run, ctx, T, checks, label, lift, margin).status != "solved"
    axial = axial_start(run, ctx, T)
    assert axial is not None and axial.shape == ((T - 1) * problem.n,)
    assert _solve_phase(run, ctx, T, checks, label, axial, margin).status == "solved"


def test_the_rungs_over_the_rack_run_back_along_the_axis_clear_of_everything(booth):
    run, contexts = booth
    ctx = _carry(contexts)
    problem, world = run.problem, run.problem.world
    ignore = allowed_contacts(problem.motions[ctx.index])
    rungs = _back_off(problem, run.checker, ctx.q_b, ctx, ignore)
    assert len(rungs) >= 2
    tool = world.tool_pose(np.asarray(ctx.q_b))
    prev = np.asarray(ctx.q_b)
    for j, q in enumerate(rungs, start=1):
        at = world.tool_pose(q)
        expected = tool[:3, 3] - tool[:3, 2] * RUNG * j
        assert np.linalg.norm(at[:3, 3] - expected) < 1e-3
        assert np.allclose(at[:3, :3], tool[:3, :3], atol=1e-3)  # the orientation kept
        assert rung_clear(problem, prev, q, ctx.held, ctx.moved, ignore, 0.0, run.checker)
        prev = q


def test_no_rung_where_backing_out_meets_the_jamb(booth):
    """The sample stands 7 cm off the window's middle: backing straight out from its
    grasp, the Panda's 20 cm hand meets the window's jamb at the first rung, empty or
    holding it, so that end has none (the first rung that fails ends a side)."""
    run, contexts = booth
    reach, carry = contexts[0], _carry(contexts)
    assert reach.held is None
    for ctx, q in ((reach, reach.q_b), (carry, carry.q_a)):
        ignore = allowed_contacts(run.problem.motions[ctx.index])
        assert _back_off(run.problem, run.checker, q, ctx, ignore) == []
