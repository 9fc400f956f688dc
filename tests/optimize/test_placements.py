"""The final stage's placements: exact footprints apart, tight packing solved jointly,
an outcome that depends on the skeleton alone, and stacks that stand."""

import itertools
import math
from pathlib import Path

import numpy as np
import pytest

from tampcli.geometry.scene import load_scene
from tampcli.geometry.world import World
from tampcli.optimize import constraints as C
from tampcli.optimize import stability as S
from tampcli.optimize.bodies import BodyInfo, pose_matrix
from tampcli.optimize.expr import RowSet, planar_pose
from tampcli.optimize.layout import Layout
from tampcli.optimize.modes import load_modes
from tampcli.optimize.problem import lower
from tampcli.optimize.result import TrajectoryResult
from tampcli.optimize.solve import solve
from tampcli.optimize.values import Placement
from tampcli.pddl import parser

from .helpers import ROOT, central_differences, lowered_folder, ops

BOX = BodyInfo("p", "box", (0.05, 0.03, 0.02), False, (0, 0, 0, 0), True, 1.0)
BOX2 = BodyInfo("q", "box", (0.04, 0.045, 0.02), False, (0, 0, 0, 0), True, 2.0)
DISK = BodyInfo("d", "cylinder", (0.03, 0.03, 0.02), False, (0, 0, 0, 0), True, 1.5)



def _rows_check(build, x):
    """Rows built by `build(rows, P, Q)` on two planar poses (blocks p0, p1) vs FD."""
    layout = Layout((("p0", 3), ("p1", 3)))

    def parts(xx):
        v = layout.unpack(xx)
        rows = RowSet()
        P = planar_pose("p0", *v["p0"][:2], 0.02, v["p0"][2])
        Q = planar_pose("p1", *v["p1"][:2], 0.06, v["p1"][2])
        cost = build(rows, P, Q)
        val, jac = rows.assemble(layout.slices(), layout.size)
        return val, jac, cost

    val, jac, _ = parts(x)
    np.testing.assert_allclose(jac, central_differences(lambda xx: parts(xx)[0], x), atol=1e-6)
    return val


@pytest.mark.parametrize("a,b", [(BOX, BOX2), (BOX, DISK), (DISK, BOX2), (DISK, DISK)])
@pytest.mark.parametrize("seed", range(4))
def test_apart_rows_match_finite_differences(a, b, seed):
    rng = np.random.default_rng(seed)
    x = np.concatenate([[0.0, 0.0, rng.uniform(-3, 3)],
                        [*rng.uniform(-0.08, 0.08, 2), rng.uniform(-3, 3)]])
    val = _rows_check(lambda rows, P, Q: C.apart(rows, "s", P, a, Q, b, "o"), x)
    assert val.shape == (1,)


def _corners(info, x, y, yaw):
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[x + c * u - s * v, y + s * u + c * v]
                     for u in (-info.half[0], info.half[0]) for v in (-info.half[1], info.half[1])])


def _overlap_by_sampling(a, pa, b, pb) -> bool:
    """Independent of the rows: does a grid of points of a's footprint fall inside b's?"""
    c, s = math.cos(pa[2]), math.sin(pa[2])
    for u in np.linspace(-a.half[0], a.half[0], 41):
        for v in np.linspace(-a.half[1], a.half[1], 41):
            w = np.array([pa[0] + c * u - s * v, pa[1] + s * u + c * v]) - pb[:2]
            cb, sb = math.cos(pb[2]), math.sin(pb[2])
            lx, ly = cb * w[0] + sb * w[1], -sb * w[0] + cb * w[1]
            if abs(lx) < b.half[0] - 1e-4 and abs(ly) < b.half[1] - 1e-4:
                return True
    return False


def test_box_separation_is_exact_not_circles():
    """Two boxes side by side 1 mm apart: apart (circles around them would overlap by cm),
    and turned into each other: overlapping, by the sampled footprints too."""
    rng = np.random.default_rng(0)
    for _ in range(30):
        pa = np.array([0.0, 0.0, rng.uniform(-1, 1)])
        pb = np.array([*rng.uniform(-0.12, 0.12, 2), rng.uniform(-1, 1)])
        rows = RowSet()
        C.apart(rows, "s", planar_pose("a", *pa[:2], 0, pa[2]), BOX,
                planar_pose("b", *pb[:2], 0, pb[2]), BOX2, "b", gap=0.0)
        sep = rows.values[0][0]
        if abs(sep) > 2e-3:
            assert (sep < 0) == (_overlap_by_sampling(BOX, pa, BOX2, pb)
                                 or _overlap_by_sampling(BOX2, pb, BOX, pa))
    rows = RowSet()
    C.apart(rows, "s", planar_pose("a", 0, 0, 0, 0), BOX, planar_pose("b", 0.091, 0, 0, 0),
            BOX2, "b", gap=0.0)
    assert rows.values[0][0] == pytest.approx(0.001)


@pytest.mark.parametrize("support", [BOX2, DISK])
def test_stacking_rows_and_cost_match_finite_differences(support):
    rng = np.random.default_rng(3)
    x = np.concatenate([[*rng.uniform(-0.01, 0.01, 2), rng.uniform(-3, 3)],
                        [*rng.uniform(-0.01, 0.01, 2), rng.uniform(-3, 3)]])

    def build(rows, P, Q):  # P rests on Q; a third body stands on P at a fixed pose
        S.footprint_on_face(rows, "s", P, BOX, Q, support)
        S.com_on_face(rows, "s", [(P, 1.0), (Q, 3.0)], BOX, Q, support)
        return S.align_cost(P, BOX, Q, support)

    _rows_check(build, x)
    layout = Layout((("p0", 3), ("p1", 3)))

    def cost(xx):
        v = layout.unpack(xx)
        return S.align_cost(planar_pose("p0", *v["p0"][:2], 0, v["p0"][2]), BOX,
                            planar_pose("p1", *v["p1"][:2], 0, v["p1"][2]), support)

    _, grad = cost(x)
    g = np.concatenate([grad["p0"], grad["p1"]])
    np.testing.assert_allclose(g, central_differences(lambda xx: np.array([cost(xx)[0]]), x)[0], atol=1e-7)


# ---------------------------------------------------------------- whole problems


def _problem_files(group: str, name: str):
    dom = ROOT / "domains" / group / "domain.pddl"
    domain = parser.parse_domain_file(dom)
    prob = parser.parse_problem_file(ROOT / "problems" / group / f"{name}.pddl")
    modes = load_modes(dom.with_name("modes.toml"), domain)
    scene = load_scene(ROOT / "problems" / group / f"{name}.scene.toml", domain, prob,
                       modes=modes, geometric=False)
    return domain, scene, modes


def _pairs_apart(problem, result):
    bodies = problem.bodies
    last = {}
    for i, p in sorted(result.placements.items()):
        last[problem.steps[i].obj] = (np.array([p.x, p.y, p.yaw]))
    for a, b in itertools.combinations(last, 2):
        assert not _overlap_by_sampling(bodies[a], last[a], bodies[b], last[b]), (a, b)


PACKING = [
    ("robust-planar", "p06", "table", "bay", "abc"),
    ("robust-planar", "p07", "depot", "row", "abcd"),
    ("robust-arm", "p05", "start", "rack", "abc"),
    ("robust-arm", "p06", "start", "lane", "abcd"),
]


@pytest.mark.parametrize("group,name,source,target,objects", PACKING)
def test_tight_packing_is_placed_jointly_in_every_order(group, name, source, target, objects):
    """Under 15 % slack along one axis: every order of the objects has a final placement
    (before: the later placements overlapped the earlier ones for every order)."""
    domain, scene, modes = _problem_files(group, name)
    with World(scene) as world:
        for order in itertools.permutations(objects):
            skeleton = [t for o in order for t in (f"(pick {o} {source})", f"(place {o} {target})")]
            problem = lower(ops(*skeleton), scene, modes, world, domain=domain)
            result = solve(problem, "final")
            assert result.solved, (order, result.worst_constraint)
            _pairs_apart(problem, result)
            region = scene.region(target)
            for i, p in result.placements.items():
                info = problem.bodies[problem.steps[i].obj]
                pts = _corners(info, p.x, p.y, p.yaw)
                assert np.all(pts >= region.lower - 1e-3) and np.all(pts <= region.upper + 1e-3)


def _pen_scene(tmp_path: Path, blockers, target=(0.26, 0.16)) -> Path:
    """A pen (30 x 20 cm, open toward -x) holding the given blockers ((x, y, sx, sy));
    the target waits in the yard."""
    text = ['[robot]\nmodel = "planar"\nbase = [0.0, 0.0, 0.035]\nstart = [-0.2, 0.25]\n'
            'radius = 0.05\nheight = 0.05\n',
            '[[objects]]\nname = "bench"\nshape = "box"\nsize = [1.6, 0.8, 0.04]\n'
            'pose = [0.0, 0.0, -0.02]\nfixed = true\n',
            '[[objects]]\nname = "pen-back"\nshape = "box"\nsize = [0.02, 0.26, 0.1]\n'
            'pose = [0.63, 0.05, 0.05]\nfixed = true\n',
            f'[[objects]]\nname = "t"\nshape = "box"\nsize = [{target[0]}, {target[1]}, 0.05]\n'
            'pose = [-0.45, -0.15, 0.025]\n']
    for i, (x, y, sx, sy) in enumerate(blockers, 1):
        text.append(f'[[objects]]\nname = "b{i}"\nshape = "box"\nsize = [{sx}, {sy}, 0.05]\n'
                    f'pose = [{x}, {y}, 0.025]\n')
    text.append('[[regions]]\nname = "yard"\non = "bench"\ncenter = [-0.4, 0.0]\n'
                'size = [0.7, 0.7]\n')
    text.append('[[regions]]\nname = "pen"\non = "bench"\ncenter = [0.45, 0.05]\n'
                'size = [0.3, 0.2]\n')
    path = tmp_path / "pen.scene.toml"
    path.write_text("\n".join(text))
    names = " ".join(f"b{i}" for i in range(1, len(blockers) + 1))
    init = " ".join(f"(in b{i} pen)" for i in range(1, len(blockers) + 1))
    (tmp_path / "pen.pddl").write_text(
        f"(define (problem pen) (:domain robust-planar)\n (:objects t {names} - block "
        f"yard pen - region)\n (:init (in t yard) {init} (handempty))\n (:goal (in t pen)))\n")
    return path


PENS = [
    [(0.36, 0.1, 0.06, 0.1), (0.52, -0.01, 0.1, 0.05)],
    [(0.4, 0.05, 0.08, 0.08), (0.55, 0.1, 0.05, 0.12)],
    [(0.35, 0.0, 0.06, 0.06), (0.45, 0.1, 0.1, 0.06), (0.55, 0.0, 0.06, 0.1)],
    [(0.33, 0.11, 0.05, 0.07), (0.46, 0.02, 0.12, 0.05), (0.56, 0.1, 0.07, 0.07)],
]


@pytest.mark.parametrize("blockers", PENS)
def test_pen_final_stage_depends_on_the_skeleton_alone(tmp_path, blockers):
    """All blockers out to the yard, then t in: feasible at the final stage on its own,
    with the same placements as its superset with a trailing useless pick, and whatever
    other skeleton's result is handed in as a warm start (before: the warm start's
    placements seeded the NLP, so the outcome depended on what had been evaluated)."""
    scene_path = _pen_scene(tmp_path, blockers)
    dom = ROOT / "domains" / "robust-planar" / "domain.pddl"
    domain = parser.parse_domain_file(dom)
    prob = parser.parse_problem_file(tmp_path / "pen.pddl")
    modes = load_modes(dom.with_name("modes.toml"), domain)
    scene = load_scene(scene_path, domain, prob, modes=modes, geometric=False)
    names = [f"b{i}" for i in range(1, len(blockers) + 1)]
    skeleton = [t for b in names for t in (f"(pick {b} pen)", f"(place {b} yard)")]
    skeleton += ["(pick t yard)", "(place t pen)"]
    # Every blocker dropped on t's spot in the yard, on top of each other.
    hostile = {2 * i + 1: Placement(-0.45, -0.15, 0.0) for i in range(len(names))}
    hostile[len(skeleton) - 1] = Placement(0.45, 0.05, 0.0)
    warm = TrajectoryResult("solved", "keyframes", tuple(skeleton[:-1]), placements=hostile)
    with World(scene) as world:
        alone = solve(lower(ops(*skeleton), scene, modes, world, domain=domain), "final")
        longer = solve(lower(ops(*skeleton, f"(pick {names[0]} yard)"), scene, modes, world,
                             domain=domain), "final")
        warmed = solve(lower(ops(*skeleton), scene, modes, world, domain=domain), "final",
                       warm)
        assert alone.solved, alone.worst_constraint
        assert longer.solved and warmed.solved
        assert longer.placements == alone.placements == warmed.placements


# ---------------------------------------------------------------- stacks


def test_stacked_cube_is_contained_and_aligned():
    """robust-arm p11: a 4.5 cm cube onto a 5 cm cube turned 30 degrees (before: 1.8 cm
    off centre and turned 19 degrees, its footprint off the top face)."""
    domain, scene, modes = _problem_files("robust-arm", "p11")
    with World(scene) as world:
        problem = lower(ops("(pick a start)", "(stack a b)"), scene, modes, world, domain=domain)
        result = solve(problem, "final")
        assert result.solved
        p = result.placements[1]
        b = problem.bodies["b"]
        assert math.hypot(p.x - b.pose[0], p.y - b.pose[1]) < 2e-3
        turn = (p.yaw - b.pose[3] + math.pi / 4) % (math.pi / 2) - math.pi / 4
        assert abs(math.degrees(turn)) < 1.0


def test_library_tower_comes_out_aligned():
    """arm-pick-place p05's tower (before: a off b by 9.4 mm, b off c by 16.2 mm)."""
    domain, scene, modes = _problem_files("arm-pick-place", "p05")
    with World(scene) as world:
        problem = lower(ops("(pick b start)", "(stack b c)", "(pick a start)", "(stack a b)"),
                        scene, modes, world, domain=domain)
        result = solve(problem, "final")
        assert result.solved
        b, a = result.placements[1], result.placements[3]
        c = problem.bodies["c"].pose
        assert math.hypot(b.x - c[0], b.y - c[1]) < 3e-3
        assert math.hypot(a.x - b.x, a.y - b.y) < 3e-3


class _After:
    """The part of verify.StepCheck that the place kind's check reads."""

    def __init__(self, problem, after):
        from tampcli.optimize.verify import StepCheck

        poses = {n: [pose_matrix(*problem.bodies[n].pose), m] for n, m in after.items()}
        self.walk = StepCheck(problem, None, None, 0, poses, {r.name: r for r in
                                                               problem.scene.regions})


def _stack_check(dx_a, dx_b=0.0, yaw_a=0.0):
    domain, scene, modes = _problem_files("arm-pick-place", "p05")
    with World(scene) as world:
        problem = lower(ops("(pick b start)", "(stack b c)", "(pick a start)", "(stack a b)"),
                        scene, modes, world, domain=domain)
        c = problem.bodies["c"].pose
        b_pose = pose_matrix(c[0] + dx_b, c[1], problem.steps[1].rest_z, 0.0)
        a_pose = pose_matrix(c[0] + dx_b + dx_a, c[1], problem.steps[3].rest_z, yaw_a)
        after = {n: pose_matrix(*i.pose) for n, i in problem.bodies.items() if not i.fixed}
        after.update(a=a_pose, b=b_pose)
        check = _After(problem, after).walk
        step = problem.steps[3]
        return step.kind.check(check, step), problem


def test_verify_refuses_an_unstable_hand_made_stack():
    ok, problem = _stack_check(0.0)
    assert ok == []
    half_b = problem.bodies["b"].half[0]
    half_a = problem.bodies["a"].half[0]
    # a's footprint sticks out of b's top by 5 mm: refused (the old rule, centre over
    # half the face, accepted it).
    out, _ = _stack_check(half_b - half_a + 0.005)
    assert any("footprint sticks out of the top of b" in m for m in out), out
    # Turned 30 degrees: the corners leave the face.
    out, _ = _stack_check(0.0, yaw_a=math.radians(30))
    assert any("footprint sticks out" in m for m in out), out


def test_verify_refuses_a_centre_of_mass_beyond_the_margin():
    """A small heavy load at the edge of a light body standing at the edge of its own
    support: every footprint contained, the load's centre of mass 2 mm from the edge of
    c's top face, inside the 20 % margin (bodies with a mass of their own)."""
    from dataclasses import replace

    _, problem = _stack_check(0.0)
    bodies = dict(problem.bodies)
    bodies.update(a=replace(bodies["a"], half=(0.002, 0.002, bodies["a"].half[2]), mass=10.0),
                  b=replace(bodies["b"], mass=0.001))
    problem = replace(problem, bodies=bodies)
    c, b, a = bodies["c"], bodies["b"], bodies["a"]
    edge = c.half[0] - b.half[0]  # b flush with c's edge
    shift = b.half[0] - a.half[0]  # a flush with b's edge
    b_pose = pose_matrix(c.pose[0] + edge, c.pose[1], problem.steps[1].rest_z, 0.0)
    a_pose = pose_matrix(c.pose[0] + edge + shift, c.pose[1], problem.steps[3].rest_z, 0.0)
    after = {n: pose_matrix(*i.pose) for n, i in bodies.items() if not i.fixed}
    after.update(a=a_pose, b=b_pose)
    step = problem.steps[3]
    out = step.kind.check(_After(problem, after).walk, step)
    assert not any("footprint" in m for m in out), out
    assert [m for m in out if "centre of mass" in m] == [
        m for m in out if "centre of mass of a, b" in m and "c's top face" in m] != [], out
    # The same stack with b at c's centre stands.
    b_pose = pose_matrix(c.pose[0], c.pose[1], problem.steps[1].rest_z, 0.0)
    after.update(a=pose_matrix(c.pose[0] + shift, c.pose[1], problem.steps[3].rest_z, 0.0),
                 b=b_pose)
    assert step.kind.check(_After(problem, after).walk, step) == []


def test_same_yaw_row_matches_finite_differences():
    x = np.array([0.01, -0.02, 0.4, 0.03, 0.05, -1.1])
    val = _rows_check(lambda rows, P, Q: C.same_yaw(rows, "s", P, Q), x)
    assert val[0] == pytest.approx(math.sin(0.4 + 1.1))


def test_planar_bay_packing_keeps_yaws_and_reaches_its_keyframes():
    """robust-planar p06: the planar robot does not turn what it carries, so the final
    placements keep each block's yaw; the disk stays on the mouth's side of each block
    it puts in (before: the keyframes failed with the disk between two blocks, 'collision
    planar_body vs a by 5.0 cm')."""
    domain, scene, modes = _problem_files("robust-planar", "p06")
    with World(scene) as world:
        problem = lower(ops("(pick a table)", "(place a bay)", "(pick b table)",
                            "(place b bay)", "(pick c table)", "(place c bay)"),
                        scene, modes, world, domain=domain)
        final = solve(problem, "final")
        assert final.solved
        for i, p in final.placements.items():
            assert p.yaw == pytest.approx(problem.bodies[problem.steps[i].obj].pose[3], abs=1e-6)
        xs = [final.placements[i].x for i in (1, 3, 5)]
        assert xs == sorted(xs, reverse=True)  # the first placed at the far end
        keyframes = solve(problem, "keyframes", final)
        assert keyframes.solved, keyframes.worst_constraint


def test_library_tower_trajectory_keeps_it_aligned():
    """The keyframe NLP chooses the placements again (through the tool): a tower pair
    keeps to its alignment rows there too (before any: b turned 8 degrees on c, a 16
    on b; the tower fell in a physics replay)."""
    from tampcli.geometry import transforms
    from tampcli.optimize.verify import verify

    domain, scene, modes = _problem_files("arm-pick-place", "p05")
    with World(scene) as world:
        problem = lower(ops("(pick b start)", "(stack b c)", "(pick a start)", "(stack a b)"),
                        scene, modes, world, domain=domain)
        result = solve(problem, "path")
        assert result.solved, result.worst_constraint
        assert verify(problem, result) == []
        end = {n: transforms.pose_from_xyzquat(v[-1]) for n, v in result.object_poses.items()}
        for top, below in (("b", "c"), ("a", "b")):
            offset = np.linalg.norm(end[top][:2, 3] - end[below][:2, 3])
            turn = transforms.yaw_of(end[top]) - transforms.yaw_of(end[below])
            turn = (turn + math.pi / 4) % (math.pi / 2) - math.pi / 4
            assert offset < 4e-3 and abs(math.degrees(turn)) < 3.0, (top, offset, turn)


def test_an_oblong_object_starts_turned_where_only_that_fits():
    from types import SimpleNamespace

    from tampcli.optimize.final_starts import _fitting_yaw

    bar = SimpleNamespace(disk=False, half=(0.10, 0.02, 0.02))
    across = SimpleNamespace(size=(0.08, 0.30))  # takes the bar only along y
    along = SimpleNamespace(size=(0.30, 0.08))
    assert _fitting_yaw(bar, 0.0, across) == pytest.approx(math.pi / 2)
    assert _fitting_yaw(bar, 0.0, along) == 0.0
    assert _fitting_yaw(bar, 0.3, SimpleNamespace(size=(0.05, 0.05))) == 0.3  # none fits


def test_an_object_that_fits_only_across_a_diagonal_starts_in_the_middle_of_its_window():
    """blind20 p01: a 15 x 3 cm pen fits a 13.6 cm square case between about 41.7 and
    48.3 degrees (either diagonal); from 0 the final NLP ended in the case's rim."""
    from types import SimpleNamespace

    from tampcli.optimize.bodies import rectangle_fits
    from tampcli.optimize.final_starts import _fitting_yaw

    pen = SimpleNamespace(disk=False, half=(0.075, 0.015, 0.015))
    case = SimpleNamespace(size=(0.136, 0.136))
    assert rectangle_fits(0.15, 0.03, 0.136, 0.136) and not rectangle_fits(0.15, 0.03, 0.12, 0.12)
    for start, middle in ((0.0, 45.0), (-0.2, -45.0), (2.0, 135.0), (3.0, 135.0), (6.5, 405.0)):
        assert math.degrees(_fitting_yaw(pen, start, case)) == pytest.approx(middle, abs=0.2)


def test_the_pen_goes_into_its_case_turned_45_degrees():
    """The final stage of blind20 p01's pen into its rimmed case, solved."""
    from tampcli.optimize.solve import solve


    folder = Path(__file__).resolve().parents[2] / "problems" / "blind20" / "p01"
    with lowered_folder(folder, "p01", ops("(pick pen pen-home)", "(place pen case)")) as problem:
        out = solve(problem, "final")
    assert out.status == "solved", out.worst_constraint
    (yaw,) = [p.yaw for p in out.placements.values()]
    turn = math.degrees(yaw) % 90.0
    assert 41.5 < turn < 48.5


@pytest.mark.parametrize("order", [("brick", "can"), ("can", "brick")])
def test_a_brick_and_a_can_share_a_tray_with_the_brick_turned_across(order):
    """blind22 p01 (written blind): a 6 x 4 cm brick and a 4.8 cm can fit the 9.4 x 6.4
    cm tray side by side only with the brick across it. From the packed row at their
    start yaws (10.8 cm long) the final NLP ended with them 6 mm into each other in
    both orders; the row now turns the brick a quarter, as it fits across."""
    from tampcli.optimize.final_starts import _row_yaws, packed

    folder = Path(__file__).resolve().parents[2] / "problems" / "blind22" / "p01"
    homes = {"brick": "brick-home", "can": "can-home"}
    skeleton = ops(*[f"({verb} {o} {where})" for o in order
                     for verb, where in (("pick", homes[o]), ("place", "tray"))])
    with lowered_folder(folder, "p01", skeleton) as problem:
        brick = next(s.index for s in problem.steps if s.kind.places and s.obj == "brick")
        turned = _row_yaws(problem)[brick] - problem.bodies["brick"].pose[3]
        assert abs(math.cos(turned)) < 1e-9  # a quarter turn
        placements, _ = packed(problem)
        assert placements[brick].yaw == pytest.approx(problem.bodies["brick"].pose[3]
                                                      + turned)
        out = solve(problem, "final")
    assert out.status == "solved", out.worst_constraint


def test_a_fixed_body_clear_of_the_region_gets_no_apart_row():
    """stages._clear_of_region: the row is left out only where every footprint inside
    the region is C.GAP apart from the body's footprint (its bounding circle), so the
    region's rows imply it; a body nearer, or in the region, keeps its row; and the
    test agrees with the exact separation at the region's worst placement."""
    from tampcli.geometry.model import Region
    from tampcli.optimize.stages import _clear_of_region

    region = Region("r", "table", (0.5, 0.0), (0.2, 0.1))  # x 0.4..0.6, y -0.05..0.05
    post = BodyInfo("post", "box", (0.02, 0.02, 0.1), True, (0.7, 0.0, 0.1, 0.6), True)
    assert _clear_of_region(post, region)  # 10 cm from the region, half diagonal 2.8 cm
    near = BodyInfo("near", "box", (0.02, 0.02, 0.1), True, (0.625, 0.0, 0.1, 0.0), True)
    assert not _clear_of_region(near, region)  # its face 5 mm from the region's edge
    inside = BodyInfo("in", "cylinder", (0.01, 0.01, 0.1), True, (0.5, 0.0, 0.1, 0.0), True)
    assert not _clear_of_region(inside, region)
    rng = np.random.default_rng(4)
    for _ in range(200):  # wherever BOX sits inside the region, a clear body is apart
        x, y, yaw = rng.uniform(0.4, 0.6), rng.uniform(-0.05, 0.05), rng.uniform(-3, 3)
        c, s = math.cos(yaw), math.sin(yaw)
        corners = [(x + a * 0.05 * c - b * 0.03 * s, y + a * 0.05 * s + b * 0.03 * c)
                   for a in (-1, 1) for b in (-1, 1)]
        if not all(0.4 <= px <= 0.6 and -0.05 <= py <= 0.05 for px, py in corners):
            continue
        rows = RowSet()
        C.apart(rows, "s", planar_pose("p", x, y, 0.02, yaw), BOX,
                planar_pose("o", 0.7, 0.0, 0.1, 0.6), post, "post")
        assert rows.values[0][0] >= 0.0


def test_an_object_put_on_itself_is_impossible_with_every_such_action():
    """blind21 p05: the IPC blocks world's `stack` lets a block onto itself; the refusal
    read `the scene has no region or body 'c1'`."""

    folder = Path(__file__).resolve().parents[2] / "problems" / "blind21" / "p05"
    with lowered_folder(folder, "p05", ops("(unstack c2 c1)", "(stack c2 c2)")) as problem:
        assert problem.error == "(stack c2 c2): c2 cannot be put on itself"
        assert problem.error_proved
        assert problem.impossible == ("stack", "c2", ("on", "c2"))


def test_a_region_beyond_the_reach_ball_rules_out_every_such_place():
    """blind22 p05: `(place bottle far)` was refused, proved, in 7 of 20 skeletons; the
    result now names what it rules out, so the search drops every such place."""
    from tampcli.optimize.keyframe_stage import beyond_reach

    folder = ROOT / "problems" / "blind22" / "p05"
    with lowered_folder(folder, "p05", ops("(pick bottle)", "(place bottle far)")) as problem:
        why, impossible = beyond_reach(problem)
        assert "region far is" in why and "beyond the arm's reach for bottle" in why
        assert impossible == ("place", "bottle", ("on", "far"))
        out = solve(problem, "final")
        assert out.proved and out.impossible == impossible
    with lowered_folder(folder, "p05", ops("(pick vase)", "(place vase goal)")) as problem:
        why, impossible = beyond_reach(problem)
        assert "(pick vase): vase stands" in why and impossible is None
    with lowered_folder(folder, "p05", ops("(pick bottle)", "(place bottle side)")) as problem:
        assert beyond_reach(problem) is None
