"""--physics: a consistent plan stays put; a plan that leaves a box in mid-air does not."""

import pytest
from render_solutions import panda_solution, planar_solution

from tampcli.render.options import RenderOptions
from tampcli.render.video import render_solution
from tampcli.solution import Solution


def test_pick_and_place_survives_dynamics():
    report = render_solution(panda_solution(), None, RenderOptions(physics=True, duration=3.0))
    physics = report["physics"]
    assert physics["objects"]["a"]["distance"] < 0.01
    assert physics["objects"]["b"]["distance"] < 0.005
    assert physics["tracking_error"] < 0.1
    # the carried cube really travelled: from x, y = (0.5, -0.25) to (0.45, 0.3)
    assert physics["objects"]["a"]["simulated"][1] == pytest.approx(0.3, abs=0.01)


def test_a_floating_placement_falls():
    sol = planar_solution()
    floating = [list(p) for p in sol.objects["box"]]
    floating[-1][2] = floating[-2][2] = 0.3  # "placed" 30 cm above the table
    bad = Solution(**{**sol.__dict__, "objects": {"box": floating}})
    report = render_solution(bad, None, RenderOptions(physics=True, duration=2.0))
    assert report["physics"]["objects"]["box"]["distance"] > 0.2
