"""`render` refuses a solution.json that is malformed or does not fit its scene:
exit 2, a message naming the key, no traceback, no video written."""

import json

import pytest
from render_solutions import PLANAR, planar_solution

from tampcli import solution as solution_file
from tampcli.errors import SolutionFileError
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.render.inputs import check_against_world, load_inputs
from tampcli.solution import Phase, Solution

SMALL = ["--width", "96", "--height", "72", "--fps", "6", "--duration", "1", "--workers", "1"]


def _good() -> dict:
    """The planar push as JSON: phases 0-12, 12-24, 24-30; box the only movable body."""
    return solution_file.to_dict(planar_solution())


def _render_fails(cli, tmp_path, data, key, words):
    path = tmp_path / "bad.json"
    path.write_text(data if isinstance(data, str) else json.dumps(data))
    out = tmp_path / "v.mp4"
    run = cli("render", path, "--video", out, *SMALL)
    assert run.code == 2, run.err
    assert "Traceback" not in run.err and "internal error" not in run.err
    assert f"{path}: {key}: " in run.err, run.err
    for word in words:
        assert word in run.err, run.err
    assert not out.exists()


def _set(data, dotted, value):
    *parents, last = dotted.split(".")
    for part in parents:
        data = data[int(part)] if isinstance(data, list) else data[part]
    if isinstance(data, list):
        data[int(last)] = value
    else:
        data[last] = value


def _phases(edit):
    def change(data):
        edit(data["phases"], len(data["trajectory"]))
    return change


def _outside(delta):
    def change(data):
        data["trajectory"][5][0] = 1.0 + delta  # x's upper limit: the scene's extent
    return change


# name -> (change to the good JSON, key in the message, words in the message)
MISMATCHES = {
    "other robot model": (lambda d: _set(d, "robot.model", "panda"), "robot.model",
                          ["'panda' but the scene", "'planar' robot"]),
    "no robot model": (lambda d: d["robot"].pop("model"), "robot.model",
                       ["missing", "'planar'"]),
    "other tool link": (lambda d: _set(d, "robot.tool_link", "hand"), "robot.tool_link",
                        ["'hand'", "'planar_body'"]),
    "a fixed body in objects": (lambda d: _set(d, "objects.table", d["objects"]["box"]),
                                "objects.table", ["fixed body"]),
    "a movable body missing": (lambda d: d["objects"].pop("box"), "objects",
                               ["no poses for 'box'", "every movable body"]),
    "beyond a joint limit": (_outside(1e-3), "trajectory",
                             ["waypoint 5: joint x = 1.001 outside its limits [-0.2, 1]"]),
    "first phase starts late": (_phases(lambda p, n: _set(p, "0.start", 1)), "phases[0].start",
                                ["starts at 1, expected 0"]),
    "a gap between phases": (_phases(lambda p, n: _set(p, "2.start", p[2]["start"] + 1)),
                             "phases[2].start", ["starts at 25, expected 24", "phases[1].end"]),
    "an overlap of phases": (_phases(lambda p, n: _set(p, "1.start", p[1]["start"] - 1)),
                             "phases[1].start", ["starts at 11, expected 12"]),
    "last phase ends early": (_phases(lambda p, n: _set(p, "2.end", n - 2)), "phases[2].end",
                              ["ends at 29, expected 30", "last waypoint"]),
    "start after end": (_phases(lambda p, n: _set(p, "1.start", p[1]["end"] + 1)), "phases[1]",
                        ["start/end out of range"]),
    "no phases": (lambda d: d.update(phases=[], objects={"box": d["objects"]["box"][:1]}),
                  "phases", ["no phases for a trajectory of 31 waypoints"]),
    "a pose too many": (lambda d: d["objects"]["box"].append(d["objects"]["box"][-1]),
                        "objects.box", ["expected 4 poses", "found 5"]),
    "a pose too few": (lambda d: d["objects"]["box"].pop(), "objects.box",
                       ["expected 4 poses", "found 3"]),
}


@pytest.mark.parametrize("name", MISMATCHES)
def test_a_solution_that_does_not_fit_its_scene(cli, tmp_path, name):
    change, key, words = MISMATCHES[name]
    data = _good()
    change(data)
    _render_fails(cli, tmp_path, data, key, words)


def _huge_int(data):
    data["trajectory"][3][1] = 10 ** 400  # valid JSON; too large for a float


# Malformed values that `solution.read` lets through and replay would trip on.
MALFORMED = {
    "plan not a list": (lambda d: _set(d, "plan", 5), "plan", ["expected a list of strings"]),
    "plan entry not a string": (lambda d: _set(d, "plan", [1]), "plan[0]",
                                ["expected a string", "found 1"]),
    "joints not a list": (lambda d: _set(d, "robot.joints", 7), "robot.joints",
                          ["expected a list of strings"]),
    "joints null": (lambda d: _set(d, "robot.joints", None), "robot.joints",
                    ["expected a list of strings"]),
    "model not a string": (lambda d: _set(d, "robot.model", 3), "robot.model",
                           ["expected a string"]),
    "skeleton not an object": (lambda d: _set(d, "skeletons", [5]), "skeletons[0]",
                               ["expected an object"]),
    "skeleton rank null": (lambda d: _set(d, "skeletons", [{"rank": None}]),
                           "skeletons[0].rank", ["expected an integer"]),
    "skeleton plan a number": (lambda d: _set(d, "skeletons", [{"plan": 3}]),
                               "skeletons[0].plan", ["expected a list of strings"]),
    "skeleton seconds a word": (lambda d: _set(d, "skeletons", [{"seconds": "x"}]),
                                "skeletons[0].seconds", ["expected a number"]),
    "scene a number": (lambda d: _set(d, "scene", 5), "scene", ["expected a path"]),
    "domain a list": (lambda d: _set(d, "domain", ["x"]), "domain", ["expected a path"]),
    "modes a number": (lambda d: _set(d, "modes", 3), "modes", ["expected a path"]),
    "action a number": (lambda d: _set(d, "phases.1.action", 3), "phases[1].action",
                        ["expected a string or null"]),
    "attached a list": (lambda d: _set(d, "phases.1.attached", ["box"]), "phases[1].attached",
                        ["expected a string or null"]),
    "empty trajectory": (lambda d: d.update(trajectory=[], phases=[], objects={}), "trajectory",
                         ["nothing to render"]),
    "empty waypoints": (lambda d: d.update(trajectory=[[]], phases=[], robot={
        **d["robot"], "joints": []}, objects={"box": d["objects"]["box"][:1]}), "trajectory",
                        ["0 joint values", "has 2"]),
    "NaN in a waypoint": (lambda d: _set(d, "trajectory.4.0", float("nan")), "trajectory",
                          ["waypoint 4 holds a non-finite value"]),
    "Infinity in a waypoint": (lambda d: _set(d, "trajectory.4.1", float("inf")), "trajectory",
                               ["waypoint 4"]),
    "a huge integer in a waypoint": (_huge_int, "trajectory", ["waypoint 3"]),
    "NaN in a pose": (lambda d: _set(d, "objects.box.1.0", float("nan")), "objects.box",
                      ["pose 1: expected 7 finite numbers"]),
    "a zero quaternion": (lambda d: _set(d, "objects.box.2", [0.3, 0.3, 0.025, 0, 0, 0, 0]),
                          "objects.box", ["pose 2 has a zero quaternion"]),
    "poses not a list": (lambda d: _set(d, "objects.box", "here"), "objects.box",
                         ["expected a list"]),
    "phases not a list": (lambda d: _set(d, "phases", {}), "phases", ["expected a list"]),
    "phase without end": (lambda d: d["phases"][0].pop("end"), "phases[0]", ["needs"]),
    "phases missing": (lambda d: d.pop("phases"), "phases", ["missing"]),
    "robot not an object": (lambda d: _set(d, "robot", "planar"), "robot",
                            ["expected an object"]),
}


@pytest.mark.parametrize("name", MALFORMED)
def test_a_malformed_solution_is_an_input_error(cli, tmp_path, name):
    change, key, words = MALFORMED[name]
    data = _good()
    change(data)
    _render_fails(cli, tmp_path, data, key, words)


def test_a_file_that_is_not_utf8(cli, tmp_path):
    path = tmp_path / "bad.json"
    path.write_bytes(b'{"version": 1, "plan": ["\xff"]}')
    run = cli("render", path, *SMALL)
    assert run.code == 2 and "not UTF-8 text" in run.err and "Traceback" not in run.err


def test_deeply_nested_json(cli, tmp_path):
    path = tmp_path / "bad.json"
    path.write_text("[" * 100_000 + "]" * 100_000)
    run = cli("render", path, *SMALL)
    assert run.code == 2 and "nested too deeply" in run.err


def _checked(sol: Solution):
    """check_against_world on an in-memory solution, without rendering."""
    inputs = load_inputs(sol)
    with World(load_scene(PLANAR / "p01.scene.toml", geometric=False)) as world:
        check_against_world(inputs, world)
        return world.upper


def test_joint_limits_allow_a_micrometre():
    sol = planar_solution()
    upper = _checked(sol)
    trajectory = list(sol.trajectory)
    for excess, fits in ((0.5e-6, True), (2e-6, False)):
        trajectory[5] = (float(upper[0]) + excess, trajectory[5][1])
        bad = Solution(**{**sol.__dict__, "trajectory": tuple(trajectory)})
        if fits:
            _checked(bad)
        else:
            with pytest.raises(SolutionFileError, match="outside its limits"):
                _checked(bad)


def test_an_instantaneous_last_phase_covers_the_end():
    """A symbolic action after the last motion: start == end == the last waypoint."""
    sol = planar_solution()
    n = len(sol.trajectory)
    phases = sol.phases + (Phase("(note box)", n - 1, n - 1),)
    objects = {"box": sol.objects["box"] + [sol.objects["box"][-1]]}
    _checked(Solution(**{**sol.__dict__, "phases": phases, "objects": objects,
                         "plan": sol.plan + ("(note box)",)}))
