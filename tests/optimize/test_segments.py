"""A motion started from a sampled path with many corners gets the segments it needs
(its cost weighed as if it had the options' `waypoints`: test_straight_line.py)."""

import numpy as np

from tampcli.optimize.motion import MAX_SEGMENTS_RATIO, segments_for


def _path(vertices: int) -> np.ndarray:
    return np.column_stack([np.arange(vertices, dtype=float), np.zeros(vertices)])


def test_a_path_with_few_corners_keeps_the_options_segments():
    assert segments_for(_path(2), 10) == 10
    assert segments_for(_path(11), 10) == 10  # 10 edges: each vertex a waypoint


def test_a_path_with_more_corners_gets_twice_its_edges_up_to_the_cap():
    assert segments_for(_path(13), 10) == 24  # blind7 p03's maze: 12 edges
    assert segments_for(_path(30), 10) == MAX_SEGMENTS_RATIO * 10  # 58 capped at 40
    # More edges than the cap: every edge still gets its own segment.
    assert segments_for(_path(60), 10) == 59
