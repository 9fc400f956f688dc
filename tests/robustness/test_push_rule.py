"""A push is a push, end to end: robust-planar-push p01 solved by `tampcli solve`,
accepted by `validate` and by the independent checker, the disk moving into the
face it touches; the same solution turned into a drag by hand is refused, and
its video's replay shows the disk behind the crate."""
import io
import json

import numpy as np
import pytest
from rich.console import Console

from tampcli.cli import main
from tampcli.cli.ui import UI
from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.render.replay import Replay
from tampcli.solution_read import read_solution
from tests.conftest import ROOT, Run
from tests.robustness.checker import check_solution
from tests.robustness.test_robust_planar import PP, _case, _push_directions

CASE = _case(PP, "p01")
PUSH = "(push crate start goal bench)"


def run(*argv) -> Run:
    """The CLI in-process, as the `cli` fixture runs it (this module solves once)."""
    out, err = io.StringIO(), io.StringIO()
    ui = UI(Console(file=out, width=200, highlight=False, soft_wrap=True),
            Console(file=err, width=200, highlight=False, soft_wrap=True))
    code = main([str(a) for a in argv], ui)
    return Run(code, out.getvalue(), err.getvalue())


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    out = tmp_path_factory.mktemp("push") / "solution.json"
    done = run("solve", CASE.domain, CASE.problem, "--time-limit", 60, "--out", out)
    assert done.code == 0, done.out + done.err
    return run, out


def test_the_channel_push_is_solved_as_a_push(solved):
    run, out = solved
    sol = json.loads(out.read_text())
    assert sol["plan"] == [PUSH]
    valid = run("validate", CASE.domain, CASE.problem, out)
    assert valid.code == 0, valid.out + valid.err
    assert check_solution(out, problem=CASE.problem) == []
    assert _push_directions(CASE, sol) == []


def test_a_hand_made_drag_is_refused(solved, tmp_path):
    run, out = solved
    sol = json.loads(out.read_text())
    (k, phase), = [(i, p) for i, p in enumerate(sol["phases"]) if p["action"] == PUSH]
    traj = np.array(sol["trajectory"])
    n = phase["end"] - phase["start"]
    # Touch the -x face, then slide along it: 3 cm sideways for every 1 cm into it.
    traj[phase["start"]:phase["end"] + 1] = traj[phase["start"]] + np.outer(
        np.arange(n + 1) / n, [0.01, 0.03])
    crate = list(sol["objects"]["crate"][k])
    crate[0] += 0.01
    crate[1] += 0.03
    for later in range(k + 1, len(sol["objects"]["crate"])):
        sol["objects"]["crate"][later] = crate
    sol["trajectory"] = traj[:phase["end"] + 1].tolist()
    sol["phases"] = sol["phases"][:k + 1]
    sol["objects"] = {n: v[:k + 2] for n, v in sol["objects"].items()}
    drag = tmp_path / "drag.json"
    drag.write_text(json.dumps(sol))
    refused = run("validate", CASE.domain, CASE.problem, drag)
    assert refused.code != 0
    assert "(a drag" in refused.out + refused.err, refused.out + refused.err
    assert _push_directions(CASE, sol)  # the robustness test's own rule agrees


def test_the_replay_shows_the_disk_behind_the_crate(solved):
    _, out = solved
    sol = read_solution(out).canonical
    scene = load_scene(ROOT / "problems" / "robust-planar-push" / "p01.scene.toml",
                       geometric=False)
    with World(scene) as world:
        replay = Replay(sol, world.tool_pose, duration=2.0, mode_kind=lambda a: "push")
        pushing = [s for s in replay.states(20) if s.label == PUSH]
        assert len(pushing) > 5
        radius, half = scene.robot.radius, 0.06
        for s in pushing:
            crate = s.poses["crate"]
            rel = crate[:3, :3].T @ (np.array([*s.q, crate[2, 3]]) - crate[:3, 3])
            assert -(half + radius) - 1e-3 <= rel[0] < -(half + radius)  # touching its -x face
            assert abs(rel[1]) <= half
            assert s.held is None and not s.fingers_closed
        assert pushing[-1].poses["crate"][0, 3] - pushing[0].poses["crate"][0, 3] > 0.3
