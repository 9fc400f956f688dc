"""A tall object grasped from the side in a shelf slot under a top board
(blind8 p03's class): the via-point start backs the hand out along its approach
before lifting it (way_out); straight up it ran through the board, and the path
NLP could not get the hand out from there."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.assemble import walk
from tampcli.optimize.collide import held_spec
from tampcli.optimize.path import allowed_contacts, via_points
from tampcli.optimize.solve import solve
from tampcli.optimize.verify import verify
from tampcli.optimize.way_out import _box_exit, _disk_exit, way_out

from .helpers import lowered_folder, ops

SLOT = Path(__file__).resolve().parent / "scenes" / "slot"
BOARD_FRONT = 0.33  # m: the board's front edge (x), slot.scene.toml


@pytest.fixture(scope="module")
def slot():
    with lowered_folder(SLOT, "slot", ops("(take flask slot)", "(set flask dst)")) as problem:
        keyframes = solve(problem, "keyframes")
        assert keyframes.solved, keyframes.worst_constraint
        yield problem, keyframes


def _contexts(problem, keyframes):
    return walk(problem, keyframes.keyframes, keyframes.choices, problem.world.start)


def test_the_grasp_in_the_slot_is_left_backwards_out_from_under_the_board(slot):
    problem, keyframes = slot
    grasp, carry = _contexts(problem, keyframes)
    for q, held in ((grasp.q_b, None), (carry.q_a, carry.held)):
        out = way_out(problem, q, carry.moved, held)
        assert out is not None and out.configs
        tool = problem.world.tool_pose(q)
        # Back along the approach: further from the board, no higher than the lift.
        assert out.tool[0, 3] < tool[0, 3] - 0.05
        assert out.tool[0, 3] < BOARD_FRONT
        assert 0.0 <= out.tool[2, 3] - tool[2, 3] <= 0.015 + 1e-9
        first = problem.world.tool_pose(out.configs[0])
        assert np.allclose(first[:3, :3], tool[:3, :3], atol=1e-3)


def test_nothing_over_the_hand_on_the_table_means_no_way_out(slot):
    problem, keyframes = slot
    _, carry = _contexts(problem, keyframes)
    assert way_out(problem, carry.q_b, carry.moved, carry.held) is None


def test_the_start_of_the_carry_out_keeps_out_of_the_board(slot):
    """Before way_out the start's first waypoints were in the board (measured on
    blind8 p03: `flask-a vs shelf-top by 4.9 cm` after the NLP from it)."""
    problem, keyframes = slot
    _, carry = _contexts(problem, keyframes)
    T = problem.options.waypoints
    x0 = via_points(problem, carry.q_a, carry.q_b, T, 0.15, carry.moved,
                    np.random.default_rng(0), carry.held)
    found = problem.checker.distances_many(x0, carry.moved, held_spec(carry.held),
                                           [allowed_contacts(problem.motions[carry.index])]
                                           * len(x0), 0.05)
    board = [c.distance for cs in found for c in cs if c.b == "body:shelf-top"]
    assert min(board, default=0.05) > -0.01


def test_exits_of_a_box_and_a_disk():
    assert _box_exit(np.array([0.1, 0.0]), np.array([-1.0, 0.0]), np.array([0.2, 0.1])) \
        == pytest.approx(0.3)
    assert _box_exit(np.array([0.3, 0.0]), np.array([-1.0, 0.0]), np.array([0.2, 0.1])) is None
    assert _disk_exit(np.array([0.0, 0.0]), np.array([0.6, 0.8]), 0.2) == pytest.approx(0.2)
    assert _disk_exit(np.array([0.3, 0.0]), np.array([1.0, 0.0]), 0.2) is None


def test_the_flask_comes_out_of_the_slot_verified(slot):
    problem, keyframes = slot
    path = solve(problem, "path", keyframes)
    assert path.solved, path.worst_constraint
    assert verify(problem, path, factor=10) == []
