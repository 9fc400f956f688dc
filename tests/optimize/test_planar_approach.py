"""The planar disk sets an object down in a tight slot along a straight line
(planar_approach.py): robust-planar p10, b between a and c with 2 mm a side, whose
turning last segment let the physics replay snag a (4.4 cm) with whitened SLSQP."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.planar_approach import _directions
from tampcli.optimize.solve import solve

from .helpers import lowered_library, ops

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def slot():
    with lowered_library(ROOT / "problems" / "robust-planar", ROOT / "domains" / "robust-planar",
                         "p10", ops("(pick b table)", "(place b shelf)")) as problem:
        yield problem


def test_the_block_goes_into_the_slot_straight_along_its_axis(slot):
    result = solve(slot, "path")
    assert result.solved, result.worst_constraint
    path = np.asarray(result.trajectory)
    end = path[-1]
    # b ends between a (x <= 0.358) and c (x >= 0.442): the last 9 cm (b's 8 cm and
    # 1 cm more) on the line x = end x, coming up along +y.
    tail = path[np.linalg.norm(path - end, axis=1) <= 0.09 + 1e-9]
    assert len(tail) >= 5
    np.testing.assert_allclose(tail[:, 0], end[0], atol=1e-9)
    assert np.all(np.diff(tail[:, 1]) > 0)


class _Contact:
    def __init__(self, normal):
        self.normal = np.asarray(normal, dtype=float)


def test_directions_along_the_slot_first_the_one_towards_the_other_end_leading():
    near = [_Contact((1.0, 0.0, 0.0)), _Contact((-1.0, 0.0, 0.0))]  # walls left and right
    found = _directions(near, np.array([-0.8, -0.3]))
    np.testing.assert_allclose(found[0], [0.0, -1.0], atol=1e-12)  # out the open side
    np.testing.assert_allclose(found[3], [0.0, 1.0], atol=1e-12)
    assert len(found) == 4 + 16
