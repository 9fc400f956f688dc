"""The planar robot's grid route: round several walls, clear of them where there is room."""

import numpy as np
import pytest

from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.planar_route import RouteOptions, planar_route
from tampcli.geometry.scene import RobotSpec, Scene
from tampcli.geometry.world import World

from .worlds import IDENTITY, box

START, GOAL = np.array([0.6, 0.35]), np.array([-0.6, -0.35])


def _staggered(gap: float = 0.22, closed: bool = False) -> Scene:
    """Two partitions across a 1.6 x 1 m floor, `gap` apart (y = +-gap/2 - 1 cm): one
    from the west edge to x = 0.3, the other from x = -0.3 to the east edge (both edge
    to edge when `closed`). The disk hovers 1 cm over the floor."""
    y = gap / 2 + 0.01
    reach = 0.8 if closed else 0.3
    low, high = (-0.8, reach), (-reach, 0.8)
    bodies = (
        box("floor", (1.6, 1.0, 0.04), (0.0, 0.0, -0.02)),
        box("low", (low[1] - low[0], 0.02, 0.1), (sum(low) / 2, -y, 0.05)),
        box("high", (high[1] - high[0], 0.02, 0.1), (sum(high) / 2, y, 0.05)),
    )
    return Scene(None, RobotSpec("planar", base=(0.0, 0.0, 0.035) + IDENTITY,
                                 start=tuple(START), radius=0.05), bodies)


def _fine(path: np.ndarray, step: float = 0.002) -> np.ndarray:
    out = [np.linspace(a, b, max(2, int(np.ceil(np.linalg.norm(b - a) / step))),
                       endpoint=False) for a, b in zip(path[:-1], path[1:], strict=True)]
    return np.concatenate(out + [path[-1:]])


def _route(scene: Scene, **kwargs):
    with World(scene) as world:
        checker = CollisionChecker(world)
        route = planar_route(checker, START, GOAL, world.lower, world.upper,
                             options=RouteOptions(**kwargs))
        if route is None:
            return None, None
        path = route.points
        least = min(checker.min_distance(q, ignore=frozenset({"floor"}), static=False, horizon=0.2)
                    for q in _fine(path))
        return path, least


def test_the_route_turns_round_both_partitions_and_keeps_clear_of_them():
    path, least = _route(_staggered())
    assert path is not None
    np.testing.assert_allclose(path[[0, -1]], [START, GOAL])
    fine = _fine(path)
    # North of the upper partition, then in the corridor east of the lower one's end,
    # then south of the lower partition: an S, not the straight line.
    assert np.any((fine[:, 0] < -0.3) & (fine[:, 1] > 0.13))
    assert np.any((fine[:, 0] > 0.3) & (np.abs(fine[:, 1]) < 0.11))
    # The floor 1 cm under the disk is no obstacle; the walls are kept at a distance
    # (the options' comfort of 4 cm, less what pulling the staircase straight may cost).
    assert least >= 0.02


def test_the_route_takes_a_passage_with_little_to_spare():
    # A corridor 12 cm wide for the 10 cm disk: 1 cm a side.
    path, least = _route(_staggered(gap=0.12))
    assert path is not None
    assert least >= 0.0


def test_no_route_when_the_partitions_close_the_floor():
    path, _ = _route(_staggered(closed=True))
    assert path is None


def test_bad_options_are_refused():
    with pytest.raises(ValueError):
        RouteOptions(step=0.0)
    with pytest.raises(ValueError):
        RouteOptions(clearance=0.05, comfort=0.04)


def _door(gap: float) -> Scene:
    """A wall across the floor at x = 0, 2 cm thick, with one door `gap` wide at y = 0;
    the disk (10 cm across) hovers 1 cm over the floor."""
    side = (1.0 - gap) / 2
    bodies = (
        box("floor", (1.6, 1.0, 0.04), (0.0, 0.0, -0.02)),
        box("north", (0.02, side, 0.1), (0.0, gap / 2 + side / 2, 0.05)),
        box("south", (0.02, side, 0.1), (0.0, -gap / 2 - side / 2, 0.05)),
    )
    return Scene(None, RobotSpec("planar", base=(0.0, 0.0, 0.035) + IDENTITY,
                                 start=(-0.5, 0.3), radius=0.05), bodies)


@pytest.mark.parametrize("gap, separated", [(0.06, True), (0.09, True), (0.104, False),
                                            (0.12, False), (0.3, False)])
def test_a_door_too_narrow_for_the_disk_is_proved_closed_and_no_other(gap, separated):
    """planar_route._separated: a proof only where no path exists (the disk is 10 cm
    across, the clearance 1 mm: a 10.4 cm door passes it with 1 mm to spare a side,
    which the 2 cm grid itself may not find a route through)."""
    start, goal = np.array([-0.5, 0.3]), np.array([0.5, -0.3])
    with World(_door(gap)) as world:
        checker = CollisionChecker(world)
        report = {}
        route = planar_route(checker, start, goal, world.lower, world.upper,
                             options=RouteOptions(), report=report)
        assert report.get("separated", False) is separated
        if separated:
            assert route is None
