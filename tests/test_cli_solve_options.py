"""`tampcli solve`'s options: one default per option (the options dataclass's),
bad values refused naming the flag, and one World per solve."""

import argparse
import dataclasses
import json
import math
from pathlib import Path

import pytest

from tampcli.bnb import BnBOptions
from tampcli.cli import render as render_cli
from tampcli.cli import solve as solve_cli
from tampcli.errors import OptionError
from tampcli.geometry import scene as scene_module
from tampcli.geometry.world import World
from tampcli.optimize.options import OptimizeOptions
from tampcli.pddl import parser as pddl_parser
from tampcli.pipeline import SolveOptions
from tampcli.render.options import RenderOptions

ROOT = Path(__file__).resolve().parent.parent
DOMAINS, PROBLEMS = ROOT / "domains", ROOT / "problems"


def default_of(options_type, name):
    (field,) = [f for f in dataclasses.fields(options_type) if f.name == name]
    return field.default


def _parse(add_parser, *argv):
    p = argparse.ArgumentParser()
    add_parser(p)
    return p, p.parse_args([str(a) for a in argv])


@pytest.mark.parametrize("flag", solve_cli.FLAGS, ids=[f.name for f in solve_cli.FLAGS])
def test_each_solve_flag_defaults_to_its_options_field(flag):
    p, _ = _parse(solve_cli.add_parser, "d.pddl", "p.pddl")
    stage = {"bnb": BnBOptions, "optimize": OptimizeOptions}[flag.stage]
    assert p.get_default(flag.field) == default_of(stage, flag.field)
    assert p.get_default(flag.field) == getattr(getattr(SolveOptions(), flag.stage), flag.field)


def test_solve_without_flags_gets_the_default_options():
    _, args = _parse(solve_cli.add_parser, "d.pddl", "p.pddl")
    assert solve_cli.options_from_args(args) == SolveOptions()


def test_solve_flags_reach_their_stage():
    _, args = _parse(solve_cli.add_parser, "d.pddl", "p.pddl", "-k", "3", "--time-limit", "7",
                     "--symbolic-weight", "0.5", "--waypoints", "4", "--anytime", "--seed", "9",
                     "--jobs", "3")
    options = solve_cli.options_from_args(args)
    assert options.bnb == BnBOptions(max_skeletons=3, time_limit=7.0, symbolic_weight=0.5,
                                     anytime=True, jobs=3)
    assert options.optimize == OptimizeOptions(waypoints=4, seed=9)


def test_render_without_flags_gets_the_default_options():
    p, args = _parse(render_cli.add_parser, "s.json")
    assert render_cli.options_from_args(args) == RenderOptions()
    for field in ("width", "height", "fps", "workers", "duration", "speed", "pause"):
        assert p.get_default(field) == default_of(RenderOptions, field)


@pytest.mark.parametrize(("flag", "value"), [
    ("-k", "0"), ("--skeletons", "-2"), ("--time-limit", "0"), ("--time-limit", "nan"),
    ("--symbolic-weight", "-1"), ("--symbolic-weight", "nan"), ("--waypoints", "1")])
def test_a_bad_option_is_exit_2_naming_the_flag(cli, flag, value):
    name = "--skeletons" if flag == "-k" else flag
    run = cli("solve", DOMAINS / "planar-tamp" / "domain.pddl",
              PROBLEMS / "planar-tamp" / "p01.pddl", flag, value)
    assert run.code == 2, run.out + run.err
    assert f"{name}: must be" in run.err and value in run.err, run.err
    assert "Traceback" not in run.err


@pytest.mark.parametrize(("options_type", "values", "field"), [
    (BnBOptions, {"max_skeletons": True}, "max_skeletons"),
    (BnBOptions, {"time_limit": -1.0}, "time_limit"),
    (OptimizeOptions, {"activation": 0.005}, "activation"),
    (OptimizeOptions, {"margin": math.inf}, "margin"),
])
def test_options_name_the_bad_field(options_type, values, field):
    with pytest.raises(OptionError) as info:
        options_type(**values)
    assert info.value.field == field and str(info.value).startswith(field)


def test_an_infinite_time_limit_is_no_limit():
    assert BnBOptions(time_limit=math.inf).time_limit == math.inf


@pytest.fixture
def built(monkeypatch):
    """Counts Worlds built, PDDL files parsed and scene files read in this process."""
    counts = {"worlds": 0, "domains": 0, "problems": 0, "scenes": 0}

    def counting(function, key):
        def wrapper(*args, **kwargs):
            counts[key] += 1
            return function(*args, **kwargs)
        return wrapper

    monkeypatch.setattr(World, "__init__", counting(World.__init__, "worlds"))
    monkeypatch.setattr(pddl_parser, "parse_domain_file",
                        counting(pddl_parser.parse_domain_file, "domains"))
    monkeypatch.setattr(pddl_parser, "parse_problem_file",
                        counting(pddl_parser.parse_problem_file, "problems"))
    monkeypatch.setattr(scene_module, "read_scene", counting(scene_module.read_scene, "scenes"))
    return counts


def test_solve_with_video_reads_each_input_once_and_builds_one_world(cli, tmp_path, built):
    """Render worker processes build their own World (a PyBullet client belongs to
    one process); this process renders in the solve's."""
    out, video = tmp_path / "s.json", tmp_path / "v.gif"
    run = cli("solve", "--quiet", "--out", out, "--video", video,
              DOMAINS / "planar-push" / "domain.pddl", PROBLEMS / "planar-push" / "p01.pddl")
    assert run.code == 0, run.err
    assert json.loads(out.read_text())["status"] == "solved"
    assert video.stat().st_size > 0
    assert built == {"worlds": 1, "domains": 1, "problems": 1, "scenes": 1}


def test_a_symbolic_solve_builds_no_world(cli, tmp_path, built):
    run = cli("solve", "--quiet", "--out", tmp_path / "s.json",
              DOMAINS / "blocksworld" / "domain.pddl", PROBLEMS / "blocksworld" / "p01.pddl")
    assert run.code == 0, run.err
    assert built == {"worlds": 0, "domains": 1, "problems": 1, "scenes": 0}


def test_check_builds_one_world_for_its_scene_report(cli, built):
    run = cli("check", "--json", DOMAINS / "planar-tamp" / "domain.pddl",
              PROBLEMS / "planar-tamp" / "p01.pddl")
    assert run.code == 0, run.err
    assert json.loads(run.out)["scene"]["robot"]["model"] == "planar"
    assert built["worlds"] == 1
