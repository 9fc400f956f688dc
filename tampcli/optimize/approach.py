"""The vertical ends of a carry among close neighbours: the object comes straight down
onto its support at a place, and goes straight up off it after a grasp.

A carry's segments are checked for collisions at a few points each, and near a
keyframe the margin to what stands closer than the margin there is half that
distance (path.MotionMargins). A last segment that brings the object down and
sideways at once can then pass through a thin rim or a neighbour between two
sample points (measured: blind8 p07, a cylinder coming down 15 cm and 10 cm
across in one segment, through a tray's rim 3.6 mm deep at s = 0.92, clear at
s = 0.75 and 1.0; blind8 p06, a box closing 10 mm on its neighbour in the last
segment, to 1 mm from it). Where the object stands nearer to something other than
its support than the margin allows at the keyframe, the carry ends with a fixed
descent: rungs RUNG
apart at most, each the object right above its resting pose, turned as there,
the top one high enough for its bottom to clear the tops of those neighbours.
The path NLP solves the carry to the top rung; the descent is appended to it. A
carry that takes an object from among close neighbours starts with the same
climb, mirrored.
(Held as equality rows of the path NLP instead, the rungs stalled SLSQP a
fraction of a millimetre short of feasible: blind8 p06 lost every skeleton.)
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from tampcli.optimize.collide import Held, contact_key, held_spec

CLEAR = 0.01  # m: the object's bottom this far over the tops of its close neighbours
MAX_HEIGHT = 0.08  # m: the highest approach; lower ones are tried where it is blocked
RUNG = 0.02  # m: the most the object comes down between two waypoints of the approach
IK_TOLERANCE = 1e-4  # IK residual of an approach configuration
SLACK = 5e-4  # m: how much nearer than at the place a rung may come to a neighbour
CHECKS = 3  # collision checks between two rungs


@dataclass(frozen=True)
class Approach:
    """The waypoints next to a place (or a grasp) that hold the object right above its
    resting pose: `targets[j]` the held object's pose (4x4) at the (j + 1)-th
    waypoint from the keyframe, `qs[j]` the configuration there. Rungs RUNG apart at most keep the
    joint-space segments between them straight to a fraction of a millimetre (a
    single 7.5 cm one bowed 1 mm into a neighbour 1 mm away: blind8 p06)."""

    targets: tuple[np.ndarray, ...]
    qs: tuple[np.ndarray, ...]

    @property
    def rungs(self) -> int:
        return len(self.targets)


def place_approach(problem, m, q_b, held: Held | None, moved: dict, checker
                   ) -> Approach | None:
    """The vertical approach of motion m (an arm's carry) to the place at its end
    (`vertical`)."""
    return vertical(problem, m, q_b, held, moved, checker, m.enter_contact)


def lift(problem, m, q_a, held: Held | None, moved: dict, checker) -> Approach | None:
    """The vertical climb of motion m (an arm's carry) off the support it starts on
    (`vertical`)."""
    return vertical(problem, m, q_a, held, moved, checker, m.leave_contact)


def vertical(problem, m, q_b, held: Held | None, moved: dict, checker, contacts
             ) -> Approach | None:
    """The vertical end of carry m at keyframe q_b, where the object rests on
    `contacts`, when something else is nearer to the object than the margin less the
    tight margin there (9 mm), or it rests on a body that moves (`stacked`); None
    otherwise.
    Its height: the neighbours' tops plus CLEAR over the object's bottom, within
    [margin + CLEAR / 2, MAX_HEIGHT]; where IK cannot reach a rung or one comes nearer
    than the tight margin to anything (or than the place to its neighbours, less
    SLACK), at a rung or at CHECKS points between two, halved down to that least
    (then None)."""
    if held is None or problem.planar or m.pushes or m.attached is None or not contacts:
        return None
    world, opts = problem.world, problem.options
    q_b = np.asarray(q_b, dtype=float)
    tool = world.tool_pose(q_b)
    rest = tool @ held.grasp
    ignore = frozenset(m.sliding)
    near = close_to(problem, m, q_b, held, moved, checker, contacts)
    if not near and not stacked(problem, contacts):
        return None
    # A rung beside a wall is as near it as the place is (p07's: 1 mm, the tight margin).
    clear = min([opts.tight_margin, *(c.distance for c in near)]) - SLACK
    bottom = rest[2, 3] - problem.bodies[held.name].half[2]
    tops = [t for t in (_top(problem, contact_key(c), moved) for c in near) if t is not None]
    least = opts.margin + CLEAR / 2
    height = min(max(max(tops, default=bottom) - bottom + CLEAR, least), MAX_HEIGHT)
    while True:
        found = _rungs(problem, q_b, tool, rest, height, held, moved, ignore, clear)
        if found is not None or height <= least:
            return found
        height = max(height / 2, least)


def stacked(problem, contacts) -> bool:
    """Whether the object rests on a body that moves (a stack): a carry that slid onto
    or off its top would drag it (blind15 p08: a cap carried sideways onto a can that
    stands on a post, its bottom level with the can's top for the last 5 cm; the physics
    replay knocked the can over)."""
    return any(name in problem.bodies and not problem.bodies[name].fixed
               for name in contacts)


def close_to(problem, m, q, held: Held, moved: dict, checker, contacts) -> list:
    """The contacts of the object held at keyframe q of motion m nearer than the margin
    less the tight one (9 mm) to something other than what it rests on (`contacts`):
    a place the keyframe NLP could only solve inside the margin, not one it left at
    the margin within its tolerance. What the object itself comes near only: an arm
    link passing a tall bottle, fingers 7 mm from a rim, are no reason to end
    straight, and the detour costs (arm-sort p01: 30 s and objective 1.56 without,
    109 s and 1.67 with them)."""
    opts = problem.options
    return [c for c in checker.distances(q, moved, held_spec(held), frozenset(m.sliding),
                                         opts.margin, static=False)
            if c.distance < opts.margin - opts.tight_margin and c.a == f"held:{held.name}"
            and contact_key(c) not in contacts]


def _rungs(problem, q_b, tool, rest, height: float, held: Held, moved, ignore,
           clear: float):
    world = problem.world
    n = max(1, int(np.ceil(height / RUNG - 1e-9)))
    targets, qs, seed = [], [], q_b
    for j in range(1, n + 1):
        rise = height * j / n
        up = tool.copy()
        up[2, 3] += rise
        q, residual = world.ik(up, seed=seed, restarts=0)
        q = np.asarray(q, dtype=float)
        if residual > IK_TOLERANCE or not rung_clear(problem, seed, q, held, moved, ignore,
                                                     clear):
            return None
        target = rest.copy()
        target[2, 3] += rise
        targets.append(target)
        qs.append(np.asarray(q, dtype=float))
        seed = q
    return Approach(tuple(targets), tuple(qs))


def axis_rungs(problem, q, direction, step: float, count: int, held: Held | None, moved,
               ignore, clear: float, checker, stop=None, limits: bool = False
               ) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """(targets, configurations) of keyframe q's tool moved `step` * j along `direction`
    (world, unit), its orientation kept, j = 1 .. `count`: each by IK seeded by the one
    before, `rung_clear` from it; the first that fails ends them, those before kept.
    `stop(q)` True ends them after the rung q; with `limits`, a rung outside the
    joint limits fails too (retreat.backoff, axial_start)."""
    world = problem.world
    tool = world.tool_pose(np.asarray(q, dtype=float))
    targets, qs, seed = [], [], np.asarray(q, dtype=float)
    for j in range(1, count + 1):
        target = tool.copy()
        target[:3, 3] += np.asarray(direction) * (step * j)
        rung, residual = world.ik(target, seed=seed, restarts=0)
        rung = np.asarray(rung, dtype=float)
        if residual > IK_TOLERANCE or (limits and (np.any(rung < world.lower)
                                                   or np.any(rung > world.upper))) \
                or not rung_clear(problem, seed, rung, held, moved, ignore, clear, checker):
            break
        targets.append(target)
        qs.append(rung)
        seed = rung
        if stop is not None and stop(rung):
            break
    return targets, qs


def rung_clear(problem, prev, q, held: Held | None, moved, ignore, clear: float,
               checker=None) -> bool:
    """Whether the rung q, and CHECKS points on the segment to it from `prev`, are
    `clear` of everything (the robot and what it holds), by `checker` (the problem's
    when None)."""
    checker, horizon = checker or problem.checker, problem.options.margin
    between = [(1 - s) * prev + s * q for s in np.arange(1, CHECKS + 1) / (CHECKS + 1)]
    return all(checker.min_distance(p, moved, held_spec(held), ignore, static=False,
                                    horizon=horizon) >= clear for p in [q, *between])


def _top(problem, key: str, moved) -> float | None:
    """The top (z) of a body named by a contact key, None for "self"."""
    info = problem.bodies.get(key)
    if info is None:
        return None
    z = moved[key][2, 3] if key in moved else info.pose[2]
    return z + info.half[2]


def joined(out, climb: Approach | None, descent: Approach | None, q_a, q_b,
           scale: float):
    """The outcome `out` of the carry between the top rungs continued down the
    descent's rungs to q_b and preceded by the climb's from q_a: the rungs become
    waypoints, their segments join the cost (scale * sum |dq|^2, as the NLP's)."""
    n = len(q_b)
    up = list(climb.qs) if climb is not None else []  # bottom rung first
    down = list(reversed(descent.qs)) if descent is not None else []  # top rung first
    x = np.vstack([*up, *np.asarray(out.x, dtype=float).reshape(-1, n), *down])
    extra = 0.0
    for path in ([np.asarray(q_a, dtype=float), *up], [*down, np.asarray(q_b, dtype=float)]):
        if len(path) > 1:
            steps = np.diff(np.array(path), axis=0)
            extra += float(np.sum(steps * steps))
    return dataclasses.replace(out, x=x.reshape(-1), cost=out.cost + scale * extra)
