"""One finger alone pushes a face narrower than the open fingers' spread (blind21 p06:
the KUKA's fingers, 8 cm apart, straddled a 4 cm cube and its push started 1 cm off),
and a round object's push keeps room in the friction cone."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.bodies import pose_matrix
from tampcli.optimize.kinds.push_check import clearance, touch_at
from tampcli.optimize.kinds.push_contact import NLP_FRICTION, finger_shift, pushing_fingers
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops

P06 = Path(__file__).resolve().parents[2] / "problems" / "blind21" / "p06"
KUKA = (0.04, 0.06)  # World.finger_span of the KUKA iiwa's open fingers (m)


def test_a_face_narrower_than_the_fingers_spread_is_pushed_by_either_finger_alone():
    assert pushing_fingers(0.02, KUKA) == (1, -1)  # a 4 cm face between fingers 8 cm apart
    assert pushing_fingers(0.044, KUKA) == (1, -1)  # overlapping them by 4 mm only
    assert pushing_fingers(0.046, KUKA) == (0,)  # a 9.2 cm face: both fingers on it
    assert pushing_fingers(0.02, None) == (0,)  # no fingers: the tool itself
    assert finger_shift(0, KUKA) == 0.0
    assert finger_shift(1, KUKA) == pytest.approx(0.05)  # the finger's middle
    assert finger_shift(-1, (0.039, 0.0674)) == pytest.approx(-0.049)  # at most 1 cm in


@pytest.fixture(scope="module")
def cube_aside():
    with lowered_folder(P06, "p06", ops("(push cube aside)")) as problem:
        yield problem


def test_the_cube_between_kerb_and_crate_is_touched_by_one_finger(cube_aside):
    out = solve(cube_aside, "keyframes")
    assert out.status == "solved", out.worst_constraint
    assert out.choices[0].finger in (1, -1)
    step = cube_aside.steps[0]
    info = cube_aside.bodies["cube"]
    gap = clearance(cube_aside, "cube", pose_matrix(*info.pose), out.keyframes.q[step.keyframes[0]])
    assert -1e-3 <= gap <= 2e-3  # the touch (CONTACT_GAP 0.5 mm), as verify allows it


def test_the_one_finger_push_passes_verify_at_the_path_stage(cube_aside):
    out = solve(cube_aside, "path")
    assert out.status == "solved", out.worst_constraint
    (entry,) = [g for g in out.grasp_report if g["object"] == "cube"]
    assert entry["fingers"] == "one" and entry["face"] == "+x"
    # Where the report says the hand's axis stood, the tool stood: measured at the push's
    # first keyframe, in the cube's frame (the +x face's tangent is the cube's -y).
    info = cube_aside.bodies["cube"]
    q0 = out.keyframes.q[cube_aside.steps[0].keyframes[0]]
    tool = np.linalg.inv(pose_matrix(*info.pose)) @ cube_aside.world.tool_poses(q0[None])[0]
    along = {"+y": tool[1, 3], "-y": -tool[1, 3]}[entry["axis_side"]]
    assert along == pytest.approx(abs(entry["axis_offset"]), abs=2e-3)
    assert abs(entry["axis_offset"]) > 0.03  # beside the 4 cm cube, not over it


P08 = Path(__file__).resolve().parents[2] / "problems" / "blind14" / "p08"


def test_a_can_pushed_by_one_finger_keeps_inside_the_cone_verify_judges_by():
    """The NLPs push within a cone a little inside verify's (NLP_FRICTION): on the edge,
    a step passed the NLP's tolerance and failed verify's (blind14 p08: the can went 27
    degrees off its touch at the path's first step, the cone's edge is 26.6)."""
    with lowered_folder(P08, "p08", ops("(push can can-start can-goal)")) as problem:
        out = solve(problem, "path")
        assert out.status == "solved", out.worst_constraint
        step = problem.steps[0]
        info = problem.bodies["can"]
        start = pose_matrix(*info.pose)
        q0 = out.keyframes.q[step.keyframes[0]]
        gap, point = touch_at(problem, "can", start, q0)
        assert gap <= 2e-3
        assert out.choices[0].finger in (1, -1)  # a 5 cm can between fingers 8 cm apart
        inward = start[:2, 3] - point[:2]
        moved = np.array(out.object_poses["can"][-1][:2]) - start[:2, 3]
        cos = inward @ moved / np.linalg.norm(inward) / np.linalg.norm(moved)
        assert math.degrees(math.acos(cos)) <= math.degrees(math.atan(NLP_FRICTION)) + 0.5


def test_a_can_between_tall_neighbours_is_pushed_by_the_front_finger_the_other_behind(
        tmp_path):
    """blind23 p03 with its neighbours 16 cm tall: a one-finger hand, spread along the
    row, has its knuckles in a neighbour (4.3 cm); the fingers one behind the other,
    the hand no wider than a finger across the row, pass."""
    folder = P08.parents[1] / "blind23" / "p03"
    for name in ("domain.pddl", "modes.toml", "p03.pddl"):
        (tmp_path / name).write_text((folder / name).read_text())
    scene = (folder / "p03.scene.toml").read_text()
    for y in ("0.075", "-0.075"):
        scene = scene.replace(f"size = [0.03, 0.08]\npose = [0.30, {y}, 0.04]",
                              f"size = [0.03, 0.16]\npose = [0.30, {y}, 0.08]")
    assert scene.count("0.16]") == 2
    (tmp_path / "p03.scene.toml").write_text(scene)
    with lowered_folder(tmp_path, "p03", ops("(push soda row-mid goal)")) as problem:
        out = solve(problem, "path")
        assert out.status == "solved", out.worst_constraint
        assert out.choices[0].crosswise
        (entry,) = out.grasp_report
        assert entry["fingers"] == "front" and entry["pusher"] == "down"
