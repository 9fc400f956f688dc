"""`render_solution` builds one World in this process for the checks, the camera
and its frames, or none when the caller lends it one."""

import imageio.v3 as iio
import numpy as np
import pytest

from tampcli.geometry.world import World
from tampcli.render.inputs import load_inputs
from tampcli.render.options import RenderOptions
from tampcli.render.video import render_solution

SMALL = {"width": 64, "height": 48, "fps": 4.0, "duration": 1.0, "pause": 0.0, "workers": 1}


@pytest.fixture
def worlds(monkeypatch):
    built = []
    original = World.__init__

    def counting(self, scene):
        built.append(scene)
        original(self, scene)

    monkeypatch.setattr(World, "__init__", counting)
    return built


def test_render_builds_one_world_for_video_and_strip(planar_json, tmp_path, worlds):
    report = render_solution(planar_json, tmp_path / "v.gif", RenderOptions(**SMALL),
                             keyframes=tmp_path / "k.png")
    assert report["frames"] > 0 and report["panels"] > 0
    assert len(worlds) == 1


def test_a_lent_world_is_used_and_left_open(planar_json, tmp_path, worlds):
    inputs = load_inputs(planar_json)
    with World(inputs.scene) as world:
        lent = render_solution(inputs, tmp_path / "lent.gif", RenderOptions(**SMALL),
                               world=world)
        assert world.tool_pose(world.start).shape == (4, 4)  # still open
    assert len(worlds) == 1
    own = render_solution(inputs, tmp_path / "own.gif", RenderOptions(**SMALL))
    assert len(worlds) == 2
    # The same frames from a lent World as from one of render's own.
    a = iio.imread(tmp_path / "lent.gif", index=None)
    b = iio.imread(tmp_path / "own.gif", index=None)
    assert lent["frames"] == own["frames"] and np.array_equal(a, b)
