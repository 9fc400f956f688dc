"""Which overlaps of the start state are refused (docs/scene.md, "The start state").

Two obstacles may overlap (one fixed solid built from parts); a movable body,
and a fixed body the problem names, may not overlap anything.
"""

from pathlib import Path

import pytest

from tampcli.errors import SceneError
from tampcli.pddl import parser

from .loading import load_checked

DATA = Path(__file__).parent / "data"

# The test scene's table, cubes `a` and `b`, and region; the robot far from it all.
BASE = """[robot]
model = "panda"

[[objects]]
name = "table"
shape = "box"
size = [1.2, 1.4, 0.04]
pose = [0.3, 0.0, -0.02]
fixed = true

[[objects]]
name = "a"
shape = "box"
size = [0.05, 0.05, 0.05]
pose = [0.45, -0.2, 0.025]

[[objects]]
name = "b"
shape = "box"
size = [0.05, 0.05, 0.05]
pose = [0.5, 0.1, 0.025]

[[regions]]
name = "goal"
on = "table"
center = [0.45, 0.25]
size = [0.15, 0.15]
"""


def _box(name: str, size, pose) -> str:
    return (f'\n[[objects]]\nname = "{name}"\nshape = "box"\nsize = {list(size)}\n'
            f"pose = {list(pose)}\nfixed = true\n")


# Two obstacle parts of a shelf at the far side of the table: 2 cm into each other.
SHELF = _box("shelf-side", (0.04, 0.3, 0.3), (0.8, 0.0, 0.15))
BOARD = _box("shelf-board", (0.2, 0.3, 0.02), (0.7, 0.0, 0.2))


@pytest.fixture(scope="module")
def pddl():
    return (parser.parse_domain_file(str(DATA / "domain.pddl")),
            parser.parse_problem_file(str(DATA / "p01.pddl")))


def _load(tmp_path, text, pddl):
    path = tmp_path / "p01.scene.toml"
    path.write_text(text)
    return path, load_checked(path, *pddl)


def test_the_shelf_parts_do_overlap(tmp_path):
    """Without a problem nothing is an obstacle: the parts' overlap is then refused."""
    path = tmp_path / "p01.scene.toml"
    path.write_text(BASE + SHELF + BOARD)
    with pytest.raises(SceneError) as info:
        load_checked(path)
    assert "'shelf-board' overlaps 'shelf-side' by 20.0 mm" in info.value.message


def test_overlapping_obstacles_are_accepted(tmp_path, pddl):
    _, scene = _load(tmp_path, BASE + SHELF + BOARD, pddl)
    assert {b.name for b in scene.bodies if b.obstacle} == {"shelf-side", "shelf-board"}


def test_movable_body_overlapping_an_obstacle_is_refused(tmp_path, pddl):
    text = BASE.replace("pose = [0.5, 0.1, 0.025]", "pose = [0.79, 0.0, 0.025]") + SHELF
    with pytest.raises(SceneError) as info:
        _load(tmp_path, text, pddl)
    error = info.value
    shelf_pose = text.splitlines().index("pose = [0.8, 0.0, 0.15]") + 1  # the later body's
    assert (error.key, error.line) == ("objects.pose", shelf_pose)
    assert "'shelf-side' overlaps 'b'" in error.message


def test_fixed_body_named_in_the_problem_overlapping_an_obstacle_is_refused(tmp_path, pddl):
    # A block 1 cm into the table top: the table is a PDDL surface, not a part of an obstacle.
    text = BASE + _box("block", (0.1, 0.1, 0.1), (0.0, 0.5, 0.04))
    with pytest.raises(SceneError) as info:
        _load(tmp_path, text, pddl)
    assert "'block' overlaps 'table' by 10.0 mm" in info.value.message


def test_resting_contact_is_not_overlap(tmp_path, pddl):
    # The cubes rest on the table top (z = 0) and `a` sinks 2 mm into it: modelling slack.
    _, scene = _load(tmp_path, BASE.replace("0.45, -0.2, 0.025", "0.45, -0.2, 0.023"), pddl)
    assert scene.body("a").pose[2] == pytest.approx(0.023)
