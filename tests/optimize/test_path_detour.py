"""A motion sampled finer after `verify` failed is not left on a long detour.

blind3 p06 (written blind): a hand entering under a shelf board to grasp a tall
box. The first path dips into the board between samples; solved again from its
last solution at finer samples it stayed feasible only by swinging the arm
round (1.2 -> 4.6 -> 18.7 rad^2), and the replay under physics knocked the box
off its pedestal. Solved afresh as well, it costs what the keyframes say."""

from __future__ import annotations

from pathlib import Path

import pytest

from tampcli.optimize.solve import solve
from tampcli.optimize.verify import verify

from .helpers import lowered_folder, ops

HERE = Path(__file__).resolve().parents[2] / "problems" / "blind3" / "p06"


@pytest.fixture(scope="module")
def shelf():
    with lowered_folder(HERE, "p06", ops("(pick box under)", "(place box pedestal)")) as problem:
        yield problem


def test_the_grasp_under_the_shelf_costs_about_what_its_keyframes_say(shelf):
    keyframes = solve(shelf, "keyframes")
    path = solve(shelf, "path", keyframes)
    assert path.solved, path.worst_constraint
    assert verify(shelf, path, factor=10) == []
    assert path.cost < 2.0 * keyframes.cost
