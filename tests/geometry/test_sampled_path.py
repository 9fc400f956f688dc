"""Sampled paths through narrow passages, checked with the collision model at fine steps."""

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tampcli.geometry import sampled_path as sp
from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.sampled_path import FINE, SamplingOptions, resample, sampled_path
from tampcli.geometry.scene import RobotSpec, Scene
from tampcli.geometry.world import World

from .worlds import IDENTITY, box

ROOT = Path(__file__).resolve().parents[2]


def _corridor_scene(gap: float, thickness: float = 0.1) -> Scene:
    """A wall across the floor at x = 0 with one slot of width `gap` at y = 0.3."""
    lo, hi = 0.3 - 0.5 * gap, 0.3 + 0.5 * gap  # the wall spans the floor, y -1 .. 1
    bodies = (
        box("floor", (2.0, 2.0, 0.02), (0.0, 0.0, -0.01)),
        box("wall_low", (thickness, lo + 1.0, 0.1), (0.0, (lo - 1.0) / 2, 0.05)),
        box("wall_high", (thickness, 1.0 - hi, 0.1), (0.0, (1.0 + hi) / 2, 0.05)),
    )
    return Scene(None, RobotSpec("planar", base=(-0.5, -0.5, 0.025) + IDENTITY, radius=0.05),
                 bodies)


def _fine_points(path, steps=20):
    pieces = [np.linspace(a, b, steps, endpoint=False)
              for a, b in zip(path[:-1], path[1:], strict=True)]
    return np.concatenate(pieces + [path[-1:]])


def _fine_min_distance(checker, path):
    return min(checker.min_distance(q, static=False) for q in _fine_points(path))


@pytest.mark.parametrize("gap", [
    0.14,
    # 5 mm and 2 mm a side: RRT-Connect's time there is heavy-tailed (seconds to a minute)
    pytest.param(0.11, marks=pytest.mark.slow),
    pytest.param(0.104, marks=pytest.mark.slow),
])
def test_a_disk_goes_through_a_slot_with_millimetres_to_spare(gap):
    with World(_corridor_scene(gap)) as world:
        checker = CollisionChecker(world)
        start, goal = np.array([-0.5, -0.5]), np.array([0.5, -0.5])
        assert checker.min_distance((start + goal) / 2, static=False) < 0  # the straight line hits
        options = SamplingOptions(checks=2_000_000, endpoint_slack=0.0, resolution=0.002)
        path = sampled_path(checker, start, goal, world.lower, world.upper, options=options)
        assert path is not None
        np.testing.assert_allclose(path[[0, -1]], [start, goal])
        assert min(checker.min_distance(q, static=False) for q in path) >= 0.0
        # Between two checked points s apart, a distance (1-Lipschitz) dips at most s / 2.
        step = options.resolution * np.linalg.norm(world.upper - world.lower)
        assert _fine_min_distance(checker, path) >= -step / 2
        fine = _fine_points(path)
        crossing = fine[np.argmin(np.abs(fine[:, 0]))]
        assert abs(crossing[1] - 0.3) < gap / 2  # it went through the slot


def test_no_path_when_the_slot_is_narrower_than_the_disk():
    with World(_corridor_scene(0.09)) as world:
        checker = CollisionChecker(world)
        path = sampled_path(checker, [-0.5, -0.5], [0.5, -0.5], world.lower, world.upper,
                            options=SamplingOptions(checks=2000))
        assert path is None


def test_clearance_is_kept():
    with World(_corridor_scene(0.2)) as world:
        checker = CollisionChecker(world)
        path = sampled_path(checker, [-0.5, -0.5], [0.5, -0.5], world.lower, world.upper,
                            options=SamplingOptions(checks=200_000, clearance=0.02,
                                                    endpoint_slack=0.0))
        assert path is not None
        assert _fine_min_distance(checker, path) >= 0.02 - 2e-3


class _Counting:
    """The checker, counting the configurations asked about (one per validity check)."""

    def __init__(self, checker):
        self.checker, self.asked = checker, 0

    def distances_many(self, qs, *args, **kwargs):
        self.asked += len(qs)
        return self.checker.distances_many(qs, *args, **kwargs)


def test_the_same_seed_gives_the_same_path_and_another_seed_another():
    with World(_corridor_scene(0.14)) as world:
        checker = CollisionChecker(world)

        def run(seed):
            return sampled_path(checker, [-0.5, -0.5], [0.5, -0.5], world.lower, world.upper,
                                options=SamplingOptions(checks=100_000, seed=seed))

        first, again, other = run(3), run(3), run(4)
        assert first is not None and other is not None
        np.testing.assert_array_equal(first, again)
        assert first.shape != other.shape or not np.array_equal(first, other)


def _checks_made(monkeypatch) -> list:
    """The validity checks counted so far, as each RRT-Connect query returns."""
    made, original = [], sp._query

    def counted(*args):
        out = original(*args)
        made.append(args[9][0])  # _query's `made`
        return out

    monkeypatch.setattr(sp, "_query", counted)
    return made


@pytest.mark.parametrize("gap, seed", [(0.14, 3), (0.12, 5), (0.2, 7)])
def test_edges_asked_in_batches_give_ompls_own_path_and_count(gap, seed, monkeypatch):
    """The batched edge check asks the configurations OMPL's DiscreteMotionValidator
    would, and counts those it would have asked up to the first invalid one: the same
    seed gives the same path, and the budget is spent alike."""
    with World(_corridor_scene(gap)) as world:
        checker = CollisionChecker(world)

        def run(own: bool):
            if own:
                monkeypatch.setattr(sp, "_batched_edges", lambda *args: None)
            made = _checks_made(monkeypatch)
            path = sampled_path(checker, [-0.5, -0.5], [0.5, -0.5], world.lower, world.upper,
                                options=SamplingOptions(checks=100_000, seed=seed))
            monkeypatch.undo()
            return path, made

        batched, batched_made = run(own=False)
        own, own_made = run(own=True)
    assert batched is not None and own is not None
    np.testing.assert_array_equal(batched, own)
    assert batched_made == own_made


def test_an_edge_is_checked_in_ompls_order():
    assert sp._edge_order(1).tolist() == [1]
    assert sp._edge_order(2).tolist() == [2, 1]
    assert sp._edge_order(7).tolist() == [7, 3, 1, 5, 2, 4, 6]
    assert sorted(sp._edge_order(20).tolist()) == list(range(1, 21))


def test_the_budget_counts_validity_checks(monkeypatch):
    with World(_corridor_scene(0.09)) as world:  # no path: the whole budget is spent
        counting = _Counting(CollisionChecker(world))
        made = _checks_made(monkeypatch)
        options = SamplingOptions(checks=3000, simplify_checks=0)
        assert sampled_path(counting, [-0.5, -0.5], [0.5, -0.5], world.lower, world.upper,
                            options=options) is None
    # Two queries at the ends; OMPL stops within an edge's checks of the budget. The
    # checker is asked every configuration of an edge at once, counted or not.
    assert made and 3000 <= made[-1] <= 3000 + 2 + 200
    assert counting.asked >= made[-1]


def test_a_deadline_passed_stops_the_query_at_once():
    with World(_corridor_scene(0.09)) as world:
        counting = _Counting(CollisionChecker(world))
        options = SamplingOptions(checks=10**9, deadline=0.0)
        assert sampled_path(counting, [-0.5, -0.5], [0.5, -0.5], world.lower, world.upper,
                            options=options) is None
        assert counting.asked <= 2 + 200


@pytest.mark.parametrize("seed", [1, 2, 3, 4, 5])
def test_no_edge_passes_through_a_wall_thinner_than_the_check_step(seed):
    """OMPL checks an edge every `resolution` of the extent (here 11 cm on a 2.2 m
    floor, against a 2 cm disk-and-wall overlap band): the path found is checked again
    ten times finer, and the query runs again finer where an edge fails."""
    with World(_corridor_scene(0.2, thickness=0.004)) as world:
        checker = CollisionChecker(world)
        options = SamplingOptions(checks=200_000, resolution=0.05, seed=seed,
                                  endpoint_slack=0.0)
        path = sampled_path(checker, [-0.5, -0.5], [0.5, -0.5], world.lower, world.upper,
                            options=options)
        assert path is not None
        # Between two points checked s apart, a distance (1-Lipschitz) dips at most s / 2;
        # through the wall it would be the disk's whole radius.
        step = options.resolution / FINE * float(np.linalg.norm(world.upper - world.lower))
        assert _fine_min_distance(checker, path) >= -step / 2


def test_resample_spaces_waypoints_evenly_along_the_path():
    path = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 3.0]])
    out = resample(path, 5)
    np.testing.assert_allclose(out, [[0, 0], [1, 0], [1, 1], [1, 2], [1, 3]])
    assert len(resample(np.zeros((2, 3)), 4)) == 4


def test_bad_options_are_refused():
    with pytest.raises(ValueError):
        SamplingOptions(resolution=0.0)
    with pytest.raises(ValueError):
        SamplingOptions(clearance=-1.0)
    with pytest.raises(ValueError):
        SamplingOptions(checks=0)


def test_nothing_reaches_the_terminal_not_even_at_exit():
    # OMPL logs by default, and nanobind reports objects alive at interpreter exit.
    script = (
        "from tests.geometry.test_sampled_path import _corridor_scene, sampled_path\n"
        "from tampcli.geometry.world import World\n"
        "from tampcli.geometry.collision import CollisionChecker\n"
        "with World(_corridor_scene(0.2)) as w:\n"
        "    c = CollisionChecker(w)\n"
        "    assert sampled_path(c, [-0.5, -0.5], [0.5, -0.5], w.lower, w.upper) is not None\n"
        "    assert sampled_path(c, [-0.5, -0.5], [0.5, -0.5], w.lower, w.upper,\n"
        "                        options=SamplingOptions(checks=200, clearance=0.5)) is None\n"
    ).replace("sampled_path\n", "sampled_path, SamplingOptions\n", 1)
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         cwd=ROOT, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout == "" and run.stderr == ""


def test_resample_keeps_every_vertex_when_there_are_waypoints_enough():
    # A corner cut between two waypoints would run into what the planner went around.
    path = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [1.1, 1.0]])
    out = resample(path, 11)
    assert len(out) == 11
    for vertex in path:
        assert np.min(np.linalg.norm(out - vertex, axis=1)) < 1e-12
    steps = np.linalg.norm(np.diff(out, axis=0), axis=1)
    assert steps.max() <= 0.26  # shares in proportion to length: 5, 4 and 1 steps
    np.testing.assert_allclose(resample(path, 3)[[0, -1]], path[[0, -1]])
