"""The empty hand's straight ends (optimize/retreat.py): it comes down to an object on
a stack and backs off one it set down on a stack along the tool's approach axis, until
its fingers are the margin clear of it; nowhere else. blind31 p06 (KUKA iiwa, two
towers of three): before these, the hand left a2 on its tower with a finger 6 mm
from it, moving sideways, and the physics replay swept a2 off."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.approach import RUNG, SLACK
from tampcli.optimize.assemble import walk
from tampcli.optimize.hand import with_hand
from tampcli.optimize.retreat import REACH, arrival, backoff, departure
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops, solved_in_physics
from .test_vertical_approach import tray_folder

TOWERS = Path(__file__).resolve().parents[2] / "problems" / "blind31" / "p06"
UNSTACK = ops("(unstack d1 a1)", "(place d1 spare)")
RESTACK = ops("(unstack d1 a1)", "(place d1 spare)", "(pick a2 pile)", "(stack a2 a1)",
              "(unstack a3 d3)")


def _narrowed(problem):
    """(the problem with the hand narrowed to the grips its keyframes chose, as the
    path stage has it where the open fingers would not fit, hand.with_hand; the
    motions' contexts at those keyframes, assemble.walk)."""
    kfr = solve(problem, "keyframes")
    assert kfr.solved, kfr.worst_constraint
    narrowed = with_hand(problem, kfr.choices)
    return narrowed, walk(narrowed, kfr.keyframes, kfr.choices, problem.world.start)


def _distance_to(problem, q, moved, name: str) -> float:
    return min((c.distance for c in problem.checker.distances(q, moved, None, frozenset(), 1.0)
                if c.b == f"body:{name}"), default=np.inf)


def _assert_along_the_axis(problem, q, moved, ends, name: str):
    """Each rung is the keyframe's tool pose moved RUNG further back along its z axis,
    turned as there; the last one alone is the margin clear of `name`, and none is
    nearer to it than the keyframe (less 1 mm)."""
    world, margin = problem.world, problem.options.margin
    tool = world.tool_pose(q)
    for j, rung in enumerate(ends.qs, start=1):
        reached = world.tool_pose(rung)
        np.testing.assert_allclose(reached[:3, 3], tool[:3, 3] - tool[:3, 2] * RUNG * j,
                                   atol=1e-4)
        np.testing.assert_allclose(reached[:3, :3], tool[:3, :3], atol=1e-4)
    assert ends.rungs * RUNG <= REACH + 1e-12
    at_keyframe = _distance_to(problem, q, moved, name)
    distances = [_distance_to(problem, rung, moved, name) for rung in ends.qs]
    assert distances[-1] >= margin
    assert all(d < margin for d in [at_keyframe, *distances[:-1]])
    assert min(distances) >= at_keyframe - 1e-3


def test_the_hand_comes_down_to_an_object_on_a_stack_along_its_axis():
    with lowered_folder(TOWERS, "p06", UNSTACK) as problem:
        narrowed, contexts = _narrowed(problem)
        ctx, m = contexts[0], narrowed.motions[0]
        assert m.attached is None and m.enter_contact == {"d1"}
        assert narrowed.motions[1].leave_contact == {"a1"}  # d1 taken off a1, movable
        ends = arrival(narrowed, m, ctx.q_b, ctx.moved, narrowed.checker)
        assert ends is not None
        _assert_along_the_axis(narrowed, ctx.q_b, ctx.moved, ends, "d1")
        # the open hand's fingers are the margin clear of d1 already: nothing to do
        assert arrival(problem, problem.motions[0], ctx.q_b, ctx.moved, problem.checker) \
            is None or _distance_to(problem, ctx.q_b, ctx.moved, "d1") < problem.options.margin


def test_the_hand_backs_off_what_it_stacked_along_its_axis():
    with lowered_folder(TOWERS, "p06", RESTACK) as problem:
        narrowed, contexts = _narrowed(problem)
        ctx, m = contexts[4], narrowed.motions[4]
        assert m.attached is None and m.leave_contact == {"a2"}
        assert narrowed.motions[3].enter_contact == {"a1"}  # a2 set down on a1, movable
        ends = departure(narrowed, m, ctx.q_a, ctx.moved, narrowed.checker)
        assert ends is not None
        _assert_along_the_axis(narrowed, ctx.q_a, ctx.moved, ends, "a2")


def test_no_straight_end_off_a_table_nor_for_a_carry(tmp_path):
    """A can on the table (tray_folder): not a stack, the NLP's path as before; a
    carry's ends are approach.py's; the arm at its start is near nothing."""
    folder = tray_folder(tmp_path, play=0.01, rims=False)
    with lowered_folder(folder, "p", ops("(pick can start)", "(place can tray)")) as problem:
        problem, ctx = _narrowed(problem)
        free, carry = problem.motions[0], problem.motions[1]
        assert arrival(problem, free, ctx[0].q_b, ctx[0].moved, problem.checker) is None
        assert arrival(problem, carry, ctx[1].q_b, ctx[1].moved, problem.checker) is None
        assert departure(problem, carry, ctx[1].q_a, ctx[1].moved, problem.checker) is None
        assert backoff(problem, free, problem.world.start, {}, problem.checker,
                       free.enter_contact) is None


def _with_plate(folder: Path, centre) -> None:
    """A fixed plate (6 x 6 x 1 cm) centred at `centre` added to p06's scene in `folder`."""
    scene = folder / "p06.scene.toml"
    base = folder / "p06.scene.base"
    if not base.exists():
        shutil.copy(scene, base)
    scene.write_text(base.read_text() + (
        '\n[[objects]]\nname = "plate"\nshape = "box"\nsize = [0.06, 0.06, 0.01]\n'
        f'pose = {[float(v) for v in centre]}\nfixed = true\n'))


@pytest.mark.parametrize("room", [0.005, 0.03])
def test_no_rung_comes_nearer_to_anything_than_the_tight_margin(tmp_path, room):
    """A plate on the tool's axis behind the hand, `room` from the arm at d1's grasp:
    no rung comes nearer to it than the tight margin (less SLACK)."""
    folder = tmp_path / "p06"
    shutil.copytree(TOWERS, folder)
    with lowered_folder(folder, "p06", UNSTACK) as problem:
        narrowed, contexts = _narrowed(problem)
        q, choices = contexts[0].q_b, solve(problem, "keyframes").choices
        tool = problem.world.tool_pose(q)
    back = 0.4  # m behind the tool's origin along its axis, brought in until `room` is left
    for _ in range(6):
        _with_plate(folder, tool[:3, 3] - tool[:3, 2] * back)
        with lowered_folder(folder, "p06", UNSTACK) as problem:
            back -= _distance_to(problem, q, {}, "plate") - room
    _with_plate(folder, tool[:3, 3] - tool[:3, 2] * back)
    with lowered_folder(folder, "p06", UNSTACK) as problem:
        problem = with_hand(problem, choices)
        assert _distance_to(problem, q, {}, "plate") == pytest.approx(room, abs=1e-3)
        ends = arrival(problem, problem.motions[0], q, {}, problem.checker)
        # IK may turn the elbow away rather than lift it: a rung is kept where it stays
        # the tight margin (less approach.SLACK) clear, wherever that leaves the arm.
        for rung in ends.qs if ends is not None else ():
            assert _distance_to(problem, rung, {}, "plate") >= \
                problem.options.tight_margin - SLACK - 1e-9


@pytest.mark.slow
def test_two_towers_stand_in_the_physics_replay(cli, tmp_path):
    """blind31 p06 solved and replayed: every piece ends where planned (a2 was swept
    off its tower by the hand leaving it sideways, 5.8 cm and 74 deg)."""
    physics = solved_in_physics(cli, TOWERS, tmp_path, time_limit=90,
                                problem=TOWERS / "p06.pddl")
    assert max(o["distance"] for o in physics["objects"].values()) < 0.003
