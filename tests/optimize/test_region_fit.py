"""The region-fit proof is exact: a footprint is refused only where it fits at no yaw."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from tampcli.geometry.model import Region
from tampcli.optimize.bodies import BodyInfo, rectangle_fits, region_misfit


def _stick(a, b):
    return BodyInfo("s", "box", (a / 2, b / 2, 0.01), False, (0.0, 0.0, 0.01, 0.0), True)


def test_a_long_stick_fits_a_square_region_only_turned():
    region = Region("goal", "table", (0.5, 0.0), (0.12, 0.12))
    assert region_misfit("s", _stick(0.14, 0.01), region) is None  # 10.6 cm wide at 45 deg
    narrow = Region("slot", "table", (0.5, 0.0), (0.12, 0.012))
    why = region_misfit("s", _stick(0.14, 0.01), narrow)
    assert why == "s (14.0 x 1.0 cm) does not fit region slot (12.0 x 1.2 cm) at any yaw"


def test_square_fits_either_way_round():
    assert rectangle_fits(0.05, 0.03, 0.03, 0.05) and rectangle_fits(0.05, 0.03, 0.05, 0.03)
    assert not rectangle_fits(0.05, 0.05, 0.049, 0.2)


def _sampled(a, b, w, h, n=20001):
    t = np.linspace(0.0, 0.5 * math.pi, n)
    ok = (a * np.cos(t) + b * np.sin(t) <= w + 1e-9) & (a * np.sin(t) + b * np.cos(t) <= h + 1e-9)
    return bool(ok.any())


sizes = st.floats(0.005, 0.3)


@settings(max_examples=400, deadline=None)
@given(sizes, sizes, sizes, sizes)
def test_agrees_with_a_dense_sweep_of_yaws(a, b, w, h):
    exact = rectangle_fits(a, b, w, h)
    if _sampled(a, b, w, h):
        assert exact  # a yaw the sweep found: never refused
    elif exact:
        # A yaw window narrower than the sweep's step: a finer sweep, with a hair of
        # room, finds it too.
        assert _sampled(a, b, w * (1 + 1e-6), h * (1 + 1e-6), n=2_000_001)
