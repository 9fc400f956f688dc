"""The final and keyframe stages of one skeleton: placements (no robot), then
IK-started keyframes in one NLP; the planar suction grips tried at each face
where the NLP's own contact angles fail."""

from __future__ import annotations

import math
import time

import numpy as np

from tampcli.geometry.reach import reach_ball
from tampcli.optimize.closing import CLOSING, closing_blocked
from tampcli.optimize.final_starts import starts
from tampcli.optimize.grips import SideGrip
from tampcli.optimize.hand import narrows, with_hand
from tampcli.optimize.init import keyframe_guess
from tampcli.optimize.keyframe_supports import into_support, with_supports
from tampcli.optimize.layout import grip_block, keyframe_block
from tampcli.optimize.nlp import FEASIBILITY
from tampcli.optimize.result import TrajectoryResult
from tampcli.optimize.run import Run
from tampcli.optimize.stages import final_layout, final_rows, keyframe_layout, keyframe_rows
from tampcli.optimize.values import (
    Keyframes,
    Placement,
    placement_blocks,
    placements_from_blocks,
)
from tampcli.optimize.world_state import grip_of
from tampcli.solution_kkt import KktStages

GRIP_BOUND = 4 * math.pi
RETRY_JITTER = 0.4  # rad: IK seed perturbation of the second keyframe attempt
FACE_SAME = 0.05  # rad: a contact angle this close to a face's middle is at that face
FIXED_GRIP = 1e-6  # rad: the bounds' half width around a grip parameter kept fixed


def beyond_reach(problem) -> tuple[str, tuple | None] | None:
    """(why, what it rules out) where the skeleton asks the arm's tool to come near a
    point it cannot (proved), else None.

    The tool's origin stays within the arm's reach ball (geometry/reach.py: a bound
    from the chain, whatever the joint values) and holds its object within the
    object's bounding sphere; so a region farther from the ball than that radius
    cannot receive the object (ruled out: that action of that object into that
    region, in every skeleton: optimize/skeleton.ImpossibleAction's tuple), and an
    object that stands that far where it started cannot be picked there before
    something else moved it (ruled out in this skeleton alone).
    """
    if problem.planar:
        return None
    ball = _reach_ball(problem)
    if ball is None:
        return None
    centre, reach = ball
    regions = {r.name: r for r in problem.scene.regions}
    moved = set()
    for step in problem.steps:
        info = problem.bodies.get(step.obj)
        if info is None:
            continue
        slack = info.sphere
        if step.held_after == step.obj and step.held_before is None and step.obj not in moved:
            gap = float(np.linalg.norm(np.asarray(info.pose[:3]) - centre))
            if gap > reach + slack:
                return (f"{step.name}: {step.obj} stands {100 * (gap - reach - slack):.0f} cm "
                        f"beyond the arm's reach ({reach:.2f} m from "
                        f"{_point(centre)}, its centre {gap:.2f} m away)"), None
        if step.kind.places and step.target in regions:
            region = regions[step.target]
            nearest = np.clip(centre[:2], region.lower, region.upper)
            gap = math.hypot(*(nearest - centre[:2]), step.rest_z - centre[2])
            if gap > reach + slack:
                role = "to" if "to" in step.kind.required else "on"
                action = step.name.strip("()").split()[0]
                return (f"{step.name}: region {step.target} is {100 * (gap - reach - slack):.0f}"
                        f" cm beyond the arm's reach for {step.obj} ({reach:.2f} m from "
                        f"{_point(centre)})"), (action, step.obj, (role, step.target))
        if step.kind.places:
            moved.add(step.obj)
    return None


def _reach_ball(problem):
    """geometry/reach.reach_ball of the problem's World, measured once (problem.memo)."""
    if "reach_ball" not in problem.memo:
        problem.memo["reach_ball"] = reach_ball(problem.world)
    return problem.memo["reach_ball"]


def _point(p) -> str:
    return f"({p[0]:.2f}, {p[1]:.2f}, {p[2]:.2f})"


def solve_placements(run: Run, origins: dict | None = None, like: dict | None = None):
    """Run the final NLP from each of final_starts.starts until one solves; returns
    (outcome or None when there is nothing to place, values). Its outcome depends on
    the skeleton alone (no warm start from another skeleton: see final_starts).
    Given `origins` (step -> (x, y)), from there alone, at the yaws of `like`."""
    problem = run.problem
    layout = final_layout(problem)
    if layout.size == 0:
        return None, {}
    bounds = [(-1e3, 1e3)] * layout.size
    best = None
    if origins is not None:
        given = {i: Placement(float(o[0]), float(o[1]), like[i].yaw) for i, o in origins.items()}
        candidates = [lambda _problem: (given, origins)]
    else:
        candidates = starts(problem)
    seen = set()
    for start in candidates:
        placements, origins = start(problem)
        key = tuple(sorted((i, round(p.x, 6), round(p.y, 6), round(p.yaw, 6))
                           for i, p in placements.items())) + tuple(
            sorted((i, round(float(o[0]), 6), round(float(o[1]), 6))
                   for i, o in origins.items()))
        if key in seen:  # shelves of one object each are the middle start again
            continue
        seen.add(key)
        out = run.nlp(lambda x, origins=origins: final_rows(problem, layout.unpack(x), origins),
                      layout, layout.pack(placement_blocks(placements)), bounds)
        if best is None or out.status == "solved" or out.violation < best[0].violation:
            best = (out, placements)
        if out.status == "solved" or time.perf_counter() > run.deadline:
            break
    out, placements = best
    return out, placements_from_blocks(layout.unpack(out.x), placements)


def final(run: Run) -> TrajectoryResult:
    far = beyond_reach(run.problem)
    if far:
        why, impossible = far
        return run.result("infeasible", worst_constraint=why, proved=True, violation=math.inf,
                          impossible=impossible)
    out, placements = solve_placements(run)
    if out is None:
        return run.result("solved", cost=0.0)
    if out.status != "solved":
        return run.result(out.status, violation=out.violation, worst_constraint=out.worst,
                          placements=placements)
    return run.result("solved", cost=0.0, violation=out.violation, placements=placements,
                      kkt=KktStages(final=out.kkt))


# ---------------------------------------------------------------- keyframes


def _shares_prefix(problem, warm) -> bool:
    return (warm is not None and warm.keyframes and len(warm.names) <= len(problem.names)
            and tuple(problem.names[:len(warm.names)]) == tuple(warm.names))


def keyframes(run: Run, warm) -> TrajectoryResult:
    """The keyframe NLP, the hand open (or as the warm start's prefix had it); where
    that fails and the fingers are part of why, again with the hand narrowed to the
    grips (hand.with_hand); where it fails still, with the planar suction grips kept at
    the middle of each face (`_face_grips`: a peg pushed into a socket by its back face)."""
    result = keyframes_with(run, warm)
    if not result.solved and not result.proved and time.perf_counter() < run.deadline \
            and (_fingers_in_the_way(run, result) or _closing(run, result)):
        again = keyframes_with(run, warm, narrow=True)
        result = again if again.solved else result
    for grips in face_grips(run.problem, result):
        if result.solved or result.proved or time.perf_counter() > run.deadline:
            break
        again = keyframes_with(run, warm, grips, narrow=result.narrowed)
        result = again if again.solved else result
    return result


def _fingers_in_the_way(run: Run, failed: TrajectoryResult) -> bool:
    """Whether the open hand's failed keyframes violate less with the hand narrowed to
    their grips: the fingers are then part of what the NLP could not clear (blind10
    p05: a bar beside a bin's rim, its fingers across the rim). One evaluation of the
    rows, not an NLP, for a failure the hand has no part in."""
    problem = run.problem
    if failed.narrowed or not failed.keyframes.q or not narrows(problem, failed.choices):
        return False
    narrow = with_hand(problem, failed.choices)
    vals = failed.keyframes.blocks()
    total = [_total_violation(keyframe_rows(at, vals, failed.choices, run.kin, checker,
                                            run.start, anchors=run.anchors))
             for at, checker in ((problem, run.checker), (narrow, narrow.checker))]
    return total[1] < total[0] - FEASIBILITY


def _closing(run: Run, failed: TrajectoryResult) -> bool:
    """Whether the open hand's keyframes failed only where the fingers close through
    something (closing.closing_blocked): narrowed to the grips, the keyframe NLP's
    collision rows keep the fingers' closed side clear too."""
    return not failed.narrowed and CLOSING in (failed.worst_constraint or "") \
        and narrows(run.problem, failed.choices)


def _total_violation(rows) -> float:
    """The rows' violations summed (m and rad)."""
    eq = np.concatenate(rows.eq.values) if rows.eq.values else np.zeros(0)
    ineq = np.concatenate(rows.ineq.values) if rows.ineq.values else np.zeros(0)
    return float(np.abs(eq).sum() + np.maximum(-ineq, 0.0).sum())


def reach(run: Run, warm) -> TrajectoryResult:
    """The keyframe NLP with collisions dropped: grasps, placements, regions and joint
    limits only. Its evaluations cost a tenth of the keyframe NLP's (no distance
    queries), and its cost, a local optimum of a relaxation, is the bound that prunes
    a skeleton before the keyframe NLP is paid for (arm-kitchen: skeletons with a
    detour through another region, 0.08 s instead of 2 s each)."""
    return keyframes_with(run, warm, collisions=False)


def keyframes_with(run: Run, warm, grips: dict[int, float] | None = None,
                    placements: dict | None = None, collisions: bool = True,
                    retries: bool = True, narrow: bool | None = None,
                    tight: bool | None = None) -> TrajectoryResult:
    """`grips`: step -> a grip parameter the NLP keeps (the NLP's choice otherwise);
    `placements`: the final stage's values to use (solved from scratch otherwise);
    `collisions`: False for the relaxation (`reach`); `retries`: False for one NLP
    from the guess (no jittered guess and, unless `tight`, no `tight_margin`);
    `narrow`: the hand narrowed to the grips chosen (hand.with_hand), open when False,
    as the warm start's prefix had it when None."""
    problem = run.problem
    if narrow is None:
        narrow = _shares_prefix(problem, warm) and warm.narrowed
    far = beyond_reach(problem)
    if far:
        why, impossible = far
        return run.result("infeasible", worst_constraint=why, proved=True, violation=math.inf,
                          impossible=impossible)
    have = warm is not None and warm.placements and all(
        s.index in warm.placements for s in problem.steps if s.kind.places)
    if placements is not None:
        final_kkt = None
    elif have and warm.names == problem.names:
        placements, final_kkt = warm.placements, warm.kkt.final
    else:
        out, placements = solve_placements(run)
        if out is not None and out.status != "solved":
            return run.result(out.status, violation=out.violation,
                              worst_constraint=f"placements: {out.worst}")
        final_kkt = None if out is None else out.kkt
    layout = keyframe_layout(problem)
    if layout.size == 0:  # symbolic actions only: nothing moves
        return run.result("solved", cost=0.0, placements=placements,
                          kkt=KktStages(final=final_kkt))
    world = problem.world
    bounds = []
    joints = {keyframe_block(k) for k in range(problem.n_keyframes)}
    fixed = {grip_block(s): t for s, t in (grips or {}).items()}
    for name, _size in layout.blocks:
        if name in joints:
            bounds.extend(zip(world.lower, world.upper, strict=True))
        elif name in fixed:
            bounds.append((fixed[name] - FIXED_GRIP, fixed[name] + FIXED_GRIP))
        else:
            bounds.append((-GRIP_BOUND, GRIP_BOUND))
    best = None
    # A planar skeleton's third try ranks the place's faces by how deep within the
    # margin the disk stands (init.GuessWalk.graded); its failure is not reported, so
    # a skeleton the first two tries fail on fails as it did (what the search learns
    # from it unchanged: blind18 p04's corridor loses its answer otherwise).
    attempts = (2 + problem.planar) if retries else 1
    for attempt in range(attempts):  # each ends the loop once solved or out of time
        guess, choices = keyframe_guess(problem, placements, run.start, run.rng,
                                        jitter=RETRY_JITTER if attempt == 1 else 0.0,
                                        graded=attempt == 2)
        if attempt == 0 and _shares_prefix(problem, warm):
            choices.update(warm.choices)
            guess = guess.warmed(warm.keyframes)
        if grips:
            guess = Keyframes(guess.q, {**guess.grip, **grips})

        at = with_hand(problem, choices) if narrow and collisions else problem
        checker = run.checker if at is problem else at.checker

        def evaluate(x, choices=choices, at=at, checker=checker):
            return keyframe_rows(at, layout.unpack(x), choices, run.kin, checker,
                                 run.start, collisions=collisions, anchors=run.anchors)

        out = run.nlp(evaluate, layout, layout.pack(guess.blocks()), bounds)
        if attempt == 2 and out.status != "solved" and collisions:
            out = _tight_keyframes(run, layout, bounds, out, choices, at, checker)
        if best is None or (out.status == "solved") or (
                attempt < 2 and out.violation < best[0].violation):
            best = (out, choices, at, checker)
        if out.status == "solved" or time.perf_counter() > run.deadline:
            break
    out, choices, at, checker = best
    if tight is None:
        tight = retries
    if out.status != "solved" and collisions and tight and time.perf_counter() < run.deadline:
        out = _tight_keyframes(run, layout, bounds, out, choices, at, checker)
    if out.status == "solved" and collisions and into_support(run, layout, out, choices, at,
                                                              checker):
        out = with_supports(run, layout, bounds, out, choices, at, checker)
    kf = Keyframes.from_blocks(layout.unpack(out.x), problem.n_keyframes, problem.grip_params)
    T = problem.options.waypoints
    phase_costs = kf.least_costs(run.start, T)
    common = dict(keyframes=kf, choices=choices, placements=placements,
                  narrowed=at is not problem)
    if out.status != "solved":
        return run.result(out.status, violation=out.violation, worst_constraint=out.worst,
                          **common)
    blocked = closing_blocked(at, kf, choices, run.start) if collisions else None
    if blocked:
        return run.result("infeasible", violation=math.inf, worst_constraint=blocked, **common)
    if out.stopped == "time":
        # Feasible but far from converged: its cost would be a meaningless bound.
        return run.result("limit", violation=out.violation, worst_constraint="time limit "
                          "reached before the keyframe NLP converged", **common)
    return run.result("solved", cost=out.cost, phase_costs=phase_costs,
                      violation=out.violation,
                      kkt=KktStages(final_kkt, out.kkt if collisions else None), **common)


def _tight_keyframes(run: Run, layout, bounds, out, choices, at, checker):
    """The keyframe NLP again with `tight_margin`, from where it failed; `out` when
    that fails too. Whatever the row it failed on: a margin row held at the margin
    can block another (blind2 p07: a level hand 1 cm short of the garage region,
    held off the roof's edge), and the margin must never turn a feasible problem
    infeasible."""
    opts = at.options
    if opts.tight_margin >= opts.margin:
        return out
    tight = at.at_margin(opts.tight_margin)

    def evaluate(x):
        return keyframe_rows(tight, layout.unpack(x), choices, run.kin, checker, run.start,
                             anchors=run.anchors)

    retry = run.nlp(evaluate, layout, out.x, bounds)
    return retry if retry.status == "solved" or retry.violation < out.violation else out


def face_grips(problem, kfr):
    """Other planar suction grips, kept fixed: the rim at the middle of each face.

    The keyframe NLP takes the cheapest contact angle near its guess; a carry through a
    passage may need the object in line with the disk (robust-planar p03: beside
    it, disk and block span 18 cm of an 11 cm doorway), which only the path
    stage finds out. Nearest faces first; the face the angle is at already is
    not tried again.
    """
    sides = _face_angles(problem, kfr)
    for j in range(4):
        grips = {i: faces[j] for i, faces in sides.items()}
        if grips and any(abs(f - kfr.keyframes.grip[i]) > FACE_SAME for i, f in grips.items()):
            yield grips


def carry_faces(problem, kfr, failed_step: int) -> list[dict]:
    """The planar suction grips of `kfr` (keyframes solved) with only the grip held in
    the motion into step `failed_step` moved to another face's middle, nearest first,
    the others kept where the keyframes have them: the carry that failed is what a
    face changes (blind8 p04: a plug held off the middle of its east face could not
    pass its doorway; face_grips turns every grip at once, and with the crates'
    grips turned too no keyframes were found)."""
    sides = _face_angles(problem, kfr)
    held = [i for i in kfr.keyframes.grip if i < failed_step]  # the carry's: the last
    if not held or max(held) not in sides:  # a drum has no faces to turn to
        return []
    s = max(held)
    kept = {i: kfr.keyframes.grip[i] for i in sides}
    # The nearest face is the one the grip is on, at its middle or not (blind27 p04: a
    # box held 5 deg off its side's middle, that side tried again: 13 s for nothing).
    return [{**kept, s: f} for f in sides[s][1:]]


def _face_angles(problem, kfr) -> dict[int, list[float]]:
    """Per planar suction grip of `kfr`, its four faces' middles (contact angles), the
    nearest the keyframes' angle first."""
    steps = {s.index: s for s in problem.steps}
    sides = {}
    if not kfr.keyframes:
        return sides
    for index, t in kfr.keyframes.grip.items():
        grip = grip_of(problem, steps[index], kfr.choices)
        if isinstance(grip, SideGrip) and grip.half is not None:
            faces = [t + _wrap(grip.yaw + j * math.pi / 2 - t) for j in range(4)]
            sides[index] = sorted(faces, key=lambda f, t=t: abs(f - t))
    return sides


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi
