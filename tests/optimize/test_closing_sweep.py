"""The fingers must close on what they grasp through nothing else (closing.sweep_contact):
blind28 p04, written blind, where the KUKA's open fingers came down outside 1 cm rails
3 mm from each part and the grip was accepted by planning, `validate` and the physics
replay (its fixed constraint holds the part whatever is between)."""

from __future__ import annotations

from pathlib import Path

from tampcli.optimize import keyframe_stage, verify
from tampcli.optimize.closing import CLOSING
from tampcli.optimize.solve import solve

from .helpers import lowered_folder, ops, path_from_keyframes

RAILS = Path(__file__).resolve().parents[2] / "problems" / "blind28" / "p04"
THROUGH_RAILS = ("(pick p2 p2-home)", "(place p2 goal2)", "(pick p1 p1-home)",
                 "(place p1 goal1)")
CRATE_FIRST = ("(push crate crate-home aside)", "(pick p1 p1-home)", "(place p1 goal1)",
               "(pick p2 p2-home)", "(place p2 goal2)")


def test_keyframes_whose_fingers_close_through_a_rail_are_refused():
    with lowered_folder(RAILS, "p04", ops(*THROUGH_RAILS)) as problem:
        kf = solve(problem, "keyframes")
        assert not kf.solved
        assert CLOSING in kf.worst_constraint and "rail" in kf.worst_constraint


def test_verify_finds_the_rail_on_its_own(monkeypatch):
    """The keyframe stage's refusal taken out, the path is found; verify (the judge of
    the path stage and of `validate`) names the rail from the trajectory alone."""
    monkeypatch.setattr(keyframe_stage, "closing_blocked", lambda *args: None)
    with lowered_folder(RAILS, "p04", ops(*THROUGH_RAILS)) as problem:
        path = path_from_keyframes(problem)
        assert not path.solved
        assert path.worst_constraint.startswith("(pick p2 p2-home): " + CLOSING)


def test_the_grip_after_the_crate_is_pushed_aside_closes_freely():
    with lowered_folder(RAILS, "p04", ops(*CRATE_FIRST)) as problem:
        path = path_from_keyframes(problem)
        assert path.solved, path.worst_constraint
        assert verify.verify(problem, path, fingers=path.fingers) == []
