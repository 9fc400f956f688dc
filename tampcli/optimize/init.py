"""Initial guesses: placements, IK keyframes, and via points for the paths.

Measured here: from a trivial initial guess SLSQP ran 37-177 s and failed on a
pick-place over a wall; from IK keyframes plus via points it converged in
under a second. So every keyframe starts at an IK solution of the tool pose
the action implies, and every path first lifts above what lies between.
"""

from __future__ import annotations

import math

import numpy as np

from tampcli.geometry import transforms
from tampcli.optimize.bodies import pose_matrix
from tampcli.optimize.grips import Grip
from tampcli.optimize.problem import PANDA_OPENING, TrajectoryProblem
from tampcli.optimize.world_state import grip_of

IK_TOLERANCE = 1e-3
MOVE_HOVER = 0.08  # m: a move's keyframe starts this far above its target
QUARTERS = (0.0, 0.5 * math.pi, math.pi, -0.5 * math.pi)


def final_guess(problem: TrajectoryProblem, warm: dict | None = None):
    """(x, y, yaw) per placement block, and the point each is pulled towards.

    The pull is to the middle of the target (region centre, support centre):
    away from rims and from clutter around the target, and a well-posed NLP
    when the target has room to spare.
    """
    vals, origins = {}, {}
    where = {n: np.array(i.pose[:2]) for n, i in problem.bodies.items()}
    yaw = {n: i.pose[3] for n, i in problem.bodies.items()}
    regions = {r.name: r for r in problem.scene.regions}
    for step in problem.steps:
        if step.kind not in ("place", "push"):
            continue
        block = f"p{step.index}"
        target = (np.asarray(regions[step.target].center, dtype=float)
                  if step.target in regions else where[step.target].copy())
        origins[block] = target
        if warm and block in warm:
            vals[block] = np.array(warm[block], dtype=float)
        else:
            vals[block] = np.array([target[0], target[1], yaw[step.obj]])
        where[step.obj] = vals[block][:2].copy()
        yaw[step.obj] = float(vals[block][2])
    return vals, origins


def keyframe_guess(problem: TrajectoryProblem, placements: dict, start, rng,
                   jitter: float = 0.0):
    """IK keyframes following the actions; returns (block values, discrete choices).

    `jitter` (rad) perturbs the IK seeds: a retry then lands in another IK branch.
    """
    world = problem.world
    vals: dict[str, np.ndarray] = {}
    choices: dict[str, float] = {}
    poses = {n: pose_matrix(*i.pose) for n, i in problem.bodies.items() if not i.fixed}
    q_prev = np.asarray(start, dtype=float)
    planar = problem.planar

    def solve_ik(target):
        seed = q_prev + rng.normal(0.0, jitter, len(q_prev)) if jitter else q_prev
        seed = np.clip(seed, world.lower, world.upper)
        q, res = world.ik(target, seed=seed, rng_seed=int(rng.integers(1 << 30)))
        return q, res

    def best_of(targets, held=None, ignore=frozenset()):
        """IK for each (target, tag): reachable first, then clear, then closest to q_prev."""
        best = None
        for target, tag in targets:
            q, res = solve_ik(target)
            clash = False
            if problem.checker is not None and len(targets) > 1:
                moved = {n: t for n, t in poses.items() if n not in (held or ("",))[0:1]}
                clash = problem.checker.min_distance(
                    q, moved, held, frozenset(ignore), static=False,
                    horizon=problem.options.margin) < problem.options.margin
            score = (res > IK_TOLERANCE, clash, float(np.linalg.norm(q - q_prev)))
            if best is None or score < best[0]:
                best = (score, q, tag)
        return best[1], best[2]

    for step in problem.steps:
        if step.kind == "none":
            continue
        if step.kind == "grasp":
            (k,) = step.keyframes
            obj_pose = poses[step.obj]
            if planar:
                p_prev = world.tool_pose(q_prev)[:2, 3]
                phi = _angle(obj_pose[:2, 3] - p_prev) + (rng.normal(0.0, 4 * jitter)
                                                           if jitter else 0.0)
                choices[f"z{step.index}"] = float(obj_pose[2, 3])
                choices[f"yaw{step.index}"] = transforms.yaw_of(obj_pose)
                grip = grip_of(problem, step, choices)
                vals[f"g{step.index}"] = np.array([phi])
                q = _planar_q(obj_pose[:3, 3], grip, phi)
            else:
                info = problem.bodies[step.obj]
                targets = []
                for psi in QUARTERS:
                    # Fingers close along the tool's y axis: the object's width there.
                    width = 2 * (info.half[1] if abs(math.cos(psi)) > 0.5 else info.half[0])
                    if not info.disk and width > PANDA_OPENING - 0.005:
                        continue
                    choices[f"psi{step.index}"] = psi
                    grip = grip_of(problem, step, choices)
                    targets.append((obj_pose @ _inv(grip.matrix(0.0)), psi))
                q, psi = best_of(targets, ignore={step.obj})
                choices[f"psi{step.index}"] = psi
            vals[f"k{k}"] = q
            q_prev = q
        elif step.kind == "place":
            (k,) = step.keyframes
            x, y, yaw = placements[f"p{step.index}"]
            grasp = problem.steps[step.grasp_step]
            grip = grip_of(problem, grasp, choices)
            if planar:
                phi = float(vals[f"g{grasp.index}"][0])
                q = _planar_q(np.array([x, y, step.rest_z]), grip, phi)
                P = pose_matrix(x, y, step.rest_z, yaw)
            else:
                targets = [(pose_matrix(x, y, step.rest_z, yaw + d) @ _inv(grip.matrix(0.0)),
                            yaw + d) for d in QUARTERS]
                q, yaw_ = best_of(targets, (step.obj, grip.matrix(0.0)), {step.support})
                P = pose_matrix(x, y, step.rest_z, yaw_)
            poses[step.obj] = P
            vals[f"k{k}"] = q
            q_prev = q
        elif step.kind == "push":
            k0, k1 = step.keyframes
            obj_pose = poses[step.obj]
            x, y, yaw = placements[f"p{step.index}"]
            u = np.array([x, y]) - obj_pose[:2, 3]
            u = u / np.linalg.norm(u) if np.linalg.norm(u) > 1e-9 else np.array([1.0, 0.0])
            grip = grip_of(problem, step, choices)
            if planar:
                phi = _angle(u)
                vals[f"g{step.index}"] = np.array([phi])
                choices[f"z{step.index}"] = float(obj_pose[2, 3])
                choices[f"yaw{step.index}"] = transforms.yaw_of(obj_pose)
                grip = grip_of(problem, step, choices)
                q0 = _planar_q(obj_pose[:3, 3], grip, phi)
                q1 = _planar_q(np.array([x, y, obj_pose[2, 3]]), grip, phi)
                yaw = transforms.yaw_of(obj_pose)
            else:
                alpha = _angle(-u)
                psi = transforms.yaw_of(obj_pose) - alpha
                vals[f"g{step.index}"] = np.array([psi])
                G = _inv(grip.matrix(psi))
                q0, _ = best_of([(obj_pose @ G, None)])
                q_prev = q0
                yaw = alpha + psi
                q1, _ = best_of([(pose_matrix(x, y, obj_pose[2, 3], yaw) @ G, None)])
            vals[f"k{k0}"], vals[f"k{k1}"] = q0, q1
            poses[step.obj] = pose_matrix(x, y, obj_pose[2, 3], yaw)
            q_prev = q1
        elif step.kind == "move":
            (k,) = step.keyframes
            T = world.tool_pose(q_prev).copy()
            if step.target is not None:
                lo, hi = target_rect(problem, step.target)
                T[:2, 3] = 0.5 * (np.asarray(lo) + np.asarray(hi))
                if not planar:
                    # Above the target, with what is held clear of it (resting contact
                    # has no useful distance gradient).
                    held_h = 2 * problem.bodies[step.held_before].half[2] \
                        if step.held_before else 0.0
                    T[2, 3] = max(T[2, 3], _top_under(problem, step.target) + held_h + MOVE_HOVER)
            q = T[:2, 3].copy() if planar else best_of([(T, None)])[0]
            vals[f"k{k}"] = np.clip(q, world.lower, world.upper)
            q_prev = vals[f"k{k}"]
    if not planar:
        _hover_before_next(problem, vals, rng)
    return vals, choices


def _hover_before_next(problem: TrajectoryProblem, vals: dict, rng) -> None:
    """Re-seed each move that leads into another keyframe from that keyframe, backwards.

    A move's keyframe only asks the hand to be above its target, so its best
    guess is the next action's configuration lifted clear: the forward guess
    (the previous hand pose slid over the target) can sit in another IK branch
    than the grasp or place that follows, and the keyframe NLP then stays in a
    local optimum several times the cost (measured on arm-kitchen: 1.28 vs 0.41).
    """
    world = problem.world
    keyframe_step = {k: step for step in problem.steps for k in step.keyframes}
    for k in range(problem.n_keyframes - 2, -1, -1):
        step = keyframe_step.get(k)
        if step is None or step.kind != "move" or step.target is None:
            continue
        q_next = vals.get(f"k{k + 1}")
        if q_next is None:
            continue
        t = world.tool_pose(q_next).copy()
        lo, hi = target_rect(problem, step.target)
        t[:2, 3] = np.clip(t[:2, 3], lo, hi)
        held_h = 2 * problem.bodies[step.held_before].half[2] if step.held_before else 0.0
        t[2, 3] = max(t[2, 3], _top_under(problem, step.target) + held_h) + MOVE_HOVER
        q, res = world.ik(t, seed=q_next, rng_seed=int(rng.integers(1 << 30)))
        if res < IK_TOLERANCE:
            vals[f"k{k}"] = np.clip(q, world.lower, world.upper)


def target_rect(problem, target):
    """(lo, hi) corners of a region, or of the rectangle inside a body's top face."""
    for r in problem.scene.regions:
        if r.name == target:
            return np.asarray(r.lower), np.asarray(r.upper)
    info = problem.bodies[target]
    c = np.asarray(info.pose[:2])
    h = np.array(info.half[:2]) if not info.disk else np.array([info.half[0]] * 2) / np.sqrt(2)
    return c - h, c + h


def _top_under(problem, target) -> float:
    body = next((r.on for r in problem.scene.regions if r.name == target), target)
    return problem.bodies[body].top


def _angle(v) -> float:
    return float(math.atan2(v[1], v[0]))


def _inv(t):
    return transforms.pose_inverse(t)


def _planar_q(obj_pos, grip: Grip, phi: float) -> np.ndarray:
    c, _, _, _ = grip.parts(phi)
    return np.asarray(obj_pos[:2], dtype=float) - c[:2]
