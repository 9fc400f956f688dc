"""What geometry teaches the skeleton source (search/learned.py).

Before any skeleton, `first_move_proofs`: the actions that cannot move their
object from its start pose whatever came before (a push, by the planar robot or
an arm, whose object's every face's friction cone misses the target; an arm's
grasp of an object standing beyond its reach), each a proved precondition "the
object was moved before" (`LearningSource.require_moved`).

Then three lessons of a failed stage, each read off the stage's result:

- a body in the way (its worst row names a movable body: optimize/blockers.py;
  or, a keyframe failure's worst row naming none, a violated collision row of
  the same action does) becomes a learned precondition: the skeletons that move
  it first come next;
- a push (a kind that moves within one face's friction cone) that ran into a
  body that never moves, or out of every cone, or into a blocker already
  learned (moved, and into the way), or whose footprint stayed out of its
  target region, is suspected: the skeletons
  without that ground action come first (`LearningSource.suspect`, an ordering);
- an action proved impossible in any skeleton (`result.impossible`: no grasp of
  the object fits, its footprint fits the region in no orientation) takes
  every ground action of that schema on that object (into that region) out
  of the task: the enumeration runs out once no plan without one is left.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from tampcli.optimize.blockers import action_of, blocker_of, fixed_body_of, fixed_obstacle_of
from tampcli.optimize.kinds import KINDS
from tampcli.optimize.push_reach import first_push_blocked, line_meets
from tampcli.search.learned import Blocker


def first_move_proofs(task, modes, scene, infos, options, ball=None) -> frozenset[Blocker]:
    """Blocker(object, action) for each ground action that cannot move its object from
    its start pose: an action of a kind that moves only within a face's friction cone
    (ModeKind.within_cone: a push, by the planar robot or an arm, judged by the same
    per-step cone and a box's yaw held at the keyframes) into a target region no
    face's cone leads to (push_reach.first_push_blocked); for an arm, a grasp
    (ModeKind.fingers) of an object standing beyond its reach `ball` ((centre,
    radius): geometry/reach.reach_ball, a bound) by more than the object's bounding
    sphere. In every skeleton, that action needs its object moved before it.
    `infos`: the movable bodies' bodies.BodyInfo by name; `options`:
    optimize.options.OptimizeOptions. Each (kind, object, region) is judged once."""
    return _off_every_cone(task, modes, scene, infos, options) | _out_of_reach(
        task, modes, infos, ball)


def _off_every_cone(task, modes, scene, infos, options) -> frozenset[Blocker]:
    """The pushes first_move_proofs rules out (gen1 planar-s04's box2; blind23 p02: an
    arm's crate whose goal lies 45 deg off every face, 2.2 s of keyframe NLP for a
    local failure)."""
    regions = {r.name: r for r in scene.regions}
    judged: dict[tuple[str, str, str], bool] = {}
    found = set()
    for op in task.operators:
        mode = modes.get_mode(op.action)
        roles = mode.bind(op.args) if mode.geometric else {}
        obj, to = roles.get("object"), roles.get("to")
        if obj not in infos or to not in regions:
            continue
        key = (mode.kind, obj, to)
        if key not in judged:
            judged[key] = KINDS[mode.kind].within_cone and \
                first_push_blocked(infos[obj], regions[to], options.waypoints)
        if judged[key]:
            found.add(Blocker(obj, op.name, f"no face's friction cone leads from {obj}'s "
                                            f"start into {to}"))
    return frozenset(found)


def _out_of_reach(task, modes, infos, ball) -> frozenset[Blocker]:
    """The grasps first_move_proofs rules out for an arm (blind22 p05: a vase 1.10 m
    out, each skeleton picking it 5 to 9 s of keyframe NLP before)."""
    if ball is None:
        return frozenset()
    centre, reach = ball
    found = set()
    for op in task.operators:
        mode = modes.get_mode(op.action)
        if not mode.geometric or KINDS[mode.kind].fingers is not True:
            continue
        info = infos.get(mode.bind(op.args).get("object"))
        if info is None:
            continue
        far = float(np.linalg.norm(np.asarray(info.pose[:3]) - centre))
        if far > reach + info.sphere:
            obj = mode.bind(op.args)["object"]
            found.add(Blocker(obj, op.name, f"{obj} stands {far:.2f} m from the arm's "
                                            f"reach centre, beyond its {reach:.2f} m"))
    return frozenset(found)


_PUSH_RULE = "motion not into the pushed face"
_OUTSIDE = ": footprint outside region "


def teacher(source, task, modes, movable: frozenset[str], scene=None,
            infos=None, rows_of=None) -> Callable[[Any], None]:
    """`learn(result)` for branch and bound: `source` a LearningSource over `task`.
    With the planar robot's `scene` and every body's BodyInfo (`infos`), a push that
    ran into a fixed body also orders the other pushes of its object whose straight
    line from the object's start crosses that body after a move of the object.
    `rows_of(result)`: the rows a failed keyframe stage left violated
    (bnb/violations.Violation, worst first), read where its worst row names no body."""

    def matches(op, action: str, obj: str, role) -> bool:
        if op.action != action:
            return False
        bound = modes.get_mode(action).bind(op.args)
        return bound["object"] == obj and (role is None or bound[role[0]] == role[1])

    kinds = {op.name: KINDS[modes.get_mode(op.action).kind] for op in task.operators}
    # The wall and blocker-again suspicions read the planar robot's failures: its body
    # pushes, so a collision of its body with a wall is the push's own. An arm's link
    # against a fixed rim at a push says where the arm came from, not the push: ordering
    # that push last cost blind8 p05 its 6-action answer (7 actions, objective 3.39
    # against 2.01, the 6-action skeleton never drawn in 1000).
    planar = scene is not None and scene.robot.model == "planar"

    ops = {op.name: op for op in task.operators}

    def held_at(names, action: str) -> str | None:
        """What the robot holds during `action` of the skeleton `names`: the object of
        the last grasp before it not set down since."""
        held = None
        for name in names:
            if name == action:
                return held
            op, kind = ops.get(name), kinds.get(name)
            if op is None or kind is None:
                continue
            if kind.fingers is True:
                held = modes.get_mode(op.action).bind(op.args).get("object")
            elif kind.places:
                held = None
        return None

    def learn(result) -> None:
        worst = getattr(result, "worst_constraint", None)
        # What the failing action carries is not in its way (blind24 p05: a parcel carried
        # to a checkpoint, its row against the bench, was learned "moved before" its own
        # carry): only the other movable bodies may be.
        held = held_at(getattr(result, "names", ()), action_of(worst))
        others = movable - {held}
        blocker = blocker_of(worst, others)
        if blocker is None and rows_of is not None:
            blocker = _pressing(result, worst, rows_of, others)
        again = blocker is not None and not source.learn(blocker)
        # A push (within one face's cone) that runs into a wall, or out of every cone, or
        # into a body it was already known to need moved first (moving it did not help:
        # it was moved into the way, gen1 planar-s02's box2 in goal2): skeletons without
        # that push come first (an ordering: the NLPs are local).
        pushed = fixed_obstacle_of(worst, movable) if planar else None
        if pushed is None and blocker is not None and (
                (again and planar) or _PUSH_RULE in worst):
            pushed = blocker.action
        if pushed is None and _OUTSIDE in (worst or ""):
            # The object keeps its yaw: its footprint against the region is the same
            # wherever the push stands in a skeleton (x-s18: 40 final-stage failures).
            pushed = action_of(worst)
        if pushed is not None and getattr(kinds.get(pushed), "within_cone", False):
            source.suspect(pushed)
            wall = fixed_body_of(worst, movable)
            if wall is not None and infos is not None and wall in infos:
                beyond = _beyond(task, modes, scene, infos, pushed, infos[wall])
                if beyond:
                    source.learn(*beyond)
        impossible = getattr(result, "impossible", None)
        if impossible is not None:
            source.forbid_operators(frozenset(
                op.name for op in task.operators if matches(op, *impossible)))

    return learn


def _pressing(result, worst, rows_of, movable) -> Blocker | None:
    """A movable body the failing action's own rows collide with, where its worst row
    names none: the NLP gave up a little on the hand's tilt or contact to keep out of
    that body (blind22 p05: `(pick cube): tool tilted by 1.0 deg`, the wrist 1 cm into
    the bottle beside the cube; the bottle was never learned, and the 4-action
    skeletons came in cost order). The same lesson as a worst row naming it."""
    action = action_of(worst)
    if action is None or getattr(result, "stage", None) != "keyframes":
        return None
    for row in rows_of(result):
        if row.step == action:
            found = blocker_of(f"{row.step}: {row.words}", movable)
            if found is not None:
                return found
    return None


def _beyond(task, modes, scene, infos, pushed: str, wall) -> list[Blocker]:
    """Blocker(object, push) for every push of `pushed`'s object (the same kind) into a
    region whose straight line from the object's start meets `wall`, swept by the
    pusher beside the object: from its start, that push likely runs into the wall
    too; skeletons that move the object elsewhere first come next (an ordering)."""
    ops = {op.name: op for op in task.operators}
    mode = modes.get_mode(ops[pushed].action)
    obj = mode.bind(ops[pushed].args)["object"]
    info, regions = infos.get(obj), {r.name: r for r in scene.regions}
    if info is None or scene.robot.model != "planar":
        return []
    clearance = scene.robot.radius + info.radius
    found = []
    for op in task.operators:
        other = modes.get_mode(op.action)
        if other.kind != mode.kind or not other.geometric:
            continue
        roles = other.bind(op.args)
        to = regions.get(roles["to"])
        if roles["object"] == obj and to is not None \
                and line_meets(info.pose[:2], to, wall, clearance):
            found.append(Blocker(obj, op.name))
    return found


def named_lessons(source) -> dict[str, list[str]]:
    """What `source` (a LearningSource) learned, by name, for the solution's stats
    (blind22: the counts alone left a user guessing which body the search came to
    move first)."""
    def words(found):
        return sorted(b.words() for b in found)

    return {"learned": words(source.blockers), "proved_first_moves": words(source.proved),
            "suspected": sorted(source.suspects)}
