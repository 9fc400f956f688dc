"""`render` on the shapes of solution.json `solve` does not write: Panda finger
columns, a motion split in several, a retreat. Real renders, read back."""

import json
from collections.abc import Callable

import imageio.v3 as iio
import numpy as np
from render_solutions import PANDA, panda_solution

from tampcli import solution as solution_file
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.render.options import RenderOptions
from tampcli.render.video import render_solution
from tests.solution_shapes import add_fingers, split_motion

SMALL = ["--width", "96", "--height", "72", "--fps", "6", "--duration", "1", "--pause", "0.2",
         "--workers", "1"]


def _panda_dict() -> dict:
    """Pick a, place a, move back: motion, pick, carry, place, retreat."""
    return solution_file.to_dict(panda_solution())


def _opening(data) -> Callable[[int], float]:
    carry = next(p for p in data["phases"] if p["attached"] == "a" and p["action"] is None)
    return lambda i: 0.025 if carry["start"] <= i < carry["end"] else 0.04


def test_nine_columns_split_motions_and_a_retreat(cli, tmp_path):
    data = _panda_dict()
    assert data["phases"][-1]["action"] is None  # it ends with a retreat already
    with World(load_scene(PANDA / "p01.scene.toml", geometric=False)) as world:
        data = split_motion(data, 2, data["phases"][2]["start"] + 4, world)
    order = ("panda_finger_joint1",) + tuple(data["robot"]["joints"]) + ("panda_finger_joint2",)
    data = add_fingers(data, _opening(data), order)
    assert len(data["trajectory"][0]) == 9
    path, out = tmp_path / "nine.json", tmp_path / "nine.mp4"
    path.write_text(json.dumps(data))
    run = cli("render", path, "--video", out, "--json", *SMALL)
    assert run.code == 0, run.err
    report = json.loads(run.out)
    frames = iio.imread(out, index=None)
    assert report["frames"] == len(frames) > 6
    assert frames.shape[1:] == (72, 96, 3)
    scene = frames[:, :-12].astype(int)
    assert max(np.abs(b - a).mean() for a, b in zip(scene, scene[1:], strict=False)) > 1.0


def test_the_canonical_form_times_a_video_as_the_plain_one(tmp_path):
    """Split motions and finger columns change the file, not the motion shown."""
    plain = tmp_path / "plain.json"
    solution_file.write(panda_solution(), plain)
    data = _panda_dict()
    with World(load_scene(PANDA / "p01.scene.toml", geometric=False)) as world:
        data = split_motion(data, 0, 3, world)
        data = split_motion(data, 3, data["phases"][3]["start"] + 5, world)
    data = add_fingers(data, _opening(data))
    reshaped = tmp_path / "reshaped.json"
    reshaped.write_text(json.dumps(data))
    options = RenderOptions(width=64, height=48, fps=6.0, workers=1)
    a = render_solution(plain, None, options, keyframes=tmp_path / "a.png")
    b = render_solution(reshaped, None, options, keyframes=tmp_path / "b.png")
    assert a["seconds"] == b["seconds"] > 0
    assert a["panels"] == b["panels"] == 2
