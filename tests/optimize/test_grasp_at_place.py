"""A retried keyframe guess chooses each grip for the place that ends the hold too.

blind3 p05 (written blind): three boxes packed in a row in a narrow tray. At the
pick either pair of faces is clear; at the place only fingers closing across the
boxes' long sides stay out of the neighbours' room. The first guess keeps the
pick's own choice (the keyframe NLP can slide a placement where there is room);
the retry must close across the long sides of the boxes put in beside others."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.grasp_families import closing_width
from tampcli.optimize.init import keyframe_guess
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops

HERE = Path(__file__).resolve().parents[2] / "problems" / "blind3" / "p05"
SKELETON = ops("(pick a start)", "(place a tray)", "(pick b start)", "(place b tray)",
               "(pick c start)", "(place c tray)")


@pytest.fixture(scope="module")
def packed():
    with lowered_folder(HERE, "p05", SKELETON) as problem:
        yield problem


def test_the_retry_closes_the_fingers_across_the_long_sides(packed):
    final = solve(packed, "final")
    assert final.solved
    _, choices = keyframe_guess(packed, final.placements, packed.world.start,
                                np.random.default_rng(0), jitter=0.4)
    # a goes into an empty tray (either pair of faces is clear there); b and c next
    # to what is already in.
    for step in packed.steps:
        if step.name in ("(pick b start)", "(pick c start)"):
            info = packed.bodies[step.obj]
            width = closing_width(info, choices[step.index].psi)
            assert width == pytest.approx(2 * max(info.half[:2])), step.name
