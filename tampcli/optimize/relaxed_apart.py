"""Objects kept apart in the planar relaxation: a disjunction, branched on lazily.

An object put down must not overlap what rests beside it. For two upright
boxes (their yaws fixed: the planar robot turns nothing) that is the
separating axis theorem: along one of the four face normals u of the two
footprints, |u.(c - p)| >= w_a(u) + w_b(u), the footprints' half widths
along u. Each side of each axis is a linear row, so "apart" is a union of
eight polyhedra, and the QP with it is a small branch and bound: solve,
find a pair the optimum overlaps, branch on its rows, best node first. The
least bound of the open nodes is a proved bound at any point, so a budget
of QPs only loosens it. validate calls an overlap a collision when it goes
deeper than its PENETRATION; FCL measures that depth to ~1e-4 m, so the
rows keep twice that slack.

Other shapes (disks, meshes, tilted bodies) and bodies at other heights are
left out, which only lowers the bound.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass

import numpy as np

from tampcli.optimize.bodies import REST_TOLERANCE
from tampcli.optimize.convex_qp import ConvexQP, QPBound, solve_convex_qp
from tampcli.optimize.verify import PENETRATION

SLACK = 2 * PENETRATION
VIOLATED = 1e-7  # m: an optimum this far inside every option of a pair overlaps there


@dataclass(frozen=True)
class Apart:
    """`c` (a variable) apart from `other` (a variable or a constant (x, y)): one of
    `options`, each (u, w): u.(c - other) >= w."""

    c: int
    other: int | np.ndarray
    options: tuple[tuple[np.ndarray, float], ...]
    label: str = ""  # "(place t pen): overlaps b": what a blocked placement says

    def row(self, option: int, n: int) -> tuple[np.ndarray, float]:
        """The option as a row a'x <= b of an n-variable QP."""
        u, w = self.options[option]
        a = np.zeros(n)
        a[self.c:self.c + 2] = -u
        if isinstance(self.other, np.ndarray):
            return a, -float(u @ self.other) - w
        a[self.other:self.other + 2] += u
        return a, -w

    def reach(self, boxes) -> list[tuple[float, float]]:
        """(least, most) of u.(c - other) over the variables' boxes, per option;
        `boxes(i)` is variable i's (lo, hi)."""
        clo, chi = boxes(self.c)
        olo, ohi = (self.other, self.other) if isinstance(self.other, np.ndarray) \
            else boxes(self.other)
        out = []
        for u, _ in self.options:
            low = np.sum(np.minimum(u * clo, u * chi)) - np.sum(np.maximum(u * olo, u * ohi))
            high = np.sum(np.maximum(u * clo, u * chi)) - np.sum(np.minimum(u * olo, u * ohi))
            out.append((float(low), float(high)))
        return out

    def overlaps(self, x: np.ndarray) -> bool:
        c = x[self.c:self.c + 2]
        p = self.other if isinstance(self.other, np.ndarray) else x[self.other:self.other + 2]
        return all(u @ (c - p) < w - VIOLATED for u, w in self.options)


def footprint(problem, name: str) -> tuple[np.ndarray, np.ndarray] | None:
    """(rotation, half extents) of an upright box's footprint; None for any other shape."""
    info = problem.bodies[name]
    if problem.scene.body(name).shape != "box" or not info.upright:
        return None
    c, s = math.cos(info.pose[3]), math.sin(info.pose[3])
    return np.array([[c, -s], [s, c]]), np.array(info.half[:2])


def apart(problem, step, c: int, other: str, at: int | np.ndarray, boxes) -> Apart | None:
    """The options that keep the step's box at variable c apart from box `other` at
    `at`; None when nothing is to branch on: another shape, another height, or
    apart anyway wherever the variables' boxes (`boxes(i)`: lo, hi) let them be."""
    obj = step.obj
    a, b = footprint(problem, obj), footprint(problem, other)
    ia, ib = problem.bodies[obj], problem.bodies[other]
    overlap = min(ia.top, ib.top) - max(ia.bottom, ib.bottom)
    if a is None or b is None or overlap <= SLACK + 2 * REST_TOLERANCE:
        return None
    options: list[tuple[np.ndarray, float]] = []
    for R in (a[0], b[0]):
        for axis in (0, 1):
            u = R[:, axis]
            if any(abs(u @ v) > 1.0 - 1e-9 for v, _ in options):
                continue  # boxes at the same yaw share their axes
            w = float(np.abs(a[0].T @ u) @ a[1] + np.abs(b[0].T @ u) @ b[1]) - SLACK
            options += [(u, w), (-u, w)]
    pair = Apart(c, at, tuple(options), f"{step.name}: overlaps {other}")
    if any(low >= w for (low, _), (_, w) in zip(pair.reach(boxes), options, strict=True)):
        return None
    return pair


def blocks_alone(pair: Apart, boxes) -> bool:
    """No option of the pair fits the variables' boxes: the other body alone leaves
    no room (a body standing in the target region, say)."""
    return all(high < w for (_, high), (_, w) in zip(pair.reach(boxes), pair.options,
                                                       strict=True))


def solve_apart(qp: ConvexQP, pairs: list[Apart],
                budget: int) -> tuple[QPBound, int, Apart | None]:
    """The least proved bound of the QP with every pair apart, from at most `budget`
    QPs; (the bound, QPs solved, the pair the relaxation without them overlaps).
    Best node first: the node popped is the least open one, so its bound holds
    for them all."""
    root = solve_convex_qp(qp)
    solved, count = 1, 0
    first = next((p for p in pairs if root.x is not None and p.overlaps(root.x)), None)
    if not pairs or math.isinf(root.value) or not root.proved:
        return root, solved, first
    heap = [(root.value, count, (), root)]
    n = len(qp.c)
    while heap:
        value, _, chosen, node = heapq.heappop(heap)
        done = {i for i, _ in chosen}
        split = next((i for i, p in enumerate(pairs)
                      if i not in done and node.x is not None and p.overlaps(node.x)), None)
        if split is None or solved + len(pairs[split].options) > budget:
            return node, solved, first
        for option in range(len(pairs[split].options)):
            rows = [*chosen, (split, option)]
            extra = [pairs[i].row(o, n) for i, o in rows]
            child = solve_convex_qp(ConvexQP(
                qp.P, qp.c, qp.r, np.vstack([qp.A, [a for a, _ in extra]]),
                np.concatenate([qp.b, [b for _, b in extra]]), qp.E, qp.f, qp.lo, qp.hi))
            solved += 1
            if not child.proved:
                return node, solved, first  # not for a convex QP: stop at a proved bound
            if not math.isinf(child.value):
                count += 1
                heapq.heappush(heap, (child.value, count, tuple(rows), child))
    return QPBound(math.inf, True, None, None), solved, first
