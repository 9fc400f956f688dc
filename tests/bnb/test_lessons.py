"""What geometry teaches the skeleton source before and during the search
(bnb/lessons.py): proofs on gen1's planar instances, and a teacher's orderings."""

from pathlib import Path
from types import SimpleNamespace

import pytest

from tampcli.bnb.lessons import first_move_proofs, named_lessons, teacher
from tampcli.geometry.reach import reach_ball
from tampcli.geometry.world import World
from tampcli.optimize.bodies import body_info
from tampcli.optimize.options import OptimizeOptions
from tampcli.pipeline import InputPaths, Timers, read_inputs
from tampcli.search.learned import Blocker, LearningSource
from tampcli.search.topk import TopK

GEN1 = Path(__file__).resolve().parents[2] / "problems" / "gen1"
BLIND22 = GEN1.parent / "blind22"


def _inputs(name):
    folder = GEN1 / name
    return read_inputs(InputPaths(str(folder / "domain.pddl"), str(folder / "problem.pddl")),
                       Timers())


@pytest.fixture(scope="module")
def s04():
    inputs = _inputs("planar-s04")
    with World(inputs.scene) as world:
        infos = {n: body_info(inputs.scene.body(n), world) for n in world.movable_names}
        yield inputs, infos


def test_a_push_off_every_cone_from_the_start_is_proved_to_need_a_move_first(s04):
    """planar-s04 (README: box2's goal lies outside every face's friction cone)."""
    inputs, infos = s04
    proofs = first_move_proofs(inputs.task, inputs.modes, inputs.scene, infos,
                               OptimizeOptions())
    assert Blocker("box2", "(push box2 home2 goal2 bench)") in proofs
    # The crate's goal lies straight along a face normal: its push stays open.
    assert not any(b.action == "(push crate1 home1 goal1 bench)" for b in proofs)
    # Only pushes, each on the object it pushes, and only its own start matters: the
    # same push from every symbolic `from` region is in or out together.
    assert all(b.action.startswith(f"(push {b.body} ") for b in proofs)
    for b in proofs:
        to = b.action.split()[3]
        same = {op.name for op in inputs.task.operators if op.action == "push"
                and op.args[0] == b.body and op.args[2] == to}
        assert same <= {p.action for p in proofs}


def test_no_proof_for_an_arm_within_its_reach():
    inputs = _inputs("arm-clutter-s01")
    with World(inputs.scene) as world:
        infos = {n: body_info(inputs.scene.body(n), world) for n in world.movable_names}
        assert first_move_proofs(inputs.task, inputs.modes, inputs.scene, infos,
                                 OptimizeOptions(), reach_ball(world)) == frozenset()


def _blind_proofs(folder: Path, stem: str, ball: bool = True) -> frozenset[Blocker]:
    """first_move_proofs on a blind set's problem (folder/stem.pddl), with the arm's
    reach ball or without."""
    inputs = read_inputs(InputPaths(str(folder / "domain.pddl"), str(folder / f"{stem}.pddl")),
                         Timers())
    with World(inputs.scene) as world:
        infos = {n: body_info(inputs.scene.body(n), world) for n in world.movable_names}
        return first_move_proofs(inputs.task, inputs.modes, inputs.scene, infos,
                                 OptimizeOptions(), reach_ball(world) if ball else None)


def test_a_pick_of_an_object_beyond_the_arms_reach_needs_it_moved_first():
    """blind22 p05: a vase 1.10 m out (the Panda's reach ball: 0.949 m from its
    shoulder); each skeleton picking it cost 5 to 9 s of keyframe NLP before."""
    assert _blind_proofs(BLIND22 / "p05", "p05") == {Blocker("vase", "(pick vase)")}
    assert _blind_proofs(BLIND22 / "p05", "p05", ball=False) == frozenset()  # no ball, no proof


def test_an_arms_push_off_every_cone_from_the_start_is_proved_too():
    """blind23 p02: the KUKA's crate, too wide to grip, whose dock lies 45 deg off
    every face's normal from its start; its pushes toward the mid spots stay open."""
    proofs = _blind_proofs(BLIND22.parent / "blind23" / "p02", "p02")
    assert Blocker("crate", "(push crate home dock)") in proofs
    assert all(b.action.startswith("(push crate ") and b.action.endswith(" dock)")
               for b in proofs)


def test_the_proofs_leave_the_pick_and_place_plans(s04):
    inputs, infos = s04
    source = LearningSource(inputs.task, lambda t: TopK(t, loopless=True),
                            lambda op: frozenset(op.args[:1]) & frozenset(infos))
    source.require_moved(first_move_proofs(inputs.task, inputs.modes, inputs.scene, infos,
                                           OptimizeOptions()))
    first = next(source)
    assert "(push box2 home2 goal2 bench)" not in first.names
    assert first.cost > 8  # the four pushes (cost 8) are gone
    named = named_lessons(source)  # the solution's stats name them
    assert ("box2 moved before (push box2 home2 goal2 bench) (no face's friction cone "
            "leads from box2's start into goal2)") in named["proved_first_moves"]
    assert named["learned"] == [] and named["suspected"] == []
    source.learn(Blocker("crate1", "(push box2 home2 goal2 bench)"))
    assert named_lessons(source)["learned"] == ["crate1 moved before (push box2 home2 goal2 bench)"]


def test_the_teacher_suspects_a_push_into_a_wall_and_a_drag_but_not_a_pick(s04):
    inputs, infos = s04
    heard = []
    source = SimpleNamespace(learn=lambda b: heard.append(("learn", b)) or True,
                             suspect=lambda n: heard.append(("suspect", n)),
                             forbid_operators=lambda names: heard.append(("forbid", names)))
    learn = teacher(source, inputs.task, inputs.modes, frozenset(infos), inputs.scene)
    wall = ("motion 5 before (push box3 home3 goal3 bench): collision planar_body vs wall2 "
            "(margin 1 mm) by 6.0 cm")
    learn(SimpleNamespace(worst_constraint=wall))
    assert heard == [("suspect", "(push box3 home3 goal3 bench)")]
    heard.clear()
    drag = "(push box3 home3 goal1 bench): motion not into the pushed face (a drag) by 7 cm"
    learn(SimpleNamespace(worst_constraint=drag))
    assert heard == [("learn", Blocker("box3", "(push box3 home3 goal1 bench)")),
                     ("suspect", "(push box3 home3 goal1 bench)")]
    heard.clear()
    pick = ("motion 3 before (pick box3 home3): collision planar_body vs wall2 "
            "(margin 1 mm) by 1.0 cm")
    learn(SimpleNamespace(worst_constraint=pick))
    assert heard == []
    # A pushed footprint left out of its region (the object cannot turn): suspected; a
    # place so failing is not (the rule is the pushes').
    learn(SimpleNamespace(worst_constraint="(push box4 home4 home3 bench): footprint outside "
                                           "region home3 by 0.1 cm"))
    assert heard == [("suspect", "(push box4 home4 home3 bench)")]
    heard.clear()
    learn(SimpleNamespace(worst_constraint="(place box4 home3): footprint outside region "
                                           "home3 by 0.1 cm"))
    assert heard == []


def test_a_push_into_a_wall_orders_the_pushes_beyond_it_from_the_same_start(s04):
    """planar-s04: box3 starts east of two walls; pushed towards goal3 (west of them)
    it ran into wall2. Its pushes into regions whose line from its start crosses
    wall2 are learned to need a move first (an ordering); those on its side are not."""
    inputs, _ = s04
    with World(inputs.scene) as world:
        infos = {b.name: body_info(b, world) for b in inputs.scene.bodies}
    learned, suspected = [], []
    source = SimpleNamespace(learn=lambda *b: learned.extend(b) or True,
                             suspect=suspected.append,
                             forbid_operators=lambda names: None)
    movable = frozenset(n for n, i in infos.items() if not i.fixed)
    learn = teacher(source, inputs.task, inputs.modes, movable, inputs.scene, infos)
    learn(SimpleNamespace(worst_constraint=(
        "motion 5 before (push box3 home3 goal3 bench): collision planar_body vs wall2 "
        "(margin 1 mm) by 6.0 cm")))
    assert suspected == ["(push box3 home3 goal3 bench)"]
    targets = {b.action.split()[3] for b in learned}
    assert all(b.body == "box3" and b.action.startswith("(push box3 ") for b in learned)
    assert {"goal3", "goal4", "home2"} <= targets  # all west of the walls
    assert "home3" not in targets  # where it stands
    regions = {r.name: r for r in inputs.scene.regions}
    wall = infos["wall2"].pose[0]
    assert all(regions[t].center[0] < wall for t in targets)


def test_a_push_blocked_again_by_a_body_already_learned_is_suspected(s04):
    """The first overlap teaches "move box2 first"; the same overlap again (box2 was
    moved, into the way) suspects the push; a pick so blocked is not suspected."""
    inputs, infos = s04
    suspected = []
    source = LearningSource(inputs.task, lambda t: TopK(t, loopless=True),
                            lambda op: frozenset(op.args[:1]) & frozenset(infos))
    source.suspect = suspected.append
    learn = teacher(source, inputs.task, inputs.modes, frozenset(infos), inputs.scene)
    overlap = SimpleNamespace(worst_constraint="(push box3 home3 goal2 bench): overlaps box2 "
                                               "by 0.5 cm")
    learn(overlap)
    assert suspected == [] and Blocker("box2", "(push box3 home3 goal2 bench)") \
        in source.blockers
    learn(overlap)
    assert suspected == ["(push box3 home3 goal2 bench)"]
    pick = SimpleNamespace(worst_constraint="motion 2 before (pick box3 home3): collision "
                                            "planar_body vs box2 (margin 1 mm) by 1 cm")
    learn(pick)
    learn(pick)
    assert suspected == ["(push box3 home3 goal2 bench)"]


def test_an_arms_push_is_not_suspected_for_a_link_against_a_fixed_body(s04):
    """The wall and blocker-again suspicions are the planar robot's: an arm's link
    against a fixed rim at a push says where the arm came from (blind8 p05 lost its
    6-action answer to that ordering); the push-rule row is still read."""
    inputs, infos = s04
    heard = []
    source = SimpleNamespace(learn=lambda b: heard.append(("learn", b)) or False,
                             suspect=lambda n: heard.append(("suspect", n)),
                             forbid_operators=lambda names: heard.append(("forbid", names)))
    arm = SimpleNamespace(robot=SimpleNamespace(model="panda"), regions=())
    learn = teacher(source, inputs.task, inputs.modes, frozenset(infos), arm)
    learn(SimpleNamespace(worst_constraint="(push box3 home3 goal3 bench): collision "
                                           "panda_link7 vs wall2 (margin 1 mm) by 0.4 cm"))
    learn(SimpleNamespace(worst_constraint="(push box3 home3 goal2 bench): overlaps box2 "
                                           "by 0.5 cm"))
    assert not [h for h in heard if h[0] == "suspect"]


def test_a_keyframe_failure_naming_no_body_teaches_the_body_its_action_collides_with():
    """blind22 p05: `(pick cube): tool tilted by 1.0 deg`, the wrist 1 cm into the bottle
    beside the cube at that point: the bottle is learned, as if the row had named it."""
    from tampcli.bnb.violations import Violation

    learned = []
    source = SimpleNamespace(learn=lambda *b: learned.extend(b) or True,
                             forbid_operators=lambda names: None)
    task = SimpleNamespace(operators=())
    rows = (Violation("(pick cube)", "tool tilted by 1 deg", 0.018),
            Violation("(place cube goal)", "collision panda_hand vs vase (margin 1 mm) by 2 cm",
                      0.02),
            Violation("(pick cube)", "collision panda_link7 vs bottle (margin 1 mm) by 1 cm",
                      0.010))
    learn = teacher(source, task, None, frozenset({"cube", "bottle", "vase"}),
                    rows_of=lambda result: rows)
    failed = SimpleNamespace(stage="keyframes", worst_constraint="(pick cube): tool tilted "
                             "by 1.0 deg", impossible=None)
    learn(failed)
    assert learned == [Blocker("bottle", "(pick cube)")]  # not the vase: another action's
    learned.clear()
    learn(SimpleNamespace(stage="path", worst_constraint=failed.worst_constraint,
                          impossible=None))
    assert learned == []


def test_what_an_action_carries_is_not_learned_to_be_in_its_way():
    """blind24 p05: a failing `go` with the parcel in hand named the parcel against the
    bench; the parcel is carried, not in the way. Not held, it would be a blocker."""
    folder = BLIND22.parent / "blind24" / "p05"
    inputs = read_inputs(InputPaths(str(folder / "domain.pddl"), str(folder / "p05.pddl")),
                         Timers())
    heard = []
    source = SimpleNamespace(learn=lambda b: heard.append(b) or True,
                             suspect=lambda n: None, forbid_operators=lambda names: None)
    learn = teacher(source, inputs.task, inputs.modes, frozenset({"parcel"}), inputs.scene)
    worst = "(go cp-e): collision parcel vs bench (margin 1 mm) by 0.1 cm"
    learn(SimpleNamespace(worst_constraint=worst, names=("(grab parcel pad)", "(go cp-e)")))
    assert heard == []
    learn(SimpleNamespace(worst_constraint=worst, names=(
        "(grab parcel pad)", "(drop parcel dropzone)", "(go cp-e)")))
    assert heard == [Blocker("parcel", "(go cp-e)")]
