"""The rows of the "final" and "keyframes" NLPs, from one walk over the skeleton.

final:     x = (x, y, yaw) of every placement (place, push end); no robot.
keyframes: x = a configuration per keyframe + grip parameters; the held
           object's pose is the tool's pose composed with its grip, so a
           placement is a function of the place keyframe.
Both walks keep `state`: the pose (PoseX) of every resting movable object.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from tampcli.optimize import constraints as C
from tampcli.optimize.collide import body_matrices, contact_rows, held_of, held_spec, row_keys
from tampcli.optimize.expr import PoseX, RowSet, constant_pose, held_posex, planar_pose
from tampcli.optimize.grips import held_pose
from tampcli.optimize.init import target_rect
from tampcli.optimize.problem import Layout, TrajectoryProblem
from tampcli.optimize.world_state import grip_of, reach_of, vertical_overlap


@dataclass
class Rows:
    eq: RowSet = field(default_factory=RowSet)
    ineq: RowSet = field(default_factory=RowSet)
    cost: float = 0.0
    cost_grad: dict = field(default_factory=dict)  # block -> (size,)


def final_layout(problem: TrajectoryProblem) -> Layout:
    return Layout(tuple((f"p{s.index}", 3) for s in problem.steps if s.kind in ("place", "push")))


def keyframe_layout(problem: TrajectoryProblem) -> Layout:
    blocks = [(f"k{k}", problem.n) for k in range(problem.n_keyframes)]
    blocks += [(f"g{s}", 1) for s in problem.grip_params]
    return Layout(tuple(blocks))


def _start_state(problem) -> tuple[dict[str, PoseX], dict[str, float]]:
    movable = {n: i for n, i in problem.bodies.items() if not i.fixed}
    return ({n: constant_pose(*i.pose) for n, i in movable.items()},
            {n: i.pose[2] for n, i in movable.items()})


def _placement_rows(rows: Rows, problem, step, P: PoseX, state: dict, heights: dict) -> None:
    """Where a released or pushed object ends: inside its region / on its body, apart.

    `heights`: the resting height of every movable object (from the stack below it,
    not from x, so the set of rows does not change between evaluations).
    """
    info = problem.bodies[step.obj]
    name = step.name
    regions = {r.name: r for r in problem.scene.regions}
    if step.target in regions:
        C.inside_region(rows.ineq, name, P, info, regions[step.target])
    elif step.target is not None:
        C.on_top_of(rows.ineq, name, P, state[step.target] if step.target in state
                    else constant_pose(*problem.bodies[step.target].pose),
                    problem.bodies[step.target])
    z = step.rest_z
    for other, Q in state.items():
        if other in (step.obj, step.support):
            continue
        oinfo = problem.bodies[other]
        if vertical_overlap(z, info.half[2], heights[other], oinfo.half[2]):
            C.apart_disks(rows.ineq, name, P, info.radius, Q, oinfo.radius, other)
    # Against fixed bodies the object's inscribed circle: these rows steer the
    # placement (and decide the "final" stage); the keyframe stage's collision
    # rows then check the true shapes, so a circumscribed circle would only
    # reject tight placements that are feasible.
    for other, oinfo in problem.bodies.items():
        if oinfo.fixed and other != step.support and vertical_overlap(
                z, info.half[2], oinfo.pose[2], oinfo.half[2]):
            C.apart_rect(rows.ineq, name, P, info.radius if info.disk else
                         min(info.half[0], info.half[1]), oinfo)


def final_rows(problem: TrajectoryProblem, vals: dict, origins: dict) -> Rows:
    """`origins`: block -> (x, y) the cost pulls towards (the target's middle)."""
    rows = Rows()
    state, heights = _start_state(problem)
    centre, reach = reach_of(problem)
    for step in problem.steps:
        if step.kind == "grasp":
            state.pop(step.obj, None)
        elif step.kind in ("place", "push"):
            block = f"p{step.index}"
            x, y, yaw = vals[block]
            P = planar_pose(block, x, y, step.rest_z, yaw)
            _placement_rows(rows, problem, step, P, state, heights)
            if np.isfinite(reach):
                C.within_reach(rows.ineq, step.name, P, centre, reach)
            state[step.obj] = P
            heights[step.obj] = step.rest_z
            d = np.array([x, y]) - origins[block]
            rows.cost += 1e-2 * float(d @ d)
            rows.cost_grad[block] = np.array([2e-2 * d[0], 2e-2 * d[1], 0.0])
    return rows


def keyframe_rows(problem: TrajectoryProblem, vals: dict, choices: dict, kin, checker,
                  start: np.ndarray, collisions: bool = True) -> Rows:
    rows = Rows()
    opts = problem.options
    state, heights = _start_state(problem)
    held = None  # (name, grip step)
    planar = problem.planar
    bodies = list(problem.bodies)

    def q_of(k):
        return vals[f"k{k}"]

    # The tool frames of all keyframes at once (one batched forward kinematics).
    tool_frames = kin.frames([q_of(k) for k in range(problem.n_keyframes)])

    def gripped(k, grip_step_index):
        step = problem.steps[grip_step_index]
        grip = grip_of(problem, step, choices)
        t_block = f"g{grip_step_index}" if grip.has_param else None
        t = float(vals[t_block][0]) if t_block else 0.0
        frame = tool_frames[k]
        return frame, grip, t, t_block, held_posex(held_pose(frame, grip, t), f"k{k}", t_block)

    # Collision rows of all keyframes come from one batched query after the walk,
    # each keyframe in its own world state (what rests where, what is held).
    pending = []

    def collide(k, step, held_spec, frame, ignore):
        if collisions:
            moved = {n: P for n, P in state.items() if P.jac}
            pending.append((k, step.name, held_spec, frame, frozenset(ignore), moved))

    for step in problem.steps:
        if step.kind == "grasp":
            (k,) = step.keyframes
            frame, grip, t, t_block, H = gripped(k, step.index)
            info = problem.bodies[step.obj]
            C.same_pose(rows.eq, rows.ineq, step.name, H, state[step.obj], planar,
                        yaw=not info.disk and not planar)
            collide(k, step, _held_spec(problem, held, choices, vals), frame, {step.obj})
            held = (step.obj, step.index)
            state.pop(step.obj)
        elif step.kind == "place":
            (k,) = step.keyframes
            frame, grip, t, t_block, H = gripped(k, step.grasp_step)
            if not planar:
                C.upright(rows.eq, step.name, H, step.obj)
                C.rest_height(rows.eq, step.name, H, step.rest_z, step.support)
            _placement_rows(rows, problem, step, H, state, heights)
            collide(k, step, held_of(step.obj, grip, t, t_block), frame, {step.support})
            state[step.obj] = H
            heights[step.obj] = step.rest_z
            held = None
        elif step.kind == "push":
            k0, k1 = step.keyframes
            frame, grip, t, t_block, H0 = gripped(k0, step.index)
            info = problem.bodies[step.obj]
            C.same_pose(rows.eq, rows.ineq, step.name, H0, state[step.obj], planar,
                        yaw=not info.disk and not planar)
            collide(k0, step, None, frame, {step.obj})
            frame, grip, t, t_block, H1 = gripped(k1, step.index)
            if not planar:
                C.upright(rows.eq, step.name, H1, step.obj)
                C.rest_height(rows.eq, step.name, H1, step.rest_z, step.support)
            state.pop(step.obj)
            _placement_rows(rows, problem, step, H1, state, heights)
            collide(k1, step, held_of(step.obj, grip, t, t_block), frame, {step.support})
            state[step.obj] = H1
        elif step.kind == "move":
            (k,) = step.keyframes
            frame = tool_frames[k]
            if step.target is not None:
                tool = PoseX(np.concatenate([frame.p, np.zeros(9)]),
                             {f"k{k}": np.vstack([frame.Jp, np.zeros((9, problem.n))])})
                lo, hi = target_rect(problem, step.target)
                C.point_in_rect(rows.ineq, step.name, tool, lo, hi,
                                f"tool outside {step.target}")
            collide(k, step, _held_spec(problem, held, choices, vals), frame, set())
    if pending:
        contacts = checker.distances_many(
            np.array([q_of(k) for k, *_ in pending]),
            [body_matrices(moved) for *_, moved in pending],
            [held_spec(h) for _, _, h, _, _, _ in pending],
            [ignore for *_, ignore, _ in pending], opts.activation)
        for (k, name, h, frame, ignore, moved), found in zip(pending, contacts, strict=True):
            contact_rows(rows.ineq, name, found, [(f"k{k}", 1.0)], frame, h, moved,
                         row_keys(bodies, ignore, h), opts.activation, opts.margin)
    # Cost: sum over motions of |dq|^2 / T, the least path cost through these keyframes.
    T = opts.waypoints
    prev, prev_block = np.asarray(start, dtype=float), None
    for k in range(problem.n_keyframes):
        d = q_of(k) - prev
        rows.cost += float(d @ d) / T
        g = 2.0 * d / T
        rows.cost_grad[f"k{k}"] = rows.cost_grad.get(f"k{k}", 0.0) + g
        if prev_block is not None:
            rows.cost_grad[prev_block] = rows.cost_grad[prev_block] - g
        prev, prev_block = q_of(k), f"k{k}"
    return rows


def _held_spec(problem, held, choices, vals):
    if held is None:
        return None
    name, grip_step = held
    grip = grip_of(problem, problem.steps[grip_step], choices)
    t_block = f"g{grip_step}" if grip.has_param else None
    t = float(vals[t_block][0]) if t_block else 0.0
    return held_of(name, grip, t, t_block)


