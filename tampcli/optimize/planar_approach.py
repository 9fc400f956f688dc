"""The straight ends of a planar carry among close neighbours: into a slot, and out.

The planar disk carries an object beside it. Set down in a slot with
millimetres a side (robust-planar p10: b between a and c, 2 mm a side), a last
segment that turns as it comes in can bring the object's corner past a
neighbour's between two sample points, within the margins the motion allows
there (path.MotionMargins), and the physics replay snags it (a pushed 4.4 cm).
Where the held object stands nearer to something than the margin less the
tight margin at the keyframe (approach.vertical's test), the carry ends with a
straight entry instead: rungs RUNG apart along one direction, far enough for
the object to leave its close neighbours (its length and CLEAR), each no nearer
to anything than the tight margin (or than the keyframe is, less SLACK), with
approach.CHECKS points checked between two (approach.rung_clear). The directions tried: along the faces of the
close contacts (across their normals: the slot's axis), then DIRECTIONS even
ones; those nearest the way to the motion's other end first. A pick from such
a slot starts with the same exit, mirrored. None where no direction is clear:
the motion is then solved as any other.
"""

from __future__ import annotations

import numpy as np

from tampcli.optimize.approach import CLEAR, RUNG, SLACK, Approach, close_to, rung_clear
from tampcli.optimize.collide import Held

DIRECTIONS = 16


def straight(problem, m, q_end, q_other, held: Held | None, moved: dict, checker,
             contacts) -> Approach | None:
    """The straight end of planar carry m at keyframe `q_end` (its other end
    `q_other`), where the object rests on `contacts`; None where it needs none or
    none is clear (module doc)."""
    if held is None or not problem.planar or m.pushes or m.attached is None \
            or not contacts:
        return None
    opts = problem.options
    q_end = np.asarray(q_end, dtype=float)
    ignore = frozenset(m.sliding)
    near = close_to(problem, m, q_end, held, moved, checker, contacts)
    if not near:
        return None
    clear = min(opts.tight_margin, *(c.distance for c in near)) - SLACK
    length = 2.0 * float(max(problem.bodies[held.name].half[:2])) + CLEAR
    toward = np.asarray(q_other, dtype=float) - q_end
    for d in _directions(near, toward):
        found = _rungs(problem, q_end, d, length, held, moved, ignore, clear)
        if found is not None:
            return found
    return None


def _directions(near, toward: np.ndarray) -> list[np.ndarray]:
    """Unit directions in the plane: across the close contacts' normals, then even
    ones, each sorted by how nearly it points `toward` (ties keep that order)."""
    axes = []
    for c in near:
        n = np.asarray(c.normal[:2], dtype=float)
        if np.linalg.norm(n) > 1e-6:
            n = n / np.linalg.norm(n)
            axes += [np.array([-n[1], n[0]]), np.array([n[1], -n[0]])]
    angles = 2.0 * np.pi * np.arange(DIRECTIONS) / DIRECTIONS
    even = [np.array([np.cos(a), np.sin(a)]) for a in angles]
    norm = float(np.linalg.norm(toward))
    unit = toward / norm if norm > 1e-9 else np.zeros(2)

    def ranked(ds):
        return sorted(ds, key=lambda d: -float(d @ unit))

    return ranked(axes) + ranked(even)


def _rungs(problem, q_end, d, length: float, held: Held, moved, ignore, clear: float):
    world = problem.world
    n = max(1, int(np.ceil(length / RUNG - 1e-9)))
    rest = world.tool_pose(q_end) @ held.grasp
    targets, qs, prev = [], [], q_end
    for j in range(1, n + 1):
        q = q_end + d * (length * j / n)
        if np.any(q < world.lower) or np.any(q > world.upper) \
                or not rung_clear(problem, prev, q, held, moved, ignore, clear):
            return None
        target = rest.copy()
        target[:2, 3] += q - q_end
        targets.append(target)
        qs.append(q)
        prev = q
    return Approach(tuple(targets), tuple(qs))
