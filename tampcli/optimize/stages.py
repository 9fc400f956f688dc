"""The rows of the "final" and "keyframes" NLPs, from one walk over the skeleton.

final:     x = (x, y, yaw) of every placement (place, push end); no robot.
keyframes: x = a configuration per keyframe + grip parameters; the held
           object's pose is the tool's pose composed with its grip, so a
           placement is a function of the place keyframe.
Both walks keep `state`: the pose (PoseX) of every resting movable object;
each step's kind adds its rows (kinds/*.py: final_rows, keyframe_rows).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from tampcli.optimize import constraints as C
from tampcli.optimize import stability as S
from tampcli.optimize.collide import (
    body_matrices,
    contact_key,
    contact_rows,
    held_of,
    held_spec,
    row_keys,
)
from tampcli.optimize.expr import PoseX, RowSet, constant_pose, held_posex, planar_pose
from tampcli.optimize.grips import held_pose
from tampcli.optimize.layout import Layout, grip_block, keyframe_block, placement_block
from tampcli.optimize.problem import TrajectoryProblem
from tampcli.optimize.world_state import grip_of, reach_of, vertical_overlap

PULL = 1e-2  # cost per m^2 of a placement's distance from its origin (final NLP)


@dataclass
class Rows:
    eq: RowSet = field(default_factory=RowSet)
    ineq: RowSet = field(default_factory=RowSet)
    cost: float = 0.0
    cost_grad: dict = field(default_factory=dict)  # block -> (size,)
    # (block a, block b) -> (size a, size b) second derivatives of the cost, each pair
    # once (a before b in the layout); empty where not given (SLSQP does not use it).
    cost_hess: dict = field(default_factory=dict)


def final_layout(problem: TrajectoryProblem) -> Layout:
    return Layout(tuple((placement_block(s.index), 3) for s in problem.steps if s.kind.places))


def keyframe_layout(problem: TrajectoryProblem) -> Layout:
    blocks = [(keyframe_block(k), problem.n) for k in range(problem.n_keyframes)]
    blocks += [(grip_block(s), 1) for s in problem.grip_params]
    return Layout(tuple(blocks))


def _start_state(problem) -> tuple[dict[str, PoseX], dict[str, float], dict[str, str | None]]:
    """(pose, resting height, support) of every movable object at the start."""
    movable = {n: i for n, i in problem.bodies.items() if not i.fixed}
    return ({n: constant_pose(*i.pose) for n, i in movable.items()},
            {n: i.pose[2] for n, i in movable.items()},
            {n: problem.start_supports.get(n) for n in movable})


def _pose_of(problem, name: str, state: dict) -> PoseX:
    return state[name] if name in state else constant_pose(*problem.bodies[name].pose)


def _stability_rows(rows: Rows, problem, step, state: dict, supports: dict) -> None:
    """The placed object and every body under it keep their loads' centre of mass
    over their supports' top faces (stability.py)."""
    bodies = problem.bodies
    base, support, seen = step.obj, step.support, set()
    while support is not None and base not in seen:
        seen.add(base)
        load = [(state[n], bodies[n].mass) for n in S.load_of(base, state, supports)]
        S.com_on_face(rows.ineq, step.name, load, bodies[base], _pose_of(problem, support, state),
                      bodies[support])
        if support not in state:
            break
        base, support = support, supports.get(support)


def _clear_of_region(info, region) -> bool:
    """A fixed body whose footprint (its bounding circle) stays C.GAP clear of the
    region's rectangle: a footprint inside the region is apart from it, so its apart
    row is implied by the region's rows (arm-sort: most of each place's apart rows,
    the other tray's rims and the far obstacles, each evaluation of every NLP)."""
    (cx, cy), (sx, sy) = region.center, region.size
    dx = max(abs(info.pose[0] - cx) - 0.5 * sx, 0.0)
    dy = max(abs(info.pose[1] - cy) - 0.5 * sy, 0.0)
    radius = info.half[0] if info.disk else math.hypot(info.half[0], info.half[1])
    return math.hypot(dx, dy) - radius >= C.GAP


def _placement_rows(rows: Rows, problem, step, P: PoseX, state: dict, heights: dict,
                    supports: dict) -> None:
    """Where a released or pushed object ends: inside its region / on its body, apart,
    standing (stability.py). The object joins `state` resting on its support.

    `heights`: the resting height of every movable object (from the stack below it,
    not from x, so the set of rows does not change between evaluations).
    """
    info = problem.bodies[step.obj]
    name = step.name
    regions = {r.name: r for r in problem.scene.regions}
    if step.target in regions:
        C.inside_region(rows.ineq, name, P, info, regions[step.target])
    elif step.target is not None:
        S.footprint_on_face(rows.ineq, name, P, info, _pose_of(problem, step.target, state),
                            problem.bodies[step.target])
    z = step.rest_z
    for other, Q in state.items():
        if other in (step.obj, step.support):
            continue
        oinfo = problem.bodies[other]
        if vertical_overlap(z, info.half[2], heights[other], oinfo.half[2]):
            C.apart(rows.ineq, name, P, info, Q, oinfo, other)
    region = regions.get(step.target)
    for other, oinfo in problem.bodies.items():
        if oinfo.fixed and other != step.support and vertical_overlap(
                z, info.half[2], oinfo.pose[2], oinfo.half[2]) and not (
                region is not None and _clear_of_region(oinfo, region)):
            C.apart(rows.ineq, name, P, info, constant_pose(*oinfo.pose), oinfo, other)
    state[step.obj] = P
    heights[step.obj] = z
    supports[step.obj] = step.support
    _stability_rows(rows, problem, step, state, supports)


def _stacked(problem, step) -> bool:
    """Placed on a body rather than into a region."""
    return step.target is not None and step.target not in {r.name for r in problem.scene.regions}


class FinalWalk:
    """The "final" NLP's walk: resting poses so far, as functions of the placements."""

    def __init__(self, problem: TrajectoryProblem, vals: dict, origins: dict):
        self.problem = problem
        self.vals = vals
        self.origins = origins
        self.rows = Rows()
        self.state, self.heights, self.supports = _start_state(problem)
        self.last = dict(self.state)  # where each object last rested (it keeps that yaw held)
        self.centre, self.reach = reach_of(problem)

    def place(self, step) -> None:
        """The step's object comes to rest at its placement block: near its origin on a
        region, aligned with the body below on a body (the costs are the NLP's objective)."""
        block = placement_block(step.index)
        x, y, yaw = self.vals[block]
        P = planar_pose(block, x, y, step.rest_z, yaw)
        stacked = _stacked(self.problem, step)
        support = _pose_of(self.problem, step.support, self.state) if stacked else None
        _placement_rows(self.rows, self.problem, step, P, self.state, self.heights,
                        self.supports)
        if np.isfinite(self.reach):
            C.within_reach(self.rows.ineq, step.name, P, self.centre, self.reach)
        if self.problem.planar:
            # The planar robot does not turn what it carries or pushes.
            C.same_yaw(self.rows.eq, step.name, P, self.last[step.obj])
        self.last[step.obj] = P
        if stacked:
            cost, grad = S.align_cost(P, self.problem.bodies[step.obj], support,
                                      self.problem.bodies[step.support])
            self.rows.cost += cost
            for k, g in grad.items():
                self.rows.cost_grad[k] = self.rows.cost_grad.get(k, 0.0) + g
        else:
            d = np.array([x, y]) - self.origins[step.index]
            self.rows.cost += PULL * float(d @ d)
            self.rows.cost_grad[block] = np.array([2 * PULL * d[0], 2 * PULL * d[1], 0.0])


def final_rows(problem: TrajectoryProblem, vals: dict, origins: dict) -> Rows:
    """`origins`: step index -> (x, y) the cost pulls towards (the target's middle)."""
    walk = FinalWalk(problem, vals, origins)
    for step in problem.steps:
        step.kind.final_rows(walk, step)
    return walk.rows


class KeyframeWalk:
    """The keyframe NLP's walk: resting poses, what is held, pending collision queries."""

    def __init__(self, problem: TrajectoryProblem, vals: dict, choices: dict, tool_frames,
                 collisions: bool, anchors: dict | None = None, supports: bool = False):
        self.problem = problem
        self.support_rows = supports  # `collide`'s rows between the arm and a place's support
        self.anchors = anchors or {}  # step index -> ((x, y), radius) its placement keeps to
        self.planar = problem.planar
        self.vals = vals
        self.choices = choices
        self.tool_frames = tool_frames
        self.collisions = collisions
        self.rows = Rows()
        self.state, self.heights, self.supports = _start_state(problem)
        self.held = None  # (name, grip step)
        # Collision rows of all keyframes come from one batched query after the walk,
        # each keyframe in its own world state (what rests where, what is held).
        self.pending = []

    def _grip_t(self, grip_step_index):
        grip = grip_of(self.problem, self.problem.steps[grip_step_index], self.choices)
        t_block = grip_block(grip_step_index) if grip.has_param else None
        t = float(self.vals[t_block][0]) if t_block else 0.0
        return grip, t, t_block

    def gripped(self, k, grip_step_index):
        """(tool frame, grip, t, t block, held pose) at keyframe k, held by that step's grip."""
        grip, t, t_block = self._grip_t(grip_step_index)
        frame = self.tool_frames[k]
        return frame, grip, t, t_block, held_posex(held_pose(frame, grip, t),
                                                   keyframe_block(k), t_block)

    def held_now(self):
        """What is held at this point of the walk, as the collision rows take it."""
        if self.held is None:
            return None
        name, grip_step = self.held
        grip, t, t_block = self._grip_t(grip_step)
        return held_of(name, grip, t, t_block)

    def collide(self, k, step, held, frame, ignore) -> None:
        """The keyframe's collision rows, queried after the walk; `ignore`: the bodies
        it has no rows for. Where an arm sets an object down its support is left out
        (the object rests on it); with `supports`, out of the object's rows only, the
        arm's links keeping the tight margin from it (keyframe_stage.keyframes_with
        asks for them where a solved keyframe's links went into a support: blind34
        p01, a low put-down under a hood solved with the forearm 2.2 cm inside the
        table, which only the path stage's check found)."""
        if self.collisions:
            moved = {n: P for n, P in self.state.items() if P.jac}
            support = step.support if (self.support_rows and step.kind.places
                                        and held is not None and not self.planar
                                        and step.support in ignore) else None
            if support is not None:
                ignore = set(ignore) - {support}
            self.pending.append((k, step.name, held, frame, frozenset(ignore), moved,
                                 bool(step.kind.places), support))

    def placement_rows(self, step, P: PoseX) -> None:
        """The step's object rests at P from here on (it joins `state`), a box of a tower
        aligned with the box below (rows: the objective stays the motion's cost)."""
        bodies = self.problem.bodies
        # The planar robot keeps the yaw of what it moves: not its to line up.
        if not self.planar and _stacked(self.problem, step) and S.tower_pair(
                bodies[step.obj], bodies[step.support]):
            S.aligned(self.rows.ineq, step.name, P,
                      _pose_of(self.problem, step.support, self.state), bodies[step.support])
        _placement_rows(self.rows, self.problem, step, P, self.state, self.heights,
                        self.supports)
        if step.index in self.anchors:
            C.near(self.rows.ineq, step.name, P, *self.anchors[step.index])


def keyframe_rows(problem: TrajectoryProblem, vals: dict, choices: dict, kin, checker,
                  start: np.ndarray, collisions: bool = True, anchors: dict | None = None,
                  supports: bool = False) -> Rows:
    """`anchors`: step index -> ((x, y), radius): placements kept near a spot
    (optimize/relocate: clear of a later motion)."""
    opts = problem.options
    bodies = list(problem.bodies)

    def q_of(k):
        return vals[keyframe_block(k)]

    # The tool frames of all keyframes at once (one batched forward kinematics).
    tool_frames = kin.frames([q_of(k) for k in range(problem.n_keyframes)])
    walk = KeyframeWalk(problem, vals, choices, tool_frames, collisions, anchors, supports)
    for step in problem.steps:
        step.kind.keyframe_rows(walk, step)
    rows, pending = walk.rows, walk.pending
    if pending:
        contacts = checker.distances_many(
            np.array([q_of(k) for k, *_ in pending]),
            [body_matrices(p[5]) for p in pending],
            [held_spec(p[2]) for p in pending],
            [p[4] for p in pending], opts.activation)
        for (k, name, h, frame, ignore, moved, placing, support), found in zip(
                pending, contacts, strict=True):
            keys, at = row_keys(bodies, ignore, h), [(keyframe_block(k), 1.0)]
            if placing and h is not None and not problem.planar:
                # What an arm sets down keeps the placement rows' gap (`apart`: 1 mm) from
                # its neighbours, not the margin the robot keeps: the final stage packs
                # them so (arm-sort: cubes 1 mm apart in a bin, a keyframe NLP held to
                # 1 cm between them failed until its tight retry). Not the planar disk's:
                # its first suction face then solves, a straight push into a slot 1 mm
                # from a neighbour all the way in, which the physics replay snags
                # (robust-planar p10: the neighbour pushed 4.4 cm; the margin's keyframes
                # fail there and the tight retry takes the NLP's own angle, drift 0).
                own = f"held:{h.name}"
                contact_rows(rows.ineq, name, [c for c in found if c.a != own], at, frame,
                             h, moved, keys, opts.activation, opts.margin,
                             {support: opts.tight_margin} if support else None)
                contact_rows(rows.ineq, name, [c for c in found if c.a == own
                                               and contact_key(c) != support], at, frame,
                             h, moved, keys, opts.activation, opts.tight_margin,
                             {"self": opts.margin})
            else:
                contact_rows(rows.ineq, name, found, at, frame, h, moved, keys,
                             opts.activation, opts.margin)
    # Cost: sum over motions of |dq|^2 / T, the least path cost through these keyframes.
    T = opts.waypoints
    prev, prev_block = np.asarray(start, dtype=float), None
    for k in range(problem.n_keyframes):
        block = keyframe_block(k)
        d = q_of(k) - prev
        rows.cost += float(d @ d) / T
        g = 2.0 * d / T
        rows.cost_grad[block] = rows.cost_grad.get(block, 0.0) + g
        if prev_block is not None:
            rows.cost_grad[prev_block] = rows.cost_grad[prev_block] - g
        prev, prev_block = q_of(k), block
    return rows
