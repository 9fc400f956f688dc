"""A search without a solution says what stopped it: the rows violated at the NLP's best
point by action (not only the worst), and whether the skeletons left were excluded by a
heuristic (prefixes forbidden after a local failure) rather than tried."""

import dataclasses
import time
from pathlib import Path

import pytest

from tampcli.bnb import BnBOptions, branch_and_bound
from tampcli.pipeline import InputPaths, SolveOptions, Timers, read_inputs
from tampcli.pipeline import solve as solve_paths
from tampcli.stage_evaluator import Geometry, StageEvaluator
from tests.bnb.test_bnb import R, Source, table_evaluator

ROOT = Path(__file__).resolve().parents[2]


def test_the_reason_names_the_prefixes_that_excluded_the_rest_and_is_no_proof():
    src = Source([(("x", "y", "z"), 3), (("x", "y", "w"), 4)])
    ev = table_evaluator({(("x", "y"), "keyframes"): R("infeasible", worst_constraint="ik")})
    res = branch_and_bound(src, ev, BnBOptions())
    assert res.status == "limit" and res.stats["stop"] == "every skeleton tried"
    assert ("x", "y", "w") not in src.drawn
    assert "every skeleton was tried" not in res.reason
    assert "1 prefix(es) forbidden after a local NLP failure (x y)" in res.reason
    assert "not a proof" in res.reason


def test_an_exhausted_source_says_which_skeletons_it_yields():
    class Scoped(Source):
        scope = "loopless: none passes a symbolic state twice"

    ev = table_evaluator({(("a",), "final"): R("infeasible", worst_constraint="far")})
    res = branch_and_bound(Scoped([(("a",), 1)]), ev, BnBOptions())
    assert res.reason.startswith("every skeleton was tried (1; loopless: none passes")
    assert "not a proof" in res.reason
    proved = table_evaluator({(("a",), "final"): R("infeasible", "far", proved=True)})
    res = branch_and_bound(Scoped([(("a",), 1)]), proved, BnBOptions())
    assert res.status == "unsolvable" and "not a proof" not in res.reason


def test_the_diagnosis_of_each_failure_named_comes_with_it():
    failed = R("infeasible", worst_constraint="(pick a): tilted")
    seen = []

    def diagnose(ops, result):
        seen.append((tuple(op.name for op in ops), result))
        return "(pick a) tilted by 0.5 deg; (place a) collision hand vs bottle by 2 cm"

    ev = table_evaluator({(("pick", "place"), "keyframes"): failed})
    res = branch_and_bound(Source([(("pick", "place"), 2)]), ev,
                           BnBOptions(prefix_pruning=False), diagnose=diagnose)
    assert seen == [(("pick", "place"), failed)]
    assert "[violated at the NLP's best point, by action: (pick a) tilted by 0.5 deg; " \
           "(place a) collision hand vs bottle by 2 cm]" in res.reason
    seen.clear()
    res = branch_and_bound(Source([(("pick", "place"), 2)]), table_evaluator({}),
                           BnBOptions(), diagnose=diagnose)
    assert res.status == "solved" and seen == []


def test_the_violated_rows_of_a_real_keyframe_failure_start_with_the_reported_one():
    """blind4 p02: the target's pick, with the block 2 cm beside it, fails at the keyframes."""
    folder = ROOT / "problems" / "blind4" / "p02"
    inputs = read_inputs(InputPaths(str(folder / "domain.pddl"), str(folder / "p02.pddl")),
                         Timers())
    from tampcli.bnb.violations import violated_rows
    from tampcli.geometry.collision import CollisionChecker
    from tampcli.geometry.world import World
    from tampcli.optimize.grips import Kinematics

    with World(inputs.scene) as world:
        evaluate = StageEvaluator(inputs, Geometry(world, CollisionChecker(world)), SolveOptions(),
                              time.perf_counter() + 60)
        ops = {op.name: op for op in inputs.task.operators}
        plan = (ops["(pick target nook)"], ops["(place target goal)"])
        final = evaluate(plan, "final", None)
        result = evaluate(plan, "keyframes", final)
        assert result.status == "infeasible"
        rows = violated_rows(evaluate._lowered(plan), result, Kinematics(world))
        assert rows and rows[0].amount == pytest.approx(result.violation, rel=1e-6)
        what = rows[0].words.rpartition(" by ")[0]
        assert result.worst_constraint.startswith(f"{rows[0].step}: {what} by ")
        assert all(a.amount >= b.amount > 1e-4 for a, b in zip(rows, rows[1:], strict=False))
        text = evaluate.violated(plan, result)
        assert text.startswith(f"{rows[0].step} {rows[0].words}")
        assert evaluate.violated(plan, final) is None  # solved: nothing to say


def test_blind4_p01_first_version_names_the_place_not_only_the_pick(tmp_path):
    """p01 as first written: roof 48 cm up, a 15 cm bottle behind the bay. `solve` said
    only `(pick cube counter): tool tilted by 0.5 deg`; the place's rows come with it now."""
    folder = ROOT / "problems" / "blind4" / "p01"
    for name in ("domain.pddl", "modes.toml", "p01.pddl"):
        (tmp_path / name).write_text((folder / name).read_text())
    scene = (folder / "p01.scene.toml").read_text()
    first = scene.replace("pose = [0.58, 0.15, 0.59]", "pose = [0.58, 0.15, 0.49]") \
        .replace("size = [0.03, 0.06]", "size = [0.03, 0.15]") \
        .replace("pose = [0.665, 0.15, 0.18]", "pose = [0.665, 0.15, 0.225]")
    assert first.count("0.49]") == 1 and "0.225]" in first
    (tmp_path / "p01.scene.toml").write_text(first)
    solution = solve_paths(InputPaths(str(tmp_path / "domain.pddl"), str(tmp_path / "p01.pddl")),
                           SolveOptions(BnBOptions(time_limit=60)))
    assert solution.status == "limit"
    # the one loopless skeleton, then the regrasps (none feasible either)
    assert solution.reason.startswith("every skeleton was tried (3; loopless ones, then")
    detail = solution.reason.partition("[violated at the NLP's best point, by action: ")[2]
    assert "(pick cube counter)" in detail and "(place cube bay)" in detail, solution.reason


def test_an_object_no_grasp_fits_makes_the_problem_unsolvable_at_once():
    """blind6 p08 (written blind): a 7.5 cm case, the Panda takes 7.3 cm at most, and no
    push. The proof holds for every pick of the case, wherever it stands: the search
    drops them all and ends `unsolvable`, not at its limits."""
    folder = ROOT / "problems" / "blind6" / "p08"
    solution = solve_paths(InputPaths(str(folder / "domain.pddl"), str(folder / "p08.pddl")),
                           SolveOptions(BnBOptions(time_limit=60)))
    assert solution.status == "unsolvable", solution.reason
    assert "no grasp of case fits" in solution.reason
    assert len(solution.skeletons) == 1


def test_an_object_larger_than_its_goal_region_makes_the_problem_unsolvable_at_once(tmp_path):
    """arm-pick-place p03 with its goal region 3 cm wide: the footprint proof holds for
    every place of a there, so the search drops them and ends `unsolvable` after one
    skeleton (before: `limit` at the skeleton limit, 20 skeletons failing alike)."""
    for name in ("domain.pddl", "modes.toml"):
        (tmp_path / name).write_text((ROOT / "domains" / "arm-pick-place" / name).read_text())
    folder = ROOT / "problems" / "arm-pick-place"
    (tmp_path / "p03.pddl").write_text((folder / "p03.pddl").read_text())
    scene = (folder / "p03.scene.toml").read_text()
    assert scene.count("size = [0.15, 0.15]") == 1
    (tmp_path / "p03.scene.toml").write_text(scene.replace("size = [0.15, 0.15]",
                                                           "size = [0.03, 0.15]"))
    events = []
    solution = solve_paths(InputPaths(str(tmp_path / "domain.pddl"), str(tmp_path / "p03.pddl")),
                           SolveOptions(BnBOptions(time_limit=60)), events.append)
    assert solution.status == "unsolvable", solution.reason
    assert "does not fit region goal (3.0 x 15.0 cm)" in solution.reason
    # The live line says it is a proof, not a local failure (blind18's DOC_GAPS 9).
    outcomes = [e.outcome for e in events if e.kind == "outcome"]
    assert outcomes == ["proved infeasible"], outcomes
    assert "proved impossible in any skeleton" in solution.reason
    assert len(solution.skeletons) == 1


def test_a_mesh_too_wide_as_its_bounding_box_proves_nothing(tmp_path):
    """blind7 p01's hexagonal prism scaled 1.5 times: 8.7 cm across its corners, 7.5 cm
    across its flats, more than the Panda takes either way. Its bounding box is all the
    planner knows of it, and a test on a bounding box is no proof: the search goes on,
    `limit`, not `unsolvable`, and no action is taken out of the task."""
    folder = ROOT / "problems" / "blind7" / "p01"
    for f in folder.iterdir():
        (tmp_path / f.name).write_bytes(f.read_bytes())
    scene = (tmp_path / "p01.scene.toml").read_text()
    assert scene.count('mesh = "hexnut.obj"') == 1
    (tmp_path / "p01.scene.toml").write_text(scene.replace(
        'mesh = "hexnut.obj"', 'mesh = "hexnut.obj"\nscale = [1.5, 1.5, 1.0]'))
    solution = solve_paths(InputPaths(str(tmp_path / "domain.pddl"), str(tmp_path / "p01.pddl")),
                           SolveOptions(BnBOptions(time_limit=20, max_skeletons=3)))
    assert solution.status == "limit", solution.reason
    assert "(as its bounding box)" in solution.reason
    assert "proved impossible" not in solution.reason


def test_no_skeleton_left_by_the_proofs_is_not_called_symbolically_unsolvable(tmp_path):
    """blind28 p06: `plan` had the plan, `solve` said 'the task is symbolically
    unsolvable' after a reach proof, made before any skeleton, ruled out its pick.
    Here a true one: the cube 1.2 m from the Panda's base (its reach ball: 0.949 m
    about the shoulder), the only action that moves it a pick."""
    for name in ("domain.pddl", "modes.toml"):
        (tmp_path / name).write_text((ROOT / "domains" / "arm-pick-place" / name).read_text())
    folder = ROOT / "problems" / "arm-pick-place"
    (tmp_path / "p01.pddl").write_text((folder / "p01.pddl").read_text())
    scene = (folder / "p01.scene.toml").read_text()
    far = {"size = [1.2, 1.4, 0.04]": "size = [1.8, 1.4, 0.04]",
           "pose = [0.3, 0.0, -0.02]": "pose = [0.6, 0.0, -0.02]",
           "pose = [0.45, -0.2, 0.025]": "pose = [1.2, -0.2, 0.025]",
           "center = [0.45, -0.2]": "center = [1.2, -0.2]"}
    for old, new in far.items():
        assert scene.count(old) == 1
        scene = scene.replace(old, new)
    (tmp_path / "p01.scene.toml").write_text(scene)
    solution = solve_paths(InputPaths(str(tmp_path / "domain.pddl"), str(tmp_path / "p01.pddl")),
                           SolveOptions(BnBOptions(time_limit=60)))
    assert solution.status == "unsolvable", solution.reason
    assert "symbolically" not in solution.reason
    assert "geometric proof(s) made before any skeleton" in solution.reason
    assert len(solution.skeletons) == 0


def test_a_search_ended_by_proofs_names_them_and_what_proves_each():
    """blind35 DOC_GAPS 5: the reason said only how many proofs there were."""
    from tampcli.bnb.outcome import Ending, explain

    cone = ("crate moved before (push crate home dock) (no face's friction cone leads "
            "from crate's start into dock)")
    reason = explain(Ending("exhausted", 0, True, proofs=1, proof_names=(cone,)), [], (),
                     BnBOptions())
    assert reason.startswith("no skeleton: every plan breaks one of the 1 geometric proof(s)")
    assert cone in reason


def test_a_stage_refused_before_any_nlp_counts_no_nlp_solve():
    """blind35 DOC_GAPS 6: a final stage proved infeasible before any NLP counted one."""
    @dataclasses.dataclass(frozen=True)
    class Proved(R):
        nlp_solves: int = 0

    src = Source([(("a",), 1)])
    ev = table_evaluator({(("a",), "final"): Proved("infeasible", worst_constraint="far",
                                                    proved=True)})
    res = branch_and_bound(src, ev, BnBOptions())
    assert res.status == "unsolvable" and res.stats["nlp_solves"] == 0
    # An evaluator that does not say how many it solved counts one a stage.
    ev = table_evaluator({(("a",), "final"): R("infeasible", worst_constraint="far",
                                               proved=True)})
    assert branch_and_bound(Source([(("a",), 1)]), ev, BnBOptions()).stats["nlp_solves"] == 1


def test_a_proof_made_while_lowering_forbids_its_prefix_and_keeps_the_bound():
    """blind37 p02: `(pick plate home): plate is under another object`, proved from the
    actions up to the pick alone, was refuted again in 35 skeletons starting so."""
    src = Source([(("x", "y", "z"), 3), (("x", "y", "w"), 4), (("v",), 5)])
    ev = table_evaluator({(("x", "y", "z"), "final"): R(
        "infeasible", worst_constraint="y: plate is under another object", proved=True,
        failed_actions=2)})
    res = branch_and_bound(src, ev, BnBOptions())
    assert ("x", "y", "w") not in src.drawn
    assert res.stats["prefixes_forbidden"] == 1
    first = next(r for r in res.skeletons if r.plan == ("x", "y", "z"))
    assert first.reason.endswith("(prefix x y is proved infeasible)")
    assert res.status == "solved" and res.best_plan[0].name == "v"
