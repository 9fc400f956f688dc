"""Every scene of the problem library loads, with its domain's modes, start state checked."""

from pathlib import Path

import pytest

from tampcli.geometry.locate import find_modes
from tampcli.optimize.modes import load_modes
from tampcli.pddl import parser

from .loading import load_checked

ROOT = Path(__file__).resolve().parents[2]
SCENES = sorted(ROOT.glob("problems/*/*.scene.toml"))


def test_the_library_has_scenes():
    assert len(SCENES) >= 16


@pytest.mark.parametrize("scene_path", SCENES, ids=[f"{p.parent.name}/{p.name}" for p in SCENES])
def test_library_scene_loads(scene_path):
    problem_path = scene_path.with_name(scene_path.name.replace(".scene.toml", ".pddl"))
    domain_path = ROOT / "domains" / scene_path.parent.name / "domain.pddl"
    domain = parser.parse_domain_file(str(domain_path))
    problem = parser.parse_problem_file(str(problem_path))
    modes_path = find_modes(domain_path)
    modes = load_modes(modes_path, domain) if modes_path else None
    scene = load_checked(scene_path, domain, problem, modes)
    assert scene.bodies
