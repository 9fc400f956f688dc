"""broad.broad_gaps, in both its forms (transposed on many rows, plain on a few), is the
larger of the world-aligned box gap and the sphere gap, for every broadcast the
checker uses (links x bodies, self pairs, held parts x bodies)."""

import numpy as np
import pytest

from tampcli.geometry.broad import TRANSPOSED_FROM, broad_gaps


def _direct(a_c, a_aabb, a_s, a_radius, b_c, b_aabb, b_s, b_radius):
    apart = np.maximum(np.abs(a_c - b_c) - a_aabb - b_aabb, 0.0)
    box = np.sqrt((apart ** 2).sum(axis=-1))
    sphere = np.linalg.norm(a_s - b_s, axis=-1) - a_radius - b_radius
    return np.maximum(box, sphere)


def _boxes(rng, *shape):
    centres = rng.normal(scale=0.12, size=(*shape, 3))
    return (centres, rng.uniform(0.0, 0.1, (*shape, 3)),
            centres + rng.normal(scale=0.02, size=(*shape, 3)))


@pytest.mark.parametrize("rows", [3, 5 * TRANSPOSED_FROM])
def test_broad_gaps_forms(rows):
    rng = np.random.default_rng(rows)
    lc, la, ls = _boxes(rng, rows, 11)
    lr = rng.uniform(0.05, 0.15, 11)
    for shared in (1, rows):  # one world state for all rows, or one per row
        bc, ba, bs = _boxes(rng, shared, 7)
        br = rng.uniform(0.05, 0.15, 7)
        args = (lc[:, :, None], la[:, :, None], ls[:, :, None], lr[None, :, None],
                bc[:, None], ba[:, None], bs[:, None], br)
        got = broad_gaps(*args)
        assert got.shape == (rows, 11, 7)
        np.testing.assert_allclose(got, _direct(*args), atol=1e-12)
    ia, ib = rng.integers(11, size=(2, 30))
    args = (lc[:, ia], la[:, ia], ls[:, ia], lr[ia], lc[:, ib], la[:, ib], ls[:, ib], lr[ib])
    got = broad_gaps(*args)
    assert got.shape == (rows, 30)
    np.testing.assert_allclose(got, _direct(*args), atol=1e-12)
    # Some pairs on each side of a 0.05 m activation: the comparison is not vacuous.
    assert 0 < (got <= 0.05).sum() < got.size
