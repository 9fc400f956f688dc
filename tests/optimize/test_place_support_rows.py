"""Where an arm sets an object down, the keyframe NLP leaves the support out of its
rows (the object rests on it); where a solved keyframe's link then went into the
support, the NLP is solved again with the rows between the arm and the support
(keyframe_supports.into_support, with_supports; stages.KeyframeWalk.collide). blind34
p01: the block put down under a low hood, its keyframe solved with the Panda's forearm
2.2 cm inside the table, which only the path stage's check found."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tampcli.optimize.keyframe_stage import keyframes
from tampcli.optimize.run import Run
from tampcli.optimize.stages import keyframe_rows

from .helpers import lowered_folder, ops

P01 = Path(__file__).resolve().parents[2] / "problems" / "blind34" / "p01"
SKELETON = ("(pick-up block block-home)", "(put-down block pad)", "(pick-up puck puck-home)",
            "(stack puck block)")


@pytest.fixture(scope="module")
def hood():
    with lowered_folder(P01, "p01", ops(*SKELETON)) as problem:
        run = Run(problem, "path")
        yield run, keyframes(run, None)


def test_no_link_of_the_arm_goes_into_the_table_at_a_put_down(hood):
    run, kf = hood
    assert kf.solved
    problem = run.problem
    put_down = problem.steps[1]
    assert put_down.kind.places and put_down.support == "table"
    (k,) = put_down.keyframes
    q = np.asarray(kf.keyframes.q[k])
    # The block rests where the keyframes put it (it is let go here, not held).
    moved = {"block": _pose(kf.placements[put_down.index], problem.bodies["block"].pose[2])}
    near = [c for c in run.checker.distances(q, moved, None, frozenset(), 0.05, static=False)
            if c.b == "body:table" and c.a.startswith("link:")]
    tight = problem.options.tight_margin
    assert min(c.distance for c in near) >= tight - 2e-4


def test_the_put_downs_rows_name_the_table_for_the_links_not_for_the_block(hood):
    run, kf = hood
    problem = run.problem
    rows = keyframe_rows(problem, kf.keyframes.blocks(), kf.choices, run.kin, run.checker,
                         run.start, supports=True)
    plain = keyframe_rows(problem, kf.keyframes.blocks(), kf.choices, run.kin, run.checker,
                          run.start)
    assert not any(lab.step == "(put-down block pad)" and "vs table" in lab.what
                   for lab in plain.ineq.labels)  # only asked for where needed
    rows_at = [lab.what for lab in rows.ineq.labels if lab.step == "(put-down block pad)"]
    table = [what for what in rows_at if what.endswith("vs table (margin 1 mm)")]
    # The forearm, 1 mm over the table there, has its row; the block resting on the
    # table has none.
    assert table and all(what.startswith("collision panda_") for what in table)
    assert not any("block vs table" in what for what in rows_at)


def _pose(placement, z: float) -> np.ndarray:
    c, s = np.cos(placement.yaw), np.sin(placement.yaw)
    pose = np.eye(4)
    pose[:2, :2] = [[c, -s], [s, c]]
    pose[:3, 3] = (placement.x, placement.y, z)
    return pose
