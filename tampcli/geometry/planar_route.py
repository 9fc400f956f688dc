"""A planar robot's route between two configurations, kept clear of the walls.

The planar robot translates and never turns, and what it holds turns with it:
its configuration space is the plane, and the signed distance of robot (and
held object) to any body is 1-Lipschitz in that plane. So a grid of distances
answers for the whole plane: where two neighbouring points s apart are each d
clear, everything between them is at least d - s/2 clear. A route is the
shortest path over that grid (Dijkstra), each step dearer the nearer it is to
something (at `comfort` and beyond it costs its length), then pulled straight
where the distances allow.

Why: the via-point start bends the straight line round the first body it
crosses only (and runs through the next wall), and RRT-Connect's path grazes
each corner it turns (it keeps the tight margin), its few vertices far apart;
from either, on 10 segments, the path NLP of gen1 planar-s02's carry round two
staggered partitions ended 5 to 7 cm inside a wall. From a route through the
middle of the passages, on segments no longer than the disk is wide, with rows
at every sample point from the first solve (motion.py), it solves at once.

Validity is the sampled planner's (sampled_path.py): every pair at least
`clearance` apart, except within `endpoint_slack` of either end, where a pair
closer than that at the end may stay as close as it is there. The ends join the
grid along straight edges checked at `fine` steps. (Near the ends the floors
differ from pair to pair, and the Lipschitz bound is an estimate there.) The
route is a start for the NLP, which with the zero-margin check at 10x stays the
judge.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

from tampcli.geometry.sampled_path import CONTACT_DEPTH

# Grid offsets of a point's neighbours (each edge once: the graph is undirected).
NEIGHBOURS = ((1, 0), (0, 1), (1, 1), (1, -1))
VERTICAL = 0.999  # |normal z| of a contact across a horizontal gap
PULL_LOOKAHEAD = 6  # vertices past the last that could be reached straight
# m beyond a cell's diagonal a corner's slack must fall for the cell to count as
# blocked (`_separated`): room for the signed distance's own error.
SEPARATION_MARGIN = 0.002
REFINE = 4  # a grid cell near a collision is divided this many times a side (`_separated`)


@dataclass(frozen=True)
class RouteOptions:
    """`step` (m): the grid's spacing (wider where the plane would need more than
    `max_points` points); `clearance` (m): the distance every pair keeps;
    `comfort` (m): the clearance beyond which a step costs only its length;
    `nearness`: a step at `clearance` costs 1 + nearness times its length;
    `endpoint_slack` (m): the distance from either end within which a pair may be
    as close as at that end; `fine` (m): the check step along the ends' edges."""

    step: float = 0.02
    max_points: int = 20000
    clearance: float = 0.001
    comfort: float = 0.04
    nearness: float = 3.0
    endpoint_slack: float = 0.05
    fine: float = 0.005

    def __post_init__(self):
        if not (self.step > 0 and self.fine > 0 and self.max_points >= 4):
            raise ValueError("step and fine are positive lengths, max_points at least 4")
        if not 0 <= self.clearance < self.comfort or self.nearness < 0:
            raise ValueError("0 <= clearance < comfort, and nearness >= 0")


@dataclass(frozen=True)
class Route:
    """`points` (K, 2): the route's vertices, the ends included; `least` (m): the
    least distance of any pair at its grid points away from the ends (capped at
    comfort + clearance): under the optimizer's margin, the passage is narrower than
    twice the margin."""

    points: np.ndarray
    least: float


@dataclass(frozen=True)
class _Grid:
    """Points (nx * ny, 2), x-major, and their slack: the least distance of any pair
    less the distance that pair must keep there (capped at comfort)."""

    xs: np.ndarray
    ys: np.ndarray
    slack: np.ndarray  # (nx, ny)

    def point(self, i: int, j: int) -> np.ndarray:
        return np.array([self.xs[i], self.ys[j]])

    def at(self, k: int) -> np.ndarray:
        """The point of flat index k."""
        return self.point(k // len(self.ys), k % len(self.ys))

    def interpolated(self, p: np.ndarray) -> np.ndarray:
        """The slack at points p (k, 2), interpolated bilinearly (clamped to the grid)."""
        fx = np.clip((p[:, 0] - self.xs[0]) / (self.xs[1] - self.xs[0]), 0, len(self.xs) - 1)
        fy = np.clip((p[:, 1] - self.ys[0]) / (self.ys[1] - self.ys[0]), 0, len(self.ys) - 1)
        i = np.minimum(np.floor(fx).astype(int), len(self.xs) - 2)
        j = np.minimum(np.floor(fy).astype(int), len(self.ys) - 2)
        u, v = fx - i, fy - j
        s = self.slack
        return ((1 - u) * (1 - v) * s[i, j] + u * (1 - v) * s[i + 1, j]
                + (1 - u) * v * s[i, j + 1] + u * v * s[i + 1, j + 1])


def planar_route(checker, q_start, q_goal, lower, upper, *, body_poses=None, held=None,
                 ignore: frozenset[str] = frozenset(),
                 options: RouteOptions = RouteOptions(),
                 report: dict | None = None) -> Route | None:
    """A route from q_start to q_goal, every grid edge on it valid
    by the slack at its ends (Lipschitz) or, where the grid has no route so, by
    checks at `fine` steps, and the ends' edges checked at `fine` steps; None where
    the grid has none. Then, into `report` (when given), `separated`: whether the grid
    proves that no path at all joins them (`_separated`)."""
    q_start, q_goal = np.asarray(q_start, float), np.asarray(q_goal, float)
    if len(q_start) != 2:
        raise ValueError("a planar route is for a configuration space of two dimensions")
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    horizon = options.comfort + options.clearance

    def contacts(qs):
        return checker.distances_many(qs, body_poses, held, [ignore] * len(qs), horizon)

    ends = [(q, _pairs(found)) for q, found in zip((q_start, q_goal),
                                                   contacts(np.array([q_start, q_goal])),
                                                   strict=True)]

    def slack(qs) -> np.ndarray:
        """Per point, the least distance of a pair less the floor it keeps there."""
        qs = np.asarray(qs, float).reshape(-1, 2)
        out = np.full(len(qs), options.comfort)
        near = [np.linalg.norm(qs - q, axis=1) <= options.endpoint_slack for q, _ in ends]
        for k, found in enumerate(contacts(qs)):
            found = _level(found)
            if not found:
                continue
            at_ends = [at for (_, at), close in zip(ends, near, strict=True) if close[k]]
            if not at_ends:
                out[k] = min(out[k], min(c.distance for c in found) - options.clearance)
                continue
            for pair, d in _pairs(found).items():
                floor = min([options.clearance] + [at.get(pair, np.inf) - CONTACT_DEPTH
                                                   for at in at_ends])
                out[k] = min(out[k], d - floor)
        return out

    grid = _grid(lower, upper, options, slack)
    graph = _Graph(grid, options)
    for e, (q, _) in enumerate(ends):
        graph.join(e, q, slack)
    chain = graph.shortest()
    if chain is None and graph.unsure:
        graph.check_unsure(slack)
        chain = graph.shortest()
    if chain is None:
        if report is not None:
            report["separated"] = _separated(grid, q_start, q_goal, options, slack)
        return None
    points = np.array([q_start if k == graph.n else q_goal if k == graph.n + 1
                       else grid.at(k) for k in chain])
    flat = grid.slack.reshape(-1)
    away = [flat[k] for k, p in zip(chain, points, strict=True) if k < graph.n
            and min(np.linalg.norm(p - q_start), np.linalg.norm(p - q_goal))
            > options.endpoint_slack]
    least = options.clearance + min(away, default=options.comfort)
    return Route(_pulled(points, grid, options), float(least))


def _separated(grid: _Grid, q_start: np.ndarray, q_goal: np.ndarray,
               options: RouteOptions, slack) -> bool:
    """Whether no path from q_start to q_goal keeps the clearance anywhere in the plane.

    The grid's cells where something is in collision are divided REFINE times a side,
    `slack` asked at their points. A fine cell is blocked where one of its corners'
    slack is below minus its diagonal (and SEPARATION_MARGIN for the distance's own
    error): every point of it then has a negative slack (1-Lipschitz), its boundary
    included. A path through the plane crosses cells that share an edge, or a corner,
    which is free and so leaves the cells sharing its edges unblocked: it stays in one
    edge-connected set of unblocked cells. The cells within `endpoint_slack` (and a
    diagonal) of either end are never blocked, where the slack's floors differ from
    pair to pair. So start and goal in different sets is a proof (blind33 p02: a bar
    held across a 12.4 cm door, which RRT-Connect spent its whole budget, 23 s, not
    finding). Cells left whole count as unblocked: a proof missed, never a false one."""
    from scipy import ndimage

    xs, ys, coarse = grid.xs, grid.ys, grid.slack
    nx, ny = len(xs) - 1, len(ys) - 1
    k = REFINE
    hx, hy = (xs[1] - xs[0]) / k, (ys[1] - ys[0]) / k
    fx = xs[0] + hx * np.arange(nx * k + 1)
    fy = ys[0] + hy * np.arange(ny * k + 1)
    fine = np.full((len(fx), len(fy)), np.inf)
    fine[::k, ::k] = coarse
    least = np.minimum.reduce([coarse[:-1, :-1], coarse[1:, :-1], coarse[:-1, 1:],
                               coarse[1:, 1:]])
    whole = least < -(math.hypot(k * hx, k * hy) + SEPARATION_MARGIN)  # blocked as is
    ask = np.zeros_like(fine, dtype=bool)
    for i, j in zip(*np.nonzero((least < 0) & ~whole), strict=True):
        ask[i * k:(i + 1) * k + 1, j * k:(j + 1) * k + 1] = True
    ask[::k, ::k] = False  # known
    where = np.nonzero(ask)
    if len(where[0]):
        fine[where] = slack(np.stack([fx[where[0]], fy[where[1]]], axis=1))
    diagonal = math.hypot(hx, hy)
    deep = fine < -(diagonal + SEPARATION_MARGIN)
    blocked = deep[:-1, :-1] | deep[1:, :-1] | deep[:-1, 1:] | deep[1:, 1:]
    blocked |= np.kron(whole, np.ones((k, k), dtype=bool)).astype(bool)
    centres = np.stack(np.meshgrid(0.5 * (fx[:-1] + fx[1:]), 0.5 * (fy[:-1] + fy[1:]),
                                   indexing="ij"), axis=-1)
    for q in (q_start, q_goal):
        blocked &= np.linalg.norm(centres - q, axis=-1) > options.endpoint_slack + diagonal
    sets, _ = ndimage.label(~blocked)  # edge-connected (4-neighbour) sets

    def cell(q):
        i = int(np.clip(np.searchsorted(fx, q[0]) - 1, 0, len(fx) - 2))
        j = int(np.clip(np.searchsorted(fy, q[1]) - 1, 0, len(fy) - 2))
        return sets[i, j]

    return bool(cell(q_start) != cell(q_goal))


def _level(found) -> list:
    """The contacts a move in the plane can close: not a gap straight up or down (a
    convex body under the disk, the bench 1 cm below it: the horizontal plane between
    them separates them wherever the disk goes)."""
    return [c for c in found if c.distance <= 0 or abs(c.normal[2]) < VERTICAL]


def _pairs(found) -> dict:
    out: dict = {}
    for c in _level(found):
        out[(c.a, c.b)] = min(out.get((c.a, c.b), np.inf), c.distance)
    return out


def _grid(lower, upper, options: RouteOptions, slack) -> _Grid:
    """The plane within the joint limits at `step` (wider if it would take more than
    `max_points` points), each point's slack."""
    extent = upper - lower
    step = max(options.step, math.sqrt(float(np.prod(extent)) / options.max_points))
    nx, ny = (max(2, int(math.floor(e / step)) + 1) for e in extent)
    xs = np.linspace(lower[0], upper[0], nx)
    ys = np.linspace(lower[1], upper[1], ny)
    points = np.stack(np.meshgrid(xs, ys, indexing="ij"), axis=-1).reshape(-1, 2)
    return _Grid(xs, ys, slack(points).reshape(nx, ny))


def _dearness(slack, options: RouteOptions):
    """A step's cost per unit length at this slack: 1 from comfort on."""
    room = options.comfort - options.clearance
    return 1.0 + options.nearness * np.clip(1.0 - np.asarray(slack) / room, 0.0, None)


class _Graph:
    """The grid's points (0 .. n-1) and the two ends (n: start, n + 1: goal), joined by
    the edges known valid; `unsure`: edges between two valid points whose slack
    does not prove their middle clear (a passage about a grid step wide)."""

    def __init__(self, grid: _Grid, options: RouteOptions):
        self.grid, self.options = grid, options
        nx, ny = grid.slack.shape
        self.n = nx * ny
        hx, hy = grid.xs[1] - grid.xs[0], grid.ys[1] - grid.ys[0]
        index = np.arange(self.n).reshape(nx, ny)
        self.rows, self.cols, self.weights = [], [], []
        self.unsure = []
        for di, dj in NEIGHBOURS:
            i0, i1 = max(0, -di), nx - max(0, di)
            j0, j1 = max(0, -dj), ny - max(0, dj)
            a = grid.slack[i0:i1, j0:j1]
            b = grid.slack[i0 + di:i1 + di, j0 + dj:j1 + dj]
            length = math.hypot(di * hx, dj * hy)
            ok = a + b - length >= 0  # the least slack along the edge (1-Lipschitz)
            here, there = index[i0:i1, j0:j1], index[i0 + di:i1 + di, j0 + dj:j1 + dj]
            self.rows += list(here[ok])
            self.cols += list(there[ok])
            self.weights += list(length * _dearness(0.5 * (a[ok] + b[ok]), options))
            doubt = ~ok & (a >= 0) & (b >= 0)
            self.unsure += [(u, v, length) for u, v in zip(here[doubt], there[doubt],
                                                           strict=True)]

    def join(self, end: int, q: np.ndarray, slack) -> None:
        """Edges from an end to the valid grid points within two steps of it whose
        straight edge from it is valid at `fine` steps."""
        grid = self.grid
        h = max(grid.xs[1] - grid.xs[0], grid.ys[1] - grid.ys[0])
        points = np.stack(np.meshgrid(grid.xs, grid.ys, indexing="ij"), axis=-1).reshape(-1, 2)
        far = np.linalg.norm(points - q, axis=1)
        for k in np.flatnonzero((far <= 2 * h) & (grid.slack.reshape(-1) >= 0)):
            count = max(2, math.ceil(far[k] / self.options.fine) + 1)
            along = slack(np.linspace(q, points[k], count))
            if np.all(along >= 0):
                self._add(self.n + end, int(k), far[k], float(np.min(along)))

    def check_unsure(self, slack) -> None:
        """The unsure edges checked at `fine` steps: the valid ones join the graph."""
        count = max(2, math.ceil(max(e[2] for e in self.unsure) / self.options.fine))
        s = np.arange(1, count) / count
        points = np.concatenate([np.outer(1 - s, self.grid.at(u)) + np.outer(s, self.grid.at(v))
                                 for u, v, _ in self.unsure])
        along = slack(points).reshape(len(self.unsure), count - 1)
        flat = self.grid.slack.reshape(-1)
        for (u, v, length), values in zip(self.unsure, along, strict=True):
            if np.all(values >= 0):
                self._add(u, v, length, float(min(flat[u], flat[v], *values)))
        self.unsure = []

    def _add(self, u: int, v: int, length: float, least: float) -> None:
        self.rows.append(u)
        self.cols.append(v)
        self.weights.append(length * float(_dearness(least, self.options)) + 1e-12)

    def shortest(self) -> list[int] | None:
        """The cheapest chain of points from start (n) to goal (n + 1), or None."""
        n = self.n
        graph = coo_matrix((self.weights, (self.rows, self.cols)), shape=(n + 2, n + 2))
        dist, pred = dijkstra(graph.tocsr(), directed=False, indices=n,
                              return_predecessors=True)
        if not np.isfinite(dist[n + 1]):
            return None
        chain, k = [n + 1], n + 1
        while k != n:
            k = int(pred[k])
            chain.append(k)
        return chain[::-1]


def _pulled(points: np.ndarray, grid: _Grid, options: RouteOptions) -> np.ndarray:
    """The grid's staircase pulled straight: from each kept vertex, the farthest later
    one (looking PULL_LOOKAHEAD vertices past the last that passed) whose straight
    edge keeps, by the grid's slack interpolated, the least of comfort and what the
    route keeps over that stretch, less a quarter of a grid step. A start for the NLP,
    not a proof: the route's own edges are the valid ones."""
    h = max(grid.xs[1] - grid.xs[0], grid.ys[1] - grid.ys[0])
    on_route = grid.interpolated(points)
    kept, i = [0], 0
    last = len(points) - 1
    while i < last:
        best = i + 1
        for j in range(i + 2, last + 1):
            if j - best > PULL_LOOKAHEAD:
                break
            need = max(0.0, min(options.comfort, float(np.min(on_route[i:j + 1]))) - h / 4)
            count = max(2, math.ceil(np.linalg.norm(points[j] - points[i]) / (h / 2)) + 1)
            inner = np.linspace(points[i], points[j], count)[1:-1]
            if np.min(grid.interpolated(inner), initial=np.inf) >= need:
                best = j
        kept.append(best)
        i = best
    return points[kept]
