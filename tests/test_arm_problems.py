"""The built-in arms' problems end to end (slow): solved, validated, rendered, and
replayed with dynamics, the cubes ending where the plan put them."""

from __future__ import annotations

import json

import pytest

from tests.conftest import ROOT

PROBLEMS = [f"{arm}/{p}" for arm in ("arm-kuka", "arm-xarm") for p in ("p01", "p02")]


@pytest.mark.slow
@pytest.mark.parametrize("key", PROBLEMS)
def test_arm_problem_solves_validates_and_renders(cli, key, tmp_path):
    domain = ROOT / "domains" / key.split("/")[0] / "domain.pddl"
    problem = ROOT / "problems" / f"{key}.pddl"
    out = tmp_path / "solution.json"
    run = cli("solve", "--quiet", "--time-limit", "30", "--out", out, domain, problem)
    assert run.code == 0, run.err
    solution = json.loads(out.read_text())
    assert solution["status"] == "solved" and len(solution["plan"]) == 2
    check = cli("validate", domain, problem, out)
    assert check.code == 0, check.out + check.err
    panels = tmp_path / "keyframes.png"
    video = tmp_path / "video.gif"
    run = cli("render", out, "--json", "--physics", "--keyframes", panels, "--video", video,
              "--width", "160", "--height", "120", "--fps", "5", "--workers", "1")
    assert run.code == 0, run.err
    report = json.loads(run.out)
    assert panels.stat().st_size > 0 and video.stat().st_size > 0
    assert report["physics"]["max_distance"] < 0.03, report["physics"]["objects"]
    assert report["physics"]["tracking_error"] < 0.1
