"""A tower's alignment in the keyframe NLP: rows (not a pull in the objective), where
they apply, their Jacobians against finite differences."""

import math

import numpy as np
import pytest

from tampcli.geometry.world import World
from tampcli.optimize import stability as S
from tampcli.optimize.bodies import BodyInfo
from tampcli.optimize.expr import PoseX, RowSet, planar_pose
from tampcli.optimize.grips import Kinematics
from tampcli.optimize.init import final_guess, keyframe_guess
from tampcli.optimize.layout import keyframe_block
from tampcli.optimize.problem import lower
from tampcli.optimize.stages import keyframe_layout, keyframe_rows

from .helpers import central_differences, ops
from .test_placements import _problem_files


def _box(name, a, b):
    return BodyInfo(name, "box", (a / 2, b / 2, 0.02), False, (0, 0, 0, 0), True, 1.0)


def _disk(name, d):
    return BodyInfo(name, "cylinder", (d / 2, d / 2, 0.02), False, (0, 0, 0, 0), True, 1.0)



def _aligned_rows(x, pose):
    rows = RowSet()
    S.aligned(rows, "s", pose("p", x[:3]), pose("q", x[3:]), _box("q", 0.05, 0.05))
    slices = {"p": slice(0, 3), "q": slice(3, 6)}
    return rows.assemble(slices, 6)


def _planar(block, v):
    return planar_pose(block, v[0], v[1], 0.05, v[2])


def _linear(block, v):
    """A pose whose 12 numbers are an arbitrary linear map of v: every entry of the
    rows' gradient w.r.t. the axes is exercised, not only its yaw direction."""
    j = np.random.default_rng(len(block)).normal(size=(12, 3))
    base = _planar(block, (0.0, 0.0, 0.3 * len(block))).v
    return PoseX(base + j @ v, {block: j})


@pytest.mark.parametrize("pose", [_planar, _linear])
@pytest.mark.parametrize("seed", range(5))
def test_aligned_rows_match_finite_differences(pose, seed):
    x = np.random.default_rng(seed).uniform(-2.0, 2.0, 6)
    x[[0, 1, 3, 4]] *= 0.005  # centres a few mm apart: both sides of the limit
    _, jac = _aligned_rows(x, pose)
    np.testing.assert_allclose(jac, central_differences(lambda xx: _aligned_rows(xx, pose)[0], x), atol=1e-7)


@pytest.mark.parametrize("turn, inside", [(0.0, True), (1.9, True), (2.1, False), (10.0, False),
                                          (45.0, False), (88.1, True), (90.0, True),
                                          (-1.9, True), (-2.1, False), (178.5, True)])
def test_turn_rows_allow_align_turn_modulo_a_quarter_turn(turn, inside):
    base = 0.7
    val, _ = _aligned_rows(np.array([0.01, 0.0, base + math.radians(turn), 0.01, 0.0, base]),
                           _planar)
    assert val[0] == pytest.approx(S.ALIGN_SHIFT / 2)  # centred: half the limit
    assert (val[1:].min() >= 0) == inside
    if turn == 0.0:  # the rows read in rad: the slack left on either side
        assert val[1:] == pytest.approx([S.ALIGN_TURN] * 2, rel=1e-3)


@pytest.mark.parametrize("shift, inside", [(0.0, True), (2.9e-3, True), (3.1e-3, False),
                                           (1e-2, False)])
def test_shift_row_allows_align_shift_in_any_direction(shift, inside):
    for a in np.linspace(0, 2 * math.pi, 7):
        x = np.array([shift * math.cos(a), shift * math.sin(a), 0.2, 0.0, 0.0, 0.2])
        val, _ = _aligned_rows(x, _planar)
        assert (val[0] >= 0) == inside
        if 0 < shift < 5e-3:  # reads in m near the limit
            assert val[0] == pytest.approx(S.ALIGN_SHIFT - shift, rel=0.05, abs=1e-5)


def test_only_a_box_that_cannot_turn_freely_on_the_face_is_in_a_tower():
    cube4, cube5, cube6 = _box("a", 0.04, 0.04), _box("b", 0.05, 0.05), _box("c", 0.06, 0.06)
    platform = _box("p", 0.1, 0.1)
    assert S.tower_pair(cube4, cube5) and S.tower_pair(cube5, cube6)  # near-equal sizes
    assert S.tower_pair(cube5, cube5)
    assert not S.tower_pair(cube4, cube6)  # a 4 cm cube fits a 6 cm face at every yaw
    assert not S.tower_pair(cube6, platform)
    assert S.tower_pair(_box("bar", 0.12, 0.02), platform)  # an oblong bar does not
    assert not S.tower_pair(_disk("d", 0.05), cube5)
    assert not S.tower_pair(cube4, _disk("d", 0.05))


def test_keyframe_objective_is_the_motion_alone_and_rows_bound_the_turn():
    """arm-pick-place p05's tower: the keyframe NLP's cost is the joint motion through
    its keyframes (no pull), with a centre row and two turn rows per stacked box."""
    domain, scene, modes = _problem_files("arm-pick-place", "p05")
    with World(scene) as world:
        problem = lower(ops("(pick b start)", "(stack b c)", "(pick a start)", "(stack a b)"),
                        scene, modes, world, domain=domain)
        placements, _ = final_guess(problem)
        vals, choices = keyframe_guess(problem, placements, world.start,
                                       np.random.default_rng(0))
        layout = keyframe_layout(problem)
        x = layout.pack(vals.blocks()) + np.random.default_rng(1).normal(0, 0.05, layout.size)
        v = layout.unpack(x)
        rows = keyframe_rows(problem, v, choices, Kinematics(world), problem.checker,
                             world.start, collisions=False)
        qs = [np.asarray(world.start)] + [v[keyframe_block(k)]
                                          for k in range(problem.n_keyframes)]
        motion = sum(float(np.sum((b - a) ** 2)) for a, b in zip(qs[:-1], qs[1:], strict=True))
        assert rows.cost == pytest.approx(motion / problem.options.waypoints, rel=1e-12)
        labels = [(lab.step, lab.what) for lab in rows.ineq.labels
                  if lab.what.startswith(("turned from", "centre off the centre"))]
        assert labels == [(problem.steps[i].name, what.format(s)) for i, s in ((1, "c"), (3, "b"))
                          for what in ("centre off the centre of {}",
                                       "turned from the faces of {}",
                                       "turned from the faces of {}")]


@pytest.mark.parametrize("seed", range(4))
def test_tilt_row_matches_finite_differences(seed):
    """constraints.tilt_within (what is carried, where a move ends) on a pose whose 12
    numbers are a linear map of x."""
    from tampcli.optimize import constraints as C

    def rows_at(x):
        rows = RowSet()
        C.tilt_within(rows, "s", _linear("p", x), "o", math.radians(3.0))
        return rows.assemble({"p": slice(0, 3)}, 3)

    x = np.random.default_rng(seed).uniform(-0.5, 0.5, 3)
    val, jac = rows_at(x)
    np.testing.assert_allclose(jac, central_differences(lambda xx: rows_at(xx)[0], x),
                               atol=1e-7)
    upright = PoseX(np.concatenate([np.zeros(3), [1, 0, 0], [0, 1, 0], [0, 0, 1]]))
    rows = RowSet()
    C.tilt_within(rows, "s", upright, "o", math.radians(3.0))
    assert rows.assemble({}, 0)[0][0] == pytest.approx(1 - math.cos(math.radians(3.0)))
