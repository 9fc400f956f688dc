"""A path stage whose time runs out before every grip was tried reads `limit`, whatever
the first grip's failure: it proves nothing and forbids no prefix (blind33 p02, written
blind: the planar disk's first face failed its carry, the other faces took the rest of
the 30 s, and the record said `path stage infeasible`, forbidding the prefix)."""

from __future__ import annotations

from pathlib import Path

from tampcli.optimize import path_stage
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops

BAR = Path(__file__).resolve().parents[2] / "problems" / "blind33" / "p02"
SKELETON = ("(grab bar nook)", "(drop bar goal)")


def _first_grip_fails(monkeypatch, out_of_time: bool) -> list:
    """path_through made to fail every grip, the stage's time over after the first
    when `out_of_time`; the grips tried, in order."""
    tried = []

    def failing(run, kfr):
        tried.append(kfr.keyframes.grip)
        if out_of_time:
            run.deadline = 0.0
        return run.result("infeasible", worst_constraint="motion 1 before (drop bar goal): "
                          "collision bar vs nook-e (margin 1 mm) by 4.1 cm", violation=0.041,
                          failed_actions=2)

    monkeypatch.setattr(path_stage, "path_through", failing)
    return tried


def test_a_stage_out_of_time_with_grips_untried_is_a_limit(monkeypatch):
    tried = _first_grip_fails(monkeypatch, out_of_time=True)
    with lowered_folder(BAR, "p02", ops(*SKELETON)) as problem:
        out = solve(problem, "path")
    assert len(tried) == 1
    assert out.status == "limit" and not out.proved
    assert out.worst_constraint.startswith("motion 1 before (drop bar goal)")


def test_a_stage_that_tried_every_grip_in_time_stays_infeasible(monkeypatch):
    tried = _first_grip_fails(monkeypatch, out_of_time=False)
    with lowered_folder(BAR, "p02", ops(*SKELETON)) as problem:
        out = solve(problem, "path")
    assert len(tried) > 1  # the other faces were tried
    assert out.status == "infeasible"


def test_a_carry_the_plane_proves_blocked_is_not_sampled(monkeypatch):
    """blind33 p02: the bar held by its long face cannot pass the 12.4 cm door. The
    plane's grid proves it (planar_route._separated), so no grip's carry spends the
    sampling budget (23 s of it for the first grip before), every grip is tried within
    the stage's time, and the stage fails as infeasible, not cut off."""
    from tampcli.optimize import motion

    sampled = []
    original = motion._sampled_start

    def counting(run, ctx, share, deadline=None):
        sampled.append((ctx.index, ctx.held is not None))
        return original(run, ctx, share, deadline)

    monkeypatch.setattr(motion, "_sampled_start", counting)
    with lowered_folder(BAR, "p02", ops(*SKELETON)) as problem:
        out = solve(problem, "path")
    assert out.status == "infeasible"
    assert not [s for s in sampled if s[1]]  # no carry sampled
