"""The path stage of one skeleton: one NLP per motion through the keyframes,
judged by `verify` at 10x; objects set down in a later motion's way moved
(relocate); the planar suction grips tried at each face."""

from __future__ import annotations

import dataclasses
import math
import time

from tampcli.optimize import relocate
from tampcli.optimize import verify as verify_mod
from tampcli.optimize.assemble import assemble, walk
from tampcli.optimize.closing import CLOSING
from tampcli.optimize.grasp_report import grasp_report
from tampcli.optimize.hand import finger_columns, with_hand
from tampcli.optimize.keyframe_stage import (
    FACE_SAME,
    carry_faces,
    face_grips,
    keyframes,
    keyframes_with,
    solve_placements,
)
from tampcli.optimize.kkt import combined
from tampcli.optimize.motion import passable, solve_motion
from tampcli.optimize.planar_motion import held_blocks
from tampcli.optimize.result import TrajectoryResult
from tampcli.optimize.run import Run
from tampcli.optimize.values import Keyframes

# Path solves per skeleton that `verify` judges: each round after the first samples the
# failing motions twice as finely (3, 7, 15 points a segment by default); a motion that
# ends in a narrow slot can dip into a wall between 7.
VERIFY_ROUNDS = 3
DETOUR = 2.0  # a motion sampled finer that costs this many times more is solved afresh too


def path(run: Run, warm) -> TrajectoryResult:
    problem = run.problem
    answer = None  # a longer skeleton's path whose first motions are this one's
    if (warm is not None and warm.solved and warm.stage in ("keyframes", "path")
            and warm.names == problem.names and warm.keyframes):
        kfr = warm
        if len(warm.keyframes) > problem.n_keyframes:  # the answer's, cut (eliminate.py)
            kfr = answer = _cut(warm, problem)
    else:
        run.stage = "keyframes"
        kfr = keyframes(run, warm)
        run.stage = "path"
        if not kfr.solved:
            return run.result(kfr.status, violation=kfr.violation,
                              worst_constraint=kfr.worst_constraint, proved=kfr.proved)
    # A suction grip off a face's middle first gets that face (a carry in line with
    # the disk), then the NLP's own angle, then the other faces.
    faces = list(face_grips(problem, kfr))
    result = last = None
    run.in_the_way = ()
    # The answer's own grips first, its motions known to pass.
    order = [None] + faces if answer is not None else faces[:1] + [None] + faces[1:]
    order = [(grips, kfr if grips is None else None) for grips in order]
    if answer is None and problem.planar and faces:
        order = _passable_first(run, warm, order, kfr.narrowed)
    carried: set[int] = set()  # the steps whose carry's faces were queued alone
    tried: set[frozenset] = set()  # the grips whose path was solved
    cut = False  # grips left untried at the stage's time limit
    while order:
        grips, start = order.pop(0)
        if result is not None and (result.solved or result.status == "bounded"
                                   or _robot_in_the_way(run)):
            break
        if result is not None and time.perf_counter() > run.deadline:
            cut = True
            break
        if grips is not None and (_before_the_grips(last, grips)
                                  or _after_the_grips(problem, last, grips)):
            continue
        if grips is None and start is not None and start.solved \
                and _after_the_grips(problem, last, start.keyframes.grip):
            continue  # the NLP's own grips: as any other
        if start is None:
            run.stage = "keyframes"
            start = _face_keyframes(run, warm, grips, first=result is None, narrow=kfr.narrowed)
            run.stage = "path"
        if start.solved:
            key = _grip_key(start.keyframes.grip)
            if key in tried:  # a face queued again whose keyframes came out the same
                continue
            tried.add(key)
            last = _relocated(run, warm, grips, start, path_through(run, start))
            result = last if result is None or last.solved or _deeper(last, result) \
                else result
            if problem.planar and not last.solved and last.failed_actions:
                _carry_faces_next(order, 0, carried, problem, start, last.failed_actions - 1)
    if result is not None and not result.solved and result.status == "infeasible" and (
            cut or last.status == "limit"):
        # The stage's time ran out before every grip was tried (blind33 p02: the first
        # face's carry failed, the others took the rest of the 30 s): a limit, which
        # proves nothing and forbids no prefix, whatever the first grip's failure says.
        result = dataclasses.replace(result, status="limit")
    return result


def _carry_faces_next(order: list, at: int, carried: set, problem, start, step: int) -> None:
    """Into `order` at `at`, once per step: the carry into `step` on the other faces
    of what it holds, the other grips where the keyframes `start` have them
    (keyframe_stage.carry_faces), before the orders that turn every grip at once."""
    if step not in carried:
        carried.add(step)
        order[at:at] = [(g, None) for g in carry_faces(problem, start, step)]


SCREEN_SHARE = 0.2  # of the path stage's time left, at most, for _passable_first's look


def _passable_first(run: Run, warm, order, narrow: bool):
    """`order`, (grips, keyframes or None) pairs, with the first whose every carry is
    passable (motion.passable: a straight line or a grid route) moved to the front,
    the keyframes solved for the look kept. A grip whose carry has neither is tried
    after: its sampler's long search (a fourth of the stage, then the look for a body
    in the way) is for when no grip has a route (robust-planar p03: a doorway with
    5 mm a side, which only the sampler finds). The look goes on past the first grip
    only where what is held blocks its carry (planar_motion.held_blocks: blind19 p04's
    door blocked by a puck looks no further), the carry that stopped it looked at
    first, from the grips that left the fewest carries blocked so far, and ends at
    SCREEN_SHARE of the time left (robust-planar pen-k4: its other
    faces' keyframes, 3 s on a slow machine, left the relocation that solves it short
    of time)."""
    until = time.perf_counter() + SCREEN_SHARE * (run.deadline - time.perf_counter())
    order = list(order)
    looked, stopped, carried, fewest, seen = [], None, set(), math.inf, set()
    while len(looked) < len(order):
        grips, start = order[len(looked)]
        if time.perf_counter() > until:
            break
        if grips is not None:
            key = _grip_key(grips)
            if key in seen:  # queued again from another start: looked at already
                del order[len(looked)]
                continue
            seen.add(key)
        if start is None:
            run.stage = "keyframes"
            start = _face_keyframes(run, warm, grips, first=True, narrow=narrow,
                                    fresh=bool(looked))
            run.stage = "path"
        # A grip's keyframes unsolved here are solved again in turn, with retries.
        looked.append((grips, start if start.solved else None))
        if not start.solved:
            continue
        # The carries a grip decides: a push's motion goes where its face says, whatever
        # the grips (blind27 p04: a crate's push looked at first ended the look before
        # the box carried through the door was).
        carries = sorted((ctx for ctx in walk(run.problem, start.keyframes, start.choices,
                                              run.start)
                          if ctx.held is not None
                          and not run.problem.motions[ctx.index].pushes),
                         key=lambda ctx: ctx.index != stopped)
        blocked = [ctx for ctx in carries if not passable(run, ctx)]
        if not blocked:
            return [looked[-1]] + looked[:-1] + order[len(looked):]
        by_held = [ctx for ctx in blocked if held_blocks(run, ctx)]
        if not by_held or by_held[0] is not blocked[0]:
            if stopped is None:
                break
            continue
        stopped = blocked[0].index if stopped is None else stopped
        if len(blocked) <= fewest:
            # A grip that frees one carry is where the others' faces are turned from
            # (blind27 p04: each box through the door needs its own face; turned one
            # at a time from the keyframes' grips, the pair was never looked at).
            fewest, carried = len(blocked), set()
        for ctx in by_held:  # each looked at next on its other faces
            _carry_faces_next(order, len(looked), carried, run.problem, start,
                              run.problem.step_of_keyframe(ctx.index).index)
    return looked + order[len(looked):]


def _grip_key(grips: dict) -> frozenset:
    """The faces `grips` holds at, a full turn apart or not (0 and 360 degrees)."""
    return frozenset((i, round(math.remainder(t, 2 * math.pi), 3)) for i, t in grips.items())


def _cut(longer: TrajectoryResult, problem) -> TrajectoryResult:
    """A longer skeleton's solved path as the warm start of its prefix `problem`: its
    keyframes, grips and motions up to the prefix's last (action elimination dropping
    the answer's last actions: its motions pass again as they are)."""
    n, steps = problem.n_keyframes, len(problem.steps)
    kf = longer.keyframes
    return dataclasses.replace(
        longer, keyframes=Keyframes(kf.q[:n], {s: t for s, t in kf.grip.items() if s < steps}),
        choices={s: c for s, c in longer.choices.items() if s < steps},
        motions={k: w for k, w in longer.motions.items() if k < n})


def _robot_in_the_way(run: Run) -> bool:
    """Whether the last motion to fail was blocked by a body the skeleton never moved,
    against the robot itself (relocate.in_the_way), or against what it holds where the
    planar robot alone has no route either (motion.py): no other face of what it
    carries makes room there (blind15 p06: a crate in a corridor, 4 s a face; blind19
    p04: a puck in the only doorway, 19 s for the other faces)."""
    return bool(run.in_the_way) and (
        run.blocked_alone or any(part.startswith("link:") for _, part in run.in_the_way))


def _deeper(failed, than) -> bool:
    """Whether the path `failed` got past more actions than the failed path `than`: the
    skeleton's failure is then the deeper one, whose prefix is forbidden and whose
    body in the way is learned (blind25 p02: the pick's first face, between two
    crates, unreachable; its west face passed, and the parking after it was blocked
    by the second crate; reported at the first face, every skeleton starting with
    that pick was forbidden, the answer among them)."""
    a, b = failed.failed_actions, than.failed_actions
    return a is not None and (b is None or a > b)


def _before_the_grips(failed, grips) -> bool:
    """Whether the last path failed on a motion into a step before every grasp whose
    grip `grips` would change: another face there leaves that motion's ends where
    they were (gen1 planar-s02: whole paths solved again per face, about 45 s)."""
    if failed is None or failed.failed_actions is None:
        return False
    return failed.failed_actions - 1 < min(grips)


def _after_the_grips(problem, failed, grips) -> bool:
    """Whether the last path failed on a motion after the retreat from the place of
    every grip `grips` turns (against the failed path's own): those motions' ends stay
    where they were (blind27 p04: a push of b2 into a wall, then the faces of b1, put
    down two actions before, tried for 28 s)."""
    if failed is None or failed.failed_actions is None or not failed.keyframes:
        return False
    held = failed.keyframes.grip
    turned = [i for i, t in grips.items()
              if i in held and abs(math.remainder(t - held[i], 2 * math.pi)) > FACE_SAME]
    if not turned:
        return False
    step = failed.failed_actions - 1
    ends = {s.grasp_step: s.index for s in problem.steps
            if s.kind.places and s.grasp_step is not None}
    return all(i in ends and step > ends[i] + 1 for i in turned)


def _face_keyframes(run: Run, warm, grips, first: bool, narrow: bool, fresh: bool = False):
    """The keyframes with the planar suction grips kept at `grips`. A face tried first
    is a guess worth one NLP, where it fails the NLP's own angle comes next
    (planar-tamp p01: 0.8 s of retries for nothing); and only where it is reachable
    at all: the keyframe NLP without collisions (a tenth of the cost) first, whose
    answer it then starts from (planar-tamp p01: a face the disk cannot reach took
    26 iterations, 0.37 s, to fail; its relaxation fails in 0.03 s). `fresh`: where
    the relaxation fails from the warm start, from a fresh guess too (the screening's
    turned faces)."""
    if not first:
        return keyframes_with(run, warm, grips, narrow=narrow)
    probe = keyframes_with(run, warm, grips, collisions=False, retries=False)
    if not probe.solved and warm is not None and fresh:
        # From the warm start's configurations, held at the old faces, SLSQP can stall
        # with the grips fixed (blind27 p04: 'tool off the contact pose by 6.4 cm' at a
        # face the fresh guess reaches at once).
        probe = keyframes_with(run, None, grips, collisions=False, retries=False)
    if not probe.solved:
        return probe
    return keyframes_with(run, probe, grips, retries=False, narrow=narrow, tight=True)


RELOCATIONS = 2  # rounds of objects moved out of a failed motion's way, per grip choice


def _relocated(run: Run, warm, grips, kfr, found: TrajectoryResult) -> TrajectoryResult:
    """`found`, or where its motion failed for an object this skeleton set down in
    the way (relocate), the path through placements moved clear of it."""
    for _ in range(RELOCATIONS):
        obstruction, run.obstruction = run.obstruction, None
        if found.solved or obstruction is None or time.perf_counter() > run.deadline:
            return found
        for move in relocate.relocations(run, obstruction, kfr.placements):
            out, placements = solve_placements(run, move.origins, kfr.placements)
            if out.status != "solved" or not relocate.still_clear(run, obstruction, placements):
                continue
            run.stage, run.anchors = "keyframes", move.anchors
            again = keyframes_with(run, warm, grips, placements, narrow=kfr.narrowed)
            run.stage, run.anchors = "path", None
            if again.solved:
                kfr, found = again, path_through(run, again)
                break
        else:
            return found
    run.obstruction = None
    return found


def path_through(run: Run, kfr) -> TrajectoryResult:
    """The path stage through the keyframes of `kfr` (solved), the hand as they were
    solved with: open, or narrowed to their grips (hand.with_hand)."""
    base = run.problem
    run.problem = with_hand(base, kfr.choices) if kfr.narrowed else base
    run.checker = run.problem.checker
    try:
        return _path_through(run, kfr)
    finally:
        run.problem, run.checker = base, base.checker


def _path_through(run: Run, kfr) -> TrajectoryResult:
    problem = run.problem
    kf, choices = kfr.keyframes, kfr.choices
    contexts = walk(problem, kf, choices, run.start)
    opts = problem.options
    T = opts.waypoints
    waypoints, kkts = {}, {}
    checks = opts.interpolation_checks
    failing: set[int] = set()
    # Motions solved so far, and the least cost through the keyframes of the rest: a
    # bound on the path's cost, the keyframes being fixed.
    least = list(kf.least_costs(run.start, T))
    costs: dict[int, float] = {}
    for attempt in range(VERIFY_ROUNDS):
        for ctx in contexts:
            if attempt and ctx.index not in failing:
                continue
            # A motion sampled finer starts from its last solution (collision-free at
            # the coarser samples), not from scratch.
            out = solve_motion(run, ctx, T, checks, _phase_label(problem, ctx.index),
                               warm=waypoints.get(ctx.index, kfr.motions.get(ctx.index)))
            if attempt and out.status == "solved" and out.cost > DETOUR * costs[ctx.index] \
                    and time.perf_counter() < run.deadline:
                # Sampled finer, the motion's warm start can only stay feasible by a long
                # detour (blind3 p06: a hand entering under a shelf, 1.2 -> 4.6 -> 18.7
                # rad^2); from scratch, at this resolution, it may not need one.
                cold = solve_motion(run, ctx, T, checks, _phase_label(problem, ctx.index))
                if cold.status == "solved" and cold.cost < out.cost:
                    out = cold
            if out.status != "solved":
                label = _phase_label(problem, ctx.index)
                return run.result(out.status, violation=out.violation,
                                  worst_constraint=out.worst or label, keyframes=kf,
                                  choices=choices, placements=kfr.placements,
                                  failed_actions=problem.step_of_keyframe(ctx.index).index + 1)
            waypoints[ctx.index] = out.x.reshape(-1, problem.n)
            kkts[ctx.index] = out.kkt
            costs[ctx.index] = out.cost
            if attempt == 0 and run.cutoff is not None:
                least[ctx.index] = out.cost
                bound = sum(least)
                if bound >= run.cutoff:
                    return run.result(
                        "bounded", cost=bound, keyframes=kf, choices=choices,
                        placements=kfr.placements,
                        worst_constraint=f"path bound {bound:.4g} after "
                        f"{_phase_label(problem, ctx.index)}")
        traj, phases, poses, grasps, events = assemble(problem, run.start, waypoints,
                                                       contexts)
        # Each motion's cost as its NLP weighed it (path.phase_rows_fn: T_k / T times its
        # segments' sum, the vertical ends of approach.py included), not the plain sum
        # over the trajectory: a motion on more segments would look cheaper.
        phase_costs = tuple(costs[k] for k in range(problem.n_keyframes))
        result = run.result("solved", cost=float(sum(phase_costs)), phase_costs=phase_costs,
                            kkt=dataclasses.replace(kfr.kkt, path=combined(kkts.values())),
                            trajectory=traj, fingers=finger_columns(problem, events, choices,
                                                                    len(traj)),
                            grasp_report=grasp_report(problem, choices, kf),
                            phases=phases, object_poses=poses, keyframes=kf, choices=choices,
                            placements=kfr.placements, grasps=grasps,
                            motions=dict(waypoints))
        # Judged with the fingers as the solution gives them (closed on what is held).
        problems = verify_mod.verify(problem, result, fingers=result.fingers)
        if not problems:
            return result
        if all(CLOSING in p for p in problems):
            break  # at the keyframes, which finer motions leave as they are
        # A collision between the sample points: sample the failing phases finer.
        failing.clear()
        failing.update({i for i, _ in verify_mod.failing_motions(problem, result,
                                                                 fingers=result.fingers)}
                       or range(problem.n_keyframes))
        checks = 2 * checks + 1
        if time.perf_counter() > run.deadline:
            break
    return run.result("infeasible", violation=math.inf, worst_constraint=problems[0],
                      keyframes=kf, choices=choices, placements=kfr.placements)


def _phase_label(problem, k) -> str:
    return f"motion {k} before {problem.step_of_keyframe(k).name}"
