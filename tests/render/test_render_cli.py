"""`tampcli render`: outputs, JSON report, and every bad input as exit 2."""

import json

import imageio.v3 as iio
from render_solutions import planar_solution

from tampcli import solution as solution_file
from tampcli.solution import Solution

SMALL = ["--width", "96", "--height", "72", "--fps", "6", "--duration", "1", "--pause", "0.2",
         "--workers", "1"]


def test_render_mp4_and_keyframes(cli, planar_json, tmp_path):
    out, strip = tmp_path / "v.mp4", tmp_path / "k.png"
    run = cli("render", planar_json, "--video", out, "--keyframes", strip, *SMALL)
    assert run.code == 0, run.err
    assert f"wrote {out}" in run.out and "1 keyframe panels" in run.out
    assert iio.imread(out, index=None).shape == (round(1.6 * 6) + 1, 72, 96, 3)
    # not a terminal: progress comes as plain lines on stderr, the last one complete
    assert "rendering v.mp4: 11/11 frames" in run.err.splitlines()[-1]
    assert "Traceback" not in run.err


def test_json_report(cli, planar_json, tmp_path):
    out = tmp_path / "v.gif"
    run = cli("render", planar_json, "--video", out, "--json", *SMALL)
    assert run.code == 0, run.err
    report = json.loads(run.out)
    assert report["status"] == "ok" and report["path"] == str(out)
    assert report["frames"] == 11 and report["width"] == 96


def test_default_output_beside_the_solution(cli, tmp_path):
    path = tmp_path / "plan.json"
    solution_file.write(planar_solution(), path)
    run = cli("render", path, "--quiet", *SMALL)
    assert run.code == 0, run.err
    assert run.out == ""
    assert (tmp_path / "plan.mp4").stat().st_size > 0


def test_camera_flag(cli, planar_json, tmp_path):
    run = cli("render", planar_json, "--keyframes", tmp_path / "k.png", "--json",
              "--camera", "eye=1,1,1 target=0.3,0.3,0", "--camera", "fov=40", *SMALL)
    assert run.code == 0, run.err
    camera = json.loads(run.out)["camera"]
    assert camera["eye"] == [1.0, 1.0, 1.0] and camera["fov"] == 40.0


def test_solution_path_after_the_camera(cli, planar_json, tmp_path):
    """--camera takes one value, so it does not swallow the solution path."""
    run = cli("render", "--camera", "eye=1,1,1 target=0.3,0.3,0", planar_json,
              "--keyframes", tmp_path / "k.png", "--json", *SMALL)
    assert run.code == 0, run.err
    assert json.loads(run.out)["camera"]["target"] == [0.3, 0.3, 0.0]
    run = cli("render", "--camera", "eye=1,1,1,target=0.3,0.3,0,fov=30", planar_json,
              "--keyframes", tmp_path / "k.png", "--json", *SMALL)
    assert run.code == 0, run.err
    assert json.loads(run.out)["camera"]["fov"] == 30.0


def test_bad_camera_is_usage_error(cli, planar_json, tmp_path):
    # fov=0 would divide by zero in automatic framing (this scene has no [camera])
    for spec in ("eye=1,1", "eyes=1,1,1", "eye=a,b,c", "eye=0.3,0.3,0 target=0.3,0.3,0",
                 "fov=0"):
        run = cli("render", planar_json, "--keyframes", tmp_path / "k.png", "--camera", spec)
        assert run.code == 2, (spec, run.err)
        assert "--camera" in run.err and "Traceback" not in run.err


def test_bad_extension(cli, planar_json, tmp_path):
    run = cli("render", planar_json, "--video", tmp_path / "v.webm", *SMALL)
    assert run.code == 2
    assert "unknown video format '.webm'" in run.err
    run = cli("render", planar_json, "--keyframes", tmp_path / "k.tiff", *SMALL)
    assert run.code == 2 and "unknown image format" in run.err


def test_unwritable_path(cli, planar_json, tmp_path):
    (tmp_path / "f").write_text("")
    run = cli("render", planar_json, "--video", tmp_path / "f" / "v.mp4", *SMALL)
    assert run.code == 2
    assert "cannot write" in run.err and "Traceback" not in run.err


def test_bad_numbers(cli, planar_json):
    for flags in (["--fps", "0"], ["--width", "5"], ["--workers", "-1"], ["--duration", "-2"]):
        run = cli("render", planar_json, *flags)
        assert run.code == 2, flags
        assert flags[0] in run.err


def _write(tmp_path, **changes) -> str:
    sol = planar_solution()
    path = tmp_path / "bad.json"
    solution_file.write(Solution(**{**sol.__dict__, **changes}), path)
    return path


def test_joint_count_mismatch(cli, tmp_path):
    path = _write(tmp_path, trajectory=tuple(q + (0.0,) for q in planar_solution().trajectory),
                  robot={"model": "planar", "joints": ["x", "y", "z"]})
    run = cli("render", path, "--video", tmp_path / "v.mp4", *SMALL)
    assert run.code == 2
    assert "robot.joints: unknown joint 'z': expected joints of the scene's robot (x, y)" \
        in run.err
    assert not (tmp_path / "v.mp4").exists()


def test_joint_names_mismatch(cli, tmp_path):
    path = _write(tmp_path, robot={"model": "planar", "joints": ["u", "v"]})
    run = cli("render", path, *SMALL)
    assert run.code == 2 and "robot.joints" in run.err


def test_unknown_object(cli, tmp_path):
    sol = planar_solution()
    path = _write(tmp_path, objects={"crate": sol.objects["box"]})
    run = cli("render", path, "--video", tmp_path / "v.mp4", *SMALL)
    assert run.code == 2
    assert "objects.crate" in run.err and "'crate' is no body of the scene" in run.err


def test_missing_scene(cli, tmp_path):
    path = _write(tmp_path, scene="nowhere.scene.toml")
    run = cli("render", path, *SMALL)
    assert run.code == 2 and "scene file not found" in run.err


def test_not_a_solution(cli, tmp_path):
    path = tmp_path / "s.json"
    path.write_text("{\"version\": 1}")
    run = cli("render", path, *SMALL)
    assert run.code == 2 and "missing" in run.err
    run = cli("render", tmp_path / "absent.json", *SMALL)
    assert run.code == 2 and "file not found" in run.err


def test_physics_report(cli, planar_json):
    run = cli("render", planar_json, "--physics", "--json", *SMALL)
    assert run.code == 0, run.err
    physics = json.loads(run.out)["physics"]
    assert set(physics["objects"]) == {"box"}
    assert physics["objects"]["box"]["distance"] < 0.02
    run = cli("render", planar_json, "--physics", *SMALL)
    assert "physics replay" in run.out and "box" in run.out
