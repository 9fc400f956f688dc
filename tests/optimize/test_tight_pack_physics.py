"""Two boxes packed into a tray between tall end walls with 5 mm of play for three
gaps, solved and replayed in physics (blind8 p06's class): both stay where planned."""

from __future__ import annotations

import shutil

import pytest

from .helpers import ROOT, solved_in_physics

BOX = 0.053  # m: the boxes' side
PLAY = 0.005  # m: the tray's length less the two boxes'


def pack_folder(path):
    """arm-pick-place: boxes p and q on the table, turned 0.5 and -0.4 rad, into a
    tray 10 cm wide and 2 BOX + PLAY long (along y) between 7.5 cm end walls, with
    3 cm rims along its long sides."""
    src = ROOT / "domains" / "arm-pick-place"
    shutil.copy(src / "domain.pddl", path / "domain.pddl")
    shutil.copy(src / "modes.toml", path / "modes.toml")
    (path / "p.pddl").write_text(
        "(define (problem tight-pack) (:domain arm-pick-place)\n"
        "  (:objects p q - block sp sq tray - region)\n"
        "  (:init (at p sp) (at q sq) (clear p) (clear q) (handempty))\n"
        "  (:goal (and (at p tray) (at q tray))))\n")
    length = 2 * BOX + PLAY
    x, y, t = 0.47, 0.05, 0.012
    fixed = [("table", (1.0, 1.4, 0.04), (0.4, 0.0, -0.02)),
             ("floor", (0.10, length, 0.01), (x, y, 0.005)),
             ("end-a", (0.124, t, 0.075), (x, y - length / 2 - t / 2, 0.0375)),
             ("end-b", (0.124, t, 0.075), (x, y + length / 2 + t / 2, 0.0375)),
             ("rim-near", (t, length, 0.03), (x - 0.05 - t / 2, y, 0.015)),
             ("rim-far", (t, length, 0.03), (x + 0.05 + t / 2, y, 0.015))]
    text = '[robot]\nmodel = "panda"\nbase = [0.0, 0.0, 0.0]\n'
    for name, size, pose in fixed:
        text += (f'\n[[objects]]\nname = "{name}"\nshape = "box"\nsize = {list(size)}\n'
                 f'pose = {list(pose)}\nfixed = true\n')
    for name, (bx, by, yaw) in (("p", (0.40, -0.30, 0.5)), ("q", (0.58, -0.22, -0.4))):
        text += (f'\n[[objects]]\nname = "{name}"\nshape = "box"\n'
                 f'size = [{BOX}, {BOX}, 0.06]\npose = [{bx}, {by}, 0.03, {yaw}]\n')
        text += (f'\n[[regions]]\nname = "s{name}"\non = "table"\ncenter = [{bx}, {by}]\n'
                 'size = [0.09, 0.09]\n')
    text += (f'\n[[regions]]\nname = "tray"\non = "floor"\ncenter = [{x}, {y}]\n'
             f'size = [0.10, {length}]\n')
    (path / "p.scene.toml").write_text(text)
    return path


@pytest.mark.slow
def test_a_tight_pack_stays_put_in_the_physics_replay(cli, tmp_path):
    physics = solved_in_physics(cli, pack_folder(tmp_path), tmp_path, time_limit=120)
    for name in ("p", "q"):
        drift = physics["objects"][name]
        assert drift["distance"] < 0.003 and drift["angle_deg"] < 2.0, (name, drift)
