"""A region must lie on its support's top face: nothing can be placed on air.

The region is an axis-aligned rectangle in the world's x-y plane; its support
is a box or an upright cylinder, possibly turned about z. Each corner of the
rectangle, taken into the support's frame, must lie within the top face (a
rectangle or a disc) up to REGION_TOLERANCE.
"""

from __future__ import annotations

import numpy as np

REGION_TOLERANCE = 0.001  # m: rounding in hand-written scene coordinates
_UPRIGHT = 1e-6  # |1 - z-axis . world z| below which a support stands upright


def region_overhang(region, support) -> tuple[float, tuple[float, float]] | None:
    """(how far, which corner) the region's worst corner lies off the top face, or None.

    The support must be upright (`is_upright`): the caller refuses others."""
    pose = support.matrix
    lo, hi = region.lower, region.upper
    corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    local = (corners - pose[:2, 3]) @ pose[:2, :2]  # world x-y -> support x-y (upright)
    if support.shape == "box":
        half = 0.5 * np.array(support.size[:2])
        outside = np.max(np.abs(local) - half, axis=1)
    else:
        outside = np.linalg.norm(local, axis=1) - support.size[0]
    worst = int(np.argmax(outside))
    if outside[worst] <= REGION_TOLERANCE:
        return None
    return float(outside[worst]), (float(corners[worst, 0]), float(corners[worst, 1]))


def is_upright(support) -> bool:
    z = support.matrix[:3, 2]
    return abs(1.0 - z[2]) <= _UPRIGHT
