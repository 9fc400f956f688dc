"""An object stacked on a box starts at a yaw its footprint fits the box's top at
(final_starts._stacked_yaw): blind34 p04's 6 x 3 cm bar, standing at -20 degrees, onto
a 6.4 x 3.4 cm plate turned 35 degrees ended across it (`footprint off the top of
plate-a by 1.3 cm`) in 15 of 18 skeletons: the pull sin^2(2 dyaw) is as low a quarter
turn off."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from tampcli.optimize.final_starts import starts
from tampcli.optimize.keyframe_stage import final
from tampcli.optimize.run import Run

from .helpers import lowered_folder, ops

P04 = Path(__file__).resolve().parents[2] / "problems" / "blind34" / "p04"


@pytest.fixture(scope="module")
def kit():
    with lowered_folder(P04, "p04", ops("(pick bar bar-home)", "(place bar plate-a)")) as p:
        yield p


def test_the_bar_starts_along_the_turned_plate(kit):
    plate = kit.bodies["plate-a"].pose[3]
    assert kit.bodies["bar"].pose[3] == pytest.approx(math.radians(-20), abs=1e-3)
    for start in starts(kit):
        placements, _ = start(kit)
        yaw = placements[1].yaw
        assert abs(math.remainder(yaw - plate, math.pi)) < math.radians(1)


def test_the_final_stage_puts_the_bar_on_the_plate(kit):
    out = final(Run(kit, "final"))
    assert out.status == "solved", out.worst_constraint
    yaw = out.placements[1].yaw
    assert abs(math.remainder(yaw - kit.bodies["plate-a"].pose[3], math.pi)) < math.radians(2)
