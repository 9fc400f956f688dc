"""Starting points of the "final" NLP: where each placement begins, and what pulls it.

The final NLP places every object of a skeleton at once, so an earlier
placement still moves when a later one needs its room; what the starting
point decides is which local optimum SLSQP finds. Measured on the robust
packing problems (several objects into one region, under 15 % slack): from
every object at the region's middle the NLP ended with two of them
overlapping for every order. Four starts, tried in turn until one solves:
the region's middle (with room to spare the NLP pushes the objects apart
from there; the keyframe stage, whose grasp sides follow the robot's
approach, was tuned on such placements); a row along the region's long
side, the first placed at the end farthest from the robot (a later one need
not pass it), equal gaps (first when a region is tight: see `starts`); each
placement where it is clearest of what rests there by then; shelves, rows
across the way from the robot filled from the far end (first where a row
does not fit the region). Each start is a function of the skeleton
alone: never of a neighbouring skeleton's result, so a skeleton's outcome
does not depend on what was evaluated before it or on what follows it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tampcli.optimize.values import Placement

GRID = 9  # candidate points per side of a region for the clearest start


def _regions(problem) -> dict:
    return {r.name: r for r in problem.scene.regions}


def _placing(problem) -> list:
    return [s for s in problem.steps if s.kind.places]


def _extent(info, yaw: float, axis: int) -> float:
    """The footprint's width along world axis `axis` at `yaw`."""
    if info.disk:
        return 2 * info.half[0]
    c, s = abs(math.cos(yaw)), abs(math.sin(yaw))
    hx, hy = info.half[0], info.half[1]
    return 2 * (c * hx + s * hy if axis == 0 else s * hx + c * hy)


YAW_STEPS = 1800  # yaws looked at over a half turn (0.1 degree apart) by _fitting_yaw


def _fitting_yaw(info, yaw: float, region) -> float:
    """The start yaw where the footprint fits the region there; else a quarter turn
    from it when that fits (an oblong object put down across: the NLP does not turn it
    that far by itself); else the middle of the window of yaws that fit nearest to it
    (blind20 p01: a 15 x 3 cm pen fits a 13.6 cm square case between 41.7 and 48.3
    degrees only; from 0 the final NLP ended 0.8 cm into the case's rim in each of 318
    skeletons). The start yaw where no yaw fits."""
    def fits(y):
        return all(_extent(info, y, axis) <= region.size[axis] for axis in (0, 1))

    if fits(yaw):
        return yaw
    if fits(yaw + 0.5 * math.pi):
        return yaw + 0.5 * math.pi
    turns = yaw + np.linspace(0.0, math.pi, YAW_STEPS, endpoint=False)
    ok = np.array([fits(t) for t in turns])
    if not ok.any():
        return yaw
    # Windows as runs of fitting turns, the half turn closed into a circle (a footprint
    # is the same turned by pi): the first run joins the last where both touch its ends.
    shift = int(np.argmin(ok))  # a turn that does not fit: no window wraps past it
    ok, turns = np.roll(ok, -shift), np.roll(turns, -shift)
    turns = np.unwrap(turns, period=math.pi)
    edges = np.flatnonzero(np.diff(np.concatenate(([0], ok.astype(int), [0]))))
    middles = 0.5 * (turns[edges[::2]] + turns[edges[1::2] - 1])
    middles -= math.pi * np.round((middles - yaw) / math.pi)  # the nearest equivalents
    return float(middles[np.argmin(np.abs(middles - yaw))])


@dataclass(frozen=True)
class _Face:
    size: np.ndarray  # (x, y) widths, in the frame of the body it tops


def _stacked_yaw(problem, step, yaw: dict) -> float:
    """The start yaw of an object stacked on a box, as `_fitting_yaw` gives it for the
    box's top face in the box's frame (at the yaw the box has by then): the final NLP's
    pull, sin^2(2 dyaw), is as happy a quarter turn off, so an oblong object started 55
    degrees from an oblong plate ended across it (blind34 p04: a 6 x 3 cm bar onto a
    6.4 x 3.4 cm plate turned 35 degrees, `footprint off the top by 1.3 cm` in 15 of 18
    skeletons). Its own yaw where the support is no box, or the object a disk."""
    info, support = problem.bodies[step.obj], problem.bodies[step.target]
    if info.disk or support.shape != "box":
        return yaw[step.obj]
    turn = yaw[step.target]
    face = _Face(2.0 * np.asarray(support.half[:2], dtype=float))
    return turn + _fitting_yaw(info, yaw[step.obj] - turn, face)


def _robot_xy(problem) -> np.ndarray:
    world = problem.world
    return np.asarray(world.tool_pose(world.start)[:2, 3], dtype=float)


def _walk(problem, pick, yaws: dict | None = None) -> tuple[dict, dict]:
    """(placements, origins) with `pick(step, where, yaw, target)` choosing each
    placement on a region; a stacked object starts over its support. `yaws`: step ->
    the yaw a placement on a region starts at (default `_fitting_yaw`)."""
    placements, origins = {}, {}
    where = {n: np.array(i.pose[:2]) for n, i in problem.bodies.items()}
    yaw = {n: i.pose[3] for n, i in problem.bodies.items()}
    regions = _regions(problem)
    for step in _placing(problem):
        if step.target in regions:
            if yaws is not None and step.index in yaws:
                yaw[step.obj] = yaws[step.index]
            elif not problem.planar:  # an arm may turn what it carries; the disk may not
                yaw[step.obj] = _fitting_yaw(problem.bodies[step.obj], yaw[step.obj],
                                             regions[step.target])
            xy = np.asarray(pick(step, where, yaw, regions[step.target]), dtype=float)
        else:
            xy = where[step.target].copy()
            if not problem.planar:
                yaw[step.obj] = _stacked_yaw(problem, step, yaw)
        origins[step.index] = xy
        placements[step.index] = Placement(float(xy[0]), float(xy[1]), float(yaw[step.obj]))
        where[step.obj] = xy
    return placements, origins


def packed(problem) -> tuple[dict, dict]:
    """Placements into one region in a row along its long side, the first farthest
    from the robot, equal gaps between them and at the ends; an arm's oblong object
    turned a quarter where that shortens the row and it still fits across."""
    yaws = _row_yaws(problem)
    slots = _row_slots(problem, yaws)
    return _walk(problem, lambda step, where, yaw, region: slots[step.index], yaws)


def _row_yaws(problem) -> dict[int, float]:
    """step -> the yaw of its object in `packed`'s row: its start yaw or a quarter turn
    from it, the one whose extent along the region's long side is the shorter while its
    extent across fits (blind22 p01: a 6 x 4 cm brick and a 4.8 cm can in a 9.4 x 6.4
    cm tray fit side by side only with the brick across; from the row at the start
    yaws, 10.8 cm long, the final NLP ended with them 6 mm into each other). Only where
    several objects go into a region; the planar robot does not turn what it moves."""
    yaws: dict[int, float] = {}
    if problem.planar:
        return yaws
    for name, region in _regions(problem).items():
        steps = [s for s in _placing(problem) if s.target == name]
        if len(steps) < 2:
            continue
        axis = int(np.argmax(region.size))
        for s in steps:
            info = problem.bodies[s.obj]
            turns = [t for t in (info.pose[3], info.pose[3] + 0.5 * math.pi)
                     if _extent(info, t, 1 - axis) <= region.size[1 - axis]]
            if turns and not info.disk:
                yaws[s.index] = min(turns, key=lambda t: _extent(info, t, axis))
    return yaws


def _row_slots(problem, yaws: dict[int, float] | None = None) -> dict[int, np.ndarray]:
    """step -> (x, y) of `packed` (each object at its yaw in `yaws`, else its start
    yaw)."""
    regions = _regions(problem)
    robot = _robot_xy(problem)
    yaws = yaws or {}
    slots: dict[int, np.ndarray] = {}
    for name, region in regions.items():
        steps = [s for s in _placing(problem) if s.target == name]
        if not steps:
            continue
        axis = int(np.argmax(region.size))
        lo, hi = float(region.lower[axis]), float(region.upper[axis])
        widths = [_extent(problem.bodies[s.obj],
                          yaws.get(s.index, problem.bodies[s.obj].pose[3]), axis)
                  for s in steps]
        gap = (hi - lo - sum(widths)) / (len(steps) + 1)
        far_high = abs(hi - robot[axis]) >= abs(lo - robot[axis])
        at = hi if far_high else lo
        sign = -1.0 if far_high else 1.0
        for s, w in zip(steps, widths, strict=True):
            centre = at + sign * (gap + 0.5 * w)
            at = centre + sign * 0.5 * w
            xy = np.asarray(region.center, dtype=float).copy()
            xy[axis] = centre
            slots[s.index] = xy
    return slots


def shelved(problem) -> tuple[dict, dict]:
    """Placements into one region in shelves: rows across the direction from the robot,
    filled in the skeleton's order from the region's far end, a row closed once an
    object does not fit beside what is in it (what is put down later never passes what
    was put down before); equal gaps between the objects of a row, and between the rows
    and the region's ends. A region the shelves do not fit gets the packed row; one
    that receives a single object, its middle."""
    rows = _row_slots(problem)
    slots = {}
    for name, region in _regions(problem).items():
        steps = [s for s in _placing(problem) if s.target == name]
        if len(steps) < 2:
            slots.update({s.index: np.asarray(region.center, dtype=float) for s in steps})
            continue
        found = _shelves(problem, region, steps)
        slots.update(found if found is not None else {s.index: rows[s.index] for s in steps})
    return _walk(problem, lambda step, where, yaw, region: slots[step.index])


def _shelves(problem, region, steps) -> dict | None:
    """step -> (x, y) in shelves (`shelved`), or None where they do not fit.

    The depth axis is the world axis along which the region lies farther from the
    robot; each object's footprint at its start yaw (the yaw `_walk` gives it)."""
    robot = _robot_xy(problem)
    centre = np.asarray(region.center, dtype=float)
    depth = int(np.argmax(np.abs(centre - robot)))
    side = 1 - depth
    far = 1.0 if centre[depth] >= robot[depth] else -1.0
    sizes = []
    for s in steps:
        info = problem.bodies[s.obj]
        yaw = info.pose[3]
        if not problem.planar:
            yaw = _fitting_yaw(info, yaw, region)
        sizes.append((_extent(info, yaw, depth), _extent(info, yaw, side)))
    shelves: list[list[int]] = [[]]
    for i, (_, w) in enumerate(sizes):
        used = sum(sizes[j][1] for j in shelves[-1])
        if shelves[-1] and used + w > region.size[side]:
            shelves.append([])
        shelves[-1].append(i)
    deep = [max(sizes[j][0] for j in shelf) for shelf in shelves]
    if sum(deep) > region.size[depth] or any(
            sum(sizes[j][1] for j in shelf) > region.size[side] for shelf in shelves):
        return None
    gap = (region.size[depth] - sum(deep)) / (len(shelves) + 1)
    at = centre[depth] + far * 0.5 * region.size[depth]  # the far end
    out = {}
    for shelf, d in zip(shelves, deep, strict=True):
        middle = at - far * (gap + 0.5 * d)
        at = middle - far * 0.5 * d
        widths = [sizes[j][1] for j in shelf]
        lateral = (region.size[side] - sum(widths)) / (len(shelf) + 1)
        edge = centre[side] - 0.5 * region.size[side]
        for j, w in zip(shelf, widths, strict=True):
            xy = centre.copy()
            xy[depth] = middle
            xy[side] = edge + lateral + 0.5 * w
            edge = xy[side] + 0.5 * w
            out[steps[j].index] = xy
    return out


def clearest(problem) -> tuple[dict, dict]:
    """Each placement at the grid point of its region farthest from what rests there
    (at the start, or placed by an earlier step of this start) by then."""
    bodies = problem.bodies
    resting = {n for n, i in bodies.items() if not i.fixed}

    def pick(step, where, yaw, region):
        info = bodies[step.obj]
        lo, hi = np.asarray(region.lower), np.asarray(region.upper)
        half = 0.5 * np.array([_extent(info, yaw[step.obj], 0), _extent(info, yaw[step.obj], 1)])
        a, b = np.minimum(lo + half, region.center), np.maximum(hi - half, region.center)
        xs, ys = np.linspace(a[0], b[0], GRID), np.linspace(a[1], b[1], GRID)
        cand = np.array([[x, y] for x in xs for y in ys])
        others = [n for n in resting if n != step.obj]
        if not others:
            return np.asarray(region.center, dtype=float)
        gaps = np.min([np.linalg.norm(cand - where[n], axis=1) - bodies[n].radius
                       for n in others], axis=0)
        return cand[int(np.argmax(gaps))]

    return _walk(problem, pick)


def centred(problem) -> tuple[dict, dict]:
    """Every placement at its region's middle (a well-posed NLP with room to spare)."""
    return _walk(problem, lambda step, where, yaw, region: region.center)


TIGHT = 0.3  # a region whose row of placements leaves less of its length free is packed


def _row_use(problem) -> float:
    """The largest share of its long side a region's row of placements takes (at the
    objects' start yaws); 0 where no region receives several."""
    use = 0.0
    for name, region in _regions(problem).items():
        steps = [s for s in _placing(problem) if s.target == name]
        if len(steps) < 2:
            continue
        axis = int(np.argmax(region.size))
        used = sum(_extent(problem.bodies[s.obj], problem.bodies[s.obj].pose[3], axis)
                   for s in steps)
        use = max(use, used / region.size[axis])
    return use


def starts(problem) -> tuple:
    """The starts to try in order: the shelves first where a region's row would not fit
    along its long side (blind27 p05: a slab and two boxes, 20 cm of row in a 14.6 cm
    square pocket, packed as a column and a column of two); the packed row first when
    a region is tight (less than TIGHT of its long side to spare); else the middle."""
    use = _row_use(problem)
    if use > 1.0:
        return (shelved, packed, centred, clearest)
    if use > 1.0 - TIGHT:
        return (packed, centred, clearest, shelved)
    return (centred, packed, clearest, shelved)
