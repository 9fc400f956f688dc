"""Real renders to mp4, gif and keyframe strips, read back with imageio."""

import imageio.v3 as iio
import numpy as np
import pytest
from PIL import Image

from tampcli.errors import SolutionFileError, UsageError
from tampcli.geometry.world import World
from tampcli.render.encode import strip_geometry
from tampcli.render.options import RenderOptions
from tampcli.render.video import render_solution

SMALL = {"width": 160, "height": 120, "fps": 8.0, "duration": 1.5, "pause": 0.25}


def _frames(path):
    return iio.imread(path, index=None)


@pytest.fixture(scope="module")
def panda_mp4(panda_json, tmp_path_factory):
    out = tmp_path_factory.mktemp("mp4") / "panda.mp4"
    report = render_solution(panda_json, out, RenderOptions(workers=1, **SMALL))
    return out, report


def test_mp4_has_the_frames_and_size_asked(panda_mp4):
    out, report = panda_mp4
    frames = _frames(out)
    # 1.5 s of motion + 4 pauses of 0.25 s at 8 fps, both ends included
    assert report["frames"] == round((1.5 + 4 * 0.25) * 8) + 1 == len(frames)
    assert frames.shape[1:] == (120, 160, 3)
    assert iio.immeta(out)["codec"] == "h264"
    assert report["seconds"] == pytest.approx(2.5)


def test_frames_change_while_the_robot_moves(panda_mp4):
    out, _ = panda_mp4
    frames = _frames(out).astype(int)
    scene = frames[:, : -20]  # above the caption bar
    diffs = [np.abs(b - a).mean() for a, b in zip(scene, scene[1:], strict=False)]
    # the first two frames are the start pause; then the arm moves
    assert diffs[0] < 1.0
    assert diffs[3] > 1.0 and diffs[4] > 1.0
    # the arm comes back to its start, but the cube is no longer where it was
    end_to_end = np.abs(scene[0] - scene[-1]).max(axis=2) > 60
    assert end_to_end.sum() > 20
    assert (np.abs(scene[-2] - scene[-1]).max(axis=2) > 60).sum() < 5  # the end pause


def test_parallel_workers_give_the_same_frames_in_order(panda_json, panda_mp4, tmp_path):
    serial, _ = panda_mp4
    out = tmp_path / "parallel.mp4"
    report = render_solution(panda_json, out, RenderOptions(workers=2, **SMALL))
    assert report["workers"] == 2
    a, b = _frames(serial).astype(int), _frames(out).astype(int)
    assert a.shape == b.shape
    # same content up to encoder noise; a swapped chunk would differ by far more
    assert max(np.abs(x - y).mean() for x, y in zip(a, b, strict=True)) < 1.0


def test_gif(planar_json, tmp_path):
    out = tmp_path / "planar.gif"
    report = render_solution(planar_json, out, RenderOptions(workers=1, **SMALL))
    frames = _frames(out)
    assert frames.shape[1:3] == (120, 160)
    # identical consecutive frames (pauses) are merged in a GIF; the duration stays
    assert 2 < len(frames) <= report["frames"]
    with Image.open(out) as gif:
        total = 0
        for i in range(gif.n_frames):
            gif.seek(i)
            total += gif.info["duration"]
    assert total == pytest.approx(report["frames"] * 1000 / 8, rel=0.1)
    assert np.abs(frames[0].astype(int) - frames[-1]).mean() > 0.5
    # one palette for all frames: the empty background keeps its colour
    assert len({tuple(f[0, 0]) for f in frames}) == 1


def test_keyframe_strip_has_a_panel_per_geometric_action(panda_json, tmp_path):
    out = tmp_path / "strip.png"
    report = render_solution(panda_json, None, RenderOptions(**SMALL), keyframes=out)
    assert report["panels"] == 2 and report["frames"] == 0
    with Image.open(out) as image:
        assert image.size == strip_geometry(2, 160, 120)
        pixels = np.asarray(image.convert("RGB")).astype(int)
    left, right = pixels[:, :160], pixels[:, -160:]
    assert np.abs(left - right).mean() > 1.0


def test_relative_paths_are_found_beside_the_solution(relative_copy, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path.parent)  # not where the solution is
    out = tmp_path / "strip.png"
    assert render_solution(relative_copy, None, RenderOptions(**SMALL), keyframes=out)["panels"] == 2


def test_scene_camera_is_used(tmp_path):
    from render_solutions import panda_solution

    from tampcli import solution as solution_file

    path = tmp_path / "s.json"
    solution_file.write(panda_solution(scene="p02.scene.toml", problem="p02.pddl"), path)
    report = render_solution(path, None, RenderOptions(**SMALL), keyframes=tmp_path / "k.png")
    assert report["camera"]["eye"] == (0.2, 0.0, 2.0)


def test_camera_flag_overrides(panda_json, tmp_path):
    options = RenderOptions(camera={"eye": (2.0, 0.0, 1.0)}, **SMALL)
    report = render_solution(panda_json, None, options, keyframes=tmp_path / "k.png")
    assert report["camera"]["eye"] == (2.0, 0.0, 1.0)


@pytest.mark.parametrize("name", ["out.avi", "out", "out.MP3"])
def test_unknown_extension(panda_json, tmp_path, name):
    with pytest.raises(UsageError, match="unknown video format"):
        render_solution(panda_json, tmp_path / name, RenderOptions(**SMALL))


def test_unwritable_path_fails_before_rendering(panda_json, tmp_path):
    blocker = tmp_path / "file.txt"
    blocker.write_text("not a directory")
    with pytest.raises(UsageError, match="cannot write"):
        render_solution(panda_json, blocker / "out.mp4", RenderOptions(**SMALL))
    folder = tmp_path / "looks-like.png"
    folder.mkdir()
    with pytest.raises(UsageError, match="is a directory"):
        render_solution(panda_json, None, RenderOptions(**SMALL), keyframes=folder)


def test_odd_size_mp4_is_refused(panda_json, tmp_path):
    with pytest.raises(UsageError, match="even"):
        render_solution(panda_json, tmp_path / "o.mp4", RenderOptions(width=161, height=120))
    assert not (tmp_path / "o.mp4").exists()


def test_solution_without_trajectory(tmp_path):
    from render_solutions import panda_solution

    from tampcli import solution as solution_file
    from tampcli.solution import Solution

    sol = panda_solution()
    empty = Solution(**{**sol.__dict__, "status": "limit", "reason": "time limit",
                        "trajectory": (), "phases": (), "objects": {}})
    path = tmp_path / "s.json"
    solution_file.write(empty, path)
    with pytest.raises(SolutionFileError, match="nothing to render"):
        render_solution(path, tmp_path / "o.mp4", RenderOptions(**SMALL))
    assert not (tmp_path / "o.mp4").exists()


@pytest.mark.parametrize("modes,panels", [(None, 2), ("modes.toml", 2),
                                          ("modes_note_moves.toml", 3)])
def test_modes_decide_which_actions_get_a_panel(tmp_path, modes, panels):
    from render_solutions import PANDA, panda_solution

    from tampcli.solution import Solution

    sol = panda_solution(with_note=True)
    sol = Solution(**{**sol.__dict__, "modes": str(PANDA / modes) if modes else None})
    report = render_solution(sol, None, RenderOptions(**SMALL), keyframes=tmp_path / "k.png")
    assert report["panels"] == panels


def test_a_pause_is_rendered_once(panda_json):
    from tampcli.render.frames import _runs
    from tampcli.render.inputs import load_inputs
    from tampcli.render.video import _plan

    inputs = load_inputs(panda_json)
    with World(inputs.scene) as world:
        replay, _ = _plan(inputs, world, RenderOptions(**SMALL))
    states = replay.states(8)
    unique, repeats = _runs(states)
    assert sum(repeats) == len(states) and len(unique) < len(states)
    assert repeats[0] >= 2  # the start pause: 0.25 s at 8 fps


def test_abandoning_a_parallel_render_stops_its_workers(panda_json):
    import multiprocessing

    from tampcli.render.frames import FrameJob, render_frames
    from tampcli.render.inputs import load_inputs
    from tampcli.render.video import _plan

    inputs = load_inputs(panda_json)
    with World(inputs.scene) as world:
        replay, camera = _plan(inputs, world, RenderOptions(**SMALL))
    frames = render_frames(FrameJob(inputs.scene, camera, 64, 48), replay.states(8), workers=2)
    assert next(frames).shape == (48, 64, 3)
    frames.close()
    assert not [p for p in multiprocessing.active_children() if p.name.startswith("tampcli")]


def test_progress_bar_on_a_terminal(planar_json, tmp_path):
    import io

    from rich.console import Console

    from tampcli.cli.ui import UI

    out, err = io.StringIO(), io.StringIO()
    ui = UI(Console(file=out, force_terminal=True, width=100),
            Console(file=err, force_terminal=True, width=100))
    assert ui.interactive
    report = render_solution(planar_json, tmp_path / "v.gif", RenderOptions(**SMALL), ui=ui)
    assert report["frames"] > 0
    assert "rendering v.gif" in err.getvalue() and "\x1b[" in err.getvalue()


def test_a_worker_that_dies_is_an_error_not_a_hang(panda_json):
    import multiprocessing
    import os
    import signal

    from tampcli.render.frames import FrameJob, render_frames
    from tampcli.render.inputs import load_inputs
    from tampcli.render.video import _plan

    inputs = load_inputs(panda_json)
    with World(inputs.scene) as world:
        replay, camera = _plan(inputs, world, RenderOptions(**{**SMALL, "pause": 0.0}))
    states = replay.states(60)
    assert len(states) > 60
    frames = render_frames(FrameJob(inputs.scene, camera, 32, 24), states, workers=2)
    next(frames)
    (worker,) = [p for p in multiprocessing.active_children() if p.name.startswith("tampcli")]
    os.kill(worker.pid, signal.SIGKILL)
    with pytest.raises(RuntimeError, match="died"):
        for _ in frames:
            pass
    assert not [p for p in multiprocessing.active_children() if p.name.startswith("tampcli")]


@pytest.mark.parametrize("change,key", [
    ("short_poses", "objects.a"), ("bad_phase", "phases[1]"), ("nan", "trajectory")])
def test_an_in_memory_solution_is_checked_like_a_file(change, key):
    from render_solutions import panda_solution

    from tampcli.solution import Phase, Solution

    sol = panda_solution()
    if change == "short_poses":
        sol = Solution(**{**sol.__dict__, "objects": {**sol.objects, "a": sol.objects["a"][:2]}})
    elif change == "bad_phase":
        phases = list(sol.phases)
        phases[1] = Phase("(pick a table)", 999, 999, "a")
        sol = Solution(**{**sol.__dict__, "phases": tuple(phases)})
    else:
        sol = Solution(**{**sol.__dict__, "trajectory": ((float("nan"),) * 7,)
                          + sol.trajectory[1:]})
    with pytest.raises(SolutionFileError) as err:
        render_solution(sol, None, RenderOptions(**SMALL))
    assert err.value.key == key
