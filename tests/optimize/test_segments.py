"""A motion started from a sampled path with many corners gets the segments it needs,
and its cost is weighed as if it had the options' `waypoints`."""

import numpy as np

from tampcli.optimize.assemble import motion_costs
from tampcli.optimize.motion import MAX_SEGMENTS_RATIO, segments_for
from tampcli.solution import Phase


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


def test_a_straight_motion_costs_the_same_on_any_number_of_segments():
    q_a, q_b, T = np.zeros(3), np.array([0.3, -0.2, 0.5]), 10
    for segments in (T, 24, 40):
        traj = np.linspace(q_a, q_b, segments + 1)
        (cost,) = motion_costs(traj, [Phase(None, 0, segments)], T)
        np.testing.assert_allclose(cost, np.sum((q_b - q_a) ** 2) / T)


def test_each_motion_is_weighed_by_its_own_segments_and_actions_cost_nothing():
    T = 4
    traj = np.concatenate([np.linspace(0.0, 1.0, 5), np.linspace(1.0, 3.0, 9)[1:]])[:, None]
    phases = [Phase(None, 0, 4), Phase("(pick a)", 4, 4), Phase(None, 4, 12)]
    first, second = motion_costs(traj, phases, T)
    np.testing.assert_allclose([first, second], [1.0 / 4, 4.0 / 4])
