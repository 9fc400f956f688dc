"""Collision-free paths by sampling: OMPL's RRT-Connect plus its shortcutting.

A path NLP started from a straight line or a via-point detour can stall in
a narrow passage: its gradients push the path against both walls at once.
A sampling-based planner over the same collision model (CollisionChecker,
the NLP's own signed distances) finds a path through the passage, which the
NLP then smooths. The path is only a start: the NLP and the zero-margin
check at 10x resolution stay the judges of what is returned.

Validity of a configuration: every covered pair at least `clearance` apart
(robot links, a held object, self-collision). Within `endpoint_slack` of
either end (in joint space), a pair closer than that at the end (the hand
touching what it is about to grasp or has just let go, a held object on the
surface it is put on, a keyframe in a slot) may stay as close as it is
there, but no closer: a path may not cut through the block just set down.

The same query and `seed` give the same path: OMPL's generator of seeds is
set before each query builds its planner and samplers (every one of their
generators is made within the query), and the budgets count validity
checks, not seconds, so the answer does not depend on the machine's load
(blind7 p03: with wall-time budgets, one run found its maze path and the
next did not). `deadline` is a safety limit only (the caller's time limit).

OMPL prints its log on the terminal by default: the level is set to none
for the query, and every OMPL object is released before returning (nanobind
warns at exit about objects still alive).
"""

from __future__ import annotations

import gc
import time
from collections import deque
from dataclasses import dataclass

import numpy as np

# Validity checks of RRT-Connect's first run before a restart (about 0.25 s at the
# 4,000 checks a second measured on blind3 p03 and blind7 p03).
FIRST_SLICE = 1000
# OMPL checks an edge every `resolution` of the space's extent: 0.23 rad on the xArm6's
# 23 rad, up to 13 cm of tool motion, so an edge may pass through a 4 cm flask or a
# 1 cm wall between two checks (blind8 p03: two sampled approaches of three ended with
# a finger 1.5 and 2.2 cm inside the flask, which the NLP cannot pull back round it).
# A path found is checked again FINE times finer; where an edge fails, the query runs
# again REFINE times finer with the budget left.
FINE = 10
REFINE = 4
# m: how much deeper than at the nearer end a pair may be near an end (numerical noise
# on a touching contact; it may not cut through what the motion starts or ends at).
CONTACT_DEPTH = 2e-4
# Configurations of an edge asked of the checker at once.
EDGE_BATCH = 32


@dataclass(frozen=True)
class SamplingOptions:
    """`checks`: validity checks RRT-Connect may make (over its restarts);
    `simplify_checks`: those shortcutting may make; `seed`: OMPL's seed for
    this query; `deadline`: a time.perf_counter() value past which the query
    gives up whatever its budget (None: none);
    `resolution`: OMPL's validity-checking step along an edge, as a fraction
    of the joint space's extent (coarse: the NLP refines, the 10x check
    judges); `clearance` (m): the distance every pair keeps;
    `endpoint_slack`: joint-space distance (rad or m) from either end within
    which contacts are allowed."""

    checks: int = 8000
    simplify_checks: int = 2000
    seed: int = 1
    deadline: float | None = None
    resolution: float = 0.01
    clearance: float = 0.0
    endpoint_slack: float = 0.05

    def __post_init__(self):
        if self.checks <= 0 or self.simplify_checks < 0:
            raise ValueError("the check budgets are a positive and a non-negative count")
        if not 0 < self.resolution < 1:
            raise ValueError("resolution is a fraction of the space's extent, in (0, 1)")
        if self.clearance < 0 or self.endpoint_slack < 0:
            raise ValueError("clearance and endpoint_slack are non-negative")


def sampled_path(checker, q_start, q_goal, lower, upper, *, body_poses=None, held=None,
                 ignore: frozenset[str] = frozenset(),
                 options: SamplingOptions = SamplingOptions()) -> np.ndarray | None:
    """Waypoints (K, n) from q_start to q_goal, every one valid and the edges
    checked at `options.resolution`; None when none is found within the budget."""
    from ompl import base as ob
    from ompl import geometric as og
    from ompl import util as ou

    q_start, q_goal = np.asarray(q_start, float), np.asarray(q_goal, float)
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    n = len(q_start)

    horizon = options.clearance + 0.01

    def pairs(qs: np.ndarray) -> list[dict]:
        rows = checker.distances_many(qs, body_poses, held, [ignore] * len(qs), horizon)
        return [{(c.a, c.b): c.distance for c in row} for row in rows]

    at_start, at_goal = pairs(q_start[None])[0], pairs(q_goal[None])[0]
    made = [0]  # validity checks so far

    def judge(qs: np.ndarray) -> np.ndarray:
        """Each row's validity, asked in one batch (uncounted: the caller counts)."""
        out = np.ones(len(qs), dtype=bool)
        for r, (q, found) in enumerate(zip(qs, pairs(qs), strict=True)):
            ends = [at for end, at in ((q_start, at_start), (q_goal, at_goal))
                    if np.linalg.norm(q - end) <= options.endpoint_slack]
            for pair, d in found.items():
                floor = min([options.clearance] + [at.get(pair, np.inf) - CONTACT_DEPTH
                                                   for at in ends])
                if d < floor:
                    out[r] = False
                    break
        return out

    def valid(q: np.ndarray) -> bool:
        made[0] += 1
        return bool(judge(np.asarray(q, float)[None])[0])

    def edge(a: np.ndarray, b: np.ndarray, count: int) -> bool:
        """OMPL's check of the edge a -> b in `count` steps (`_edge_order`), its
        configurations asked in batches: a checker call costs about six configurations'
        worth of its own (numpy's per-call work), and RRT-Connect's edges are up to 20
        steps. Counted as OMPL counts: up to and including the first invalid one."""
        order = _edge_order(count)
        for lo_ in range(0, len(order), EDGE_BATCH):
            ts = order[lo_:lo_ + EDGE_BATCH] / count
            ok = judge(a[None] + ts[:, None] * (b - a)[None])
            if not ok.all():
                made[0] += int(np.argmin(ok)) + 1
                return False
            made[0] += len(ts)
        return True

    deadline = np.inf if options.deadline is None else options.deadline

    def spent(limit: int):
        return ob.PlannerTerminationCondition(
            lambda: made[0] >= limit or time.perf_counter() > deadline)

    lo = np.minimum(lower, np.minimum(q_start, q_goal))
    hi = np.maximum(upper, np.maximum(q_start, q_goal))
    fine = options.resolution / FINE * float(np.linalg.norm(hi - lo))
    previous = ou.getLogLevel()
    ou.setLogLevel(ou.LOG_NONE)
    path = None
    try:
        ou.RNG.setSeed(max(1, int(options.seed) % (1 << 31)))  # OMPL refuses seed 0
        limit = made[0] + options.checks
        for resolution in (options.resolution, options.resolution / REFINE):
            if made[0] >= limit:
                break
            found = _query(ob, og, n, lo, hi, q_start, q_goal, (valid, edge), resolution,
                           made, limit - made[0], options.simplify_checks, spent, deadline)
            if found is None:
                break
            path = found
            if _edges_valid(path, edge, fine):
                break
    finally:
        gc.collect()
        ou.setLogLevel(previous)
    if path is None:
        return None
    path[0], path[-1] = q_start, q_goal
    return path


def _query(ob, og, n, lo, hi, q_start, q_goal, checks_of, resolution, made, checks,
           simplify_checks, spent, deadline):
    """One RRT-Connect query (with restarts) and its shortcutting at `resolution`: the
    path (K, n), or None; every OMPL object released before returning. `checks_of`:
    (a configuration's validity, an edge's in a number of steps)."""
    valid, edge = checks_of
    space = ob.RealVectorStateSpace(n)
    bounds = ob.RealVectorBounds(n)
    for i in range(n):
        bounds.setLow(i, float(lo[i]))
        bounds.setHigh(i, float(hi[i]))
    space.setBounds(bounds)
    setup = og.SimpleSetup(space)
    setup.setStateValidityChecker(lambda s: valid(np.fromiter((s[i] for i in range(n)),
                                                              float, n)))
    info = setup.getSpaceInformation()
    info.setStateValidityCheckingResolution(resolution)
    batched = _batched_edges(ob, info, space, n, edge)
    if batched is not None:  # (None: OMPL's own, one configuration a call; tests compare)
        info.setMotionValidator(batched)
    start, goal = space.allocState(), space.allocState()
    for i in range(n):
        start[i], goal[i] = float(q_start[i]), float(q_goal[i])
    setup.setStartAndGoalStates(start, goal)
    setup.setPlanner(og.RRTConnect(info))
    path = None
    if _solve_with_restarts(setup, made, checks, spent, deadline):
        if simplify_checks > 0:
            setup.simplifySolution(spent(made[0] + simplify_checks))
        found = setup.getSolutionPath()
        path = np.array([[found.getState(k)[i] for i in range(n)]
                         for k in range(found.getStateCount())])
        del found
    del setup, info, start, goal, space, bounds, batched
    return path


def _edges_valid(path: np.ndarray, edge, step: float) -> bool:
    """Every edge of `path` valid at points `step` apart (joint-space distance)."""
    return all(edge(a, b, max(1, int(np.ceil(np.linalg.norm(b - a) / step))))
               for a, b in zip(path[:-1], path[1:], strict=True))


def _edge_order(count: int) -> np.ndarray:
    """The steps (of `count`) OMPL's DiscreteMotionValidator checks on an edge, in its
    order: the far end, then the midpoints of ever smaller halves (a collision is
    found sooner than walking the edge)."""
    order, spans = [count], deque([(1, count - 1)] if count >= 2 else [])
    while spans:
        first, last = spans.popleft()
        mid = (first + last) // 2
        order.append(mid)
        if first < mid:
            spans.append((first, mid - 1))
        if last > mid:
            spans.append((mid + 1, last))
    return np.array(order, dtype=float)


def _batched_edges(ob, info, space, n: int, edge):
    """OMPL's discrete edge check, with the configurations of an edge asked at once."""

    class BatchedEdges(ob.MotionValidator):
        def checkMotion(self, s1, s2):
            return edge(np.fromiter((s1[i] for i in range(n)), float, n),
                        np.fromiter((s2[i] for i in range(n)), float, n),
                        space.validSegmentCount(s1, s2))

    return BatchedEdges(info)


def _solve_with_restarts(setup, made: list, checks: int, spent, deadline: float) -> bool:
    """RRT-Connect's time to a path through a narrow passage is heavy-tailed:
    measured on a 2-D slot of 1 cm in C-space, 1,245 to 337,332 validity
    checks over three runs (a cheap check, resolution 0.004). Restarts with growing
    slices (FIRST_SLICE checks, doubling) cut the tail; each restart clears the trees.
    `made[0]` counts the checks so far; `spent(limit)` is the termination condition
    at `limit` checks (or the deadline). A run that stops short of its slice without
    a path gave up (an invalid start or goal): no restart."""
    limit = made[0] + checks
    budget = FIRST_SLICE
    while made[0] < limit and time.perf_counter() <= deadline:
        until = min(made[0] + budget, limit)
        if setup.solve(spent(until)) and setup.haveExactSolutionPath():
            return True
        if made[0] < until and time.perf_counter() <= deadline:
            return False
        setup.clear()
        budget *= 2
    return False


def resample(path: np.ndarray, count: int) -> np.ndarray:
    """`count` waypoints along `path` (ends kept), evenly spaced by joint-space arc
    length, except that every vertex of the path is one of them when there are no
    more vertices than `count`: a corner cut between two waypoints could run into
    the obstacle the planner went around. Each segment then gets a share of the
    points proportional to its length (at least one step)."""
    path = np.asarray(path, float)
    if count < 2:
        raise ValueError("a path has at least two waypoints")
    steps = np.linalg.norm(np.diff(path, axis=0), axis=1)
    along = np.concatenate([[0.0], np.cumsum(steps)])
    if along[-1] == 0.0:
        return np.repeat(path[:1], count, axis=0)
    if len(path) > count:
        at = np.linspace(0.0, along[-1], count)
    else:
        at = np.concatenate([np.linspace(a, b, n, endpoint=False) for a, b, n in
                             zip(along, along[1:], _shares(steps, count - 1), strict=False)]
                            + [along[-1:]])
    return np.stack([np.interp(at, along, path[:, j]) for j in range(path.shape[1])], axis=1)


def _shares(lengths: np.ndarray, total: int) -> np.ndarray:
    """`total` steps over segments of these lengths: one each, the rest by largest
    remainder in proportion to length."""
    n = np.ones(len(lengths), dtype=int)
    extra = total - len(lengths)
    if extra > 0 and lengths.sum() > 0:
        want = lengths / lengths.sum() * total - 1.0
        floor = np.clip(np.floor(want), 0, None).astype(int)
        while floor.sum() > extra:
            floor[int(np.argmax(floor))] -= 1
        n += floor
        order = np.argsort(-(want - floor))
        for i in order[:extra - int(floor.sum())]:
            n[i] += 1
    return n
