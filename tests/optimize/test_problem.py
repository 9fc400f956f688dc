"""Lowering (phases, keyframes, errors), the variable layout, the options."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tampcli.optimize.layout import Layout
from tampcli.optimize.options import OptimizeOptions
from tampcli.optimize.problem import lower
from tampcli.optimize.solve import solve

from .helpers import ops


@given(st.lists(st.tuples(st.text("abcdefgh", min_size=1, max_size=4),
                          st.integers(0, 5)), max_size=6, unique_by=lambda b: b[0]),
       st.integers(0, 2**31 - 1))
def test_pack_unpack_round_trip(blocks, seed):
    layout = Layout(tuple(blocks))
    rng = np.random.default_rng(seed)
    x = rng.normal(size=layout.size)
    values = layout.unpack(x)
    assert list(values) == [b for b, _ in blocks]
    np.testing.assert_array_equal(layout.pack(values), x)
    for (name, size), s in zip(blocks, layout.slices().values(), strict=True):
        assert s.stop - s.start == size
        np.testing.assert_array_equal(values[name], x[s])


def test_unpack_rejects_a_wrong_size():
    with pytest.raises(ValueError, match="expected 3 values"):
        Layout((("a", 3),)).unpack(np.zeros(4))


@pytest.mark.parametrize("bad", [dict(waypoints=1), dict(margin=-0.1),
                                 dict(activation=0.005), dict(max_iterations=0),
                                 dict(time_limit=0.0), dict(interpolation_checks=-1),
                                 dict(seed=1.5)])
def test_options_are_checked_when_built(bad):
    with pytest.raises(ValueError):
        OptimizeOptions(**bad)


def test_pick_place_phases_and_keyframes(wall):
    scene, modes, world = wall
    p = lower(ops("(pick a start)", "(place a goal)"), scene, modes, world)
    assert p.error is None
    assert [s.kind.name for s in p.steps] == ["grasp", "place"]
    assert p.n_keyframes == 2
    assert [m.kind for m in p.motions] == ["free", "carry"]
    assert p.motions[0].enter_contact == {"a"}  # the fingers close on a
    assert p.motions[1].leave_contact == {"table"}  # a lifts off the table
    assert p.motions[1].enter_contact == {"table"}  # and is put down on it
    assert p.steps[1].support == "table"
    assert p.steps[1].rest_z == pytest.approx(0.025)


def test_symbolic_action_is_an_instant_phase(planar):
    scene, _, world = planar
    from tampcli.optimize.modes import Mode

    modes = {"pick": Mode("pick", "grasp", "?o", params=("?o", "?from")),
             "wait": Mode("wait", "none")}
    p = lower(ops("(wait)", "(pick o start)"), scene, modes, world)
    assert p.error is None
    assert [s.kind.name for s in p.steps] == ["none", "grasp"]
    assert p.n_keyframes == 1


@pytest.mark.parametrize("plan, words", [
    (("(place a goal)",), "a is not held"),
    (("(pick a start)", "(place a nowhere)"), "no region or body 'nowhere'"),
    (("(pick a start)", "(pick a start)"), "already holding a"),
    (("(pick wall start)",), "wall is fixed"),
    (("(pick ghost start)",), "no object 'ghost'"),
])
def test_skeleton_errors_are_proved_infeasible_not_raised(wall, plan, words):
    scene, modes, world = wall
    p = lower(ops(*plan), scene, modes, world)
    assert words in p.error
    for stage in ("final", "keyframes", "path"):
        r = solve(p, stage)
        assert r.status == "infeasible" and r.proved
        assert words in r.worst_constraint


def test_a_skeleton_of_symbolic_actions_only(planar):
    from tampcli.optimize.modes import Mode

    scene, _, world = planar
    p = lower(ops("(wait)", "(wait)"), scene, {"wait": Mode("wait", "none")}, world)
    for stage in ("final", "keyframes"):
        assert solve(p, stage).solved
    result = solve(p, "path")
    assert result.solved and result.cost == 0.0
    assert len(result.trajectory) == 1
    assert [(ph.start, ph.end) for ph in result.phases] == [(0, 0), (0, 0)]
    assert all(len(v) == 3 for v in result.object_poses.values())
