"""A region lies on its support's top face: boxes turned about z, and discs."""

import math

import pytest

from tampcli.geometry.model import Body, Region
from tampcli.geometry.region_check import REGION_TOLERANCE, is_upright, region_overhang


def _turned_box(yaw: float) -> Body:
    q = (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
    return Body(name="shelf", shape="box", size=(0.8, 0.2, 0.02), pose=(0.5, 0.0, 0.3, *q))


def test_a_turned_box_holds_what_lies_along_its_turned_length():
    along_y = Region("r", "shelf", center=(0.5, 0.3), size=(0.1, 0.1))
    assert region_overhang(along_y, _turned_box(0.0)) is not None
    assert region_overhang(along_y, _turned_box(math.pi / 2)) is None


def test_overhang_is_measured_at_the_worst_corner():
    region = Region("r", "shelf", center=(0.88, 0.0), size=(0.1, 0.1))
    far, corner = region_overhang(region, _turned_box(0.0))
    assert far == pytest.approx(0.03)
    assert corner[0] == pytest.approx(0.93)


def test_a_disc_holds_a_square_only_when_its_corners_are_within_the_radius():
    disc = Body(name="plate", shape="cylinder", size=(0.1, 0.02), pose=(0.0, 0.0, 0.01, 0.0, 0.0, 0.0, 1.0))
    inside = Region("r", "plate", center=(0.0, 0.0), size=(0.14, 0.14))  # corner at 0.099
    outside = Region("r", "plate", center=(0.0, 0.0), size=(0.15, 0.15))  # corner at 0.106
    assert region_overhang(inside, disc) is None
    far, _ = region_overhang(outside, disc)
    assert far == pytest.approx(math.hypot(0.075, 0.075) - 0.1) and far > REGION_TOLERANCE


def test_a_tilted_support_is_not_upright():
    tilt = (math.sin(0.1), 0.0, 0.0, math.cos(0.1))
    assert not is_upright(Body(name="ramp", shape="box", size=(1, 1, 0.02), pose=(0, 0, 0, *tilt)))
    assert is_upright(_turned_box(1.0))
