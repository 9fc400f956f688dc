"""Placements moved out of a later motion's way.

The final NLP chooses every placement of a skeleton without knowing the
motions between them: an object set down in a region can land in the only
corridor a later carry has (robust-planar pen-k1: the blocker taken out of
the pen is put down at the yard's edge, right in front of the pen's open
end, and the target can no longer be carried in). Where a motion finds no
path, the sampling planner runs again with the objects this skeleton moved
earlier left out. If that finds a path that some of them block, those are
the culprits: each gets a new origin in its region, the grid point clearest
of that path (exact distances of the robot and what it holds along the path,
through the same CollisionChecker) and of what rests near, and the final NLP
is solved again pulled towards it. The placement that comes out is kept only
if it still leaves the path clear; the keyframes and paths are then solved
again for it. Nothing here is proved: a relocation is a better start.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tampcli.geometry.sampled_path import SamplingOptions, resample, sampled_path
from tampcli.optimize.collide import held_spec
from tampcli.optimize.path import allowed_contacts

GRID = 11  # candidate points per side of a region
PATH_POINTS = 60  # configurations along the found path checked against a candidate
CLEAR = 0.02  # m: the clearance a relocated object keeps from the path
ANCHOR = 0.1  # m: the farthest an anchored placement may stray from its spot


@dataclass(frozen=True)
class Obstruction:
    """A path of motion `motion` found with `blockers` (objects this skeleton set
    down earlier) left out, which they block at the poses they were given."""

    motion: int
    path: np.ndarray  # (K, n)
    blockers: tuple[str, ...]
    held: tuple | None  # the checker's held spec during the motion

    @property
    def held_name(self) -> str | None:
        return self.held[0] if self.held is not None else None
    moved: dict  # name -> 4x4, every object away from its start pose
    ignore: frozenset


def relocatable(problem, motion: int, moved: dict) -> dict[str, int]:
    """Objects moved before `motion` whose last placement was into a region: name ->
    the index of that placing step."""
    regions = {r.name for r in problem.scene.regions}
    before = problem.motions[motion].step
    last: dict[str, int] = {}
    for step in problem.steps:
        if step.index < before and step.kind.places and step.obj in moved:
            last[step.obj] = step.index
    return {n: i for n, i in last.items() if problem.steps[i].target in regions}


def find(run, ctx, options: SamplingOptions) -> Obstruction | None:
    """The Obstruction of motion `ctx` by objects this skeleton moved, or None;
    `options`: the sampling query's budget and seed."""
    problem = run.problem
    held = held_spec(ctx.held)
    movable = relocatable(problem, ctx.index, ctx.moved)
    if held is not None:
        # What the motion carries is no obstruction of its own (blind33 p02: a bar put
        # back where it was and taken again, 17 s sampling a path that ignored it).
        movable.pop(held[0], None)
    if not movable:
        return None
    m = problem.motions[ctx.index]
    ignore = allowed_contacts(m) | frozenset(movable)
    kept = {n: p for n, p in ctx.moved.items() if n not in movable}
    path = sampled_path(run.checker, ctx.q_a, ctx.q_b, problem.world.lower, problem.world.upper,
                        body_poses=kept, held=held, ignore=ignore, options=options)
    if path is None:
        return None
    dense = resample(path, PATH_POINTS)
    blockers = tuple(n for n in movable
                     if _clearance(run.checker, dense, ctx.moved, held, ignore, n,
                                   ctx.moved[n]) < CLEAR)
    if not blockers:
        return None
    return Obstruction(ctx.index, path, blockers, held, dict(ctx.moved), ignore)


def resting(problem, ctx) -> frozenset[str]:
    """The movable bodies still at their start pose in motion `ctx`, besides what it
    holds, what it may touch and what it comes to touch (the object a pick or push
    approaches, the support a place carries to: moved first, the action could not be
    done as it stands; blind25 p02's disk, its pick keyframe between two crates, was
    found blocked by the crate it was to pick, and the search stopped trying that
    crate's other faces): those in_the_way leaves out."""
    held = held_spec(ctx.held)
    m = problem.motions[ctx.index]
    ignore = allowed_contacts(m) | m.enter_contact
    return frozenset(n for n, info in problem.bodies.items()
                     if not info.fixed and n not in ctx.moved and n not in ignore
                     and (held is None or n != held[0]))


def in_the_way(run, ctx, options: SamplingOptions, path=None) -> tuple[tuple[str, str], ...]:
    """(body, the checker's name of the robot's part: "link:..." or "held:...") for
    each movable body still at its start pose that a
    path of motion `ctx` runs into (nearer than the sampler's clearance), the path
    found with all of them left out (or `path`, one found so already); the deepest
    first. () when no such body stands in the way or no path is found even so.

    A motion that finds no path where one exists with such a body out of the way is
    blocked by it: its failure names the body (motion.py), and the skeletons that move
    it first come next (bnb/lessons.py); a corridor a crate stands in otherwise fails
    naming the wall beside it, which teaches nothing (blind15 p06)."""
    problem = run.problem
    m = problem.motions[ctx.index]
    held = held_spec(ctx.held)
    ignore = allowed_contacts(m)
    bodies = resting(problem, ctx)
    if not bodies:
        return ()
    if path is None:
        path = sampled_path(run.checker, ctx.q_a, ctx.q_b, problem.world.lower,
                            problem.world.upper, body_poses=ctx.moved, held=held,
                            ignore=ignore | bodies, options=options)
    if path is None:
        return ()
    dense = resample(path, PATH_POINTS)
    found = []
    for name in sorted(bodies):
        distance, part = _nearest(run.checker, dense, ctx.moved, held, ignore, name)
        if distance < options.clearance:
            found.append((distance, name, part))
    return tuple((name, part) for _, name, part in sorted(found))


def _clearance(checker, qs, moved: dict, held, ignore, name: str, pose) -> float:
    """Smallest distance between `name` at `pose` and the robot (and what it holds)
    over the configurations qs."""
    return _nearest(checker, qs, {**moved, name: pose}, held, ignore, name)[0]


def _nearest(checker, qs, poses: dict, held, ignore, name: str) -> tuple[float, str]:
    """(smallest distance, the checker's name of the robot part or held object nearest:
    "link:..." or "held:...") between body `name`
    (at `poses`' pose, or its start pose) and the robot over the configurations qs."""
    rows = checker.distances_many(qs, poses, held, [ignore - {name}] * len(qs),
                                  activation=CLEAR + 0.05)
    key = f"body:{name}"
    found = [(c.distance, c.b if c.a == key else c.a) for contacts in rows
             for c in contacts if key in (c.a, c.b)]
    return min(found, default=(np.inf, ""), key=lambda f: f[0])


@dataclass(frozen=True)
class Relocation:
    """New origins for the final NLP (step index -> (x, y): the blockers' moved, the
    others where they were), and the anchors the keyframe NLP keeps the blockers'
    placements to (step index -> ((x, y), radius): the keyframe NLP's cost, the path
    length, would otherwise pull them back into the way)."""

    origins: dict
    anchors: dict


def relocations(run, obstruction: Obstruction, placements: dict) -> list[Relocation]:
    """Relocations, best first: the blockers in turn, each at a grid point of its
    region clear of the obstruction's path, as far as can be from what else rests
    there (the blockers already relocated included); the j-th relocation takes each
    blocker's j-th best point."""
    problem = run.problem
    steps = relocatable(problem, obstruction.motion, obstruction.moved)
    regions = {r.name: r for r in problem.scene.regions}
    dense = resample(obstruction.path, PATH_POINTS)
    clear: dict[str, list[tuple[np.ndarray, float]]] = {}
    for name in obstruction.blockers:
        pose = obstruction.moved[name]
        region = regions[problem.steps[steps[name]].target]
        clear[name] = []
        for xy in _grid(region, problem.bodies[name], pose):
            candidate = pose.copy()
            candidate[:2, 3] = xy
            gap = _clearance(run.checker, dense, obstruction.moved, obstruction.held,
                             obstruction.ignore, name, candidate)
            if gap >= CLEAR:
                clear[name].append((xy, gap))
    base = {i: np.array([p.x, p.y]) for i, p in placements.items()}
    found = []
    for j in range(3):
        resting = {n: np.asarray(i.pose[:2]) for n, i in problem.bodies.items()
                   if not i.fixed and n != obstruction.held_name}
        resting.update({n: np.asarray(p[:2, 3]) for n, p in obstruction.moved.items()})
        for name in obstruction.blockers:
            del resting[name]
        origins, anchors = dict(base), {}
        for name in obstruction.blockers:
            ranked = _ranked(problem.bodies, name, clear[name], resting)
            if len(ranked) <= j:
                return found
            xy, gap = ranked[j]
            resting[name] = xy
            origins[steps[name]] = xy
            anchors[steps[name]] = (xy, min(gap, ANCHOR) - 0.5 * CLEAR)
        found.append(Relocation(origins, anchors))
    return found


def _ranked(bodies, name: str, candidates, resting: dict) -> list:
    """`candidates` (xy, gap to the path) not overlapping what rests, the roomiest
    first (gap between footprints' bounding circles, plus the path's clearance)."""
    scored = []
    for xy, gap in candidates:
        room = min((float(np.linalg.norm(xy - where)) - bodies[name].radius - bodies[n].radius
                    for n, where in resting.items()), default=1.0)
        if room > 0:
            scored.append((-(room + min(gap, 0.1)), len(scored), xy, gap))
    return [(xy, gap) for *_, xy, gap in sorted(scored)]


def _grid(region, info, pose) -> np.ndarray:
    """Grid points of `region` where the object's footprint (at its pose's yaw) fits."""
    c, s = abs(pose[0, 0]), abs(pose[1, 0])
    hx, hy = info.half[0], info.half[1]
    half = np.array([c * hx + s * hy, s * hx + c * hy]) if not info.disk else info.half[:2]
    lo = np.asarray(region.lower) + half
    hi = np.asarray(region.upper) - half
    centre = np.asarray(region.center, dtype=float)
    lo, hi = np.minimum(lo, centre), np.maximum(hi, centre)
    xs, ys = np.linspace(lo[0], hi[0], GRID), np.linspace(lo[1], hi[1], GRID)
    return np.array([[x, y] for x in xs for y in ys])


def still_clear(run, obstruction: Obstruction, placements: dict) -> bool:
    """Do the blockers, at their new placements, leave the obstruction's path clear?"""
    problem = run.problem
    steps = relocatable(problem, obstruction.motion, obstruction.moved)
    dense = resample(obstruction.path, PATH_POINTS)
    for name in obstruction.blockers:
        p = placements[steps[name]]
        pose = obstruction.moved[name].copy()
        c, s = np.cos(p.yaw), np.sin(p.yaw)
        pose[:2, :2] = [[c, -s], [s, c]]
        pose[:2, 3] = (p.x, p.y)
        if _clearance(run.checker, dense, obstruction.moved, obstruction.held,
                      obstruction.ignore, name, pose) < 0.5 * CLEAR:
            return False
    return True
