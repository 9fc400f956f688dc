"""`tampcli solve` end to end: solution.json, exit codes, skeleton records, determinism."""

import json
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

DOMAINS, PROBLEMS = ROOT / "domains", ROOT / "problems"
SPEC_KEYS = {"version", "domain", "problem", "scene", "status", "reason", "plan",
             "symbolic_cost", "cost", "lower_bound", "robot", "trajectory", "phases", "objects",
             "skeletons", "stats"}


def _solve(cli, tmp_path, domain, problem, *flags, name="solution.json"):
    out = tmp_path / name
    run = cli("solve", "--quiet", "--out", out, *flags, DOMAINS / domain / "domain.pddl",
              problem)
    return run, json.loads(out.read_text())


def test_infeasible_cheapest_skeleton_gives_way_to_a_later_one(cli, tmp_path):
    """planar-tamp p02: a blocker sits in the goal region, so the 2-action skeleton fails."""
    run, sol = _solve(cli, tmp_path, "planar-tamp", PROBLEMS / "planar-tamp" / "p02.pddl")
    assert run.code == 0, run.err
    assert SPEC_KEYS <= set(sol)
    assert sol["status"] == "solved" and sol["reason"] is None
    assert len(sol["plan"]) == 4
    first = sol["skeletons"][0]
    assert len(first["plan"]) == 2
    assert first["outcome"] in ("infeasible", "pruned")
    # The phases cover the trajectory, one per action plus the motions between them.
    phases = sol["phases"]
    assert phases[0]["start"] == 0 and phases[-1]["end"] == len(sol["trajectory"]) - 1
    assert all(a["end"] == b["start"] for a, b in zip(phases, phases[1:], strict=False))
    assert [p["action"] for p in phases if p["action"]] == sol["plan"]
    assert all(len(v) == len(phases) + 1 for v in sol["objects"].values())
    assert sol["lower_bound"] is not None and sol["lower_bound"] <= sol["symbolic_cost"]
    check = cli("validate", DOMAINS / "planar-tamp" / "domain.pddl",
                PROBLEMS / "planar-tamp" / "p02.pddl", tmp_path / "solution.json")
    assert check.code == 0, check.out + check.err


def test_goal_out_of_reach_ends_with_exit_1_and_a_reason(cli, tmp_path):
    """The goal region moved to the far corner of a larger table, 1.15 m from the Panda's
    shoulder: beyond its reach ball (0.949 m: geometry/reach.py) by more than the cube's
    bounding sphere. (At the corner of the library's table, 0.97 m, a proof would not
    hold: the stretched arm with a level hand comes within 2.5 cm of the region.)"""
    problem = tmp_path / "p01.pddl"
    shutil.copy(PROBLEMS / "arm-pick-place" / "p01.pddl", problem)
    scene = (PROBLEMS / "arm-pick-place" / "p01.scene.toml").read_text()
    far = scene.replace("center = [0.45, 0.2]", "center = [0.95, 0.75]").replace(
        "size = [1.2, 1.4, 0.04]", "size = [1.6, 1.8, 0.04]")
    assert far != scene
    (tmp_path / "p01.scene.toml").write_text(far)
    run, sol = _solve(cli, tmp_path, "arm-pick-place", problem, "--time-limit", "30")
    assert run.code == 1, run.out + run.err
    # Proved: the region is farther than the stretched arm plus the cube's radius.
    assert sol["status"] == "unsolvable"
    assert "beyond the arm's reach" in sol["reason"] and "goal" in sol["reason"]
    assert sol["plan"] in (None, [])
    assert sol["stats"]["seconds"]["total"] <= 45  # the limit is checked between NLP solves


def test_same_input_and_seed_give_the_same_plan_and_cost(cli, tmp_path):
    problem = PROBLEMS / "planar-tamp" / "p01.pddl"
    runs = [_solve(cli, tmp_path, "planar-tamp", problem, "--seed", "3", name=f"s{i}.json")[1]
            for i in range(2)]
    assert runs[0]["plan"] == runs[1]["plan"]
    assert runs[0]["cost"] == pytest.approx(runs[1]["cost"], abs=1e-12)
    assert runs[0]["trajectory"] == runs[1]["trajectory"]


def test_a_problem_without_scene_is_solved_symbolically_and_says_so(cli, tmp_path):
    out = tmp_path / "s.json"
    run = cli("solve", "--out", out, DOMAINS / "blocksworld" / "domain.pddl",
              PROBLEMS / "blocksworld" / "p01.pddl")
    assert run.code == 0, run.err
    assert "symbolic" in (run.out + run.err).lower()
    sol = json.loads(out.read_text())
    assert sol["status"] == "solved" and len(sol["plan"]) == 6
    assert sol["scene"] is None


def test_piped_output_is_plain_lines(cli, tmp_path):
    """Not a terminal: no live display and no box-drawing tables, one line per event."""
    run = cli("solve", "--out", tmp_path / "s.json", DOMAINS / "planar-push" / "domain.pddl",
              PROBLEMS / "planar-push" / "p01.pddl")
    assert run.code == 0, run.err
    text = run.out + run.err
    assert not any(ch in text for ch in "┏┃━╇")
    assert "(pick box start)\n(place box goal)\n" in run.out  # the seed's push is a drag


def test_the_report_says_which_face_each_push_pushes(cli, tmp_path):
    """robust-planar-push p02: the crate (unturned) pushed east from `start` to
    `corner`, then north to `goal`: the -x face, then the -y face, by the disk's rim,
    within the middle half of the 10 cm face; the terminal says so too."""
    problem = PROBLEMS / "robust-planar-push" / "p02.pddl"
    run, sol = _solve(cli, tmp_path, "robust-planar-push", problem)
    assert run.code == 0, run.err
    pushes = [g for g in sol["grasps"] if "pusher" in g]
    assert {g["family"] for g in pushes} == {"push"}
    assert [(g["action"], g["face"], g["pusher"]) for g in pushes] == [
        ("(push crate start corner bench)", "-x", "rim"),
        ("(push crate corner goal bench)", "-y", "rim")]
    assert all(abs(g["offset"]) <= 0.5 * 0.05 + 1e-6 for g in pushes)
    loud = cli("solve", DOMAINS / "robust-planar-push" / "domain.pddl", problem)
    assert "push (push crate start corner bench): the disk's rim on crate's -x face" in loud.err
