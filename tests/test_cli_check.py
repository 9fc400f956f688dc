"""`tampcli check`: tables, JSON, warnings, the grounding and scene parts."""

import json
import shutil

import pybullet_data

from tests.conftest import IPC, ROOT

BW = ROOT / "domains" / "blocksworld" / "domain.pddl"
BW1 = ROOT / "problems" / "blocksworld" / "p01.pddl"
ELEVATORS = IPC / "elevators-opt08-strips"
PLANAR = ROOT / "domains" / "planar-tamp" / "domain.pddl"
PLANAR1 = ROOT / "problems" / "planar-tamp" / "p01.pddl"


def test_domain_alone_prints_its_tables(cli):
    run = cli("check", BW)
    assert run.code == 0, run.err
    for text in ("domain blocksworld", "requirements declared", "predicates (5)", "actions (4)",
                 "pick-up", "handempty"):
        assert text in run.out
    assert "problem" not in run.out


def test_json_has_every_part(cli):
    run = cli("check", ELEVATORS / "domain.pddl", ELEVATORS / "p01.pddl", "--json")
    assert run.code == 0, run.err
    data = json.loads(run.out)
    assert data["status"] == "ok"
    d, p = data["domain"], data["problem"]
    assert d["requirements"] == {"declared": [":typing", ":action-costs"],
                                 "used": [":strips", ":action-costs", ":typing"]}
    assert d["types"]["slow-elevator"] == ["elevator"]
    assert d["predicates"]["lift-at"] == 2
    assert d["functions"] == {"total-cost": 0, "travel-slow": 2, "travel-fast": 2}
    assert d["actions"]["board"] == 5
    assert p["objects"] == {"count": 9, "fast-elevator": 1, "passenger": 3, "slow-elevator": 2}
    assert (p["init_facts"], p["init_values"], p["goal_atoms"]) == (75, 31, 3)
    assert p["metric"] == "minimize (total-cost)"
    if data["grounded"] is not None:  # grounding is another module; counted when present
        assert data["grounded"]["operators"] > 0 and not data["grounded"]["unit_cost"]
    assert data["scene"] is None and data["warnings"] == []


def test_problem_table_lists_objects_per_type(cli):
    run = cli("check", ELEVATORS / "domain.pddl", ELEVATORS / "p01.pddl")
    assert run.code == 0, run.err
    assert "objects: passenger" in run.out and "init facts" in run.out
    assert "goal atoms" in run.out


def test_long_listings_are_cut_in_tables_but_not_in_json(cli):
    domain = IPC / "psr-small" / "p10-domain.pddl"
    problem = next((IPC / "psr-small").glob("p10-s*.pddl"))
    table = cli("check", domain)
    assert "more (see --json)" in table.out
    data = json.loads(cli("check", domain, problem, "--json").out)
    assert len(data["domain"]["actions"]) > 25


def test_requirement_warnings_go_to_stderr(cli, tmp_path):
    domain = tmp_path / "d.pddl"
    domain.write_text("(define (domain d) (:requirements :strips)\n"
                      "  (:predicates (p ?x) (q ?x))\n"
                      "  (:action a :parameters (?x) :precondition (not (p ?x)) :effect (p ?x)))\n")
    run = cli("check", domain)
    assert run.code == 0
    assert f"warning: {domain}:3:45: uses negative conditions without declaring " \
           ":negative-preconditions" in run.err
    quiet = cli("check", domain, "--quiet")
    assert quiet.err == "" and quiet.out == ""
    data = json.loads(cli("check", domain, "--json").out)
    assert len(data["warnings"]) == 1


def test_scene_part_is_merged_when_the_problem_has_a_scene(cli):
    run = cli("check", PLANAR, PLANAR1, "--json")
    assert run.code == 0, run.err
    scene = json.loads(run.out)["scene"]
    if scene is None:  # the geometry package is another engineer's; absent here
        return
    assert scene["scene"].endswith("p01.scene.toml")
    assert {b["name"] for b in scene["bodies"]} >= {"a", "b"}


def test_scene_flags_need_a_problem(cli):
    run = cli("check", BW, "--scene", "x.toml")
    assert run.code == 2
    assert "need a PROBLEM" in run.err


def test_semantic_error_exit_code_and_caret(cli, tmp_path):
    problem = tmp_path / "p.pddl"
    problem.write_text("(define (problem p) (:domain blocksworld)\n"
                       "  (:objects a b - block)\n  (:init (clear c))\n  (:goal (on a b)))\n")
    run = cli("check", BW, problem)
    assert run.code == 2
    assert f"{problem}:3:17: unknown object or constant c" in run.err
    assert run.err.rstrip().endswith("^")
    assert run.out == ""
    assert cli("check", BW, BW1).code == 0


def test_modes_without_a_scene_is_a_warning(cli, tmp_path):
    run = cli("check", BW, BW1, "--modes", tmp_path / "modes.toml")
    assert run.code == 0
    assert "modes.toml: not checked, the problem has no scene" in run.err


def test_fluents_declared_for_costs_are_a_warning_not_a_refusal(cli, tmp_path):
    domain, problem = tmp_path / "d.pddl", tmp_path / "p.pddl"
    domain.write_text("(define (domain d)\n  (:requirements :typing :fluents)\n"
                      "  (:types place) (:predicates (at ?x - place))\n"
                      "  (:functions (total-cost) (length ?x ?y - place))\n"
                      "  (:action go :parameters (?x ?y - place) :precondition (at ?x)\n"
                      "    :effect (and (not (at ?x)) (at ?y)"
                      " (increase (total-cost) (length ?x ?y)))))\n")
    problem.write_text("(define (problem p) (:domain d) (:objects a b - place)\n"
                       "  (:init (at a) (= (total-cost) 0) (= (length a a) 0) (= (length a b) 2)\n"
                       "         (= (length b a) 2) (= (length b b) 0))\n"
                       "  (:goal (at b)) (:metric minimize (total-cost)))\n")
    run = cli("check", domain, problem, "--json")
    assert run.code == 0, run.err
    data = json.loads(run.out)
    assert data["warnings"] == [f"{domain}:2:26: declares :fluents, which tampcli supports only "
                                "as action costs; here the functions are only action costs, so "
                                "they are read as such"]
    assert data["domain"]["requirements"]["used"] == [":strips", ":action-costs", ":typing"]


GEO = ROOT / "tests" / "geometry" / "data"


def _has_row(out: str, *cells: str) -> bool:
    """Whether a table line of `out` starts with these cells, in this order."""
    return any([c.strip() for c in line.strip("│┃").split("│")][:len(cells)] == list(cells)
               for line in out.splitlines())


def test_scene_tables_show_joints_bodies_and_regions(cli):
    run = cli("check", GEO / "domain.pddl", GEO / "p01.pddl")
    assert run.code == 0, run.err

    def row(*cells):
        assert _has_row(run.out, *cells), f"no row {cells} in:\n{run.out}"

    row("panda_joint4", "-3.142", "0.000", "-2.356")
    row("panda_joint6", "-0.087", "3.822", "1.571")
    row("table", "box 1.2x1.4x0.04", "0.3 0 -0.02", "-", "yes")
    row("a", "box 0.05x0.05x0.05", "0.45 -0.2 0.025", "yaw 17.2°", "no")
    row("b", "cylinder r 0.03 h 0.08", "0.5 0.1 0.04", "-", "no")
    row("wall", "box 0.02x0.3x0.3", "0.75 0 0.15", "-", "obstacle")
    row("goal", "table", "0.45 0.25", "0.15x0.15")
    row("self-collision pairs", "39 link pairs checked (see --json)")
    row("robot stands on", "table")
    # Two hulls, each rounded by PyBullet's 1 mm margin: 2 mm closer than their cores.
    row("robot-robot", "link:panda_link5", "link:panda_link7", "20.1")
    row("body-body", "body:table", "body:a", "0.0")


def test_scene_json_lists_the_self_collision_pairs(cli):
    run = cli("check", GEO / "domain.pddl", GEO / "p01.pddl", "--json")
    assert run.code == 0, run.err
    scene = json.loads(run.out)["scene"]
    pairs = scene["self_collision_pairs"]
    assert len(pairs) == 39 and ["link:panda_link1", "link:panda_hand"] in pairs
    assert ["link:panda_link1", "link:panda_link2"] not in pairs  # adjacent links
    robot = scene["robot"]
    assert robot["joints"][3] == "panda_joint4"
    # pybullet_data's Panda URDF: joint 4 in [-3.1416, 0]
    assert (robot["lower"][3], robot["upper"][3], robot["start"][3]) == (-3.1416, 0.0, -2.356)


def test_scene_table_shows_mesh_files_and_scale(cli, tmp_path):
    for name in ("domain.pddl", "p01.pddl", "modes.toml"):
        shutil.copy(GEO / name, tmp_path / name)
    duck = f"{pybullet_data.getDataPath()}/duck_vhacd.obj"
    (tmp_path / "p01.scene.toml").write_text(
        (GEO / "p01.scene.toml").read_text()
        + f'\n[[objects]]\nname = "duck"\nshape = "mesh"\nmesh = "{duck}"\nscale = 0.1\n'
        "pose = [0.0, 0.55, 0.3, 1.5708, 0.0, 0.0]\nfixed = true\n")
    run = cli("check", tmp_path / "domain.pddl", tmp_path / "p01.pddl")
    assert run.code == 0, run.err
    assert _has_row(run.out, "duck", "mesh duck_vhacd.obj x 0.1", "0 0.55 0.3",
                    "rpy 90.0 0.0 0.0°", "obstacle"), run.out
    body = json.loads(cli("check", tmp_path / "domain.pddl", tmp_path / "p01.pddl",
                          "--json").out)["scene"]["bodies"][-1]
    assert (body["file"], body["scale"]) == (duck, [0.1, 0.1, 0.1])


def test_a_robot_starting_within_the_margin_of_a_body_is_warned_of(cli, tmp_path):
    """blind5 p07 as first written: the KUKA's palm 1.3 mm from a partition."""
    folder = ROOT / "problems" / "blind5" / "p07"
    for f in folder.iterdir():
        shutil.copy(f, tmp_path / f.name)
    scene = tmp_path / "p07.scene.toml"
    text = scene.read_text()
    assert "start = [-0.8, 0.6," in text
    scene.write_text(text.replace("start = [-0.8, 0.6,", "start = [0.0, 0.6,"))
    run = cli("check", tmp_path / "domain.pddl", tmp_path / "p07.pddl")
    assert run.code == 0, run.err
    assert "warning: the robot starts 1.3 mm from partition (gripper_palm): closer than " \
           "solve's 10 mm margin" in run.err
    clear = cli("check", folder / "domain.pddl", folder / "p07.pddl")
    assert "the robot starts" not in clear.err


def _blind7(tmp_path, stem, edit=None):
    """(domain, problem) of a copy of blind7's problem `stem` in a folder of its own."""
    folder = ROOT / "problems" / "blind7" / stem
    tmp_path = tmp_path / stem
    tmp_path.mkdir()
    for f in folder.iterdir():
        shutil.copy(f, tmp_path / f.name)
    if edit:
        edit(tmp_path)
    return tmp_path / "domain.pddl", tmp_path / f"{stem}.pddl"


def test_a_box_sunk_into_its_support_is_told_the_z_that_rests_it(cli, tmp_path):
    """blind7 p04 (written blind, an error case): a gauge's centre at the table top."""
    run = cli("check", *_blind7(tmp_path, "p04"))
    assert run.code == 2
    assert "p04.scene.toml:22: objects.pose: 'gauge' overlaps 'table' by 35.0 mm in the " \
           "start state (expected it resting on 'table': pose z = 0.035)" in run.err


def test_a_movable_mesh_must_start_unturned_and_centred_on_its_origin(cli, tmp_path):
    """blind7 p05: a prism mesh turned 30 deg was refused as 9.2 cm wide (its turned
    bounding box), a false proof; a mesh whose origin is at its base was moved by the
    wrong point."""
    turned = cli("check", *_blind7(tmp_path, "p05"))
    assert turned.code == 2
    assert "objects.pose: a movable mesh must start unturned" in turned.err
    assert "'big' is turned 30.0 deg" in turned.err

    def base_origin(folder):
        obj = folder / "hexnut.obj"
        lines = [f"v {ln.split()[1]} {ln.split()[2]} {float(ln.split()[3]) + 0.03:.6f}"
                 if ln.startswith("v ") else ln for ln in obj.read_text().splitlines()]
        obj.write_text("\n".join(lines) + "\n")
        scene = folder / "p01.scene.toml"
        text = scene.read_text()
        assert text.count("pose = [0.44, -0.22, 0.03]") == 1
        scene.write_text(text.replace("pose = [0.44, -0.22, 0.03]", "pose = [0.44, -0.22, 0.0]"))

    (tmp_path / "based").mkdir()
    based = cli("check", *_blind7(tmp_path / "based", "p01", base_origin))
    assert based.code == 2
    assert "a movable mesh's origin must be the centre of its bounding box" in based.err
    assert "(0.0000, 0.0000, 0.0300) m from it" in based.err
    assert cli("check", *_blind7(tmp_path, "p01")).code == 0


def test_a_turned_robot_base_is_shown_with_its_yaw(cli):
    """blind9 p03: `base = [0, 0, 0, 1.5708]` was shown as `base 0 0 0` and as
    [0.0, 0.0, 0.0] in the JSON, the yaw the arm is loaded with dropped from both."""
    folder = ROOT / "problems" / "blind9" / "p03"
    files = (folder / "domain.pddl", folder / "p03.pddl")
    run = cli("check", *files)
    assert run.code == 0, run.err
    assert _has_row(run.out, "base", "0 0 0, yaw 90.0°"), run.out
    base = json.loads(cli("check", *files, "--json").out)["scene"]["robot"]["base"]
    assert len(base) == 7 and base[:5] == [0.0] * 5
    assert abs(base[5] - 0.5 ** 0.5) < 1e-5 and abs(base[6] - 0.5 ** 0.5) < 1e-5
    straight = cli("check", GEO / "domain.pddl", GEO / "p01.pddl")
    assert _has_row(straight.out, "base", "0 0 0"), straight.out
    base = json.loads(cli("check", GEO / "domain.pddl", GEO / "p01.pddl",
                          "--json").out)["scene"]["robot"]["base"]
    assert base == [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]


def test_check_warns_of_an_object_beyond_the_arms_reach(cli):
    """blind22 p05's vase stands 1.14 m from the Panda's shoulder (its reach ball: 0.95 m);
    the distractor's region is no goal, so only the object's own warning tells."""
    folder = ROOT / "problems" / "blind22" / "p05"
    run = cli("check", folder / "domain.pddl", folder / "p05.pddl")
    assert run.code == 0
    warned = [line for line in run.err.splitlines() if "beyond its reach" in line]
    assert len(warned) == 1 and "object 'vase'" in warned[0], run.err


def test_check_warns_of_an_object_no_grasp_of_the_arm_takes(cli, tmp_path):
    """blind32 p04 (written blind): its author asked for a warning before a 60 s solve.
    The 1.6 cm coin and the 8 cm case are taken by the xArm6; a 1.0 cm coin and a
    9 cm case are not."""
    folder = tmp_path / "p04"
    shutil.copytree(ROOT / "problems" / "blind32" / "p04", folder)
    args = ("check", folder / "domain.pddl", folder / "p04.pddl")
    run = cli(*args)
    assert run.code == 0 and "can move it" not in run.err, run.err
    scene = folder / "p04.scene.toml"
    text = scene.read_text()
    for old, new in (("size = [0.012, 0.016]\npose = [0.3, 0.02, 0.008]",
                      "size = [0.012, 0.010]\npose = [0.3, 0.02, 0.005]"),
                     ("size = [0.08, 0.12, 0.06]", "size = [0.09, 0.12, 0.06]")):
        assert old in text
        text = text.replace(old, new)
    scene.write_text(text)
    run = cli(*args)
    assert run.code == 0
    assert ("warning: coin is 1.0 cm tall: lower than any grasp of the xarm6 takes (from "
            "the top 1.41 cm and up") in run.err, run.err
    # Its domain has no push (blind38 DOC_GAPS 5: "only a push can move it" said so anyway).
    assert "warning: case is 9.0 cm across at its narrowest: wider than the xarm6's " \
           "gripper takes (8.19 cm); no action of the domain can move it" in run.err


B38 = ROOT / "problems" / "blind38"


def _copy(folder, tmp_path):
    for f in folder.iterdir():
        shutil.copy(f, tmp_path / f.name)
    return tmp_path


def test_a_floating_object_is_warned_of_with_the_z_it_likely_meant(cli, tmp_path):
    """blind38 DOC_GAPS 1: a box 2 cm over the bench passed `check` without a word."""
    d = _copy(B38 / "p06", tmp_path)
    scene = d / "p06.scene.toml"
    scene.write_text(scene.read_text().replace("pose = [-0.2, -0.25, 0.025]",
                                               "pose = [-0.2, -0.25, 0.045]"))
    run = cli("check", d / "domain.pddl", d / "p06.pddl")
    assert run.code == 0, run.err
    assert "'p2' floats 2.0 cm over" in run.err and "did you mean pose z = 0.025?" in run.err
    # As written (resting), no such warning.
    shutil.copy(B38 / "p06" / "p06.scene.toml", scene)
    assert "floats" not in cli("check", d / "domain.pddl", d / "p06.pddl").err


def test_a_misspelled_support_gets_the_name_it_likely_meant(cli, tmp_path):
    """blind38 DOC_GAPS 8: `on = "tabel"` said only that it is no object of the scene."""
    d = _copy(B38 / "p02", tmp_path)
    scene = d / "p02.scene.toml"
    text = scene.read_text()
    assert 'on = "table"' in text
    scene.write_text(text.replace('on = "table"', 'on = "tabel"', 1))
    run = cli("check", d / "domain.pddl", d / "p02.pddl")
    assert run.code == 2
    assert "is on 'tabel', which is no object of the scene (did you mean 'table'?)" in run.err
