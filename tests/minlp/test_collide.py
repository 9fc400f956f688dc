"""Separation valid between waypoints: a segment whose ends are both clear of a box but
which cuts its corner is refused; one that passes the corner is accepted."""

import math

import pytest
from pyscipopt import Model

from tampcli.minlp.collide import separate
from tampcli.minlp.footprint import box, disk, separating_faces

DISK = disk("robot", 0.05, 0.0, 0.05, 16, outer=True)
BOX = box("box", (0.2, 0.2, 0.05), 0.0, 0.0, 0.05)


def _feasible(*ends) -> bool:
    model = Model()
    model.hideOutput()
    points = [tuple(model.addVar(f"p{i}{a}", lb=v, ub=v) for a, v in enumerate(end))
              for i, end in enumerate(ends)]
    separate(model, points, (0.0, 0.0), DISK, BOX, 1.0, "sep")
    model.optimize()
    return model.getStatus() == "optimal"


def _clearance(p) -> float:
    """The true distance from the disk's centre at p to the box, minus the radius."""
    dx, dy = max(abs(p[0]) - 0.1, 0.0), max(abs(p[1]) - 0.1, 0.0)
    return math.hypot(dx, dy) - 0.05


def test_a_segment_cutting_the_corner_is_refused_though_both_ends_are_clear():
    a, b = (-0.25, 0.0), (0.0, 0.25)
    mid = (-0.125, 0.125)
    assert _clearance(a) > 0 and _clearance(b) > 0 and _clearance(mid) < 0
    assert _feasible(a) and _feasible(b)
    assert not _feasible(a, b)


def test_a_segment_passing_the_corner_is_accepted():
    assert _feasible((-0.4, 0.0), (0.0, 0.4))


def test_the_outer_polygon_contains_the_disk_and_the_inner_one_lies_inside_it():
    outer = disk("d", 0.2, 0.0, 1.0, 8, outer=True)
    inner = disk("d", 0.2, 0.0, 1.0, 8, outer=False)
    for n in outer.normals():
        assert outer.support(n) == pytest.approx(0.2)  # tangent to the circle
    assert max(math.hypot(*v) for v in inner.vertices) == pytest.approx(0.2)
    assert max(math.hypot(*v) for v in outer.vertices) > 0.2


def test_the_faces_of_two_boxes_are_the_separating_axes_of_their_sum():
    a = box("a", (0.2, 0.1, 1.0), 0.0, 0.0, 1.0)
    b = box("b", (0.4, 0.2, 1.0), math.pi / 2, 0.0, 1.0)  # turned: half extents 0.1, 0.2
    faces = separating_faces(a, b)
    assert len(faces) == 4  # shared axes are not repeated
    offsets = sorted(off for _, off in faces)
    assert offsets == pytest.approx([0.1 + 0.1, 0.1 + 0.1, 0.05 + 0.2, 0.05 + 0.2])
