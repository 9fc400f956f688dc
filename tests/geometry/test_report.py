import json
import shutil
from pathlib import Path

import pytest

from tampcli.errors import SceneError
from tampcli.geometry.report import scene_summary
from tampcli.optimize.modes import load_modes
from tampcli.pddl import parser

DATA = Path(__file__).parent / "data"


def _summary(domain, problem, dir_: Path):
    modes = dir_ / "modes.toml"
    return scene_summary(domain, problem, dir_ / "p01.pddl",
                         modes=load_modes(modes, domain) if modes.is_file() else None)


def _load(dir_: Path):
    return (parser.parse_domain_file(str(dir_ / "domain.pddl")),
            parser.parse_problem_file(str(dir_ / "p01.pddl")))


def test_summary_of_the_test_scene():
    domain, problem = _load(DATA)
    summary = _summary(domain, problem, DATA)
    json.dumps(summary)  # JSON-ready
    assert summary["robot"]["model"] == "panda" and len(summary["robot"]["joints"]) == 7
    assert summary["robot"]["tool_link"] == "panda_grasptarget"
    assert [b["name"] for b in summary["bodies"]] == ["table", "a", "b", "wall"]
    assert summary["bodies"][3]["obstacle"] is True
    assert summary["regions"][0]["name"] == "goal"
    assert summary["action_modes"] == {"pick": "grasp", "place": "place", "wait": "none"}
    assert summary["support"] == ["table"]
    assert summary["warnings"] == []
    # The cubes rest on the table: resting contact, reported at distance ~0, not refused.
    rest = [c for c in summary["start_contacts"] if {c["a"], c["b"]} == {"body:a", "body:table"}]
    assert not rest or abs(rest[0]["distance"]) < 1e-6


def test_no_scene_gives_none(tmp_path):
    domain, problem = _load(DATA)
    shutil.copy(DATA / "p01.pddl", tmp_path / "p01.pddl")
    assert _summary(domain, problem, tmp_path) is None


def _copy_with(tmp_path, scene_text=None, modes_text=None) -> Path:
    for name in ("domain.pddl", "p01.pddl", "p01.scene.toml", "modes.toml"):
        shutil.copy(DATA / name, tmp_path / name)
    if scene_text is not None:
        (tmp_path / "p01.scene.toml").write_text(scene_text)
    if modes_text is not None:
        (tmp_path / "modes.toml").write_text(modes_text)
    return tmp_path


def test_warns_about_unreachable_goal_region_and_unmoded_action(tmp_path):
    text = (DATA / "p01.scene.toml").read_text().replace(
        'size = [1.2, 1.4, 0.04]\npose = [0.3, 0.0, -0.02]',
        'size = [3.0, 3.0, 0.04]\npose = [0.3, 0.0, -0.02]').replace(
        "center = [0.45, 0.25]", "center = [1.5, 1.2]")
    modes = (DATA / "modes.toml").read_text().replace('[wait]\nmode = "none"\n', "")
    d = _copy_with(tmp_path, text, modes)
    domain, problem = _load(d)
    summary = _summary(domain, problem, d)
    assert any("goal region 'goal'" in w and "beyond its reach" in w for w in summary["warnings"])
    assert any("'wait' has no table" in w for w in summary["warnings"])


def test_refuses_a_start_in_collision(tmp_path):
    text = (DATA / "p01.scene.toml").read_text() + (
        '\n[[objects]]\nname = "crate"\nshape = "box"\nsize = [0.2, 0.2, 0.2]\n'
        'pose = [0.3, 0.0, 0.45]\nfixed = true\n')
    d = _copy_with(tmp_path, text)
    domain, problem = _load(d)
    with pytest.raises(SceneError) as info:
        _summary(domain, problem, d)
    assert info.value.key == "robot.start" and "in collision" in info.value.message
    assert info.value.line == 5


def test_start_pairs_cover_bodies_near_walls_and_each_other(tmp_path):
    # b (radius 3 cm) 2 cm in front of the wall's face at x = 0.74
    text = (DATA / "p01.scene.toml").read_text().replace("pose = [0.5, 0.1, 0.04]",
                                                         "pose = [0.69, 0.1, 0.04]")
    d = _copy_with(tmp_path, text)
    domain, problem = _load(d)
    summary = _summary(domain, problem, d)
    pairs = {frozenset((c["a"], c["b"])): c for c in summary["start_contacts"]}
    near_wall = pairs[frozenset(("body:b", "body:wall"))]
    assert near_wall["kind"] == "body-body"
    assert near_wall["distance"] == pytest.approx(0.02, abs=1e-4)
    assert pairs[frozenset(("body:a", "body:table"))]["kind"] == "body-body"
    kinds = {c["kind"] for c in summary["start_contacts"]}
    assert kinds <= {"robot-body", "robot-robot", "body-body"} and "robot-robot" in kinds
    distances = [c["distance"] for c in summary["start_contacts"]]
    assert distances == sorted(distances) and max(distances) < summary["start_contacts_within"]


def test_start_pairs_table_has_clear_headers(cli):
    run = cli("check", DATA / "domain.pddl", DATA / "p01.pddl")
    assert run.code == 0, run.err
    table = run.out[run.out.index("start state: pairs closer than 5 cm"):]
    header = table.splitlines()[2]
    assert [h.strip() for h in header.strip("┃ ").split("┃")] == [
        "pair", "part", "other part", "distance (mm)"]
    assert "body-body" in table and "body:wall" in table
