"""The hand opened only as wide as the skeleton's grips need (optimize/hand.py),
where the open hand fails.

blind10 p05 (written blind): bar-2, 2.4 cm across, stands with its long side
6 cm from a bin's rim. The Panda's fingers fully open reach 5.7 cm from the
tool's axis, so with the 1 cm margin no grip across the bar cleared the rim
(the bar's 6.8 cm length fits the open hand too, but the rim is then at its
end). Opened to the bar's width and 6 mm a side, the fingers stand clear.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.grasp_families import closing_width
from tampcli.optimize.hand import CLEARANCE, grasp_width, hand_for, hand_of, with_hand
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, lowered_library, ops

FOLDER = Path(__file__).resolve().parents[2] / "problems" / "blind10" / "p05"
SKELETON = ops("(pick-up bar-2 mat)", "(bin-bar bar-2 bin-r)")
RIM = "bin-r-tray-rim-w"


@pytest.fixture(scope="module")
def bar():
    with lowered_folder(FOLDER, "p05", SKELETON) as problem:
        yield problem


@pytest.fixture(scope="module")
def solved(bar):
    return solve(bar, "path")


@pytest.mark.parametrize("width", [0.012, 0.024, 0.048, 0.06])
def test_the_hand_opens_to_the_width_and_the_clearance(bar, width):
    hand = hand_for(bar.world, width)
    need = width + 2 * CLEARANCE
    # Measured on the finger shapes: at least what is needed, within the bisection.
    assert need <= hand.opening <= need + 1e-6
    (open_, closed), _ = bar.world.finger_range
    assert all(closed <= v <= open_ for v in hand.values)
    touching = hand_for(bar.world, width, clearance=0.0)
    assert width <= touching.opening <= width + 1e-6
    assert all(t < v for t, v in zip(touching.values, hand.values, strict=True))


def test_a_width_the_hand_barely_takes_keeps_it_open(bar):
    assert hand_for(bar.world, bar.world.gripper_opening - CLEARANCE).values is None
    assert hand_for(bar.world, None).values is None


def test_the_width_is_the_chosen_faces(bar, solved):
    (grasp,) = [s for s in bar.steps if s.kind.fingers is True]
    choice = solved.choices[grasp.index]
    assert grasp_width(bar, solved.choices) == closing_width(bar.bodies["bar-2"], choice.psi)
    assert grasp_width(bar, {}) is None
    assert hand_of(bar, {}) == bar.hand  # nothing grasped: open


def test_a_checker_with_fingers_answers_as_rows_that_give_them(bar):
    rng = np.random.default_rng(3)
    world = bar.world
    qs = world.start + rng.normal(0.0, 0.3, size=(12, world.n))
    values = hand_for(world, 0.03).values
    narrow = bar.checker.with_fingers(values)
    by_default = narrow.distances_many(qs, activation=0.5)
    given = bar.checker.distances_many(qs, activation=0.5, fingers=np.tile(values, (12, 1)))
    opened = bar.checker.distances_many(qs, activation=0.5)

    def table(rows):
        return [sorted((c.a, c.b, round(c.distance, 12)) for c in row) for row in rows]

    assert table(by_default) == table(given)
    assert table(by_default) != table(opened)  # the fingers moved: some distance changed


def test_the_bar_beside_the_rim_is_picked_with_the_hand_narrowed(bar, solved):
    assert solved.solved, solved.worst_constraint
    assert solved.narrowed  # the open hand failed first
    narrowed = with_hand(bar, solved.choices)
    assert narrowed.hand.opening < bar.world.gripper_opening - 0.01
    q = np.asarray(solved.keyframes.q[0])
    margin = bar.options.margin

    def rim_distance(checker):
        found = checker.distances(q, ignore=frozenset({"bar-2"}), activation=0.1)
        return min(c.distance for c in found if RIM in c.b)

    # Where the NLP put the hand, the open fingers would be within the margin of the
    # rim (or in it); the hand it planned with keeps the margin.
    assert rim_distance(narrowed.checker) >= margin - 1e-4
    assert rim_distance(bar.checker) < margin - 0.005


def test_the_finger_columns_close_on_the_bar_while_it_is_held(bar, solved):
    narrowed = with_hand(bar, solved.choices)
    fingers = solved.fingers
    assert fingers.shape == (len(solved.trajectory), 2)
    grasp_at = next(p.end for p in solved.phases if p.action == "(pick-up bar-2 mat)")
    place_at = next(p.end for p in solved.phases if p.action == "(bin-bar bar-2 bin-r)")
    (grasp,) = [s for s in bar.steps if s.kind.fingers is True]
    width = closing_width(bar.bodies["bar-2"], solved.choices[grasp.index].psi)
    touching = hand_for(bar.world, width, clearance=0.0).values
    assert np.allclose(fingers[grasp_at:place_at + 1], touching)
    assert np.allclose(fingers[:grasp_at], narrowed.hand.values)
    assert np.allclose(fingers[place_at + 1:], narrowed.hand.values)


def test_the_report_says_which_faces_the_fingers_close_on(bar, solved):
    (entry,) = solved.grasp_report
    assert entry["action"] == "(pick-up bar-2 mat)" and entry["object"] == "bar-2"
    # The grip across the bar's 2.4 cm (its y faces: it is 6.8 cm along x), the only
    # one clear of the rim; the hand opened for it.
    assert entry["faces"] == "±y" and entry["width"] == pytest.approx(0.024)
    assert entry["hand_opening"] == pytest.approx(0.024 + 2 * CLEARANCE, abs=1e-6)
    assert (entry["pitch"] is None) == (entry["family"] == "top")


def test_a_plan_with_a_push_keeps_the_hand_open():
    """blind10 p08: a cup picked, a crate pushed; the push's contact is modelled on
    the open fingers, and validate checks it so."""
    folder = FOLDER.parent / "p08"
    skeleton = ops("(grab cup lane)", "(stow cup spare)", "(shove crate c-home lane bay)",
                   "(grab tag rack)", "(perch tag crate bay)")
    with lowered_folder(folder, "p08", skeleton) as problem:
        grasps = [s for s in problem.steps if s.kind.fingers is True]
        assert grasps and hand_of(problem, {}) == problem.hand
        first = solve(problem, "keyframes")
        assert first.solved
        assert grasp_width(problem, first.choices) is not None  # it grasps...
        assert hand_of(problem, first.choices).values is None  # ...and stays open


def test_an_object_straddled_by_mm_keeps_half_that_on_the_way_down():
    """arm-pick-place p01: the hand opened 6 mm a side of the 5 cm cube. The approach
    keeps half the keyframe's distance to the cube before its last segment, not the
    1 cm margin (which only a detour could keep: arm-kitchen's motions then cost up
    to 7 times their straight line)."""
    from tampcli.optimize.assemble import walk
    from tampcli.optimize.path import motion_margins

    folder = FOLDER.parents[1] / "arm-pick-place"
    domain = FOLDER.parents[2] / "domains" / "arm-pick-place"
    skeleton = ops("(pick a start)", "(place a goal)")
    with lowered_library(folder, domain, "p01", skeleton) as problem:
        kfr = solve(problem, "keyframes")
        narrowed = with_hand(problem, kfr.choices)
        ctx = walk(narrowed, kfr.keyframes, kfr.choices, problem.world.start)[0]
        m = narrowed.motions[0]
        opts = narrowed.options
        d = narrowed.checker.min_distance(ctx.q_b, ctx.moved, None, frozenset(), static=False)
        assert 2 * opts.tight_margin < d < opts.margin  # straddled with millimetres
        own = motion_margins(narrowed.checker, m, ctx.q_a, ctx.q_b, None, ctx.moved,
                             opts.margin, opts.tight_margin, straddle=True)
        assert own.near["a"] == pytest.approx(d / 2, abs=1e-6)
        # The open hand keeps the margin until the last segment, as it always did.
        assert "a" not in motion_margins(narrowed.checker, m, ctx.q_a, ctx.q_b, None,
                                         ctx.moved, opts.margin, opts.tight_margin).near
        path = solve(problem, "path", warm=dataclasses.replace(kfr, narrowed=True))
        assert path.narrowed
        assert path.solved
        # No detour: within 1 % of the straight line's |dq|^2 / T, the least there is.
        dq = np.asarray(ctx.q_b) - np.asarray(ctx.q_a)
        assert path.phase_costs[0] == pytest.approx(float(dq @ dq) / opts.waypoints, rel=0.01)


def test_a_plan_the_open_hand_solves_keeps_it_open():
    """arm-pick-place p01: nothing near the cube but the table; the open hand solves
    it, so the solution's fingers are left out (open unless closed on the cube)."""
    folder = FOLDER.parents[1] / "arm-pick-place"
    domain = FOLDER.parents[2] / "domains" / "arm-pick-place"
    with lowered_library(folder, domain, "p01", ops("(pick a start)", "(place a goal)")
                         ) as problem:
        path = solve(problem, "path")
        assert path.solved and not path.narrowed
        assert hand_of(problem, path.choices) != problem.hand  # narrowing was possible
        assert path.fingers is None
