"""The fingers must close on what they grasp through nothing else (closing.sweep_contact):
blind28 p04, written blind, where the KUKA's open fingers came down outside 1 cm rails
3 mm from each part and the grip was accepted by planning, `validate` and the physics
replay (its fixed constraint holds the part whatever is between)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from tampcli.optimize import keyframe_stage, verify
from tampcli.optimize.closing import CLOSING
from tampcli.optimize.hand import closing_depth
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


COIN = Path(__file__).resolve().parents[2] / "problems" / "blind32" / "p04"


def test_the_xarms_fingertips_swing_down_as_they_close():
    """The xArm6's linkage: its fingertips reach 1.1 cm beyond the tool origin open and
    2.4 cm closed on a 2.4 cm coin; the KUKA's slide and reach as far closed as open."""
    with lowered_folder(COIN, "p04", ops("(pick coin coin-dish)", "(put coin ship)")) as xarm:
        open_depth = xarm.hand.depth
        assert closing_depth(xarm, 0.024) > open_depth + 0.005
        assert closing_depth(xarm, 0.024) >= closing_depth(xarm, 0.06)
    with lowered_folder(RAILS, "p04", ops(*THROUGH_RAILS)) as kuka:
        assert closing_depth(kuka, 0.03) == pytest.approx(kuka.hand.depth, abs=1e-4)


def test_a_coin_lower_than_the_closed_fingertips_is_gripped_with_them_clear():
    """blind32 p04 (written blind): a coin 1.6 cm tall, which the xArm6's open fingertips
    clear. With the grasp's depth taken from the open hand every grasp's closing sweep
    went 1 cm into the table; taken from the closed fingertips, the tool origin stays
    above the coin's top and the fingers close on it clear of the table."""
    with lowered_folder(COIN, "p04", ops("(pick coin coin-dish)", "(put coin ship)")) as problem:
        path = path_from_keyframes(problem)
        assert path.solved, path.worst_constraint
        assert verify.verify(problem, path, fingers=path.fingers) == []
        grip = problem.steps[0].kind.grip(problem, problem.steps[0], path.choices[0])
        coin_top = problem.bodies["coin"].half[2]
        assert grip.c0[2] > coin_top  # the tool origin above the coin


def test_a_coin_too_thin_for_the_closed_fingertips_is_refused_at_the_keyframes(tmp_path):
    """The same coin 1.0 cm tall: the closed fingertips cannot reach it clear of the
    table, and the closing sweep says so."""
    shutil.copytree(COIN, tmp_path / "p04")
    scene = tmp_path / "p04" / "p04.scene.toml"
    text = scene.read_text()
    coin = "size = [0.012, 0.016]\npose = [0.3, 0.02, 0.008]"
    assert coin in text
    scene.write_text(text.replace(coin, "size = [0.012, 0.010]\npose = [0.3, 0.02, 0.005]"))
    with lowered_folder(tmp_path / "p04", "p04",
                        ops("(pick coin coin-dish)", "(put coin ship)")) as problem:
        kf = solve(problem, "keyframes")
        assert not kf.solved
        assert CLOSING in kf.worst_constraint and "table" in kf.worst_constraint
