"""End to end on a problem of the library: solve it, then render what solve wrote."""

import json

import imageio.v3 as iio
import pytest

from tampcli.render.encode import strip_geometry

ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_solve_then_render_planar_push(cli, tmp_path):
    solution, video = tmp_path / "p01.json", tmp_path / "solve.mp4"
    run = cli("solve", ROOT / "domains/planar-push/domain.pddl",
              ROOT / "problems/planar-push/p01.pddl", "--out", solution, "--video", video,
              "--time-limit", "120")
    assert run.code == 0, run.err
    assert iio.imread(video, index=None).shape[1:] == (480, 640, 3)
    strip, gif = tmp_path / "k.png", tmp_path / "r.gif"
    run = cli("render", solution, "--video", gif, "--keyframes", strip, "--width", "160",
              "--height", "120", "--fps", "10", "--physics", "--json")
    assert run.code == 0, run.err
    report = json.loads(run.out)
    plan = json.loads(solution.read_text())["plan"]
    assert report["panels"] == len(plan)
    assert iio.imread(strip).shape[1::-1] == strip_geometry(len(plan), 160, 120)
    # Pushing is by contact alone in the physics replay, so a curved push may
    # well lose the box: only ask for a well-formed report here.
    physics = report["physics"]["objects"]["box"]
    assert 0.0 <= physics["distance"] < 5.0 and len(physics["simulated"]) == 7
