"""One motion's path NLP (its keyframes fixed): the margin schedule, its starts, and
the points between waypoints added lazily.

`run` is the solve's bookkeeping (run.Run): the problem, its deadline, the
checker and kinematics, and `path_nlp` (one counted solve by the options' backend).
"""

from __future__ import annotations

import dataclasses
import math
import time

import numpy as np

from tampcli.geometry.sampled_path import resample, sampled_path
from tampcli.optimize import planar_motion, relocate
from tampcli.optimize.approach import joined
from tampcli.optimize.axial_start import axial_start
from tampcli.optimize.collide import held_spec
from tampcli.optimize.hand import narrowed
from tampcli.optimize.nlp import FEASIBILITY, nlp_feasible, outcome_of
from tampcli.optimize.path import (
    allowed_contacts,
    motion_margins,
    phase_rows_fn,
    sample_clearance,
    via_points,
)
from tampcli.optimize.retreat import straight_ends

LAZY_BAND = 0.01  # m: a point between waypoints this close to its limit gets its rows
LAZY_ROUNDS = 3
SEED_BAND = 0.03  # m: a point between waypoints this close at the start has rows from the first solve
# Of a motion's sampling budget: the first try with everything in place, and (where it
# fails) as much again with the objects this skeleton moved left out (relocate.find);
# the rest for everything in place again.
FIRST_SHARE = 0.25
MAX_SEGMENTS_RATIO = 4  # a motion's segments at most, as a multiple of `waypoints`


def solve_motion(run, ctx, T: int, checks: int, label: str, warm=None):
    """One motion's path (`_solve_motion`); a carry that takes an object from, or sets
    it down among, close neighbours solved between the tops of its vertical ends
    (approach.py; the planar disk's: straight ends in the plane, planar_approach.py),
    the ends joined to it. `warm`, as this returns it, ends included."""
    problem = run.problem
    climb, descent = straight_ends(problem, problem.motions[ctx.index], ctx, run.checker)
    if climb is None and descent is None:
        return _solve_motion(run, ctx, T, checks, label, warm)
    first = climb.rungs if climb is not None else 0
    last = descent.rungs if descent is not None else 0
    if warm is not None:
        warm = np.asarray(warm).reshape(-1, problem.n)
        warm = warm[first:len(warm) - last]
    inner = dataclasses.replace(ctx, q_a=climb.qs[-1] if climb is not None else ctx.q_a,
                                q_b=descent.qs[-1] if descent is not None else ctx.q_b)
    out = _solve_motion(run, inner, T, checks, label,
                        warm if warm is not None and len(warm) else None)
    if out.status != "solved":
        return out
    segments = len(out.x) // problem.n + 1
    return joined(out, climb, descent, ctx.q_a, ctx.q_b, segments / problem.options.waypoints)


def _solve_motion(run, ctx, T: int, checks: int, label: str, warm=None):
    """One motion's path NLP under the margin schedule.

    From the via-point start (the planar robot's: its grid route, planar_route.py)
    with the options' margin; where that fails, from
    a sampled path (RRT-Connect over the same collision model, which finds
    passages the NLP's gradients cannot: pushed against both walls at once it
    stalls), first with the margin, then with `tight_margin`, so a passage
    narrower than twice the margin is still passed. The zero-margin check at
    10x (`verify`) judges what comes out. Returns the first solved outcome, or
    the last failure, its x the (T_k - 1) * n interior waypoints of the T_k segments
    used: T, or more from a sampled path with more corners (`segments_for`). `warm`:
    interior waypoints (T_k - 1, n) of an earlier solve of this motion, tried first
    (with the tight margin too: it solved with one of them).
    """
    problem = run.problem
    opts = problem.options
    run.in_the_way, run.blocked_alone = (), False  # this motion's own findings only
    line, line_violation = _straight_line(run, ctx, T, checks, label)
    if line_violation <= FEASIBILITY:
        return line
    held_height = 0.0
    if ctx.held is not None:
        held_height = 2 * problem.bodies[ctx.held.name].half[2]
    if warm is not None:
        warm = np.asarray(warm)
        for margin in (opts.margin, opts.tight_margin):
            out = _solve_phase(run, ctx, len(warm) + 1, checks, label, warm.reshape(-1), margin)
            if out.status == "solved" or time.perf_counter() > run.deadline:
                return out
    margin = opts.margin  # the first start's
    if problem.motions[ctx.index].pushes:
        # A push slides along its support in a straight line (a bend would be a drag):
        # no lift above the obstacles, no detour around the object it pushes.
        x0 = _straight_push(problem, ctx.q_a, ctx.q_b, T).reshape(-1)
    elif line_violation < opts.margin:
        # The line touches nothing, it is only nearer than the margin somewhere: a
        # start closer to the optimum than a lift over everything (arm-kitchen's
        # motions: 2 or 3 SLSQP iterations from it, 11 to 14 from the lift).
        x0 = line.x
    elif problem.planar and (route := planar_motion.route(run, ctx)) is not None:
        # The plane's grid route, clear of the walls with the margin, however many it
        # turns around; its segments no longer than the disk is wide.
        T = planar_segments(route.points, T, problem.scene.robot.radius)
        x0 = resample(route.points, T + 1)[1:-1].reshape(-1)
        if route.least < opts.margin:
            # Its passage is narrower than twice the margin, which no path through it
            # keeps (robust-planar p03: a doorway with 5 mm a side; from the margin,
            # then from a sampled path, 3 s lost).
            margin = opts.tight_margin
    else:
        x0 = via_points(problem, ctx.q_a, ctx.q_b, T, held_height, ctx.moved,
                        run.rng, ctx.held).reshape(-1)
    out = _solve_phase(run, ctx, T, checks, label, x0, margin)
    if out.status == "solved" or time.perf_counter() > run.deadline:
        return out
    if problem.motions[ctx.index].pushes:
        # A push is straight: a sampled detour is no start for it.
        out = _solve_phase(run, ctx, T, checks, label, x0, opts.tight_margin)
        return out if out.status == "solved" else _clear_anyway(run, ctx, T, checks, label, out)
    axial = axial_start(run, ctx, T)
    if axial is not None:
        # In and out along the approach axis: an enclosure's only way (axial_start.py).
        again = _solve_phase(run, ctx, T, checks, label, axial, margin)
        if again.status == "solved" or time.perf_counter() > run.deadline:
            return again
    # The plane's grid proves there is no path at all (the bodies where they are): no
    # sampling (blind33 p02: 23 s of it for a bar held across a door, the other grips
    # then cut off by the stage's time).
    blocked = planar_motion.separated(run, ctx)
    sampled = None if blocked else _sampled_start(run, ctx, FIRST_SHARE)
    if sampled is None:
        # No path past the objects this skeleton set down earlier: is one of them in
        # the way (the caller then moves it), or is the passage just hard to find?
        run.obstruction = relocate.find(run, ctx, run.sampling(FIRST_SHARE))
        if run.obstruction is not None:
            return out
    if sampled is None and problem.planar and (around := planar_motion.route_around(run, ctx)) is not None:
        # The plane's grid has a route only with the bodies at rest left out: one of them
        # is in the way, and its name is what the search learns from; the long sampling
        # below would most likely end the same (blind19 p04: the puck in the only
        # doorway, 15 s of sampling, then the same body named).
        run.in_the_way = relocate.in_the_way(run, ctx, run.sampling(FIRST_SHARE),
                                             around.points)
        run.blocked_alone = ctx.held is not None and not planar_motion.held_blocks(run, ctx)
    if sampled is None and not run.in_the_way and not blocked:
        # Its time ends early enough for the pass below (a fourth of what is left) on a
        # machine too slow for the checks budgeted: cut off at the stage's limit, a
        # blocked motion would fail naming the wall, not the body.
        sampled = _sampled_start(run, ctx, 1.0 - FIRST_SHARE, time.perf_counter()
                                 + (1.0 - FIRST_SHARE) * (run.deadline - time.perf_counter()))
        if sampled is None:
            # Or is a body the skeleton never moved in the way? If the motion fails, its
            # failure names that body, not the wall beside it (blind15 p06: a crate in
            # the only corridor), and the skeletons that move it first come next.
            run.in_the_way = relocate.in_the_way(run, ctx, run.sampling(FIRST_SHARE))
    if sampled is None:
        tries = [(x0, opts.tight_margin)] if margin != opts.tight_margin else []
    else:
        # A sampled path with more corners than the motion has waypoints would be cut
        # short between them, through the walls it went around (blind7 p03: a maze's
        # 12 corners on 10 segments): the motion gets the segments its path needs.
        T = (planar_segments(sampled, T, problem.scene.robot.radius) if problem.planar
             else segments_for(sampled, T))
        sampled = resample(sampled, T + 1)[1:-1].reshape(-1)
        tries = [(sampled, m) for m in dict.fromkeys((margin, opts.tight_margin))]
    for start, again in tries:
        out = _solve_phase(run, ctx, T, checks, label, start, again)
        if out.status == "solved" or time.perf_counter() > run.deadline:
            return out
    out = _clear_anyway(run, ctx, T, checks, label, out)
    return _blocked(out, label, run.in_the_way) if out.status != "solved" \
        and run.in_the_way else out


IN_THE_WAY = "in the way of every path found"  # the end of a `_blocked` row's words


def _blocked(out, label: str, blocking):
    """`out` failed, its worst row the first body in the way: (body, robot part)."""
    (body, part), *others = blocking
    part = part.partition(":")[2] or part
    more = f" (and {', '.join(b for b, _ in others)})" if others else ""
    return dataclasses.replace(
        out, status="infeasible",
        worst=f"{label}: collision {part} vs {body}{more}: {IN_THE_WAY} "
              "(one was found with it out of the way)")


def segments_for(path: np.ndarray, T: int) -> int:
    """Segments of a motion started from the sampled `path` (K vertices): T, or where
    the path has more corners, twice its K - 1 edges (room to spread the steps along
    its long edges), at most MAX_SEGMENTS_RATIO * T unless its edges alone need more."""
    edges = len(path) - 1
    if edges <= T:
        return T
    return max(edges, min(2 * edges, MAX_SEGMENTS_RATIO * T))


def planar_segments(path: np.ndarray, T: int, radius: float) -> int:
    """Segments of a planar motion started from `path`: `segments_for`'s, and at least
    as many as make each no longer than the disk's diameter (up to MAX_SEGMENTS_RATIO
    * T). Waypoints 30 cm apart at a wall's end let SLSQP's first steps carry the
    sample points between them through it (gen1 planar-s02: a 2.9 m carry round two
    partitions on 10 segments failed from a valid start, on 30 solved)."""
    length = float(np.sum(np.linalg.norm(np.diff(path, axis=0), axis=1)))
    wide = min(math.ceil(length / (2.0 * radius)), MAX_SEGMENTS_RATIO * T)
    return max(segments_for(path, T), wide)


def passable(run, ctx) -> bool:
    """Whether the planar motion `ctx` has a start the NLP solves from at once: its
    straight line within the margin of everything, or the grid route round what is
    in the way. Where neither is, only the sampler may find a passage (a narrow one),
    and a path of every grip tried may be there is none (blind19 p04: an 18 cm bar held
    side-on, 14 cm with the disk, at a 12.4 cm doorway, 28 s of sampling)."""
    opts = run.problem.options
    _, violation = _straight_line(run, ctx, opts.waypoints, opts.interpolation_checks,
                                  "a passage check")
    return violation < opts.margin or planar_motion.route(run, ctx) is not None


def _margins(run, ctx, margin: float, tight: float):
    """path.motion_margins of the motion `ctx`, its straddle rule with a narrowed hand."""
    return motion_margins(run.checker, run.problem.motions[ctx.index], ctx.q_a, ctx.q_b,
                          ctx.held, ctx.moved, margin, tight, straddle=narrowed(run.problem.hand))


def _straight_line(run, ctx, T: int, checks: int, label: str):
    """(outcome, violation) of the straight joint-space line at even steps, with the
    margin, at every sample point. Solved when feasible: its cost, sum |dq|^2, is
    then the least any path has, |q_b - q_a|^2 / T (Cauchy-Schwarz), which the NLP
    could only find again, or a worse local optimum from a start lifted over the
    obstacles (arm-kitchen: 3 of its 8 motions). (None, inf) for a push, whose line
    is the tool's (_straight_push)."""
    problem = run.problem
    m = problem.motions[ctx.index]
    if m.pushes:
        return None, np.inf
    margin = problem.options.margin
    own = _margins(run, ctx, margin, min(margin, problem.options.tight_margin))
    rows, layout = phase_rows_fn(problem, m, ctx.q_a, ctx.q_b, ctx.held, ctx.moved, run.kin,
                                 run.checker, T, checks, ctx.rest_z, label, None, margin, own)
    x = np.linspace(ctx.q_a, ctx.q_b, T + 1)[1:-1].reshape(-1)
    bounds = list(zip(np.tile(problem.world.lower, T - 1), np.tile(problem.world.upper, T - 1),
                      strict=True))
    out = outcome_of(rows, layout, x, bounds, "the straight line")
    return out, out.violation


IK_LINE_TOLERANCE = 1e-3  # IK residual of a waypoint on a push's straight line


def _straight_push(problem, q_a, q_b, T: int) -> np.ndarray:
    """Interior waypoints (T-1, n) of a push: the tool on the straight line between
    its two keyframes, its orientation kept (IK from one waypoint to the next); a
    straight line in joint space turns an arm's hand, and the object with it, on
    the way (a level hand, measured: 1.2 deg, more than the NLP could take back).
    The straight joint-space line where IK misses, and for the planar robot."""
    line = np.linspace(q_a, q_b, T + 1)[1:-1]
    if problem.planar:
        return line
    world = problem.world
    A, B = world.tool_pose(q_a), world.tool_pose(q_b)
    q, out = np.asarray(q_a, dtype=float), []
    for s in np.linspace(0.0, 1.0, T + 1)[1:-1]:
        target = A.copy()
        target[:3, 3] = (1 - s) * A[:3, 3] + s * B[:3, 3]
        q, residual = world.ik(target, seed=q, restarts=0)
        if residual > IK_LINE_TOLERANCE:
            return line
        out.append(q)
    return np.array(out)


def _clear_anyway(run, ctx, T: int, checks: int, label: str, out):
    """`out` called solved when it meets every row at every sample point with no
    margin: SLSQP stalls a fraction of a millimetre short of the tight margin in a
    slot with millimetres to spare (robust-planar p04's plank), where the margin is
    slack and the zero-margin check at 10x (`verify`) is the judge."""
    problem = run.problem
    m = problem.motions[ctx.index]
    own = _margins(run, ctx, 0.0, 0.0)
    rows, layout = phase_rows_fn(problem, m, ctx.q_a, ctx.q_b, ctx.held, ctx.moved, run.kin,
                                 run.checker, T, checks, ctx.rest_z, label, None, 0.0, own)
    if nlp_feasible(rows, layout, out.x):
        return dataclasses.replace(out, status="solved", worst=None)
    return out


def _sampled_start(run, ctx, share: float, deadline: float | None = None):
    """A sampled path (K, n) found within `share` of the sampling budget (and by
    `deadline`, when sooner than the solve's), or None."""
    problem = run.problem
    world = problem.world
    m = problem.motions[ctx.index]
    options = run.sampling(share)
    if deadline is not None and deadline < options.deadline:
        options = dataclasses.replace(options, deadline=deadline)
    path = sampled_path(run.checker, ctx.q_a, ctx.q_b, world.lower, world.upper,
                        body_poses=ctx.moved, held=held_spec(ctx.held),
                        ignore=allowed_contacts(m), options=options)
    return path


def _solve_phase(run, ctx, T: int, checks: int, label: str, x0, margin: float):
    """Coarse (waypoints only), then lazily add the points between waypoints that need it.

    The rows of a point between waypoints are added once it comes within
    LAZY_BAND of its limit (most never do: a collision query per point per
    evaluation is what the path NLP spends its time on); each round checks
    every point and adds the new offenders, so the answer is feasible at every
    sample point or reported as not.
    """
    problem = run.problem
    m = problem.motions[ctx.index]

    own = _margins(run, ctx, margin, min(margin, problem.options.tight_margin))

    def rows(n_checks, keep=None):
        return phase_rows_fn(problem, m, ctx.q_a, ctx.q_b, ctx.held, ctx.moved, run.kin,
                             run.checker, T, n_checks, ctx.rest_z, label, keep, margin, own)

    bounds = list(zip(np.tile(problem.world.lower, T - 1), np.tile(problem.world.upper, T - 1),
                      strict=True))
    coarse, layout = rows(0)
    kept: set[float] = set()
    if checks and problem.planar and not m.pushes:
        # The planar robot's rows are cheap (a disk and what it holds), and a start that
        # keeps clear of the walls (a route through the middle of the passages) has no
        # point near anything: with rows at its waypoints only, SLSQP pulls each segment
        # taut across the walls' ends between them (gen1 planar-s02, a carry round two
        # partitions: 7 cm into a wall from a start 4 cm clear). Every point from the
        # first solve (not for a push: its start is its straight line, whatever it meets).
        coarse, _ = rows(checks)
    elif checks:
        # Points between waypoints already near something at the start keep their rows
        # from the first solve: with waypoints only, SLSQP's first steps can put two
        # waypoints on either side of a thin obstacle (a block just set down), and the
        # rows added later cannot pull the segment back around it.
        slack = sample_clearance(problem, m, ctx.q_a, ctx.q_b, x0, ctx.held, ctx.moved,
                                 run.checker, T, checks, margin, SEED_BAND, own)
        kept = {tau for tau, d in slack.items() if d < SEED_BAND and tau != int(tau)}
    if kept:
        coarse, _ = rows(checks, lambda tau, kept=frozenset(kept): tau == int(tau) or tau in kept)
    out = run.path_nlp(coarse, layout, x0, bounds)
    if checks == 0:
        return out
    for _ in range(LAZY_ROUNDS):
        if out.status != "solved":
            return out
        slack = sample_clearance(problem, m, ctx.q_a, ctx.q_b, out.x, ctx.held, ctx.moved,
                                 run.checker, T, checks, margin, LAZY_BAND, own)
        if min(slack.values()) >= -FEASIBILITY:
            # Same cost, more constraints: an optimum with fewer rows that satisfies
            # all of them is an optimum of the full NLP.
            return out
        kept |= {tau for tau, d in slack.items() if d < LAZY_BAND}
        lazy, _ = rows(checks, lambda tau, kept=frozenset(kept): tau == int(tau) or tau in kept)
        out = run.path_nlp(lazy, layout, out.x, bounds)
    full, _ = rows(checks)
    if out.status != "solved" or nlp_feasible(full, layout, out.x):
        return out
    return run.path_nlp(full, layout, out.x, bounds)
